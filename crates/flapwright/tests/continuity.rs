//! Issue 37's continuity at reduced resolution: the transport scene with a dropped hinge (a
//! four-bar, a link-track, a hooked-track) at every station, both flaps' landing
//! deflection and landing gap and `ob-inner`'s offset each stepped once either way (0.2 deg,
//! 0.1 %c, 0.02 m: half the resolution, as `data/validation/continuity/sweep.py`,
//! whose table in its README covers the whole range and the other kinds). Every station's
//! peak actuator load and mechanism mass change by at most 1.5 x between neighbouring
//! steps, or the report states a change of the mechanism's arrangement between them
//! (`details.synthesis.topology`), and every station clears.

mod common;

const TRANSPORT: &str = include_str!("../../../data/scenes/transport-flap.toml");

/// One station's figures: name, peak actuator load (N) over the load cases, mechanism
/// mass (kg) and the arrangement its synthesis states (`null` where the kind states none).
type StationFigures = (String, f64, f64, serde_json::Value);

/// Per station its figures; and whether every station clears.
type Figures = (Vec<StationFigures>, bool);

fn figures(text: &str) -> Figures {
    let report = common::designed(text);
    let sizing = report.sizing.as_ref().expect("sized");
    let stations = report
        .stations
        .iter()
        .map(|station| {
            let synthesis = &station.mechanism.as_ref().expect("a mechanism").details["synthesis"];
            (
                station.name.clone(),
                common::peak_actuator_load(&report, &station.name),
                sizing.masses.station_kg(&station.name),
                synthesis["topology"].clone(),
            )
        })
        .collect();
    let clears = report.interference.as_ref().expect("checked").passes;
    (stations, clears)
}

/// The transport scene with `kind` at every station and `replace` replaced `with`.
fn variant(kind: &str, replace: &str, with: &str) -> String {
    let mut base = TRANSPORT.to_string();
    for other in ["four-bar", "dropped-hinge"] {
        base = base.replace(&format!("kind = \"{other}\""), &format!("kind = \"{kind}\""));
    }
    assert!(base.contains(replace), "the transport scene has {replace}");
    base.replace(replace, with)
}

#[test]
fn dropped_hinge_loads_and_masses_change_smoothly_between_neighbouring_inputs() {
    changes_smoothly("dropped-hinge", ["1.9", "2.0", "2.1"]);
}

/// The link-track (issue 37): its torque weighed at `rotary_actuator_load_weight` 1 and
/// its struts placed clear chose, sweeping the landing gap 1.5-2.5 %c by 0.05, between
/// links of one arrangement whose torques differed by up to 2.3x at the weight 0.2; now
/// within 1.33x, or a stated change.
#[test]
fn link_track_loads_and_masses_change_smoothly_or_state_the_change() {
    changes_smoothly("link-track", ["1.9", "2.0", "2.1"]);
}

/// The hooked-track (issue 37), its landing gap stepped across the island it had before its
/// two stations of a flap followed each other's motion (a shallower bracket clearing at
/// 1.70-1.75 %c alone: 27.7 -> 53.8 kN at ib-inner from 1.75 to 1.80, one arrangement):
/// within 1.06x at the resolution now, or a stated change.
#[test]
fn hooked_track_loads_and_masses_change_smoothly_or_state_the_change() {
    changes_smoothly("hooked-track", ["1.7", "1.75", "1.8"]);
}

/// The four-bar (issue 37), its landing gap stepped across 2.05 -> 2.10 %c, where the
/// follower at `ib-outer` took the loop nearest the other station's motion whatever its
/// load (43.8 -> 69.3 kN, 1.58x in one arrangement); it now takes the least costly of those
/// within 2 mm of the nearest (1.38x), and its support is a truss (the mass within 1.38x
/// in one arrangement at the resolution, 1.50 before).
#[test]
fn four_bar_loads_and_masses_change_smoothly_or_state_the_change() {
    changes_smoothly("four-bar", ["2.05", "2.1", "2.15"]);
}

/// `kind` at every station, each input stepped once either way of the scene's (the landing
/// gap at `gaps`, %c), neighbouring steps compared.
fn changes_smoothly(kind: &str, gaps: [&str; 3]) {
    use rayon::prelude::*;
    let sweeps: [(&str, [String; 3]); 3] = [
        (
            "landing_deg = 35.0",
            ["34.8", "35.0", "35.2"].map(|deg| format!("landing_deg = {deg}")),
        ),
        (
            "landing_gap_percent = 2.0",
            gaps.map(|gap| format!("landing_gap_percent = {gap}")),
        ),
        (
            "axis_offset_m = 1.5\n",
            ["1.48", "1.5", "1.52"].map(|offset| format!("axis_offset_m = {offset}\n")),
        ),
    ];
    let texts: Vec<(usize, String)> = sweeps
        .iter()
        .enumerate()
        .flat_map(|(k, (replace, steps))| steps.iter().map(move |with| (k, variant(kind, replace, with))))
        .collect();
    let designed: Vec<(usize, Figures)> = texts.par_iter().map(|(k, text)| (*k, figures(text))).collect();
    for (k, (replace, steps)) in sweeps.iter().enumerate() {
        let rows: Vec<&Figures> = designed.iter().filter(|(j, _)| *j == k).map(|(_, f)| f).collect();
        for (row, step) in rows.iter().zip(steps) {
            assert!(row.1, "{replace} -> {step}: a station does not clear");
        }
        for pair in rows.windows(2) {
            for (a, b) in pair[0].0.iter().zip(&pair[1].0) {
                assert_eq!(a.0, b.0);
                let ratio = |x: f64, y: f64| x.max(y) / x.min(y);
                for (name, load, mass, _) in [a, b] {
                    assert!(
                        load.is_finite() && *load > 0.0 && mass.is_finite() && *mass > 0.0,
                        "{name}: load {load} N, mass {mass} kg"
                    );
                }
                let (load, mass) = (ratio(a.1, b.1), ratio(a.2, b.2));
                let stated = a.3 != b.3;
                assert!(
                    (load <= 1.5 && mass <= 1.5) || stated,
                    "{kind} {} over {replace}: load {:.1} -> {:.1} kN (x{load:.2}), mass {:.1} -> {:.1} kg (x{mass:.2}), arrangement {} both",
                    a.0,
                    a.1 / 1e3,
                    b.1 / 1e3,
                    a.2,
                    b.2,
                    a.3
                );
            }
        }
    }
}
