//! Distribution of element loads to the support stations and, at each station, to the
//! forward and aft attachment points, by statics.
//!
//! Spanwise (stations): the flap is modelled as it is in the `003_...` multi-body model
//! (section 4.1, Fig. 13): one flap "rod" between each pair of neighbouring stations,
//! pinned at both ends. Each span is then a simply supported beam, statically
//! determinate: an element load between stations k and k+1 goes to those two by the
//! lever rule, R_k = N (y_{k+1} - y) / (y_{k+1} - y_k), R_{k+1} = N (y - y_k) / (y_{k+1} - y_k).
//! Loads outboard of the end stations (the flap's overhangs) go wholly to the nearer end
//! station: the tributary rule, each station carrying what lies between it and its
//! neighbours' lever points and the overhang beyond it. Every element's load is then split
//! into shares in [0, 1], so no station carries more than the whole flap and none a
//! negative share, however close two stations stand. (An earlier rule carried the overhang
//! as a rigid beam over the end span, the nearer reaction above N and the farther negative:
//! two stations 1 mm apart under a 13.4 m² flap gave shares of +-39,775 m².) The forces
//! balance exactly; the overhang's moment about the end station is not passed to its
//! neighbour (the flap's spanwise bending over the end span is not modelled). For two
//! stations with no overhang this is the exact simple-beam solution; for n > 2 it ignores
//! the continuity of a real one-piece flap over interior supports (a continuous beam would
//! load interior supports about 25 % more, three-moment equation).
//!
//! Chordwise (attachments): `003_...` eqs 2-3 as printed,
//! N'_1,2 = N/2 +- (M + N (l/2 + d)) / 2, are dimensionally wrong (a moment divided by 2
//! added to a force). From statics (force sum and moment sum about the aft attachment)
//! the loads are N'_1 = N/2 + (M + N (l/2 + d)) / l and N'_2 = N/2 - (M + N (l/2 + d)) / l,
//! with l the forward-to-aft attachment distance, d the distance the load acts ahead of
//! the forward attachment and M the nose-up moment: the printed "/2" should read "/l".

use serde::Serialize;

use crate::check::{finite, positive};
use crate::loads::ElementLoad;
use crate::{Error, Result};

/// Resultant load at one support station.
///
/// Frame as [`ElementLoad`]: force along the flap normal (upper side positive), moment
/// about the spanwise axis through the forward-attachment (hinge) line, nose-up positive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StationLoad {
    /// Spanwise station position, m.
    pub span_position_m: f64,
    /// Normal force carried by the station, N.
    pub normal_force_n: f64,
    /// Moment about the forward-attachment line, N m, nose-up positive.
    pub moment_about_hinge_nm: f64,
}

/// Loads a station passes to its forward and aft attachment points, along the flap
/// normal (same sign convention as the applied normal force: they sum to it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AttachmentLoads {
    /// Forward attachment load N'_1, N.
    pub forward_n: f64,
    /// Aft attachment load N'_2, N.
    pub aft_n: f64,
}

/// Distributes element loads to the stations (positions in m, strictly increasing, at
/// least two) by the pinned-segment lever rule described in the module docs.
///
/// # Errors
/// [`Error::TooFewStations`], [`Error::NotIncreasing`], [`Error::OutOfRange`] for
/// non-finite inputs.
pub fn distribute_to_stations(elements: &[ElementLoad], station_positions_m: &[f64]) -> Result<Vec<StationLoad>> {
    let n = station_positions_m.len();
    if n < 2 {
        return Err(Error::TooFewStations { required: 2, found: n });
    }
    for (index, &y) in station_positions_m.iter().enumerate() {
        finite(format!("station_positions_m[{index}]"), y)?;
        if index > 0 && y <= station_positions_m[index - 1] {
            return Err(Error::NotIncreasing {
                what: "station positions",
                index,
                value: y,
            });
        }
    }
    let mut stations: Vec<StationLoad> = station_positions_m
        .iter()
        .map(|&y| StationLoad {
            span_position_m: y,
            normal_force_n: 0.0,
            moment_about_hinge_nm: 0.0,
        })
        .collect();
    for (i, e) in elements.iter().enumerate() {
        let y = finite(format!("elements[{i}].span_position_m"), e.span_position_m)?;
        finite(format!("elements[{i}].normal_force_n"), e.normal_force_n)?;
        finite(format!("elements[{i}].chordwise_position_m"), e.chordwise_position_m)?;
        finite(format!("elements[{i}].pitching_moment_nm"), e.pitching_moment_nm)?;
        // Segment [k, k+1] holding y; an overhang goes wholly to its end station.
        let k = station_positions_m.partition_point(|&s| s <= y).clamp(1, n - 1) - 1;
        let (y0, y1) = (station_positions_m[k], station_positions_m[k + 1]);
        let inner_share = ((y1 - y) / (y1 - y0)).clamp(0.0, 1.0);
        let outer_share = 1.0 - inner_share;
        // Moment about the hinge line of a force at chordwise position s (aft positive):
        // an upward force aft of the hinge pitches nose-down, hence -N s.
        let moment = e.pitching_moment_nm - e.normal_force_n * e.chordwise_position_m;
        for (index, share) in [(k, inner_share), (k + 1, outer_share)] {
            stations[index].normal_force_n += share * e.normal_force_n;
            stations[index].moment_about_hinge_nm += share * moment;
        }
    }
    Ok(stations)
}

/// Splits a normal force and a moment into forward and aft attachment loads, in the
/// general form: force `normal_force_n` acting at chordwise position `load_position_m`,
/// nose-up moment `moment_nm` about that point, attachments at `forward_position_m` and
/// `aft_position_m` (all positions in m along the chord, aft positive, aft > forward).
///
/// From the force sum N'_1 + N'_2 = N and the moment sum about the aft attachment,
/// N'_1 (x_a - x_f) = N (x_a - x_N) + M; this is the corrected `003_...` eq 2
/// (see module docs for the printed typo).
///
/// # Errors
/// [`Error::OutOfRange`] for non-finite inputs or attachments not ordered forward < aft.
pub fn attachment_loads(
    normal_force_n: f64,
    moment_nm: f64,
    load_position_m: f64,
    forward_position_m: f64,
    aft_position_m: f64,
) -> Result<AttachmentLoads> {
    finite("normal_force_n", normal_force_n)?;
    finite("moment_nm", moment_nm)?;
    finite("load_position_m", load_position_m)?;
    finite("forward_position_m", forward_position_m)?;
    let spacing_m = positive("attachment_spacing_m", aft_position_m - forward_position_m)?;
    let forward_n = (normal_force_n * (aft_position_m - load_position_m) + moment_nm) / spacing_m;
    Ok(AttachmentLoads {
        forward_n,
        aft_n: normal_force_n - forward_n,
    })
}

/// Attachment loads of a station whose aft attachment lies `attachment_spacing_m` (l)
/// aft of the forward one: [`attachment_loads`] with the load at the hinge line.
///
/// # Errors
/// [`Error::OutOfRange`] for a spacing not in (0, inf) or non-finite loads.
pub fn station_attachment_loads(station: &StationLoad, attachment_spacing_m: f64) -> Result<AttachmentLoads> {
    attachment_loads(
        station.normal_force_n,
        station.moment_about_hinge_nm,
        0.0,
        0.0,
        attachment_spacing_m,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corrected_eq_2_form() {
        // N = 1000 N at d = 0.05 m ahead of the forward attachment, l = 0.4 m, M = 30 N m:
        // N'_1 = N/2 + (M + N (l/2 + d)) / l = 500 + (30 + 1000 * 0.25) / 0.4 = 1200 N.
        let a = attachment_loads(1000.0, 30.0, -0.05, 0.0, 0.4).unwrap();
        assert!((a.forward_n - 1200.0).abs() < 1e-9);
        assert!((a.aft_n + 200.0).abs() < 1e-9);
    }
}
