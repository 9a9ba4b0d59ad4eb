//! Issue 37's magnitudes for the hooked-track: on the transport scene with a hooked-track at
//! every station (as `flapwright study` designs it), the support is a truss (a tie and
//! three rods pinned at both ends, `003_...` section 2's truss-based support), and
//! `ob-inner`, `003_...` Table 1's case (the inboard mechanism of the outboard flap), needs at
//! most 2.5 times Table 1's actuator load and weighs within a factor of 2.5 of Table 1's
//! mechanism; every station clears and no sized member exceeds its drawn solid.
//!
//! With the struts clamped to the skin (before the truss) the same station weighed 199 kg,
//! 4.6 times Table 1's 43.1 kg, the two struts 165 kg of it.

mod common;

const TRANSPORT: &str = include_str!("../../../data/scenes/transport-flap.toml");

/// `003_...` Table 1, hooked-track: peak actuator load (N) and mechanism weight (kg).
const TABLE_1: (f64, f64) = (27.8e3, 43.1);

#[test]
fn the_hooked_tracks_truss_holds_ob_inner_within_table_1_by_two_and_a_half() {
    let text = TRANSPORT
        .replace("kind = \"four-bar\"", "kind = \"hooked-track\"")
        .replace("kind = \"dropped-hinge\"", "kind = \"hooked-track\"");
    let report = common::designed(&text);
    for station in &report.stations {
        let synthesis = &station.mechanism.as_ref().expect("a mechanism").details["synthesis"];
        // The arrangement the study and the continuity sweep compare.
        let topology = &synthesis["topology"];
        assert!(
            ["above-rail", "below-rail"].contains(&topology["roller"].as_str().unwrap_or("")),
            "{topology}"
        );
        assert!(
            ["pushing", "pulling"].contains(&topology["jack"].as_str().unwrap_or("")),
            "{topology}"
        );
    }
    let parts = ["rail", "hook", "tie", "strut-rail", "strut-hook", "brace"];
    common::assert_trussed_ob_inner_within_table_1(&report, &parts, TABLE_1.0, TABLE_1.1);
}
