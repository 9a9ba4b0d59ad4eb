//! Gap and overlap of each station's flap behind the main wing (Zaccai et al. `003`
//! definitions, measured in the station plane by `flapwright_planes::FlapBehindWing`) at the
//! scene's flap settings.

use anyhow::{Context, Result};
use flapwright_planes::{FlapBehindWing, GapOverlap};
use serde::Serialize;

use crate::pipeline::stations::PlacedStation;
use crate::scene::{FlapScene, StationScene};

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

/// Gap and overlap at each station's flap settings (`None` where the station has no flap
/// section to measure).
pub fn flap_positions(
    stations: &[StationScene],
    flaps: &[FlapScene],
    placed: &[PlacedStation],
) -> Result<Vec<Option<FlapPositionReport>>> {
    stations
        .iter()
        .zip(placed)
        .map(|(station, placed)| {
            let Some(flap) = station
                .flap
                .as_ref()
                .and_then(|name| flaps.iter().find(|f| &f.name == name))
            else {
                return Ok(None);
            };
            let Some(measure) = flap_behind_wing(placed, &flap.name)? else {
                return Ok(None);
            };
            let settings = [
                ("stowed", 0.0),
                ("takeoff", flap.settings.takeoff_deg),
                ("landing", flap.settings.landing_deg),
            ]
            .into_iter()
            .map(|(setting, deflection_deg)| SettingPosition {
                setting: setting.into(),
                deflection_deg,
                position: measure.at_rotation(f64::to_radians(deflection_deg)),
            })
            .collect();
            let te = measure.trailing_edge();
            Ok(Some(FlapPositionReport {
                trailing_edge_st_m: [te.x, te.y],
                local_chord_m: measure.chord_m(),
                settings,
            }))
        })
        .collect()
}
