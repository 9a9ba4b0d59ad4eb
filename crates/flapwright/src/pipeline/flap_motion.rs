//! The rigid motion of a flap carried by several stations, fitted to its sections as their
//! mechanisms move them: the interference check, the synthesis and the stations' attachment
//! residuals all use it.

use flapwright_interference::{fit_points, FittedFlapMotion, FlapCarrier, FlapElement};

use crate::error::{Error, Result};
use crate::pipeline::record::StationRecord;

/// The rigid motion of a flap element (the part `part`: the flap, or its aft element)
/// carried by several stations, fitted to its sections as their mechanisms move them
/// (`flapwright_interference::FittedFlapMotion`), with a speed bound for `vertices_ac`.
pub fn fitted_flap_motion(
    part: &str,
    element: FlapElement,
    carriers: &[&StationRecord],
    vertices_ac: &[nalgebra::Point3<f64>],
) -> Result<FittedFlapMotion> {
    let carriers = carriers
        .iter()
        .map(|record| {
            let placed = record.placed.as_ref().ok_or_else(|| Error::StationNotPlaced {
                station: record.station.clone(),
            })?;
            Ok(FlapCarrier {
                station: record.station.clone(),
                aircraft_from_station: *placed.station.frame.aircraft_from_station(),
                mechanism: record.mechanism.clone(),
                section_st: fit_points(&placed.polygons_of(|name| name == part)),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(FittedFlapMotion::try_new(part, element, carriers, vertices_ac)?)
}
