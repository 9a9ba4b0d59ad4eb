//! The whole-wing interference check: every moving part against every fixed part, the
//! screws against the flap, contacts by design declared instead of skipped.

use rayon::prelude::*;
use serde::Serialize;

use crate::error::Result;
use crate::part::Part;
use crate::sweep::{sweep_pair, PairClearance, SweepSettings};
use crate::track::{DeclaredContact, TrackParts};

/// What is checked: fixed structure, the flap, and each station's mechanism parts.
#[derive(Debug)]
pub struct Assembly {
    /// Wing skin, spars, torque tube (aircraft frame, not moving).
    pub fixed: Vec<Part>,
    /// Names of fixed parts the mechanism links are allowed to cross: the wing skin is cut
    /// locally and the links sit in a fairing (measured by the fairing depth instead).
    pub skins: Vec<String>,
    /// The flap, turning about its hinge line.
    pub flaps: Vec<Part>,
    /// Per station: screw, nut, fittings.
    pub stations: Vec<TrackParts>,
}

/// One checked pair.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairResult {
    /// Station of the moving part (absent for the flap).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub station: Option<String>,
    /// Clearance over the deployment.
    #[serde(flatten)]
    pub clearance: PairClearance,
    /// Clearance at least the required minimum (certified: sampled minimum less the
    /// residual bound).
    pub passes: bool,
}

/// The interference section of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InterferenceReport {
    /// Deployment range swept (flap rotation, rad).
    pub deployment_range_rad: [f64; 2],
    /// Required clearance (m).
    pub required_clearance_m: f64,
    /// Every pair checked.
    pub pairs: Vec<PairResult>,
    /// Contacts by design (joints), not checked for clearance.
    pub declared_contacts: Vec<DeclaredContact>,
    /// Every pair passes.
    pub passes: bool,
}

/// Sweeps every pair for flap rotation in `[0, end_rad]`, pairs in parallel (rayon).
pub fn check_assembly(
    assembly: &Assembly,
    end_rad: f64,
    required_clearance_m: f64,
    settings: &SweepSettings,
) -> Result<InterferenceReport> {
    let mut jobs: Vec<(Option<&str>, &Part, &Part)> = Vec::new();
    for flap in &assembly.flaps {
        for fixed in &assembly.fixed {
            jobs.push((None, flap, fixed));
        }
    }
    for station in &assembly.stations {
        let name = Some(station.station.as_str());
        let links = std::iter::once(&station.screw).chain(&station.flap_rigid);
        for link in links {
            for fixed in assembly.fixed.iter().filter(|f| !assembly.skins.contains(&f.name)) {
                jobs.push((name, link, fixed));
            }
        }
        for flap in &assembly.flaps {
            jobs.push((name, &station.screw, flap));
        }
    }
    // Pairs are independent; rayon keeps their order in the result.
    let pairs = jobs
        .into_par_iter()
        .map(|(station, a, b)| {
            let clearance = sweep_pair(a, b, 0.0, end_rad, settings)?;
            let passes = clearance.min_clearance_m - clearance.residual_bound_m >= required_clearance_m;
            Ok(PairResult {
                station: station.map(str::to_string),
                clearance,
                passes,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let passes = pairs.iter().all(|p| p.passes);
    Ok(InterferenceReport {
        deployment_range_rad: [0.0, end_rad],
        required_clearance_m,
        declared_contacts: assembly.stations.iter().flat_map(|s| s.declared.clone()).collect(),
        pairs,
        passes,
    })
}
