//! Sizing closes the loop (issue 37): a synthesised kind draws its links, struts and screw
//! from the flap chord (`flapwright_mechanism::LinkHardware::for_flap_chord`), and the sizing
//! stage then finds what the loads need. Where a member needs more than is drawn, the
//! drawn solid, the clearance the synthesis kept and the check all describe a part thinner
//! than the one that will be built. The loop sizes every synthesised station, gives a
//! station whose member or screw needs more the larger radius
//! ([`crate::kinds::SizedHardware`]), synthesises it again (the searches keep their parts
//! clear with the new radii, and may choose another mechanism, whose loads differ) and
//! repeats until no sized member exceeds its drawn solid, at most [`MAX_ITERATIONS`]
//! syntheses. Radii only grow, so the loop cannot cycle; a member that needs less than is
//! drawn keeps the drawn solid (the report's masses are the sized ones either way).
//!
//! The interference check, the fairing, the drawings, the STL, URDF and glTF files all come
//! after the loop, from its last synthesis.

use serde::Serialize;

use crate::error::Result;
use crate::kinds::SizedHardware;
use crate::pipeline::flight_loads;
use crate::pipeline::mechanisms::{sweep_station, synthesise_all};
use crate::pipeline::record::{PlacedStation, StationRecord};
use crate::scene::Scene;
use flapwright_geom::parts::WingModel;
use flapwright_mechanism::seam::DrawnRadius;

/// Most syntheses the loop runs (the first one included). Six, not four: a four-bar whose
/// truss's rods grow too thick to clear falls back to struts clamped to the skin, which
/// need thicker solids again (with a link material of 20 MPa allowable on the transport
/// scene: five syntheses, four before the truss).
pub const MAX_ITERATIONS: usize = 6;

/// A sized radius counts as larger than the drawn one beyond this relative margin (the
/// sizing's own rounding is far below it).
const GROWTH_TOLERANCE: f64 = 1e-6;

/// A solid the loop thickens is drawn at the sized radius rounded up to a whole step of
/// this (m), as bar and screw stock come: a re-synthesis that moves the loads by a fraction
/// of a percent then needs no further step, where growing to the exact sized radius crept
/// up by 0.002-0.02 % an iteration on the transport scene and never settled.
pub const RADIUS_STEP_M: f64 = 0.001;

/// What a solid the loop thickens is drawn at beyond its sized radius, before the rounding
/// to stock: the synthesis with the thicker solids may choose a slightly different
/// mechanism, whose loads differ by a few percent (0.5-5.6 % on the transport scene), and
/// without an allowance the four-bars took a third synthesis for the last millimetre.
pub const GROWTH_ALLOWANCE: f64 = 0.05;

/// `radius` with the allowance, rounded up to a whole [`RADIUS_STEP_M`].
fn stock(radius: f64) -> f64 {
    (radius * (1.0 + GROWTH_ALLOWANCE) / RADIUS_STEP_M - 1e-9).ceil() * RADIUS_STEP_M
}

/// What the loop did.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SizingLoopReport {
    /// Syntheses run (1: the first drawn solids were thick enough).
    pub iterations: usize,
    /// True when no sized member of a synthesised station exceeds its drawn solid.
    pub settled: bool,
    /// The largest relative growth of a radius in the last iteration that grew one (%); 0
    /// when none grew.
    pub last_change_percent: f64,
    /// The stations whose solids the loop thickened, with the radii it asked.
    pub stations: Vec<SizedStation>,
}

/// A station the loop thickened.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SizedStation {
    /// Station name.
    pub station: String,
    /// The radii asked.
    pub sized: SizedHardware,
}

/// The station records after the loop, its report (None where no station is synthesised
/// or nothing is sized), and warnings (a loop that did not settle, a synthesis the larger
/// solids made impossible).
pub fn synthesise_sized(
    scene: &Scene,
    model: Option<&WingModel>,
    placed: Vec<PlacedStation>,
    tube_path_ac: &[nalgebra::Point3<f64>],
) -> Result<(Vec<StationRecord>, Option<SizingLoopReport>, Vec<String>)> {
    let mut sized = vec![SizedHardware::default(); scene.station.len()];
    let mut records = synthesise_all(scene, model, placed.clone(), &sized)?;
    let synthesised: Vec<bool> = scene.station.iter().map(|s| s.mechanism.is_synthesised()).collect();
    if model.is_none() || !synthesised.iter().any(|&s| s) {
        return Ok((records, None, Vec::new()));
    }
    let mut warnings = Vec::new();
    let mut report = SizingLoopReport {
        iterations: 1,
        settled: false,
        last_change_percent: 0.0,
        stations: Vec::new(),
    };
    loop {
        let growth = needed_radii(scene, &mut records, tube_path_ac, &synthesised)?;
        let mut change = 0.0_f64;
        for (index, need) in growth {
            let current = &mut sized[index];
            if let Some(radius) = need.link_radius_m.map(stock) {
                let drawn = current.link_radius_m.unwrap_or(0.0);
                if radius > drawn {
                    change = change.max(relative_growth(need.drawn_link_radius_m, radius));
                    current.link_radius_m = Some(radius);
                }
            }
            if let Some(radius) = need.strut_radius_m.map(stock) {
                let drawn = current.strut_radius_m.unwrap_or(0.0);
                if radius > drawn {
                    change = change.max(relative_growth(need.drawn_strut_radius_m, radius));
                    current.strut_radius_m = Some(radius);
                }
            }
            if let Some(radius) = need.screw_mean_radius_m.map(stock) {
                change = change.max(relative_growth(need.drawn_screw_radius_m, radius));
                current.screw_mean_radius_m = Some(radius);
            }
        }
        if change <= GROWTH_TOLERANCE {
            report.settled = true;
            break;
        }
        report.last_change_percent = 100.0 * change;
        if report.iterations == MAX_ITERATIONS {
            warnings.push(format!(
                "sizing: after {MAX_ITERATIONS} syntheses a member still needs {:.1} % more radius than is drawn (the loop's bound): the drawn solids, the check and the files are of the last synthesis",
                100.0 * change
            ));
            break;
        }
        match synthesise_all(scene, model, placed.clone(), &sized) {
            Ok(next) => {
                records = next;
                report.iterations += 1;
            }
            Err(error) => {
                warnings.push(format!(
                    "sizing: with the sized solids the mechanisms cannot be synthesised again ({}); the drawn solids, the check and the files are of the last synthesis, thinner than sized",
                    error.chain_message()
                ));
                break;
            }
        }
    }
    report.stations = sized
        .iter()
        .zip(&scene.station)
        .filter(|(s, _)| **s != SizedHardware::default())
        .map(|(s, station)| SizedStation {
            station: station.name.clone(),
            sized: *s,
        })
        .collect();
    Ok((records, Some(report), warnings))
}

/// (sized - drawn) / drawn.
fn relative_growth(drawn: f64, sized: f64) -> f64 {
    if drawn > 0.0 {
        sized / drawn - 1.0
    } else {
        f64::INFINITY
    }
}

/// What one synthesised station needs beyond what it draws.
struct Need {
    link_radius_m: Option<f64>,
    drawn_link_radius_m: f64,
    strut_radius_m: Option<f64>,
    drawn_strut_radius_m: f64,
    screw_mean_radius_m: Option<f64>,
    drawn_screw_radius_m: f64,
}

/// Sweeps and sizes the stations (leaving each record's deployments on it) and returns, per
/// synthesised station (its index) whose sized member or screw exceeds the drawn solid,
/// the radii it needs: the largest sized radius of its members, its screw's.
fn needed_radii(
    scene: &Scene,
    records: &mut [StationRecord],
    tube_path_ac: &[nalgebra::Point3<f64>],
    synthesised: &[bool],
) -> Result<Vec<(usize, Need)>> {
    let samples = scene.resolution.deployment_samples;
    let mut ignored = Vec::new();
    for record in records.iter_mut() {
        let cases = flight_loads::load_cases(scene, record);
        record.kinematics = Some(sweep_station(record, &cases, samples, &mut ignored)?);
    }
    let (sized, _) = crate::pipeline::sizing::size_all(scene, records, tube_path_ac)?;
    let mut needs = Vec::new();
    for record in records.iter() {
        if !synthesised.get(record.index).copied().unwrap_or(false) {
            continue;
        }
        let members = record.mechanism.members();
        let mut need = Need {
            link_radius_m: None,
            drawn_link_radius_m: f64::INFINITY,
            strut_radius_m: None,
            drawn_strut_radius_m: f64::INFINITY,
            screw_mean_radius_m: None,
            drawn_screw_radius_m: 0.0,
        };
        for rod in sized.rods.iter().filter(|r| r.station == record.station) {
            if rod.name == "screw" {
                if let flapwright_mechanism::seam::Actuator::ScrewJack { screw, .. } = record.mechanism.actuator() {
                    if rod.radius_m > screw.mean_radius_m * (1.0 + GROWTH_TOLERANCE) {
                        need.screw_mean_radius_m = Some(rod.radius_m);
                        need.drawn_screw_radius_m = screw.mean_radius_m;
                    }
                }
            } else if let Some(member) = members.iter().find(|m| m.name == rod.name) {
                if rod.radius_m > member.radius_m * (1.0 + GROWTH_TOLERANCE) {
                    let (needed, drawn) = match member.drawn {
                        DrawnRadius::Link => (&mut need.link_radius_m, &mut need.drawn_link_radius_m),
                        DrawnRadius::Strut => (&mut need.strut_radius_m, &mut need.drawn_strut_radius_m),
                    };
                    *needed = Some(needed.unwrap_or(0.0).max(rod.radius_m));
                    *drawn = drawn.min(member.radius_m);
                }
            }
        }
        if need.link_radius_m.is_some() || need.strut_radius_m.is_some() || need.screw_mean_radius_m.is_some() {
            needs.push((record.index, need));
        }
    }
    Ok(needs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_thickened_solid_is_drawn_at_its_sized_radius_with_the_allowance_rounded_up_to_stock() {
        // 12.1 mm sized: 12.705 mm with the allowance, 13 mm drawn.
        assert!((stock(0.0121) - 0.013).abs() < 1e-15);
        // 19 mm: 19.95 mm, 20 mm drawn; 20 mm: 21 mm exactly, not 22.
        assert!((stock(0.019) - 0.020).abs() < 1e-15);
        assert!((stock(0.020) - 0.021).abs() < 1e-15);
        // Never thinner than sized.
        for k in 1..2000 {
            let radius = 1e-5 * k as f64;
            assert!(stock(radius) >= radius * (1.0 + GROWTH_ALLOWANCE) - 1e-12, "{radius}");
        }
    }
}
