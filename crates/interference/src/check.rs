//! The whole-wing interference check: which pairs are checked (station parts against the
//! structure, jacks against the flap, the flap against the structure, a two-element flap's
//! aft element against the structure, its main element and the station parts, parts of
//! different stations against each other), which are left out and why, and joints (contacts by
//! design) checked to stay joined within the joint's play instead of being skipped.

use rayon::prelude::*;
use serde::Serialize;

use std::collections::{BTreeMap, HashMap};

use crate::broad::{ApartPair, SweptBoxes, SWEPT_BOX_INTERVALS};
use crate::error::{Error, Result};
use crate::opening::Opening;
use crate::part::Part;
use crate::station::{DeclaredContact, StationPart, StationParts};
use crate::sweep::{sweep_contact, sweep_pair_for_verdict, JointSeparation, PairClearance, SweepSettings};
use flapwright_mechanism::seam::BodyRole;

/// What is checked: fixed structure, the flap, and each station's mechanism parts.
#[derive(Debug, Default)]
pub struct Assembly {
    /// Wing skin, spars, torque tube (aircraft frame, not moving).
    pub fixed: Vec<Part>,
    /// Names of fixed parts the mechanism links are allowed to cross: the wing skin is cut
    /// locally and the links sit in a fairing (measured by the fairing depth instead).
    pub skins: Vec<String>,
    /// The flaps' meshes, each moving with its carrying station's flap displacement; a part
    /// is named after its flap.
    pub flaps: Vec<Part>,
    /// The aft elements of two-element flaps, each with the name of its flap: moving with
    /// its carrying stations' aft-flap body (or fixed to the main element where a kind has
    /// none); a part is named `<flap>-aft`.
    pub aft_elements: Vec<(String, Part)>,
    /// Per station: every solid of the mechanism's bodies, with its role.
    pub stations: Vec<StationParts>,
}

/// One checked pair.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairResult {
    /// Station of the parts ("inner/outer" for parts of two stations; absent for the flap
    /// against the wing structure).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub station: Option<String>,
    /// Clearance over the deployment.
    #[serde(flatten)]
    pub clearance: PairClearance,
    /// The clearance this pair needs (m): the global one, or a station's larger one.
    pub required_clearance_m: f64,
    /// Clearance at least the required minimum (certified: sampled minimum less the
    /// residual bound).
    pub passes: bool,
    /// Wall time the pair's sweep took (s): for a CI report's per-case time, not written
    /// to the report (the same scene gives the same report).
    #[serde(skip)]
    pub sweep_time_s: f64,
}

/// One joint checked: parts that touch by design must not come apart by more than the
/// joint's play.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactResult {
    /// The declared contact.
    #[serde(flatten)]
    pub declared: DeclaredContact,
    /// Largest separation over the deployment.
    #[serde(flatten)]
    pub separation: JointSeparation,
    /// The certified upper bound on the separation is within the play.
    pub passes: bool,
    /// Wall time the joint's sweep took (s), as [`PairResult::sweep_time_s`].
    #[serde(skip)]
    pub sweep_time_s: f64,
}

/// Why a station's parts are not checked against the skin.
const NO_OPENING: &str =
    "no opening was cut in the skin for this station, so its parts cannot be checked against the skin";
/// Why a part joined to the flap by a joint is not checked against the flap itself.
const NO_SLOT: &str = "joined to the flap by design, and no slot was cut in the flap for this station";
/// Why a solid of the body that moves an aft element is not checked against it.
const ON_AFT_BODY: &str = "part of the body that moves the flap's aft element: rigid with it by design";
/// Why a part joined to an aft element by a joint is not checked against it.
const NO_AFT_SLOT: &str = "joined to the flap's aft element by design, and no slot was cut in it for this station";

/// A pair the check leaves out, and why (listed so nothing is skipped silently).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UncheckedPair {
    /// Station.
    pub station: String,
    /// First part.
    pub part_a: String,
    /// Second part.
    pub part_b: String,
    /// Why.
    pub reason: String,
}

/// What the check requires.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Requirements {
    /// Smallest clearance between parts that must stay apart (m).
    pub clearance_m: f64,
    /// Largest separation of parts joined by design (m): the joint's play.
    pub joint_play_m: f64,
    /// Larger clearances some stations require (m, by station name): a pair of a station's
    /// parts needs the larger of this and [`Requirements::clearance_m`], a pair of two
    /// stations' parts the largest of the three.
    pub clearance_by_station_m: BTreeMap<String, f64>,
}

impl Requirements {
    /// The clearance a pair of `station` needs ("a/b" for parts of two stations; `None`
    /// for the flap against the structure).
    pub fn clearance_for(&self, station: Option<&str>) -> f64 {
        station
            .into_iter()
            .flat_map(|s| s.split('/'))
            .filter_map(|s| self.clearance_by_station_m.get(s))
            .fold(self.clearance_m, |a, &b| a.max(b))
    }
}

/// The interference section of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InterferenceReport {
    /// Deployment range swept: the drive fraction τ, 0 stowed to 1 deployed at every
    /// station.
    pub deployment_range: [f64; 2],
    /// Required clearance (m).
    pub required_clearance_m: f64,
    /// Stations that require more (m), as [`Requirements::clearance_by_station_m`].
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub required_clearance_by_station_m: BTreeMap<String, f64>,
    /// Allowed separation of parts joined by design (m).
    pub joint_play_m: f64,
    /// Every pair swept.
    pub pairs: Vec<PairResult>,
    /// Intervals of the deployment the broad phase bounds each part over.
    pub swept_box_intervals: usize,
    /// Pairs certified clear by the broad phase alone: their swept boxes stay farther apart
    /// than the required clearance (they pass; not swept).
    pub certified_apart: Vec<ApartPair>,
    /// Contacts by design (joints): checked to stay within the joint's play, not for
    /// clearance.
    pub declared_contacts: Vec<ContactResult>,
    /// Where the skin and the flaps are opened for each station's mechanism.
    pub openings: Vec<Opening>,
    /// Pairs left out by design, with the reason.
    pub unchecked_pairs: Vec<UncheckedPair>,
    /// Every pair and every joint passes.
    pub passes: bool,
    /// Pairs were refined only until their verdict was certain
    /// ([`SweepSettings::stop_at_verdict`]): their `min_clearance_m` is the smallest sample,
    /// not the minimum located to the tolerance. Absent when false.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub stopped_at_verdict: bool,
}

/// A pair to sweep: the station label and the two parts.
type PairJob<'a> = (Option<String>, &'a Part, &'a Part);

/// The pairs to sweep, and the pairs left out with the reason.
fn pair_jobs(assembly: &Assembly) -> (Vec<PairJob<'_>>, Vec<UncheckedPair>) {
    let mut jobs: Vec<PairJob<'_>> = Vec::new();
    for (i, flap) in assembly.flaps.iter().enumerate() {
        for fixed in &assembly.fixed {
            jobs.push((None, flap, fixed));
        }
        // Neighbouring flaps deflect by their own amounts, and swept hinge lines move
        // their side faces spanwise.
        for other in &assembly.flaps[i + 1..] {
            jobs.push((None, flap, other));
        }
    }
    // An aft element against the structure, every flap (its own main element: the slot
    // between them must stay open) and every other aft element.
    for (i, (_, aft)) in assembly.aft_elements.iter().enumerate() {
        for fixed in &assembly.fixed {
            jobs.push((None, aft, fixed));
        }
        for flap in &assembly.flaps {
            jobs.push((None, aft, flap));
        }
        for (_, other) in &assembly.aft_elements[i + 1..] {
            jobs.push((None, aft, other));
        }
    }
    let structure: Vec<&Part> = assembly
        .fixed
        .iter()
        .filter(|f| !assembly.skins.contains(&f.name))
        .collect();
    let skins: Vec<&Part> = assembly
        .fixed
        .iter()
        .filter(|f| assembly.skins.contains(&f.name))
        .collect();
    let mut unchecked = Vec::new();
    for station in &assembly.stations {
        let name = || Some(station.station.clone());
        let mut skip = |a: &Part, b: &Part, reason: &str| {
            unchecked.push(UncheckedPair {
                station: station.station.clone(),
                part_a: a.name.clone(),
                part_b: b.name.clone(),
                reason: reason.into(),
            })
        };
        // Moving parts and the station's fixed hardware (tracks, supports) against the
        // structure, and against the skin with the station's opening cut in it.
        for part in &station.parts {
            for &fixed in &structure {
                jobs.push((name(), &part.part, fixed));
            }
            for &skin in &skins {
                match station.opened_skins.iter().find(|s| s.name == skin.name) {
                    Some(opened) => jobs.push((name(), &part.part, opened)),
                    None => skip(&part.part, skin, NO_OPENING),
                }
            }
        }
        // Against the flap it carries: not the flap's own body; the solids joined to it by
        // design (the joint's touching solids: a link on its fitting, a hook carrying its
        // roller) against the flap with its slot cut; everything else, on whatever body,
        // against the whole flap. Against every other flap: everything.
        let flap_body = station.parts.iter().find(|p| p.role == BodyRole::Flap).map(|p| p.body);
        for flap in &assembly.flaps {
            if station.flap.as_deref() != Some(flap.name.as_str()) {
                for part in &station.parts {
                    jobs.push((name(), &part.part, flap));
                }
                continue;
            }
            for part in station.parts.iter().filter(|p| Some(p.body) != flap_body) {
                let joined = flap_body.is_some_and(|f| part.joined_to.contains(&f));
                match (joined, &station.slotted_flap) {
                    (false, _) => jobs.push((name(), &part.part, flap)),
                    (true, Some(slotted)) => jobs.push((name(), &part.part, slotted)),
                    (true, None) => skip(&part.part, flap, NO_SLOT),
                }
            }
        }
        // Against the aft element of the flap it carries: the aft-flap body's own solids are
        // rigid with it by design (listed, not swept); what is joined to the body that moves
        // it (the aft-flap body, or the flap body for a kind without one, whose own fittings
        // are then swept against it like any part) against the aft element with the
        // station's slot cut; everything else whole.
        let aft_flap_body = station
            .parts
            .iter()
            .find(|p| p.role == BodyRole::AftFlap)
            .map(|p| p.body);
        let aft_body = aft_flap_body.or(flap_body);
        for (flap, aft) in &assembly.aft_elements {
            let carried = station.flap.as_deref() == Some(flap.as_str());
            for part in &station.parts {
                if !carried {
                    jobs.push((name(), &part.part, aft));
                } else if Some(part.body) == aft_flap_body {
                    skip(&part.part, aft, ON_AFT_BODY);
                } else if Some(part.body) == aft_body {
                    jobs.push((name(), &part.part, aft));
                } else if aft_body.is_some_and(|b| part.joined_to.contains(&b)) {
                    match &station.slotted_aft_element {
                        Some(slotted) => jobs.push((name(), &part.part, slotted)),
                        None => skip(&part.part, aft, NO_AFT_SLOT),
                    }
                } else {
                    jobs.push((name(), &part.part, aft));
                }
            }
        }
        // Same-station parts of different bodies, at least one moving, each in its
        // spanwise layer, unless they touch by design (then checked as a joint).
        let touching = |a: &Part, b: &Part| {
            station
                .declared
                .iter()
                .any(|c| (c.part_a == a.name && c.part_b == b.name) || (c.part_a == b.name && c.part_b == a.name))
        };
        let parts: Vec<&StationPart> = station.parts.iter().collect();
        for (i, a) in parts.iter().enumerate() {
            for b in &parts[i + 1..] {
                if a.body != b.body && (a.moving || b.moving) && !touching(&a.part, &b.part) {
                    jobs.push((name(), &a.part, &b.part));
                }
            }
        }
    }
    // Parts of different stations, moving or fixed, against each other.
    for (i, first) in assembly.stations.iter().enumerate() {
        for second in &assembly.stations[i + 1..] {
            let label = || Some(format!("{}/{}", first.station, second.station));
            for a in first.parts() {
                for b in second.parts() {
                    jobs.push((label(), a, b));
                }
            }
        }
    }
    (jobs, unchecked)
}

/// Sweeps every pair and every declared joint for the deployment parameter in `[0, end]`, in
/// parallel (rayon).
pub fn check_assembly(
    assembly: &Assembly,
    end: f64,
    required: &Requirements,
    settings: &SweepSettings,
) -> Result<InterferenceReport> {
    let (jobs, unchecked) = pair_jobs(assembly);
    // Broad phase: every part's swept boxes once; pairs whose boxes stay farther apart than
    // the requirement are certified by them alone (strictly: boxes that touch prove
    // nothing).
    let mut parts: Vec<&Part> = jobs.iter().flat_map(|(_, a, b)| [*a, *b]).collect();
    parts.sort_by_key(|p| std::ptr::from_ref(*p) as usize);
    parts.dedup_by_key(|p| std::ptr::from_ref(*p) as usize);
    let boxes: HashMap<usize, SweptBoxes> = parts
        .par_iter()
        .map(|p| Ok((std::ptr::from_ref(*p) as usize, SweptBoxes::of(p, end)?)))
        .collect::<Result<_>>()?;
    let key = |p: &Part| std::ptr::from_ref(p) as usize;
    // The boxes' bound; where it does not certify a moving mesh against a fixed part, the
    // mesh's own posed boxes against the fixed part's shape (a swept flap's axis-aligned
    // boxes reach the spars, its own boxes do not).
    let bound = |a: &Part, b: &Part, required_m: f64| -> Result<f64> {
        let boxed = boxes[&key(a)].lower_bound(&boxes[&key(b)]);
        if boxed > required_m {
            return Ok(boxed);
        }
        let refined = match (a.is_moving(), b.is_moving()) {
            (true, false) => boxes[&key(a)].lower_bound_to_fixed(b)?,
            (false, true) => boxes[&key(b)].lower_bound_to_fixed(a)?,
            _ => None,
        };
        Ok(refined.map_or(boxed, |r| r.max(boxed)))
    };
    let bounded = jobs
        .into_par_iter()
        .map(|job| Ok((bound(job.1, job.2, required.clearance_for(job.0.as_deref()))?, job)))
        .collect::<Result<Vec<_>>>()?;
    let (apart, jobs): (Vec<_>, Vec<_>) = bounded
        .into_iter()
        .partition(|(lower_bound, (station, _, _))| *lower_bound > required.clearance_for(station.as_deref()));
    let jobs: Vec<PairJob<'_>> = jobs.into_iter().map(|(_, job)| job).collect();
    let certified_apart = apart
        .into_iter()
        .map(|(lower_bound_m, (station, a, b))| ApartPair {
            station,
            part_a: a.name.clone(),
            part_b: b.name.clone(),
            lower_bound_m,
        })
        .collect();
    // Pairs are independent; rayon keeps their order in the result.
    let pairs = jobs
        .into_par_iter()
        .map(|(station, a, b)| {
            let required_clearance_m = required.clearance_for(station.as_deref());
            let started = std::time::Instant::now();
            let clearance = sweep_pair_for_verdict(a, b, 0.0, end, settings, required_clearance_m)?;
            let passes = clearance.min_clearance_m - clearance.residual_bound_m >= required_clearance_m;
            Ok(PairResult {
                station,
                clearance,
                required_clearance_m,
                passes,
                sweep_time_s: started.elapsed().as_secs_f64(),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let contacts = assembly
        .stations
        .iter()
        .flat_map(|station| station.declared.iter().map(move |contact| (station, contact)))
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|(station, contact)| {
            // In the station plane: a pin spans the layers of the bodies it joins.
            let part = |name: &str| {
                station
                    .parts
                    .iter()
                    .map(|p| &p.in_plane)
                    .find(|p| p.name == name)
                    .ok_or_else(|| Error::UnknownPart {
                        name: name.to_string(),
                        joint: contact.joint.clone(),
                    })
            };
            let (a, b) = (part(&contact.part_a)?, part(&contact.part_b)?);
            let started = std::time::Instant::now();
            let separation = sweep_contact(a, b, 0.0, end, required.joint_play_m, settings)?;
            let passes = separation.upper_bound_m <= required.joint_play_m;
            Ok(ContactResult {
                declared: contact.clone(),
                separation,
                passes,
                sweep_time_s: started.elapsed().as_secs_f64(),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let passes = pairs.iter().all(|p| p.passes) && contacts.iter().all(|c| c.passes);
    Ok(InterferenceReport {
        deployment_range: [0.0, end],
        required_clearance_m: required.clearance_m,
        required_clearance_by_station_m: required.clearance_by_station_m.clone(),
        joint_play_m: required.joint_play_m,
        declared_contacts: contacts,
        swept_box_intervals: SWEPT_BOX_INTERVALS,
        certified_apart,
        openings: assembly.stations.iter().filter_map(|s| s.opening.clone()).collect(),
        unchecked_pairs: unchecked,
        pairs,
        passes,
        stopped_at_verdict: settings.stop_at_verdict,
    })
}
