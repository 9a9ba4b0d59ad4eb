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

/// Drive fractions (intervals) a followed motion is sampled at.
pub const FOLLOWED_SAMPLES: usize = 24;

/// A lead reaches its take-off setting where its flap's section passes within this
/// fraction of the flap chord of the setting's (the kinds that take it as a precision
/// position meet it to 1e-9 m).
const TAKEOFF_REACHED: f64 = 1e-4;

/// The flap poses, in the station frame of `follower`, of the rigid motion the station
/// `lead` (synthesised first on `flap`, with its take-off `lead_takeoff`) gives the flap:
/// what the follower's search stays near ([`flapwright_mechanism::shared::follow`]).
///
/// One plane does not fix a rigid motion in 3D: the lead's planar motion is lifted into 3D
/// as a motion about its plane's normal, Q(s), and corrected by C(s) = M_i Q(s_i)^-1 where
/// M_i are the flap's rigid 3D poses at the settings (`PlacedStation::setting_poses_ac`,
/// a tapered flap's conical motion) and s_i the lead's drive fractions there; C's rotation
/// vector and translation are interpolated by the parabola through 0 at s = 0 and their
/// values at take-off and landing, so that the motion is the settings' poses exactly there
/// and the lead's own shape between them. The follower's poses are then its section points
/// moved by C(s) Q(s), seen in its plane and fitted by planar displacements (as
/// `flap_position::rigid_flap_settings` does at the settings). `None` where the lead cannot
/// be posed or the fit fails.
pub fn followed_motion(
    lead: &StationRecord,
    lead_takeoff: &flapwright_mechanism::PrecisionPosition,
    follower: &crate::pipeline::record::PlacedStation,
    flap: &str,
) -> Option<flapwright_mechanism::shared::follow::FollowedMotion> {
    use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
    let lead_placed = lead.placed.as_ref()?;
    let mechanism = lead.mechanism.as_ref();
    let range = mechanism.input_range();
    let lead_frame = *lead_placed.station.frame.aircraft_from_station();
    let lifted = |d: &nalgebra::Isometry2<f64>| -> Isometry3<f64> {
        let planar = Isometry3::from_parts(
            Translation3::new(d.translation.x, d.translation.y, 0.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), d.rotation.angle()),
        );
        lead_frame * planar * lead_frame.inverse()
    };
    let planar_at = |fraction: f64| -> Option<Isometry3<f64>> {
        let pose = mechanism.pose(range.at_fraction(fraction)).ok()?;
        Some(lifted(&pose.flap))
    };
    // The corrections at the settings, as (rotation vector, translation).
    let takeoff_input = mechanism.input_at_deflection(lead_takeoff.deflection_rad).ok()?;
    let takeoff_fraction = range.fraction(takeoff_input);
    // A lead that does not reach its take-off setting in its own plane (the hooked-track's
    // take-off is not a precision position: it misses by 0.1-0.2 m on `transport-flap`) is
    // followed as it moves, corrected towards the landing pose alone: corrected towards the
    // setting, the followed motion was one no hooked-track can move, and the follower's
    // search gave up 30 % of the flap chord of fairing depth trying.
    let lead_points = flapwright_interference::fit_points(&lead_placed.polygons_of(|name| name == flap));
    let (lowest_x, highest_x) = lead_points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.x), hi.max(p.x))
        });
    let reach = TAKEOFF_REACHED * (highest_x - lowest_x).max(0.0);
    let meets_takeoff = mechanism.pose(takeoff_input).ok().is_some_and(|pose| {
        lead_points
            .iter()
            .all(|p| (pose.flap * p - lead_takeoff.flap * p).norm() <= reach)
    });
    let corrections = match lead_placed.setting_poses_ac {
        Some([takeoff, landing]) => {
            let at = |pose: Isometry3<f64>, fraction: f64| -> Option<(Vector3<f64>, Vector3<f64>)> {
                let c = pose * planar_at(fraction)?.inverse();
                Some((c.rotation.scaled_axis(), c.translation.vector))
            };
            let landing = at(landing, 1.0)?;
            let takeoff = if meets_takeoff {
                at(takeoff, takeoff_fraction)?
            } else {
                (landing.0 * takeoff_fraction, landing.1 * takeoff_fraction)
            };
            Some([takeoff, landing])
        }
        None => None,
    };
    let correction = |s: f64| -> Isometry3<f64> {
        let Some([(r1, t1), (r2, t2)]) = corrections else {
            return Isometry3::identity();
        };
        let s1 = takeoff_fraction;
        if !(s1 > 0.0 && s1 < 1.0) {
            return Isometry3::new(t2 * s, r2 * s);
        }
        // The parabola through (0, 0), (s1, x1), (1, x2).
        let (w1, w2) = (s * (s - 1.0) / (s1 * (s1 - 1.0)), s * (s - s1) / (1.0 - s1));
        Isometry3::new(t1 * w1 + t2 * w2, r1 * w1 + r2 * w2)
    };
    let frame = *follower.station.frame.aircraft_from_station();
    let points = flapwright_interference::fit_points(&follower.polygons_of(|name| name == flap));
    let flap_poses = (0..=FOLLOWED_SAMPLES)
        .map(|k| {
            let s = k as f64 / FOLLOWED_SAMPLES as f64;
            let seen = frame.inverse() * correction(s) * planar_at(s)? * frame;
            let in_plane: Vec<nalgebra::Point2<f64>> = points
                .iter()
                .map(|p| seen * Point3::new(p.x, p.y, 0.0))
                .map(|q| nalgebra::Point2::new(q.x, q.y))
                .collect();
            flapwright_mechanism::shared::precision::fit_displacement(&points, &in_plane)
        })
        .collect::<Option<Vec<_>>>()?;
    // The lead's moving flap attachments where the same places of this flap section are:
    // the similarity that maps its section's chord line (trailing to leading edge) onto
    // this one's.
    let chord_ends = |placed: &crate::pipeline::record::PlacedStation| {
        let polygons = placed.polygons_of(|name| name == flap);
        let points = polygons.iter().flatten();
        let le = points.clone().copied().max_by(|a, b| a.x.total_cmp(&b.x))?;
        let te = points.copied().min_by(|a, b| a.x.total_cmp(&b.x))?;
        Some((te, le))
    };
    let attachments = match (chord_ends(lead_placed), chord_ends(follower)) {
        (Some((lead_te, lead_le)), Some((te, le))) if (lead_le - lead_te).norm() > 0.0 => {
            let (from, to) = (lead_le - lead_te, le - te);
            let scale = to.norm() / from.norm();
            let turn = nalgebra::Rotation2::rotation_between(&from, &to);
            mechanism
                .flap_attachments()
                .iter()
                .filter(|a| !a.fixed)
                .map(|a| te + turn * (a.position - lead_te) * scale)
                .collect()
        }
        _ => Vec::new(),
    };
    Some(flapwright_mechanism::shared::follow::FollowedMotion {
        station: lead.station.clone(),
        flap_poses,
        attachments,
    })
}
