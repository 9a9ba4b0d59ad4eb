//! The moving parts of a circular-arc-track station (thesis `000`, Fig. 10) as collision
//! parts: screw B0-B (capsule), nut at A (ball), and the flap's fittings A-D, F-D, G-D
//! (capsules) that carry the pins and the nut pivot. Deployment parameter: flap rotation
//! t = θ12 - θ12,i (rad).

use flapwright_geom::collision::CollisionShape;
use flapwright_mechanism::CircularArcTrack;
use nalgebra::{Isometry3, Point2, Point3, Unit, Vector3};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::motion::{AboutAxis, ScrewAboutMount};
use crate::part::Part;

/// Sizes of the solids that stand for the links (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSizes {
    /// Radius of the fitting capsules A-D, F-D, G-D.
    pub fitting_radius_m: f64,
    /// Radius of the nut ball at A.
    pub nut_radius_m: f64,
}

impl Default for LinkSizes {
    fn default() -> Self {
        Self {
            fitting_radius_m: 0.008,
            nut_radius_m: 0.020,
        }
    }
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
    /// Parts rigid with the flap: nut and fittings.
    pub flap_rigid: Vec<Part>,
    /// Contacts by design: the nut rides on the screw; the screw passes the fitting at A.
    pub declared: Vec<DeclaredContact>,
}

/// Outer radius of a square thread of mean radius r and lead l: r + l/4 (thread depth l/2).
pub fn screw_outer_radius_m(track: &CircularArcTrack) -> f64 {
    let screw = &track.spec().screw;
    screw.mean_radius_m + 0.25 * screw.lead_m
}

/// Builds the station's parts, placed by `aircraft_from_station` (the station frame: origin
/// A0 on the hinge axis, z along it).
pub fn track_parts(
    station: &str,
    aircraft_from_station: &Isometry3<f64>,
    track: &CircularArcTrack,
    sizes: &LinkSizes,
) -> Result<TrackParts> {
    let synthesis = track.synthesis();
    let spec = track.spec();
    let to_ac = |p: &Point2<f64>| aircraft_from_station.transform_point(&Point3::new(p.x, p.y, 0.0));
    let query = |source| Error::Query {
        part_a: format!("{station}.parts"),
        part_b: String::new(),
        parameter: 0.0,
        source: Box::new(source),
    };
    let b0 = synthesis.screw_mount_m;
    let a = synthesis.nut_pivot_stowed_m;
    let direction = (a - b0).normalize();
    let b = b0 + direction * spec.screw_length_m;
    let screw_radius = screw_outer_radius_m(track);
    let screw = Part::moving(
        format!("{station}.screw"),
        CollisionShape::capsule(to_ac(&b0), to_ac(&b), screw_radius).map_err(query)?,
        ScrewAboutMount {
            aircraft_from_station: *aircraft_from_station,
            mount_st: b0,
            nut_pivot_stowed_st: a,
            max_reach_m: spec.screw_length_m + screw_radius,
            min_extension_m: synthesis.stroke_start_m,
        },
    );
    let axis_point = aircraft_from_station.transform_point(&Point3::origin());
    let axis: Unit<Vector3<f64>> = Unit::new_normalize(aircraft_from_station.transform_vector(&Vector3::z()));
    let flap_motion = |points: &[Point2<f64>], radius: f64| AboutAxis {
        point_ac: axis_point,
        direction_ac: axis,
        max_radius_m: points.iter().map(|p| p.coords.norm()).fold(0.0, f64::max) + radius,
    };
    let d = spec.centre_of_mass_stowed_m;
    let mut flap_rigid = vec![Part::moving(
        format!("{station}.nut"),
        CollisionShape::ball(sizes.nut_radius_m).map_err(query)?,
        NutMotion {
            rotation: flap_motion(&[a], sizes.nut_radius_m),
            centre_ac: to_ac(&a),
        },
    )];
    for (name, pin) in [
        ("fitting-A", a),
        ("fitting-F", synthesis.outer_pin_stowed_m),
        ("fitting-G", synthesis.inner_pin_stowed_m),
    ] {
        flap_rigid.push(Part::moving(
            format!("{station}.{name}"),
            CollisionShape::capsule(to_ac(&pin), to_ac(&d), sizes.fitting_radius_m).map_err(query)?,
            flap_motion(&[pin, d], sizes.fitting_radius_m),
        ));
    }
    let declared = ["nut", "fitting-A"]
        .iter()
        .map(|other| DeclaredContact {
            station: station.to_string(),
            part_a: format!("{station}.screw"),
            part_b: format!("{station}.{other}"),
            joint: "A (nut on the screw, pivoting on the flap)".into(),
        })
        .collect();
    Ok(TrackParts {
        station: station.to_string(),
        screw,
        flap_rigid,
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
