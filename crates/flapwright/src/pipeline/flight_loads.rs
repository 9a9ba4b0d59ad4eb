//! Loads from a flight condition (issue 14 step 6): the flap's normal force by spanwise
//! elements, `N_i = C_N c_i b_i q n` (`003_...` eq. 1, [`flapwright_sizing::loads`]),
//! shared among the flap's stations by the lever rule of
//! [`flapwright_sizing::distribute_to_stations`] (each span between neighbouring stations
//! a simply supported beam, overhangs to the end stations; one station takes it all), and
//! applied at each station's flap quarter chord normal to the flap's chord line (`003_...`
//! eq. 1 and section 4.1: "the resultant flap load distribution acts on the quarter-chord
//! line"; the chord of a flap set at its own incidence leans from the station's x axis, by
//! 4-5.6 deg on `transport-flap`). The flap's weight takes the case's load factor too.
//!
//! C_N is the same along the span, so a station's share is C_N(δ) q n times its share of
//! the flap's area, found once with unit loads c_i b_i. Simplification: each station's
//! share acts at its own quarter-chord point (the moment the elements' quarter-chord line
//! makes about the station's, over a tapered flap, is not carried across).

use flapwright_geom::parts::WingModel;
use flapwright_mechanism::shared::outline::{extent_x, vertical_span};
use flapwright_mechanism::{ExternalMoment, FlapNormalForce, LoadCase};
use flapwright_sizing::{distribute_to_stations, ElementLoad};
use nalgebra::{Point2, Vector2};

use crate::error::{Error, Result};
use crate::pipeline::record::{FlapLoadShare, PlacedStation, StationRecord};
use crate::scene::{LoadCaseScene, Scene};

/// Spanwise elements of a flap: the midpoint rule's error on a flap chord that varies
/// quadratically along the span (a linear chord fraction of a linear wing chord) is
/// (span/elements)^2/24 of the chord's curvature, below 1e-4 of the area here.
pub const FLAP_ELEMENTS: usize = 40;

/// Each placed record's share of its flap's area and the point its share acts at.
pub fn shares(scene: &Scene, model: &WingModel, records: &mut [StationRecord]) -> Result<()> {
    let stations: Vec<(Option<&str>, Option<&PlacedStation>)> =
        records.iter().map(|r| (r.flap.as_deref(), r.placed.as_ref())).collect();
    let found = station_shares(scene, model, &stations)?;
    for (record, share) in records.iter_mut().zip(found) {
        if share.is_some() {
            record.flap_load_share = share;
        }
    }
    Ok(())
}

/// The share of its flap's area that each station (its flap's name and its placed plane)
/// carries and the point the share acts at; `None` for a station without a flap or plane.
pub fn station_shares(
    scene: &Scene,
    model: &WingModel,
    stations: &[(Option<&str>, Option<&PlacedStation>)],
) -> Result<Vec<Option<FlapLoadShare>>> {
    let mut found = vec![None; stations.len()];
    for (f, flap) in model.flaps().iter().enumerate() {
        let name = &scene.flap[f].name;
        let (y_in, y_out) = flap.body_span_m(model.wing())?;
        let width = (y_out - y_in) / FLAP_ELEMENTS as f64;
        let elements = (0..FLAP_ELEMENTS)
            .map(|i| {
                let y = y_in + (i as f64 + 0.5) * width;
                let (_, chord, _) = model.wing().planform_at(y)?;
                Ok(ElementLoad {
                    span_position_m: y,
                    normal_force_n: flap.chord_fraction_at(y) * chord * width,
                    chordwise_position_m: 0.0,
                    pitching_moment_nm: 0.0,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let mut carriers: Vec<(usize, &PlacedStation, f64)> = stations
            .iter()
            .enumerate()
            .filter(|(_, (flap, _))| *flap == Some(name.as_str()))
            .filter_map(|(i, (_, placed))| placed.map(|p| (i, p, p.station.frame.origin_ac().y)))
            .collect();
        carriers.sort_by(|a, b| a.2.total_cmp(&b.2));
        let area: f64 = elements.iter().map(|e| e.normal_force_n).sum();
        let areas: Vec<f64> = match carriers.len() {
            0 => continue,
            1 => vec![area],
            _ => {
                let positions: Vec<f64> = carriers.iter().map(|s| s.2).collect();
                distribute_to_stations(&elements, &positions)
                    .map_err(|source| Error::SharingLoad {
                        flap: name.clone(),
                        source,
                    })?
                    .iter()
                    .map(|s| s.normal_force_n)
                    .collect()
            }
        };
        for (&(i, placed, _), share) in carriers.iter().zip(areas) {
            let polygons = placed.flap_polygons(name);
            let misses = || Error::PlaneMissesFlap {
                station: placed.station.name.clone(),
                flap: name.clone(),
            };
            let (te, le) = extent_x(&polygons).ok_or_else(misses)?;
            let x = le - 0.25 * (le - te);
            let (lo, hi) = vertical_span(&polygons, x).ok_or_else(misses)?;
            let normal = chord_normal(&polygons).ok_or_else(misses)?;
            found[i] = Some(FlapLoadShare {
                flap_area_share_m2: share,
                quarter_chord_st_m: [x, 0.5 * (lo + hi)],
                chord_normal_st: [normal.x, normal.y],
            });
        }
    }
    Ok(found)
}

/// The unit upward normal of a flap section's chord line: the chord runs from the trailing
/// edge (the aft-most point) to the point of the section farthest from it (the leading
/// edge, as an airfoil's chord is defined), and the normal is that turned a quarter turn
/// counter-clockwise. `None` for an empty or degenerate section.
pub fn chord_normal(polygons: &[Vec<Point2<f64>>]) -> Option<Vector2<f64>> {
    let points = || polygons.iter().flatten();
    let trailing = points().min_by(|a, b| a.x.total_cmp(&b.x))?;
    let leading = points().max_by(|a, b| {
        (*a - trailing)
            .norm_squared()
            .total_cmp(&(*b - trailing).norm_squared())
    })?;
    let chord = (leading - trailing).try_normalize(0.0)?;
    Some(Vector2::new(-chord.y, chord.x))
}

/// The load case `case` at `record`: its moments, or its flight condition's normal force on
/// the record's share of the flap.
pub fn load_case(case: &LoadCaseScene, record: &StationRecord) -> LoadCase {
    load_case_on(case, record.flap_load_share)
}

/// The load case `case` on a station carrying `share` of its flap (see [`load_case`]).
pub fn load_case_on(case: &LoadCaseScene, share: Option<FlapLoadShare>) -> LoadCase {
    let external_moment = match (case.moment_nm, case.moment_stowed_nm, case.moment_deployed_nm) {
        (Some(moment), _, _) => ExternalMoment::Constant(moment),
        (None, Some(stowed_nm), Some(deployed_nm)) => ExternalMoment::Linear { stowed_nm, deployed_nm },
        // A flight condition, or (validation guarantees one form) no moment.
        _ => ExternalMoment::Constant(0.0),
    };
    let flap_normal_force = match (case.dynamic_pressure(), &case.normal_force_coefficient, share) {
        (Some(q), Some(rows), Some(share)) => Some(FlapNormalForce {
            coefficients: rows.iter().map(|[deg, c]| (deg.to_radians(), *c)).collect(),
            newtons_per_coefficient: q * case.load_factor.unwrap_or(1.0) * share.flap_area_share_m2,
            at_stowed_m: Point2::new(share.quarter_chord_st_m[0], share.quarter_chord_st_m[1]),
            normal_stowed: Vector2::new(share.chord_normal_st[0], share.chord_normal_st[1]),
        }),
        _ => None,
    };
    LoadCase {
        name: case.name.clone(),
        external_moment,
        include_inertia: false,
        flap_normal_force,
        load_factor: case.load_factor.unwrap_or(1.0),
    }
}

/// The scene's load cases in the mechanism crate's terms.
/// The scene's load cases at `record` (flight conditions shared among its flap's stations).
pub fn load_cases(scene: &Scene, record: &StationRecord) -> Vec<LoadCase> {
    scene
        .loads
        .cases
        .iter()
        .map(|case| crate::pipeline::flight_loads::load_case(case, record))
        .collect()
}

/// The load case of a scene without any: the flap's weight alone.
pub fn weight_only() -> LoadCase {
    LoadCase {
        name: "weight-only".into(),
        external_moment: ExternalMoment::Constant(0.0),
        include_inertia: false,
        flap_normal_force: None,
        load_factor: 1.0,
    }
}
