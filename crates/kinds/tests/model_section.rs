//! A model section for the kinds synthesised from flap settings, shared by the tests and
//! the benchmarks: a box wing with a cove and an elliptic flap nested in it, settings near
//! `003_...` 5.2 (take-off 15 deg, 0.5 %c gap, 3 %c overlap; landing 35 deg, 2 %c gap,
//! 0 %c overlap).

use flapwright_kinds::dropped_hinge::{DroppedHingeActuator, DroppedHingeSpec};
use flapwright_kinds::four_bar::FourBarSpec;
use flapwright_kinds::hooked_track::HookedTrackSpec;
use flapwright_kinds::link_track::LinkTrackSpec;
use flapwright_mechanism::{FlapMass, LinkHardware, PrecisionPosition, RotaryDrive, ScrewDrive, StationOutline};
use flapwright_planes::FlapBehindWing;
use nalgebra::Point2;

/// Wing: nose at x = 3, its upper skin sloping down to the lip at (-0.05, 0.175), a cove
/// below; flap: an ellipse of chord 0.8
/// nested in the cove (station frame, m).
pub fn outline() -> StationOutline {
    let wing = vec![vec![
        Point2::new(0.1, 0.0),
        Point2::new(3.0, 0.0),
        Point2::new(3.0, 0.25),
        Point2::new(0.6, 0.25),
        Point2::new(-0.05, 0.175),
        Point2::new(-0.05, 0.165),
        Point2::new(0.1, 0.12),
    ]];
    let flap = vec![(0..120)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 120.0;
            Point2::new(-0.32 + 0.4 * a.cos(), 0.1 + 0.07 * a.sin())
        })
        .collect()];
    StationOutline {
        wing: wing.into(),
        flap: flap.into(),
        structure: Default::default(),
        lip: vec![Point2::new(-0.05, 0.175)],
        lip_clearance_m: 0.0,
    }
}

/// The precision positions of the `003_...` B777 settings in this section.
pub fn settings(outline: &StationOutline) -> (PrecisionPosition, PrecisionPosition) {
    let measure = FlapBehindWing::new(&outline.wing, &outline.flap).unwrap();
    let c = measure.chord_m();
    let at = |name, deg: f64, gap: f64, overlap: f64| PrecisionPosition {
        name,
        deflection_rad: deg.to_radians(),
        flap: measure
            .displacement_for_setting(deg.to_radians(), gap * c / 100.0, overlap * c / 100.0)
            .unwrap(),
    };
    // A take-off gap of 0.5 %c, not 003's 0: a flap that touches the lip at a setting
    // passes through it on one side unless it moves tangent to its surface there, and the
    // four-bar search rejects a flap through the lip (the transport e2e keeps 003's 0).
    (at("takeoff", 15.0, 0.5, 3.0), at("landing", 35.0, 2.0, 0.0))
}

fn flap_mass() -> FlapMass {
    FlapMass {
        mass_kg: 40.0,
        centre_of_mass_stowed_m: Point2::new(-0.3, 0.1),
        gravity_mps2: nalgebra::Vector2::new(0.0, -9.81),
    }
}

fn drive() -> ScrewDrive {
    ScrewDrive {
        mean_radius_m: 0.012,
        friction_coefficient: 0.1,
        turns: 30.0,
        deployment_time_s: 20.0,
    }
}

pub fn dropped_hinge_spec() -> DroppedHingeSpec {
    let outline = outline();
    let (takeoff, landing) = settings(&outline);
    DroppedHingeSpec {
        landing,
        takeoff: Some(takeoff),
        flap_attachments: [
            outline.flap_lower_point(0.15).unwrap(),
            outline.flap_lower_point(0.5).unwrap(),
        ],
        actuator: DroppedHingeActuator::ScrewJack {
            attachment_fraction: None,
            mount: None,
            standoff_m: 0.4,
            drive: drive(),
            trade_index: None,
        },
        support_points: None,
        flap_mass: flap_mass(),
        min_transmission_angle_rad: 30f64.to_radians(),
        hardware: LinkHardware::for_flap_chord(0.8),
        outline,
        design_loads: Vec::new(),
        load_weight: flapwright_mechanism::shared::objective::DEFAULT_LOAD_WEIGHT,
        mass_weighing: None,
    }
}

/// The same dropped hinge driven by a geared rotary actuator on the hinge.
pub fn rotary_dropped_hinge_spec() -> DroppedHingeSpec {
    DroppedHingeSpec {
        actuator: DroppedHingeActuator::Rotary(RotaryDrive {
            turns: 30.0,
            deployment_time_s: 20.0,
            efficiency: 0.9,
        }),
        ..dropped_hinge_spec()
    }
}

pub fn four_bar_spec() -> FourBarSpec {
    let outline = outline();
    let (takeoff, landing) = settings(&outline);
    FourBarSpec {
        follow: None,
        takeoff,
        landing,
        forward_pivot: None,
        aft_pivot: None,
        min_transmission_angle_rad: 30f64.to_radians(),
        actuator_attachment_fraction: None,
        actuator_mount: None,
        actuator_standoff_m: 0.4,
        flap_mass: flap_mass(),
        screw_drive: drive(),
        hardware: LinkHardware::for_flap_chord(0.8),
        outline,
        design_loads: Vec::new(),
        load_weight: flapwright_mechanism::shared::objective::DEFAULT_LOAD_WEIGHT,
        load_cap: flapwright_kinds::four_bar::DEFAULT_JACK_LOAD_CAP,
        mass_weighing: None,
        trade_index: None,
    }
}

pub fn link_track_spec() -> LinkTrackSpec {
    let outline = outline();
    let (takeoff, landing) = settings(&outline);
    LinkTrackSpec {
        takeoff,
        landing,
        link_pivot: None,
        track_slope_rad: None,
        min_transmission_angle_rad: 30f64.to_radians(),
        flap_mass: flap_mass(),
        rotary: RotaryDrive {
            turns: 30.0,
            deployment_time_s: 20.0,
            efficiency: 0.9,
        },
        hardware: LinkHardware::for_flap_chord(0.8),
        outline,
        design_loads: Vec::new(),
        load_weight: flapwright_mechanism::shared::objective::DEFAULT_LOAD_WEIGHT,
        follow: None,
        trade_index: None,
    }
}

pub fn hooked_track_spec() -> HookedTrackSpec {
    let outline = outline();
    let (takeoff, landing) = settings(&outline);
    HookedTrackSpec {
        takeoff,
        landing,
        forward_attachment: None,
        aft_attachment: None,
        lead_fraction: None,
        min_transmission_angle_rad: 30f64.to_radians(),
        flap_mass: flap_mass(),
        screw_drive: drive(),
        hardware: LinkHardware::for_flap_chord(0.8),
        outline,
        design_loads: vec![flapwright_mechanism::LoadCase::thesis_cruise()],
        follow: None,
    }
}
