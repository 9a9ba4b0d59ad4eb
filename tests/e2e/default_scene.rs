//! `flapwright` with no arguments designs the embedded default scene into
//! `./flapwright-out`; everything it writes is re-read here with independent readers.

use std::collections::BTreeSet;

use crate::run_flapwright;
use crate::stl_reader::{check_closed_oriented, read_binary_stl};

fn report_without_timings(text: &str) -> serde_json::Value {
    let mut report: serde_json::Value = serde_json::from_str(text).expect("report.json is JSON");
    report.as_object_mut().unwrap().remove("timings");
    report
}

#[test]
fn no_arguments_designs_the_default_scene() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_flapwright(dir.path(), &[]);
    assert!(
        output.status.success(),
        "stderr:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let out = dir.path().join("flapwright-out");
    let report_text = std::fs::read_to_string(out.join("report.json")).unwrap();
    let report: serde_json::Value = serde_json::from_str(&report_text).unwrap();
    assert_eq!(report["scene"]["name"], "small-aircraft");
    assert_eq!(report["scene"]["sha256"].as_str().unwrap().len(), 64);

    // Every part of the scene has an STL: wing skin, flap, both spars, torque tube.
    let parts = report["parts"].as_array().unwrap();
    let kinds: BTreeSet<&str> = parts.iter().map(|p| p["kind"].as_str().unwrap()).collect();
    for kind in ["wing-skin", "flap", "spar", "torque-tube"] {
        assert!(kinds.contains(kind), "a {kind} part in {kinds:?}");
    }
    let stl_files: BTreeSet<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".stl"))
        .collect();
    let reported: BTreeSet<String> = parts
        .iter()
        .chain(report["mechanism_parts"].as_array().unwrap())
        .map(|p| p["stl_file"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(stl_files, reported, "the STL files are exactly the reported parts");

    for part in parts {
        let file = part["stl_file"].as_str().unwrap();
        let triangles = read_binary_stl(&std::fs::read(out.join(file)).unwrap());
        assert_eq!(triangles.len() as u64, part["triangles"].as_u64().unwrap(), "{file}");
        let volume = check_closed_oriented(&triangles).unwrap_or_else(|e| panic!("{file} is not watertight: {e}"));
        assert!(volume > 0.0, "{file} has positive volume, got {volume}");
        let reported_volume = part["volume_m3"].as_f64().unwrap();
        // f32 storage in STL: relative agreement to ~1e-5 is all that survives.
        assert!(
            (volume - reported_volume).abs() <= 1e-4 * reported_volume,
            "{file}: STL volume {volume} vs report {reported_volume}"
        );
        assert_eq!(part["watertight"], true, "{file}");
    }

    // Gap and overlap at each station's three settings: finite, consistent with the local
    // chord, and opening as the flap deploys (the default flap turns down and aft about a
    // hinge below the wing, so its nose leaves the cove lip).
    for station in report["stations"].as_array().unwrap() {
        let name = station["name"].as_str().unwrap();
        let position = &station["flap_position"];
        let chord = position["local_chord_m"].as_f64().unwrap();
        assert!(chord > 0.5 && chord < 5.0, "{name}: local chord {chord} m");
        let settings = position["settings"].as_array().unwrap();
        let names: Vec<&str> = settings.iter().map(|s| s["setting"].as_str().unwrap()).collect();
        assert_eq!(names, ["stowed", "takeoff", "landing"], "{name}");
        let value = |s: &serde_json::Value, key: &str| {
            let v = s[key].as_f64().unwrap_or_else(|| panic!("{name}: {key} is a number"));
            assert!(v.is_finite(), "{name}: {key}");
            v
        };
        for s in settings {
            for (metres, percent) in [("gap_m", "gap_percent_chord"), ("overlap_m", "overlap_percent_chord")] {
                let expected = 100.0 * value(s, metres) / chord;
                assert!((value(s, percent) - expected).abs() < 1e-9, "{name}: {percent}");
            }
        }
        // The trailing edge is the cove's upper lip: a vertex of the wing section within 3 mm
        // of its aft-most point (the wall leans by twist and skew), with no wing point aft of
        // it and higher (the first rule took a point 14-16 mm forward on the upper skin).
        let points = |part: &str| -> Vec<[f64; 2]> {
            let section = station["plane"]["sections"]
                .as_array()
                .unwrap()
                .iter()
                .find(|s| s["part_name"] == part)
                .unwrap_or_else(|| panic!("{name}: {part} section"));
            serde_json::from_value::<Vec<Vec<[f64; 2]>>>(section["polygons"].clone())
                .unwrap()
                .concat()
        };
        let wing = points("wing");
        let te: [f64; 2] = serde_json::from_value(position["trailing_edge_st_m"].clone()).unwrap();
        assert!(wing.contains(&te), "{name}: the lip is a section vertex");
        let aft_most = wing.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        assert!(
            te[0] - aft_most < 3e-3,
            "{name}: lip {:.1} mm ahead of the wall",
            (te[0] - aft_most) * 1e3
        );
        assert!(
            !wing.iter().any(|p| p[0] < te[0] && p[1] > te[1]),
            "{name}: nothing aft of the lip is higher"
        );
        // Stowed overlap recomputed from the sections: flap's foremost x less the lip's x.
        let nose = points("flap").iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max);
        assert!(
            (value(&settings[0], "overlap_m") - (nose - te[0])).abs() < 1e-12,
            "{name}: stowed overlap"
        );
        // Every deployment sample carries its gap and overlap; the last one is the landing
        // setting (35 deg, the end of the stroke) and the first the stowed one.
        for case in station["mechanism"]["load_cases"].as_array().unwrap() {
            let samples = case["samples"].as_array().unwrap();
            for (sample, setting) in [(&samples[0], &settings[0]), (samples.last().unwrap(), &settings[2])] {
                for key in ["gap_m", "overlap_m", "gap_percent_chord", "overlap_percent_chord"] {
                    let at_sample = sample["flap_position"][key].as_f64().unwrap();
                    assert!((at_sample - value(setting, key)).abs() < 1e-9, "{name}: {key}");
                }
            }
        }
        // The thesis mechanism turns the flap about a fixed hinge: its landing gap is far from
        // the 0-3 % chord of slotted flaps, and the report and terminal say so with the numbers.
        let landing = &settings[2];
        let warning = format!(
            "station {name}: landing at 35.0 deg has gap {:.1} % and overlap {:.1} % of the local chord",
            value(landing, "gap_percent_chord"),
            value(landing, "overlap_percent_chord")
        );
        assert!(report["warnings"].to_string().contains(&warning), "{warning}");
        for pair in settings.windows(2) {
            assert!(value(&pair[1], "gap_m") > value(&pair[0], "gap_m"), "{name}: gap opens");
            assert!(
                value(&pair[1], "overlap_m") < value(&pair[0], "overlap_m"),
                "{name}: overlap shrinks"
            );
        }
        let plots = std::fs::read_to_string(out.join(format!("plots-{name}.svg"))).unwrap();
        assert!(
            plots.contains("Gap and overlap behind the cove lip"),
            "{name}: gap/overlap plot"
        );
        // The clearance chart names the station's closest pair from the check.
        let closest = report["interference"]["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|p| p["station"] == name)
            .min_by(|a, b| {
                let signed = |p: &serde_json::Value| {
                    p["min_clearance_m"].as_f64().unwrap() - p["penetration_m"].as_f64().unwrap()
                };
                signed(a).total_cmp(&signed(b))
            })
            .unwrap();
        let short = |part: &serde_json::Value| {
            part.as_str()
                .unwrap()
                .trim_start_matches(&format!("{name}."))
                .to_string()
        };
        let legend = format!("{} vs {}", short(&closest["part_a"]), short(&closest["part_b"]));
        assert!(
            plots.contains("Clearance of the closest pairs"),
            "{name}: clearance plot"
        );
        assert!(plots.contains(&legend), "{name}: clearance plot shows {legend}");
    }

    // A second run gives the same report apart from the timings section.
    let again = run_flapwright(dir.path(), &[]);
    assert!(again.status.success());
    let second = std::fs::read_to_string(out.join("report.json")).unwrap();
    assert_eq!(report_without_timings(&report_text), report_without_timings(&second));
}

#[test]
fn refuses_to_replace_a_folder_it_did_not_write() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("precious")).unwrap();
    std::fs::write(dir.path().join("precious/notes.txt"), "keep me").unwrap();
    let output = run_flapwright(dir.path(), &["design", "--out", "precious"]);
    assert_eq!(output.status.code(), Some(2), "a foreign --out is bad input");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("precious/notes.txt")).unwrap(),
        "keep me"
    );
}
