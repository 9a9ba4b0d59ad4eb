//! What the stages share: one [`StationRecord`] per station, filled in stage by stage, and
//! the stage results it holds (the station's placed plane, its flap position at the
//! settings, its mechanism's deployments, its share of the flap's load). Every stage imports
//! this module and none of them imports another for these types.

use std::sync::Arc;

use flapwright_interference::FairingDepth;
use flapwright_mechanism::seam::InputRange;
use flapwright_mechanism::{Deployment, FlapMechanism};
use flapwright_planes::{FlapBehindWing, FlapDeployment, GapOverlap, Section, Station};
use nalgebra::{Isometry3, Point2};
use serde::Serialize;

/// One station as the stages see it, filled in stage by stage: its name and flap, its
/// mechanism behind the seam, and what each stage found. The pipeline keeps one record per
/// station, never parallel vectors matched by position.
#[derive(Debug)]
pub struct StationRecord {
    /// Station name.
    pub station: String,
    /// Its index in the scene's `[[station]]` list (for keys such as `station[i]`).
    pub index: usize,
    /// The flap it supports.
    pub flap: Option<String>,
    /// The synthesised mechanism, behind the seam: all the other stages see of it.
    pub mechanism: Arc<dyn FlapMechanism>,
    /// Its plane, frame and section cuts (planes stage; None without a wing).
    pub placed: Option<PlacedStation>,
    /// The flap behind the main wing in the station plane (gap-overlap stage).
    pub flap_behind_wing: Option<FlapBehindWing>,
    /// Gap and overlap at the flap settings (gap-overlap stage).
    pub flap_position: Option<FlapPositionReport>,
    /// How the rigid flap moved this station's settings (synthesis; empty for a flap with
    /// one station).
    pub rigid_flap: Vec<RigidFlapSetting>,
    /// Fairing depth (fairing stage).
    pub fairing: Option<FairingDepth>,
    /// Deployments under every load case (kinematics stage).
    pub kinematics: Option<MechanismReport>,
    /// Its share of its flap's flight load (after the planes, with a wing).
    pub flap_load_share: Option<crate::pipeline::record::FlapLoadShare>,
    /// How far this station moves its flap off the rigid motion fitted to all the flap's
    /// stations (synthesis; None for a flap on one station).
    pub flap_motion_miss: Option<FlapMotionMiss>,
}

/// How far a station's mechanism moves its flap's section off the flap's rigid motion,
/// fitted to every station carrying the flap (`flapwright_interference::FittedFlapMotion`,
/// the motion the interference check moves the flap by), over the deployment: what the
/// station's attachment joints must take up.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapMotionMiss {
    /// The largest distance of the station's section points from the fitted motion (m).
    pub largest_m: f64,
    /// The drive fraction where it is largest.
    pub at_fraction: f64,
    /// The largest distance as a share of the flap's local chord at the station (%).
    pub percent_local_chord: f64,
}

/// The report's record of one station's mechanism: kind-neutral apart from `details`.
#[derive(Debug, Clone, Serialize)]
pub struct MechanismReport {
    /// Mechanism kind (the scene's `kind`).
    pub kind: &'static str,
    /// The actuator input: stroke (m) or angle (rad), stowed and deployed.
    pub input: InputRange,
    /// The actuator: its type and nominal speed.
    pub actuator: flapwright_mechanism::seam::Actuator,
    /// The kind's own record: its dimensions and what synthesis computed.
    pub details: serde_json::Value,
    /// One deployment per load case.
    pub load_cases: Vec<Deployment>,
    /// Its share of its flap's flight load, where a case gives a flight condition.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flap_load_share: Option<crate::pipeline::record::FlapLoadShare>,
}

impl MechanismReport {
    /// The largest |actuator load| (N, or N m for a rotary actuator) over every load case's
    /// samples; NaN where a sample's is, so that a comparison with it fails.
    pub fn peak_actuator_load(&self) -> f64 {
        self.load_cases
            .iter()
            .flat_map(|case| &case.samples)
            .map(|sample| sample.actuator_load.abs())
            .fold(0.0, |peak: f64, load| {
                if peak.is_nan() || load.is_nan() {
                    f64::NAN
                } else {
                    peak.max(load)
                }
            })
    }
}

/// Each flap carried by two or more placed stations, with those stations' records, in the
/// order the flaps first appear.
pub fn flaps_on_several_stations(records: &[StationRecord]) -> Vec<(&str, Vec<&StationRecord>)> {
    let mut flaps: Vec<&str> = Vec::new();
    for flap in records.iter().filter_map(|r| r.flap.as_deref()) {
        if !flaps.contains(&flap) {
            flaps.push(flap);
        }
    }
    flaps
        .into_iter()
        .map(|flap| {
            let carriers: Vec<&StationRecord> = records
                .iter()
                .filter(|r| r.flap.as_deref() == Some(flap) && r.placed.is_some())
                .collect();
            (flap, carriers)
        })
        .filter(|(_, carriers)| carriers.len() >= 2)
        .collect()
}

/// A station placed in 3D.
#[derive(Debug, Clone)]
pub struct PlacedStation {
    /// The plane, frame, skew and residuals (the residuals once the mechanism is known:
    /// `stations::attachment_residuals`).
    pub station: Station,
    /// Section cuts of every part in the station plane.
    pub sections: Vec<Section>,
    /// The flap's 3D motion the residuals are measured over.
    pub deployment: FlapDeployment,
    /// The flap's take-off and landing 3D poses (aircraft frame) its settings ask for,
    /// where several stations carry it or this one's plane is skew-corrected
    /// (`stations::apply_flap_motion`); the station's precision positions are these as its plane
    /// sees them.
    pub setting_poses_ac: Option<[Isometry3<f64>; 2]>,
}

impl PlacedStation {
    /// The section polygons of the whole flap `flap` (station frame): its own part's and
    /// its aft element's, stowed.
    pub fn flap_polygons(&self, flap: &str) -> Vec<Vec<Point2<f64>>> {
        let aft = flapwright_geom::parts::aft_element_name(flap);
        self.polygons_of(|name| name == flap || name == aft)
    }

    /// The section polygons (station frame) of the parts `wanted` accepts by name.
    pub fn polygons_of(&self, wanted: impl Fn(&str) -> bool) -> Vec<Vec<Point2<f64>>> {
        self.sections
            .iter()
            .filter(|s| wanted(&s.part_name))
            .flat_map(|s| s.polygons.iter().cloned())
            .collect()
    }
}

/// Gap and overlap at one named flap setting.
#[derive(Debug, Clone, Serialize)]
pub struct SettingPosition {
    /// "stowed", "takeoff" or "landing".
    pub setting: String,
    /// Flap rotation of the setting (deg).
    pub deflection_deg: f64,
    /// Gap and overlap (m and % of the local chord).
    #[serde(flatten)]
    pub position: GapOverlap,
    /// The scene's target gap (% of the local chord), if it gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_gap_percent_chord: Option<f64>,
    /// The scene's target overlap (% of the local chord), if it gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_overlap_percent_chord: Option<f64>,
    /// Where the target gap is below the flap's sealed gap, the gap the mechanism was
    /// synthesised to instead (m): the slot is sealed, a seal on the lip closing the rest.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sealed_gap_m: Option<f64>,
    /// How far the gap misses what the mechanism was synthesised to (% of the local chord;
    /// positive: wider): the target, or the sealed gap where the setting is sealed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_miss_percent_chord: Option<f64>,
    /// How far the overlap misses its target (% of the local chord; positive: larger).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub overlap_miss_percent_chord: Option<f64>,
}

/// The gap (m) a setting's mechanism is synthesised to for a target of `gap_percent` of
/// `chord_m`, and whether the setting is sealed (the target below `sealed_gap_m`).
pub fn structural_gap_m(gap_percent: f64, chord_m: f64, sealed_gap_m: f64) -> (f64, bool) {
    let target = gap_percent * chord_m / 100.0;
    if target < sealed_gap_m {
        (sealed_gap_m, true)
    } else {
        (target, false)
    }
}

impl SettingPosition {
    /// The setting at `position`, its misses measured against the targets, and a sealed
    /// gap against the sealed gap (a sealed slot is built to it, not to the smaller target).
    pub fn new(
        setting: &str,
        deflection_deg: f64,
        position: GapOverlap,
        targets: (Option<f64>, Option<f64>),
        sealed_gap_m: Option<f64>,
        chord_m: f64,
    ) -> Self {
        let (target_gap_percent_chord, target_overlap_percent_chord) = targets;
        let built_gap_percent = sealed_gap_m
            .map(|gap| 100.0 * gap / chord_m)
            .or(target_gap_percent_chord);
        Self {
            setting: setting.into(),
            deflection_deg,
            position,
            target_gap_percent_chord,
            target_overlap_percent_chord,
            sealed_gap_m,
            gap_miss_percent_chord: built_gap_percent.map(|t| position.gap_percent_chord - t),
            overlap_miss_percent_chord: target_overlap_percent_chord.map(|t| position.overlap_percent_chord - t),
        }
    }

    /// How far the gap and the overlap miss what the setting was built to (% of the local
    /// chord; positive: larger), where the scene gives targets.
    pub fn misses(&self) -> (Option<f64>, Option<f64>) {
        (self.gap_miss_percent_chord, self.overlap_miss_percent_chord)
    }
}

/// The flap's position behind the main wing at one station.
#[derive(Debug, Clone, Serialize)]
pub struct FlapPositionReport {
    /// The main-wing trailing edge measured from (upper lip of the cove), station frame (m).
    pub trailing_edge_st_m: [f64; 2],
    /// Local clean chord the percentages refer to (m).
    pub local_chord_m: f64,
    /// Stowed, take-off and landing.
    pub settings: Vec<SettingPosition>,
    /// Where the flap's other stations move the settings from this station's own (see
    /// `flap_position::rigid_flap_settings`); empty for a flap with one station.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rigid_flap: Vec<RigidFlapSetting>,
    /// A two-element flap's second slot: the aft element behind the main element.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aft_slot: Option<AftSlotReport>,
}

/// The second slot of a two-element flap: gap and overlap of the aft element behind the
/// main element (the `003_...` definitions with the main element as the wing: the lip is
/// the main element's upper trailing edge), at the same settings, in the main element's
/// frame (the aft element's displacement relative to the main element's).
#[derive(Debug, Clone, Serialize)]
pub struct AftSlotReport {
    /// The main element's trailing edge (upper lip of its cove), stowed, station frame (m).
    pub trailing_edge_st_m: [f64; 2],
    /// The flap's local chord the percentages refer to (m): the main element's nose to the
    /// aft element's trailing edge, stowed.
    pub flap_chord_m: f64,
    /// Stowed, take-off and landing.
    pub settings: Vec<AftSlotSetting>,
}

/// The second slot at one setting.
#[derive(Debug, Clone, Serialize)]
pub struct AftSlotSetting {
    /// "stowed", "takeoff" or "landing".
    pub setting: String,
    /// The aft element's rotation relative to the main element (deg, trailing edge down).
    pub relative_deflection_deg: f64,
    /// Gap and overlap (m and % of the flap chord).
    #[serde(flatten)]
    pub position: GapOverlap,
}

/// How the rigid flap moves one station's setting from where the station's own gap and
/// overlap put the flap.
#[derive(Debug, Clone, Serialize)]
pub struct RigidFlapSetting {
    /// "takeoff" or "landing".
    pub setting: &'static str,
    /// Largest in-plane distance of the station's flap section points (all of them) from
    /// the position its own gap and overlap give (m): the measured gap and overlap miss the
    /// station's targets by at most this.
    pub shift_from_station_target_m: f64,
    /// Largest distance of the section points from the station plane at the setting (m):
    /// the out-of-plane motion the flap attachments' joints take up.
    pub out_of_plane_m: f64,
    /// The rigid flap's rotation as this plane sees it (deg): the setting's deflection
    /// give or take the conical motion's share; the station's precision position and its
    /// `settings` entry are at this deflection.
    pub deflection_in_plane_deg: f64,
}

/// A station's share of its flap's flight load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapLoadShare {
    /// The station's share of the flap area (m²): its normal force is C_N q n times this.
    pub flap_area_share_m2: f64,
    /// The flap's quarter-chord point in the station plane, stowed (station frame, m).
    pub quarter_chord_st_m: [f64; 2],
    /// The unit upward normal of the stowed flap's chord line (station frame): the normal
    /// force's direction (`003_...` eq. 1).
    pub chord_normal_st: [f64; 2],
}
