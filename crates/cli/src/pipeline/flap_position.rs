//! Gap and overlap of each station's flap behind the main wing (Zaccai et al. `003`
//! definitions, measured in the station plane by `flapwright_planes::FlapBehindWing`) at the
//! scene's flap settings.

use anyhow::{Context, Result};
use flapwright_planes::{FlapBehindWing, GapOverlap};
use serde::Serialize;

use crate::pipeline::mechanisms::StationRecord;
use crate::pipeline::stations::PlacedStation;
use crate::scene::FlapScene;

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
}

impl SettingPosition {
    /// How far the gap and the overlap miss their targets (% of the local chord; positive:
    /// larger than the target), where the scene gives targets.
    pub fn misses(&self) -> (Option<f64>, Option<f64>) {
        (
            self.target_gap_percent_chord
                .map(|t| self.position.gap_percent_chord - t),
            self.target_overlap_percent_chord
                .map(|t| self.position.overlap_percent_chord - t),
        )
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
}

/// The wing and stowed flap sections of `placed`, ready to measure; `None` when the plane
/// misses the wing or the flap.
pub fn flap_behind_wing(placed: &PlacedStation, flap_name: &str) -> Result<Option<FlapBehindWing>> {
    let (wing, flap) = (
        placed.polygons_of(|name| name == "wing"),
        placed.polygons_of(|name| name == flap_name),
    );
    if wing.is_empty() || flap.is_empty() {
        return Ok(None);
    }
    Ok(Some(FlapBehindWing::new(&wing, &flap).with_context(|| {
        format!("gap and overlap at station {}", placed.station.name)
    })?))
}

/// The flap behind the wing at each station (each record's `flap_behind_wing`, measured
/// once for the settings and the deployment samples) and the gap and overlap at its flap
/// settings (`flap_position`); None where the station has no flap section to measure.
pub fn flap_positions(flaps: &[FlapScene], records: &mut [StationRecord]) -> Result<()> {
    for record in records.iter_mut() {
        record.flap_behind_wing = match (&record.placed, record.flap.as_deref()) {
            (Some(placed), Some(flap)) => flap_behind_wing(placed, flap)?,
            _ => None,
        };
        record.flap_position = flap_position(flaps, record)?;
    }
    Ok(())
}

fn flap_position(flaps: &[FlapScene], record: &StationRecord) -> Result<Option<FlapPositionReport>> {
    let Some(flap) = record
        .flap
        .as_ref()
        .and_then(|name| flaps.iter().find(|f| &f.name == name))
    else {
        return Ok(None);
    };
    let Some(measure) = &record.flap_behind_wing else {
        return Ok(None);
    };
    let seam = record.mechanism.as_ref();
    let settings = [
        ("stowed", 0.0),
        ("takeoff", flap.settings.takeoff_deg),
        ("landing", flap.settings.landing_deg),
    ]
    .into_iter()
    .map(|(setting, deflection_deg)| {
        // Where the mechanism puts the flap at this deflection: any planar motion.
        let pose = seam.pose(seam.input_at_deflection(deflection_deg.to_radians())?)?;
        let (target_gap_percent_chord, target_overlap_percent_chord) = flap.settings.targets(setting);
        Ok(SettingPosition {
            setting: setting.into(),
            deflection_deg,
            position: measure.at_displacement(&pose.flap),
            target_gap_percent_chord,
            target_overlap_percent_chord,
        })
    })
    .collect::<Result<Vec<_>>>()?;
    let te = measure.trailing_edge();
    Ok(Some(FlapPositionReport {
        trailing_edge_st_m: [te.x, te.y],
        local_chord_m: measure.chord_m(),
        settings,
    }))
}

/// Fills each deployment sample's gap and overlap, where the mechanism puts the flap at
/// that sample's input.
pub fn annotate_samples(
    mechanism: &StationRecord,
    measure: &FlapBehindWing,
    report: &mut crate::pipeline::mechanisms::MechanismReport,
) -> Result<()> {
    for case in &mut report.load_cases {
        for sample in &mut case.samples {
            let pose = mechanism.mechanism.pose(sample.input)?;
            let at = measure.at_displacement(&pose.flap);
            sample.flap_position = Some(flapwright_mechanism::FlapGapOverlap {
                gap_m: at.gap_m,
                gap_percent_chord: at.gap_percent_chord,
                overlap_m: at.overlap_m,
                overlap_percent_chord: at.overlap_percent_chord,
            });
        }
    }
    Ok(())
}
