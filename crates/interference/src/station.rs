//! A station's mechanism as collision parts, from the mechanism seam alone
//! ([`FlapMechanism`]): each solid of each body becomes a part that moves with its body's
//! pose, with the body's certified speed bound; the joints' touching solids become
//! [`DeclaredContact`]s. Nothing here names a mechanism kind. Deployment parameter: the
//! drive fraction τ in [0, 1] common to every station of the wing (input = stowed + τ
//! travel at each; `flapwright_mechanism::seam`), so speed bounds are per unit τ: the
//! body's bound per unit input times the input travel.

use std::sync::Arc;

use flapwright_geom::collision::CollisionShape;
use flapwright_geom::TriMesh;
use flapwright_mechanism::seam::{BodyRole, FlapMechanism, JointEnd, PlanarShape, SpeedBound};
use flapwright_mechanism::spanwise::spanwise_layout;
use nalgebra::{Isometry2, Isometry3, Point2, Point3, Translation3, UnitQuaternion, Vector3};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::fairing::PlanarCapsule;
use crate::opening::{cut_opening, OpenedSurface, Opening};
use crate::part::{Motion, Part};

/// Sides of the round tubes that stand for tracks.
const TUBE_SIDES: usize = 16;

/// A contact that exists by design (a joint): checked to stay joined, not for clearance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeclaredContact {
    /// Station.
    pub station: String,
    /// First part.
    pub part_a: String,
    /// Second part.
    pub part_b: String,
    /// The joint that makes them touch.
    pub joint: String,
}

/// One part of a station and where it belongs in the mechanism.
#[derive(Debug)]
pub struct StationPart {
    /// The collision part, named `<station>.<solid>`, in its spanwise layer
    /// (`flapwright_mechanism::spanwise`).
    pub part: Part,
    /// The same solid in the station plane: joints are checked there (a pin spans the
    /// layers of the two bodies it joins).
    pub in_plane: Part,
    /// Index of its body in the mechanism's bodies.
    pub body: usize,
    /// Its body's role.
    pub role: BodyRole,
    /// True when its body moves with the deployment.
    pub moving: bool,
    /// The other bodies this solid touches by design ([`joined_solids`]): it passes
    /// through their slot, and only it does.
    pub joined_to: Vec<usize>,
}

/// For every body, for each of its solids, the other bodies it is joined to by design: a
/// joint between its body and another names the solid among its touching pairs, or names
/// no touching pair at all (then every solid of the body counts, as a bare pin joins the
/// whole body). A solid of a body that a joint holds elsewhere is not joined: on a
/// hooked-track the hook carries the flap's roller and passes through the flap's slot, the
/// jack body on the same support does not, and is checked against the whole flap.
pub fn joined_solids(mechanism: &dyn FlapMechanism) -> Vec<Vec<Vec<usize>>> {
    let bodies = mechanism.bodies();
    let mut joined: Vec<Vec<Vec<usize>>> = bodies.iter().map(|b| vec![Vec::new(); b.solids.len()]).collect();
    for joint in mechanism.joints() {
        let [JointEnd::Body(a), JointEnd::Body(b)] = joint.ends else {
            continue;
        };
        for (this, other, end) in [(a, b, 0), (b, a, 1)] {
            let Some(body) = bodies.get(this) else {
                continue;
            };
            for (s, solid) in body.solids.iter().enumerate() {
                let named = joint.touching_solids.is_empty()
                    || joint.touching_solids.iter().any(|pair| {
                        if end == 0 {
                            pair.0 == solid.name
                        } else {
                            pair.1 == solid.name
                        }
                    });
                if named && !joined[this][s].contains(&other) {
                    joined[this][s].push(other);
                }
            }
        }
    }
    joined
}

/// The parts of one station.
#[derive(Debug)]
pub struct StationParts {
    /// Station name.
    pub station: String,
    /// The flap the station carries (its flap body is that flap); parts are checked
    /// against every other flap without waivers.
    pub flap: Option<String>,
    /// Every solid of every body.
    pub parts: Vec<StationPart>,
    /// Contacts by design, from the joints.
    pub declared: Vec<DeclaredContact>,
    /// Pairs of bodies joined by a joint, with the joint (body indices; the flap body is
    /// the one with [`BodyRole::Flap`]).
    pub joined: Vec<(usize, usize, String)>,
    /// Where the skin and the flap are opened for this station ([`StationParts::cut_openings`]).
    pub opening: Option<Opening>,
    /// The wing skins with this station's opening cut (sheets, fixed): its parts are checked
    /// against these in place of the whole skins.
    pub opened_skins: Vec<Part>,
    /// Its flap with the slot cut (a sheet moving with the flap): the parts joined to the
    /// flap are checked against it.
    pub slotted_flap: Option<Part>,
    /// Its flap's aft element with the same slot cut: the parts joined to the body that
    /// moves it are checked against it.
    pub slotted_aft_element: Option<Part>,
}

impl StationParts {
    /// Every part of the station.
    pub fn parts(&self) -> impl Iterator<Item = &Part> {
        self.parts.iter().map(|p| &p.part)
    }

    /// Cuts `opening` in each of `skins` (the part and its mesh, aircraft frame) and in the
    /// station's flap (`flap`: the moving part and its stowed mesh) and its aft element
    /// (`aft_element`, likewise), placed by `aircraft_from_station`; the parts are then
    /// checked against what is left.
    pub fn cut_openings(
        &mut self,
        mut opening: Opening,
        aircraft_from_station: &Isometry3<f64>,
        skins: &[(&Part, &TriMesh)],
        flap: Option<(&Part, &TriMesh)>,
        aft_element: Option<(&Part, &TriMesh)>,
    ) -> Result<()> {
        let sheet = |part: &Part, mesh: &TriMesh, surface: OpenedSurface| -> Result<(Part, f64)> {
            let (left, removed_m2) = cut_opening(mesh, aircraft_from_station, &opening, surface);
            let shape = CollisionShape::from_surface(&left).map_err(|source| Error::Query {
                part_a: format!("{} (opened for station {})", part.name, self.station),
                part_b: String::new(),
                parameter: 0.0,
                source: Box::new(source),
            })?;
            Ok((part.reshaped(shape), removed_m2))
        };
        let mut opened = Vec::new();
        let mut skin_area_m2 = 0.0;
        for (part, mesh) in skins {
            let (sheet, removed_m2) = sheet(part, mesh, OpenedSurface::WingSkin)?;
            opened.push(sheet);
            skin_area_m2 += removed_m2;
        }
        let mut flap_area_m2 = 0.0;
        let mut slot = |element: Option<(&Part, &TriMesh)>| -> Result<Option<Part>> {
            element
                .map(|(part, mesh)| {
                    let (sheet, removed_m2) = sheet(part, mesh, OpenedSurface::Flap)?;
                    flap_area_m2 += removed_m2;
                    Ok(sheet)
                })
                .transpose()
        };
        let slotted = slot(flap)?;
        let slotted_aft = slot(aft_element)?;
        opening.flap_area_m2 = flap_area_m2;
        opening.skin_area_m2 = skin_area_m2;
        self.opened_skins = opened;
        self.slotted_flap = slotted;
        self.slotted_aft_element = slotted_aft;
        self.opening = Some(opening);
        Ok(())
    }

    /// The joint joining bodies `a` and `b`, if one does.
    pub fn joint_between(&self, a: usize, b: usize) -> Option<&str> {
        self.joined
            .iter()
            .find(|(x, y, _)| (*x == a && *y == b) || (*x == b && *y == a))
            .map(|(_, _, name)| name.as_str())
    }
}

/// A body's motion in the aircraft frame at drive fraction τ: its planar displacement from
/// the seam, lifted through the station frame, then the solid's own offset (balls are
/// centred at their local origin).
struct BodyMotion {
    mechanism: Arc<dyn FlapMechanism>,
    body: usize,
    aircraft_from_station: Isometry3<f64>,
    station_from_aircraft: Isometry3<f64>,
    offset: Isometry3<f64>,
    /// m per unit τ.
    speed_bound: f64,
    /// The body's own bound (per unit input) and the input travel, for its field.
    body_bound: SpeedBound,
    travel: f64,
}

/// The planar displacement as a rigid motion of the station frame (about its z axis).
pub(crate) fn lift(displacement: &Isometry2<f64>) -> Isometry3<f64> {
    let t = displacement.translation.vector;
    Isometry3::from_parts(
        Translation3::new(t.x, t.y, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), displacement.rotation.angle()),
    )
}

impl BodyMotion {
    fn displacement(&self, fraction: f64) -> std::result::Result<Isometry2<f64>, flapwright_mechanism::Error> {
        let input = self.mechanism.input_range().at_fraction(fraction);
        let pose = self.mechanism.pose(input)?;
        Ok(FlapElement::displacement(self.body, &pose))
    }
}

/// Marks the motion of a flap's 3D mesh: it follows the pose's flap displacement.
pub(crate) const FLAP_MESH: usize = usize::MAX;

/// Which element of a flap a 3D part is: what moves it is written in roles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FlapElement {
    /// The flap, or a two-element flap's main element: moves with the pose's flap
    /// displacement (the [`BodyRole::Flap`] body).
    Main,
    /// A two-element flap's aft element: moves with the [`BodyRole::AftFlap`] body, or
    /// with the main element where the kind has none (the aft element fixed to it).
    Aft,
}

impl FlapElement {
    /// The body that carries the element in `mechanism`: its index ([`FLAP_MESH`] for the
    /// pose's flap displacement) and the body, for its speed bound.
    pub(crate) fn carrier(self, mechanism: &dyn FlapMechanism) -> Option<(usize, &flapwright_mechanism::seam::Body)> {
        let bodies = mechanism.bodies();
        let aft = match self {
            Self::Main => None,
            Self::Aft => flapwright_mechanism::seam::aft_flap_body(bodies),
        };
        match aft {
            Some(k) => Some((k, &bodies[k])),
            None => bodies.iter().find(|b| b.role == BodyRole::Flap).map(|b| (FLAP_MESH, b)),
        }
    }

    /// The element's displacement from stowed in `pose`, for the body index
    /// [`FlapElement::carrier`] gave.
    pub(crate) fn displacement(body: usize, pose: &flapwright_mechanism::seam::MechanismPose) -> Isometry2<f64> {
        pose.aft_flap((body != FLAP_MESH).then_some(body))
    }
}

impl Motion for BodyMotion {
    fn pose_ac(&self, fraction: f64) -> std::result::Result<Isometry3<f64>, flapwright_mechanism::Error> {
        let displacement = self.displacement(fraction)?;
        Ok(self.aircraft_from_station * lift(&displacement) * self.station_from_aircraft * self.offset)
    }

    fn speed_bound(&self) -> f64 {
        self.speed_bound
    }

    /// The lifted planar motion's field at a point depends on the point's distance from
    /// the body's reference in the station plane: [`SpeedBound::within`] that distance,
    /// largest at a corner of the points' hull (the distance is convex).
    fn field_speed_bound(&self, local_points: &[Point3<f64>]) -> Option<f64> {
        let (bound, travel) = (&self.body_bound, self.travel);
        let reach_m = local_points
            .iter()
            .map(|y| {
                let p = self.station_from_aircraft * (self.offset * y);
                nalgebra::distance(&Point2::new(p.x, p.y), &bound.reference)
            })
            .fold(0.0, f64::max);
        Some(bound.within(reach_m) * travel)
    }
}

/// A flap's 3D mesh (its main or aft `element`) moving with the displacement of the body
/// that carries it at the station (`mechanism`, placed by `aircraft_from_station`);
/// `vertices_ac` bound its speed: that body's bound at the vertex farthest from the
/// station z line through its reference point.
pub fn flap_part(
    name: &str,
    element: FlapElement,
    shape: CollisionShape,
    vertices_ac: &[Point3<f64>],
    aircraft_from_station: &Isometry3<f64>,
    mechanism: &Arc<dyn FlapMechanism>,
) -> Result<Part> {
    let (body, flap_body) = element
        .carrier(mechanism.as_ref())
        .ok_or_else(|| Error::NoFlapBody { part: name.to_string() })?;
    let bound = &flap_body.speed_bound;
    // The lifted planar motion turns about the station's z axis: a point's speed grows
    // with its distance from the z line through the reference, not with its spanwise
    // offset (a flap's far end lies metres away along the span, at the same radius).
    let station_from_aircraft = aircraft_from_station.inverse();
    let reach_m = vertices_ac
        .iter()
        .map(|v| {
            let p = station_from_aircraft.transform_point(v);
            (Point2::new(p.x, p.y) - bound.reference).norm()
        })
        .fold(0.0, f64::max);
    Ok(Part::moving(
        name.to_string(),
        shape,
        BodyMotion {
            mechanism: Arc::clone(mechanism),
            body,
            aircraft_from_station: *aircraft_from_station,
            station_from_aircraft: aircraft_from_station.inverse(),
            offset: Isometry3::identity(),
            speed_bound: bound.within(reach_m) * mechanism.input_range().travel().abs(),
            body_bound: *bound,
            travel: mechanism.input_range().travel().abs(),
        },
    ))
}

/// Builds the station's parts, placed by `aircraft_from_station` (the station frame: origin
/// A0 on the hinge axis, z along it).
pub fn station_parts(
    station: &str,
    flap: Option<&str>,
    aircraft_from_station: &Isometry3<f64>,
    mechanism: &Arc<dyn FlapMechanism>,
) -> Result<StationParts> {
    let query = |source| Error::Query {
        part_a: format!("{station}.parts"),
        part_b: String::new(),
        parameter: 0.0,
        source: Box::new(source),
    };
    // Each solid in its spanwise layer (station z), so that the parts of one station can
    // be checked against each other.
    let offsets = spanwise_layout(mechanism.as_ref()).map_err(|source| Error::Pose {
        part: format!("{station} (spanwise layout)"),
        parameter: 0.0,
        source,
    })?;
    let joined_to = joined_solids(mechanism.as_ref());
    let mut parts = Vec::new();
    for (index, body) in mechanism.bodies().iter().enumerate() {
        for (s, (solid, &z)) in body.solids.iter().zip(&offsets[index]).enumerate() {
            let name = format!("{station}.{}", solid.name);
            // The solid at spanwise offset z, as a part moving with its body.
            let part_at = |z: f64| -> Result<Part> {
                let to_ac = |p: &Point2<f64>| aircraft_from_station.transform_point(&Point3::new(p.x, p.y, z));
                let (shape, offset) = match &solid.shape {
                    PlanarShape::Capsule { from, to, radius_m } if from == to => {
                        let centre = to_ac(from);
                        (
                            CollisionShape::ball(*radius_m).map_err(query)?,
                            Isometry3::translation(centre.x, centre.y, centre.z),
                        )
                    }
                    PlanarShape::Capsule { from, to, radius_m } => (
                        CollisionShape::capsule(to_ac(from), to_ac(to), *radius_m).map_err(query)?,
                        Isometry3::identity(),
                    ),
                    PlanarShape::Tube { centre_line, radius_m } => {
                        let centre_line: Vec<Point3<f64>> = centre_line.iter().map(to_ac).collect();
                        let mesh = flapwright_geom::tube_mesh(&centre_line, *radius_m, TUBE_SIDES, radius_m * 4.0)
                            .map_err(query)?;
                        (CollisionShape::from_mesh(&mesh).map_err(query)?, Isometry3::identity())
                    }
                };
                Ok(if body.is_moving() {
                    Part::moving(
                        name.clone(),
                        shape,
                        BodyMotion {
                            mechanism: Arc::clone(mechanism),
                            body: index,
                            aircraft_from_station: *aircraft_from_station,
                            station_from_aircraft: aircraft_from_station.inverse(),
                            offset,
                            speed_bound: body.speed_bound.for_shape(&solid.shape)
                                * mechanism.input_range().travel().abs(),
                            body_bound: body.speed_bound,
                            travel: mechanism.input_range().travel().abs(),
                        },
                    )
                } else {
                    Part::fixed_at(name.clone(), shape, offset)
                })
            };
            let (part, in_plane) = (part_at(z)?, part_at(0.0)?);
            parts.push(StationPart {
                part,
                in_plane,
                body: index,
                role: body.role,
                moving: body.is_moving(),
                joined_to: joined_to[index][s].clone(),
            });
        }
    }
    let mut declared = Vec::new();
    let mut joined = Vec::new();
    for joint in mechanism.joints() {
        let label = format!("{} ({})", joint.name, joint.description);
        for (a, b) in &joint.touching_solids {
            declared.push(DeclaredContact {
                station: station.to_string(),
                part_a: format!("{station}.{a}"),
                part_b: format!("{station}.{b}"),
                joint: label.clone(),
            });
        }
        if let [JointEnd::Body(a), JointEnd::Body(b)] = joint.ends {
            joined.push((a, b, joint.name.clone()));
        }
    }
    Ok(StationParts {
        station: station.to_string(),
        flap: flap.map(str::to_string),
        parts,
        declared,
        joined,
        opening: None,
        opened_skins: Vec::new(),
        slotted_flap: None,
        slotted_aft_element: None,
    })
}

/// The station's solids in its plane at drive fraction `fraction`, as the fairing measures
/// them: capsules as they are, tubes as chains of capsules; the same solids as
/// [`station_parts`].
pub fn planar_parts(mechanism: &dyn FlapMechanism, fraction: f64) -> flapwright_mechanism::Result<Vec<PlanarCapsule>> {
    let pose = mechanism.pose(mechanism.input_range().at_fraction(fraction))?;
    let mut capsules = Vec::new();
    for (body, placement) in mechanism.bodies().iter().zip(&pose.bodies) {
        for solid in &body.solids {
            let skeleton: Vec<Point2<f64>> = solid.shape.skeleton().iter().map(|p| placement * p).collect();
            let radius_m = solid.shape.radius_m();
            let capsule = |from: Point2<f64>, to: Point2<f64>| PlanarCapsule {
                part: solid.name.clone(),
                from,
                to,
                radius_m,
            };
            match skeleton.as_slice() {
                [only] => capsules.push(capsule(*only, *only)),
                many => capsules.extend(many.windows(2).map(|w| capsule(w[0], w[1]))),
            }
        }
    }
    Ok(capsules)
}
