//! The plots page of a station: what the kinematics, the gap and overlap measure and the
//! interference check found, as charts (drawing crate).

use flapwright_drawing::{Plot, Series};
use flapwright_interference::{InterferenceReport, PairResult};
use flapwright_mechanism::seam::InputQuantity;
use flapwright_mechanism::{Deployment, DeploymentSample};

/// A flap setting's gap and overlap targets at the setting's actuator input, for marks on
/// the gap and overlap plot.
#[derive(Debug, Clone)]
pub struct SettingTarget {
    /// "takeoff" or "landing".
    pub setting: String,
    /// Actuator input of the setting.
    pub input: f64,
    /// Target gap, % of the local chord.
    pub gap_percent_chord: Option<f64>,
    /// Target overlap, % of the local chord.
    pub overlap_percent_chord: Option<f64>,
}

/// The plots of one station: kinematics and loads against the actuator input (first load
/// case, or every case where they differ), gap and overlap when the station has a flap
/// section, and the clearance of its closest pairs when the interference check ran.
/// Load cases whose sweep stopped before its first sample have nothing to draw and are
/// left out; so are plots left with nothing (the report says why the sweep stopped).
pub fn station_plots(
    all_cases: &[Deployment],
    input: InputQuantity,
    targets: &[SettingTarget],
    interference: Option<&InterferenceReport>,
    station: &str,
) -> Vec<Plot> {
    // Strokes in mm, angles in degrees; forces and moments in the unit their size asks
    // (`in_engineering_units`).
    let (x_label, x_scale, load) = match input {
        InputQuantity::Stroke => ("actuator stroke [mm]", 1e3, ("actuator force", "N")),
        InputQuantity::Angle => (
            "actuator angle [deg]",
            180.0 / std::f64::consts::PI,
            ("actuator torque", "N m"),
        ),
    };
    let series = |case: &Deployment, name: String, y: &dyn Fn(&DeploymentSample) -> Option<f64>| Series {
        name,
        points: case
            .samples
            .iter()
            .filter_map(|s| Some((s.input * x_scale, y(s)?)))
            .collect(),
    };
    let cases: Vec<Deployment> = all_cases.iter().filter(|c| !c.samples.is_empty()).cloned().collect();
    let cases = cases.as_slice();
    let first = &cases[..cases.len().min(1)];
    let plot = |title: &str, y_label: &str, cases: &[Deployment], y: &dyn Fn(&DeploymentSample) -> Option<f64>| Plot {
        title: title.into(),
        x_label: x_label.into(),
        y_label: y_label.into(),
        series: cases.iter().map(|c| series(c, c.load_case.clone(), y)).collect(),
    };
    let joints: Vec<String> = first
        .iter()
        .flat_map(|c| c.samples.first())
        .flat_map(|s| s.reactions_n.keys().cloned())
        .collect();
    let mut plots = vec![
        plot("Flap deflection", "deflection [deg]", first, &|s| {
            Some(s.deflection_deg)
        }),
        plot("Transmission angle", "transmission angle [deg]", first, &|s| {
            Some(s.transmission_angle_deg)
        }),
        in_engineering_units(plot("Actuator load", "", cases, &|s| Some(s.actuator_load)), load),
        in_engineering_units(
            plot("Screw raise torque", "", cases, &|s| {
                s.actuator_torques_nm.map(|t| t.raise_torque_nm)
            }),
            ("T_R", "N m"),
        ),
        in_engineering_units(
            plot("Screw lower torque", "", cases, &|s| {
                s.actuator_torques_nm.map(|t| t.lower_torque_nm)
            }),
            ("T_L", "N m"),
        ),
        in_engineering_units(
            Plot {
                title: format!(
                    "Joint reactions ({})",
                    first.first().map_or("", |c| c.load_case.as_str())
                ),
                x_label: x_label.into(),
                y_label: String::new(),
                series: first
                    .iter()
                    .flat_map(|c| {
                        joints
                            .iter()
                            .map(|joint| series(c, joint.clone(), &|s| s.reactions_n.get(joint).copied()))
                    })
                    .collect(),
            },
            ("reaction", "N"),
        ),
    ];
    // Each target as a marker (a one-point series) at its setting's input.
    let mark = |label: String, at: f64, value: f64| Series {
        name: label,
        points: vec![(at * x_scale, value)],
    };
    let target_marks = targets.iter().flat_map(|t| {
        [
            t.gap_percent_chord
                .map(|v| mark(format!("{} gap target", t.setting), t.input, v)),
            t.overlap_percent_chord
                .map(|v| mark(format!("{} overlap target", t.setting), t.input, v)),
        ]
        .into_iter()
        .flatten()
    });
    let gap_overlap: Vec<Series> = first
        .iter()
        .flat_map(|c| {
            [
                series(c, "gap".into(), &|s| s.flap_position.map(|p| p.gap_percent_chord)),
                series(c, "overlap".into(), &|s| {
                    s.flap_position.map(|p| p.overlap_percent_chord)
                }),
            ]
        })
        .collect();
    let measured = gap_overlap.iter().all(|s| !s.points.is_empty()) && !gap_overlap.is_empty();
    plots.push(Plot {
        title: "Gap and overlap behind the cove lip".into(),
        x_label: x_label.into(),
        y_label: "% of local chord".into(),
        series: if measured {
            gap_overlap.into_iter().chain(target_marks).collect()
        } else {
            Vec::new()
        },
    });
    plots.extend(interference.and_then(|report| clearance_plot(report, station)));
    plots.retain(|plot| !plot.series.is_empty() && plot.series.iter().all(|s| !s.points.is_empty()));
    plots
}

/// `plot` (values in `unit`, N or N m) with its values and its y label in the unit their
/// largest magnitude asks: N below 10^3, kN below 10^6, MN beyond (a 120 000 N load reads
/// 120 kN), the label "`quantity` [unit]".
fn in_engineering_units(mut plot: Plot, (quantity, unit): (&str, &str)) -> Plot {
    let largest = plot
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1.abs()))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let (factor, prefix) = if largest >= 1e6 {
        (1e-6, "M")
    } else if largest >= 1e3 {
        (1e-3, "k")
    } else {
        (1.0, "")
    };
    for series in &mut plot.series {
        for point in &mut series.points {
            point.1 *= factor;
        }
    }
    plot.y_label = format!("{quantity} [{prefix}{unit}]");
    plot
}

/// How many of a station's pairs its clearance plot shows, closest first.
const CLEARANCE_PLOT_PAIRS: usize = 4;

/// Signed clearance against the deployment (drive fraction, %) of the station's closest
/// pairs, from every
/// distance evaluation of the check (the initial samples and the refinements near each
/// minimum, so the lines are densest where the clearance is smallest), with the required
/// clearance.
fn clearance_plot(report: &InterferenceReport, station: &str) -> Option<Plot> {
    let signed = |pair: &PairResult| pair.clearance.min_clearance_m - pair.clearance.penetration_m;
    let mut pairs: Vec<&PairResult> = report
        .pairs
        .iter()
        .filter(|p| p.station.as_deref() == Some(station) && !p.clearance.trace.is_empty())
        .collect();
    pairs.sort_by(|a, b| signed(a).total_cmp(&signed(b)));
    let [start, end] = report.deployment_range.map(|t| 100.0 * t);
    let prefix = format!("{station}.");
    let short = |name: &str| name.strip_prefix(&prefix).unwrap_or(name).to_string();
    let mut series: Vec<Series> = pairs
        .iter()
        .take(CLEARANCE_PLOT_PAIRS)
        .map(|pair| {
            let clearance = &pair.clearance;
            let mut points: Vec<(f64, f64)> = clearance.trace.iter().map(|&(t, d)| (100.0 * t, d * 1e3)).collect();
            if let [(_, only)] = points[..] {
                // Parts that do not move are evaluated once.
                points = vec![(start, only), (end, only)];
            }
            Series {
                name: format!("{} vs {}", short(&clearance.part_a), short(&clearance.part_b)),
                points,
            }
        })
        .collect();
    if series.is_empty() {
        return None;
    }
    let required_mm = report
        .required_clearance_by_station_m
        .get(station)
        .copied()
        .unwrap_or(report.required_clearance_m)
        .max(report.required_clearance_m)
        * 1e3;
    series.push(Series {
        name: "required".into(),
        points: vec![(start, required_mm), (end, required_mm)],
    });
    Some(Plot {
        title: "Clearance of the closest pairs".into(),
        x_label: "deployment [% of the actuator travel]".into(),
        y_label: "clearance [mm], < 0: overlap".into(),
        series,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plot_of(values: &[f64]) -> Plot {
        Plot {
            title: "t".into(),
            x_label: "x".into(),
            y_label: String::new(),
            series: vec![Series {
                name: "s".into(),
                points: values.iter().enumerate().map(|(i, &v)| (i as f64, v)).collect(),
            }],
        }
    }

    /// Forces and moments read in the unit their largest magnitude asks, a negative one
    /// counted by its size.
    #[test]
    fn a_load_plot_takes_the_unit_its_size_asks() {
        let kilo = in_engineering_units(plot_of(&[1.0e3, -120.0e3]), ("actuator force", "N"));
        assert_eq!(kilo.y_label, "actuator force [kN]");
        assert_eq!(kilo.series[0].points[1].1, -120.0);
        let plain = in_engineering_units(plot_of(&[3.0, 999.0]), ("T_R", "N m"));
        assert_eq!(
            (plain.y_label.as_str(), plain.series[0].points[1].1),
            ("T_R [N m]", 999.0)
        );
        let mega = in_engineering_units(plot_of(&[2.5e6]), ("reaction", "N"));
        assert_eq!(
            (mega.y_label.as_str(), mega.series[0].points[0].1),
            ("reaction [MN]", 2.5)
        );
    }
}
