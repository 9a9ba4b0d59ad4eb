//! The parts of a circular-arc-track station (thesis `000`, Fig. 10) as collision parts:
//! moving, the screw B0-B (capsule), the jack body round B0 turning with it (capsule), the
//! nut at A (ball) and the flap's fittings A-D, F-D, G-D (capsules) that carry the pins
//! and the nut pivot; fixed, the two slot tracks (round tubes swept along the pins' arcs
//! about A0). Deployment parameter: flap rotation t = θ12 - θ12,i (rad).

use flapwright_geom::collision::CollisionShape;
use flapwright_mechanism::CircularArcTrack;
use nalgebra::{Isometry3, Point2, Point3, Rotation2, Unit, Vector2, Vector3};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::fairing::PlanarCapsule;
use crate::motion::{AboutAxis, ScrewAboutMount};
use crate::part::Part;

/// Sizes of the solids that stand for the links (m). The defaults are representative of
/// the thesis's small-aircraft flap; the sizing stage does not feed them back yet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSizes {
    /// Radius of the fitting capsules A-D, F-D, G-D.
    pub fitting_radius_m: f64,
    /// Radius of the nut ball at A.
    pub nut_radius_m: f64,
    /// Radius of a slot track's swept solid (pin radius plus the track's wall).
    pub track_radius_m: f64,
    /// Length and radius of the jack body (gearbox housing) centred on B0 along the screw.
    pub jack_body_length_m: f64,
    /// See `jack_body_length_m`.
    pub jack_body_radius_m: f64,
}

impl Default for LinkSizes {
    fn default() -> Self {
        Self {
            fitting_radius_m: 0.008,
            nut_radius_m: 0.020,
            // An 8 mm pin in a track with a 4 mm wall.
            track_radius_m: 0.012,
            // Reaches 55 mm from B0: clear of the nut (20 mm) at the shortest stroke, 80 mm.
            jack_body_length_m: 0.060,
            jack_body_radius_m: 0.025,
        }
    }
}

/// Largest angle (rad) between points of a track's centre line: 2 degrees keeps the
/// chord within R (1 - cos 1°) = 0.015 % of the radius of the arc.
const TRACK_STEP_RAD: f64 = std::f64::consts::PI / 90.0;

/// Points round the track of a pin at `radius_m` about A0 from `start_rad` over
/// `range_rad`, extended by `extra_m` of arc at both ends so the pin's end positions sit
/// inside the track.
fn track_centre_line(radius_m: f64, start_rad: f64, range_rad: f64, extra_m: f64) -> Vec<Point2<f64>> {
    // The extension covers the pin's end caps; on a slot radius smaller than the pin it
    // would wind round many times (1e-300 m asked for 1e300 steps), and a quarter turn
    // already encloses the pin there.
    let extra_rad = (extra_m / radius_m).min(std::f64::consts::FRAC_PI_2);
    let (from, to) = (start_rad - extra_rad, start_rad + range_rad + extra_rad);
    let steps = (((to - from) / TRACK_STEP_RAD).ceil() as usize).max(1);
    (0..=steps)
        .map(|i| {
            let angle = from + (to - from) * i as f64 / steps as f64;
            Point2::new(radius_m * angle.cos(), radius_m * angle.sin())
        })
        .collect()
}

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

/// The moving parts of one station.
#[derive(Debug)]
pub struct TrackParts {
    /// Station name.
    pub station: String,
    /// The screw (turns about B0).
    pub screw: Part,
    /// The jack body round B0 (turns with the screw).
    pub jack_body: Part,
    /// Parts rigid with the flap: nut and fittings.
    pub flap_rigid: Vec<Part>,
    /// The slot tracks (fixed): outer (pin F), inner (pin G).
    pub tracks: Vec<Part>,
    /// Contacts by design: the nut rides on the screw; the screw passes the fitting at A;
    /// the pins F and G ride in their tracks; the screw turns in the jack body.
    pub declared: Vec<DeclaredContact>,
}

impl TrackParts {
    /// Every part of the station: screw, jack body, nut, fittings, tracks.
    pub fn parts(&self) -> impl Iterator<Item = &Part> {
        [&self.screw, &self.jack_body]
            .into_iter()
            .chain(&self.flap_rigid)
            .chain(&self.tracks)
    }
}

/// Outer radius of a square thread of mean radius r and lead l: r + l/4 (thread depth l/2).
pub fn screw_outer_radius_m(track: &CircularArcTrack) -> f64 {
    let screw = &track.spec().screw;
    screw.mean_radius_m + 0.25 * screw.lead_m
}

/// A station's solids in its plane (station frame, stowed): one description that
/// [`track_parts`] places in 3D and [`TrackLayout::planar_parts`] turns in the plane, so
/// the interference check and the fairing depth measure the same hardware. Built once per
/// station; posing it is cheap.
#[derive(Debug, Clone)]
pub struct TrackLayout {
    sizes: LinkSizes,
    /// Screw mount B0.
    b0: Point2<f64>,
    /// Nut pivot A, stowed.
    a: Point2<f64>,
    /// Flap centre of mass D, stowed: where the fittings meet.
    d: Point2<f64>,
    screw_length_m: f64,
    screw_radius_m: f64,
    /// Fittings rigid with the flap: name and pin (stowed), each a capsule pin-D.
    fittings: [(&'static str, Point2<f64>); 3],
    /// Slot tracks (fixed): name and centre line.
    tracks: [(&'static str, Vec<Point2<f64>>); 2],
}

impl TrackLayout {
    /// The layout of `track` with solids of `sizes`.
    pub fn new(track: &CircularArcTrack, sizes: &LinkSizes) -> Self {
        let synthesis = track.synthesis();
        let spec = track.spec();
        let a = synthesis.nut_pivot_stowed_m;
        let centre_line =
            |radius_m, start_rad| track_centre_line(radius_m, start_rad, spec.rotation_range_rad, sizes.track_radius_m);
        Self {
            sizes: *sizes,
            b0: synthesis.screw_mount_m,
            a,
            d: spec.centre_of_mass_stowed_m,
            screw_length_m: spec.screw_length_m,
            screw_radius_m: screw_outer_radius_m(track),
            fittings: [
                ("fitting-A", a),
                ("fitting-F", synthesis.outer_pin_stowed_m),
                ("fitting-G", synthesis.inner_pin_stowed_m),
            ],
            tracks: [
                (
                    "outer-track",
                    centre_line(spec.outer_slot_radius_m, spec.outer_slot_start_angle_rad),
                ),
                (
                    "inner-track",
                    centre_line(
                        spec.inner_slot_radius_m,
                        spec.outer_slot_start_angle_rad + spec.inner_slot_offset_angle_rad,
                    ),
                ),
            ],
        }
    }

    /// The station's solids in the station plane at flap rotation `t` (rad): screw and jack
    /// body turning about B0 to follow the nut, nut and fittings turning with the flap about
    /// A0, and the fixed tracks as chains of capsules; the same solids as [`track_parts`].
    pub fn planar_parts(&self, t: f64) -> Vec<PlanarCapsule> {
        let (layout, sizes) = (self, &self.sizes);
        let turn = Rotation2::new(t);
        let a = turn * layout.a;
        let d = turn * layout.d;
        let direction = layout.screw_direction(a);
        let half_body = direction * (0.5 * sizes.jack_body_length_m);
        let capsule = |part, from, to, radius_m| PlanarCapsule {
            part,
            from,
            to,
            radius_m,
        };
        let mut parts = vec![
            capsule(
                "screw",
                layout.b0,
                layout.b0 + direction * layout.screw_length_m,
                layout.screw_radius_m,
            ),
            capsule(
                "jack-body",
                layout.b0 - half_body,
                layout.b0 + half_body,
                sizes.jack_body_radius_m,
            ),
            capsule("nut", a, a, sizes.nut_radius_m),
        ];
        for (name, pin) in layout.fittings {
            parts.push(capsule(name, turn * pin, d, sizes.fitting_radius_m));
        }
        for (name, centre_line) in &layout.tracks {
            for segment in centre_line.windows(2) {
                parts.push(capsule(name, segment[0], segment[1], sizes.track_radius_m));
            }
        }
        parts
    }

    /// Unit vector from B0 along the screw when the nut pivot is at `a`.
    fn screw_direction(&self, a: Point2<f64>) -> Vector2<f64> {
        (a - self.b0).normalize()
    }
}

/// Builds the station's parts, placed by `aircraft_from_station` (the station frame: origin
/// A0 on the hinge axis, z along it).
pub fn track_parts(
    station: &str,
    aircraft_from_station: &Isometry3<f64>,
    track: &CircularArcTrack,
    sizes: &LinkSizes,
) -> Result<TrackParts> {
    let layout = TrackLayout::new(track, sizes);
    let to_ac = |p: &Point2<f64>| aircraft_from_station.transform_point(&Point3::new(p.x, p.y, 0.0));
    let query = |source| Error::Query {
        part_a: format!("{station}.parts"),
        part_b: String::new(),
        parameter: 0.0,
        source: Box::new(source),
    };
    let (b0, a) = (layout.b0, layout.a);
    let direction = layout.screw_direction(a);
    let b = b0 + direction * layout.screw_length_m;
    let screw_radius = layout.screw_radius_m;
    let turning_about_b0 = |max_reach_m: f64| ScrewAboutMount {
        aircraft_from_station: *aircraft_from_station,
        mount_st: b0,
        nut_pivot_stowed_st: a,
        max_reach_m,
        min_extension_m: track.synthesis().stroke_start_m,
    };
    let screw = Part::moving(
        format!("{station}.screw"),
        CollisionShape::capsule(to_ac(&b0), to_ac(&b), screw_radius).map_err(query)?,
        turning_about_b0(layout.screw_length_m + screw_radius),
    );
    let half_body = direction * (0.5 * sizes.jack_body_length_m);
    let jack_body = Part::moving(
        format!("{station}.jack-body"),
        CollisionShape::capsule(
            to_ac(&(b0 - half_body)),
            to_ac(&(b0 + half_body)),
            sizes.jack_body_radius_m,
        )
        .map_err(query)?,
        turning_about_b0(0.5 * sizes.jack_body_length_m + sizes.jack_body_radius_m),
    );
    let mut tracks = Vec::new();
    for (name, centre_line) in &layout.tracks {
        let centre_line: Vec<Point3<f64>> = centre_line.iter().map(to_ac).collect();
        let mesh = flapwright_geom::tube_mesh(&centre_line, sizes.track_radius_m, 16, sizes.track_radius_m * 4.0)
            .map_err(query)?;
        tracks.push(Part::fixed(
            format!("{station}.{name}"),
            CollisionShape::from_mesh(&mesh).map_err(query)?,
        ));
    }
    let axis_point = aircraft_from_station.transform_point(&Point3::origin());
    let axis: Unit<Vector3<f64>> = Unit::new_normalize(aircraft_from_station.transform_vector(&Vector3::z()));
    let flap_motion = |points: &[Point2<f64>], radius: f64| AboutAxis {
        point_ac: axis_point,
        direction_ac: axis,
        max_radius_m: points.iter().map(|p| p.coords.norm()).fold(0.0, f64::max) + radius,
    };
    let d = layout.d;
    let mut flap_rigid = vec![Part::moving(
        format!("{station}.nut"),
        CollisionShape::ball(sizes.nut_radius_m).map_err(query)?,
        NutMotion {
            rotation: flap_motion(&[a], sizes.nut_radius_m),
            centre_ac: to_ac(&a),
        },
    )];
    for (name, pin) in layout.fittings {
        flap_rigid.push(Part::moving(
            format!("{station}.{name}"),
            CollisionShape::capsule(to_ac(&pin), to_ac(&d), sizes.fitting_radius_m).map_err(query)?,
            flap_motion(&[pin, d], sizes.fitting_radius_m),
        ));
    }
    let contact = |a: &str, b: &str, joint: &str| DeclaredContact {
        station: station.to_string(),
        part_a: format!("{station}.{a}"),
        part_b: format!("{station}.{b}"),
        joint: joint.into(),
    };
    let nut_pivot = "A (nut on the screw, pivoting on the flap)";
    let declared = vec![
        contact("screw", "nut", nut_pivot),
        contact("screw", "fitting-A", nut_pivot),
        contact("screw", "jack-body", "B0 (screw turning in the jack body)"),
        contact("fitting-F", "outer-track", "F (pin in the outer slot)"),
        contact("fitting-G", "inner-track", "G (pin in the inner slot)"),
    ];
    Ok(TrackParts {
        station: station.to_string(),
        screw,
        jack_body,
        flap_rigid,
        tracks,
        declared,
    })
}

/// A ball centred at a point that turns with the flap: its local frame is placed at the
/// centre (parry balls are centred at their local origin).
#[derive(Debug, Clone, Copy)]
struct NutMotion {
    rotation: AboutAxis,
    centre_ac: Point3<f64>,
}

impl crate::part::Motion for NutMotion {
    fn pose_ac(&self, t: f64) -> Isometry3<f64> {
        self.rotation.pose_at(t) * Isometry3::translation(self.centre_ac.x, self.centre_ac.y, self.centre_ac.z)
    }

    fn speed_bound(&self) -> f64 {
        self.rotation.max_radius_m
    }
}
