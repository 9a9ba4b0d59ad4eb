//! The parts of one station against each other (issue 17): in the spanwise layers the
//! mechanism gives, two moving parts that cross in one layer fail with the pair named,
//! and the automatic layout of the same mechanism keeps them apart.

use std::sync::Arc;

use flapwright_interference::{check_assembly, station_parts, Assembly, Requirements, SweepSettings};
use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};
use flapwright_mechanism::seam::{
    Actuator, Body, DrawingNotes, FlapMechanism, InputRange, Joint, Kinetostatics, MechanismPose, NamedPoint,
};
use flapwright_mechanism::{LoadCase, Result};
use nalgebra::Isometry3;

/// The thesis track with the spanwise offsets a designer typed: every solid in the
/// station plane but the jack body, set 0.2 m aside.
#[derive(Debug)]
struct TypedLayout {
    track: CircularArcTrack,
    bodies: Vec<Body>,
}

impl TypedLayout {
    fn new() -> Self {
        let track = CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).unwrap();
        let mut bodies = track.bodies().to_vec();
        for solid in bodies.iter_mut().flat_map(|b| b.solids.iter_mut()) {
            solid.offset_m = if solid.name == "jack-body" { 0.2 } else { 0.0 };
        }
        Self { track, bodies }
    }
}

impl FlapMechanism for TypedLayout {
    fn kind(&self) -> &'static str {
        self.track.kind()
    }
    fn input_range(&self) -> InputRange {
        self.track.input_range()
    }
    fn deflection_range_rad(&self) -> f64 {
        self.track.deflection_range_rad()
    }
    fn input_at_deflection(&self, deflection_rad: f64) -> Result<f64> {
        self.track.input_at_deflection(deflection_rad)
    }
    fn deflection_at_input(&self, input: f64) -> Result<f64> {
        self.track.deflection_at_input(input)
    }
    fn flap_attachments(&self) -> Vec<NamedPoint> {
        self.track.flap_attachments()
    }
    fn bodies(&self) -> &[Body] {
        &self.bodies
    }
    fn joints(&self) -> &[Joint] {
        self.track.joints()
    }
    fn pose(&self, input: f64) -> Result<MechanismPose> {
        FlapMechanism::pose(&self.track, input)
    }
    fn kinetostatics(&self, input: f64, load: &LoadCase) -> Result<Kinetostatics> {
        self.track.kinetostatics(input, load)
    }
    fn drawing_notes(&self) -> DrawingNotes {
        self.track.drawing_notes()
    }
    fn details(&self) -> serde_json::Value {
        self.track.details()
    }
    fn actuator(&self) -> Actuator {
        self.track.actuator()
    }
    fn warnings(&self) -> Vec<String> {
        self.track.warnings()
    }
}

fn check(mechanism: Arc<dyn FlapMechanism>) -> flapwright_interference::InterferenceReport {
    let parts = station_parts("st", Some("flap"), &Isometry3::identity(), &mechanism).unwrap();
    let assembly = Assembly {
        stations: vec![parts],
        ..Default::default()
    };
    let required = Requirements {
        clearance_m: 0.003,
        joint_play_m: 0.001,
        ..Default::default()
    };
    check_assembly(&assembly, 1.0, &required, &SweepSettings::default()).unwrap()
}

#[test]
fn two_moving_parts_crossing_in_one_layer_fail_with_the_pair_named() {
    let report = check(Arc::new(TypedLayout::new()));
    assert!(!report.passes);
    let failing: Vec<(&str, &str)> = report
        .pairs
        .iter()
        .filter(|p| !p.passes)
        .map(|p| (p.clearance.part_a.as_str(), p.clearance.part_b.as_str()))
        .collect();
    // The screw (turning about B0) runs through the flap's fitting at G (turning with the
    // flap) in the station plane: 2.6 mm deep at stowed.
    assert!(
        failing
            .iter()
            .any(|&pair| pair == ("st.fitting-G", "st.screw") || pair == ("st.screw", "st.fitting-G")),
        "{failing:?}"
    );
    // Parts that touch by design are checked as joints, in the plane, and hold.
    assert!(report.declared_contacts.iter().all(|c| c.passes));
    assert!(report.unchecked_pairs.is_empty());
}

#[test]
fn the_automatic_layout_keeps_the_same_mechanism_clear() {
    let track = CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).unwrap();
    let report = check(Arc::new(track));
    let failing: Vec<_> = report.pairs.iter().filter(|p| !p.passes).collect();
    assert!(failing.is_empty(), "{failing:?}");
    assert!(report.passes);
    // Same-station pairs of different bodies are all there, swept or certified apart.
    let checked = report.pairs.len() + report.certified_apart.len();
    assert!(checked >= 15, "{checked} same-station pairs");
}

#[test]
fn a_pair_needs_the_largest_clearance_of_its_stations() {
    let required = Requirements {
        clearance_m: 0.003,
        joint_play_m: 0.001,
        clearance_by_station_m: [("inner".to_string(), 0.02), ("outer".to_string(), 0.01)].into(),
    };
    assert_eq!(required.clearance_for(None), 0.003);
    assert_eq!(required.clearance_for(Some("inner")), 0.02);
    assert_eq!(required.clearance_for(Some("mid")), 0.003);
    assert_eq!(required.clearance_for(Some("outer/inner")), 0.02);
    assert_eq!(required.clearance_for(Some("mid/outer")), 0.01);
}
