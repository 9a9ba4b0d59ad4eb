//! Issue 37's actuator ranges: a design whose actuator lies outside what real flap
//! actuators have is warned about, naming the figure (`pipeline::actuator_ranges`).

mod common;

const LIGHT_AIRCRAFT: &str = include_str!("../../../data/scenes/light-aircraft.toml");
const TRANSPORT: &str = include_str!("../../../data/scenes/transport-flap.toml");

/// The light aircraft's dropped hinges take hold of the arm near the hinge (their flap
/// chord leaves little room): strokes of 52 mm and leads of 1.3 mm (40 turns; 32 mm and
/// 0.8 mm before the placements weighed a short stroke), which the warnings name with their
/// figures; with 10 turns the lead is four times as coarse and no longer warned about.
#[test]
fn a_short_stroke_and_a_fine_lead_are_warned_about_with_their_figures() {
    let report = common::designed(LIGHT_AIRCRAFT);
    for station in ["inner", "outer"] {
        let about = |what: &str| {
            report
                .warnings
                .iter()
                .find(|w| w.starts_with(&format!("station {station}: {what}")))
                .cloned()
        };
        let stroke = about("the screw jack's stroke is").expect("a stroke warning");
        let millimetres: f64 = stroke
            .split("stroke is ")
            .nth(1)
            .and_then(|rest| rest.split(" mm").next())
            .and_then(|value| value.parse().ok())
            .expect("the stroke in mm");
        assert!(millimetres < 100.0, "{stroke}");
        assert!(about("the screw's lead is").is_some(), "{:?}", report.warnings);
    }
    let flap_mass = "flap_mass_kg = 3.5\n";
    assert_eq!(
        LIGHT_AIRCRAFT.matches(flap_mass).count(),
        2,
        "the light aircraft's two dropped hinges"
    );
    let coarse = common::designed(&LIGHT_AIRCRAFT.replace(flap_mass, "flap_mass_kg = 3.5\nscrew = { turns = 10 }\n"));
    assert_ne!(coarse.warnings.len(), 0);
    assert!(
        !coarse.warnings.iter().any(|w| w.contains("the screw's lead is")),
        "{:?}",
        coarse.warnings
    );
}

/// The transport's four-bars and dropped hinges carry at most the air load on their share
/// of the flap and stroke 0.2-0.4 m: no actuator warning.
#[test]
fn the_transports_actuators_lie_in_the_public_ranges() {
    let report = common::designed(TRANSPORT);
    let actuator =
        |w: &&String| w.contains("screw jack's") || w.contains("screw's lead") || w.contains("rotary actuator's");
    let found: Vec<&String> = report.warnings.iter().filter(actuator).collect();
    assert!(found.is_empty(), "{found:?}");
}
