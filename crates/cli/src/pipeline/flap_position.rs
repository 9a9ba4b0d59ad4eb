//! Gap and overlap of each station's flap behind the main wing (Zaccai et al. `003`
//! definitions, measured in the station plane by `flapwright_planes::FlapBehindWing`) at the
//! scene's flap settings.

use anyhow::{Context, Result};
use flapwright_mechanism::{PrecisionPosition, StationOutline};
use flapwright_planes::{FlapBehindWing, GapOverlap};
use serde::Serialize;

use crate::kinds::SynthesisContext;
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

/// What a kind synthesised from the flap settings needs at one placed station: the wing
/// and stowed flap sections, and take-off and landing as flap displacements in the plane
/// (where `flap`'s settings give gap and overlap), with the flap behind the wing they were
/// measured by (kept on the record for the gap-overlap stage).
pub fn synthesis_context(
    flap: &FlapScene,
    flaps: &[FlapScene],
    placed: &PlacedStation,
) -> Result<(SynthesisContext, Option<FlapBehindWing>)> {
    let outline = StationOutline {
        wing: placed.polygons_of(|name| name == "wing"),
        flap: placed.polygons_of(|name| name == flap.name),
        // Spars and the torque tube; other flaps' sections are not structure.
        structure: placed.polygons_of(|name| name != "wing" && !flaps.iter().any(|f| f.name == name)),
        lip: None,
    };
    let Some(measure) = flap_behind_wing(placed, &flap.name)? else {
        return Ok((SynthesisContext::default(), None));
    };
    let outline = StationOutline {
        lip: Some(measure.trailing_edge()),
        ..outline
    };
    let chord = measure.chord_m();
    let position = |name: &'static str, deflection_deg: f64| -> Result<Option<PrecisionPosition>> {
        let (Some(gap), Some(overlap)) = flap.settings.targets(name) else {
            return Ok(None);
        };
        let deflection_rad = deflection_deg.to_radians();
        let displacement = measure
            .displacement_for_setting(deflection_rad, gap * chord / 100.0, overlap * chord / 100.0)
            .with_context(|| format!("flap {} {name} setting at station {}", flap.name, placed.station.name))?;
        Ok(Some(PrecisionPosition {
            name,
            deflection_rad,
            flap: displacement,
        }))
    };
    let settings = match (
        position("takeoff", flap.settings.takeoff_deg)?,
        position("landing", flap.settings.landing_deg)?,
    ) {
        (Some(takeoff), Some(landing)) => Some((takeoff, landing)),
        _ => None,
    };
    Ok((
        SynthesisContext {
            outline: Some(outline),
            settings,
            down_st: Some({
                // The aircraft's down (-z) on the plane's in-plane axes.
                let frame = &placed.station.frame;
                nalgebra::Vector2::new(-frame.x_axis_ac().z, -frame.y_axis_ac().z)
            }),
        },
        Some(measure),
    ))
}

/// The gap and overlap at each station's flap settings (`flap_position`), measured by the
/// record's `flap_behind_wing` (set at synthesis); None where the station has no flap
/// section to measure.
pub fn flap_positions(flaps: &[FlapScene], records: &mut [StationRecord]) -> Result<()> {
    for record in records.iter_mut() {
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
