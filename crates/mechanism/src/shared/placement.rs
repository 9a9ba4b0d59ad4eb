//! Default placement of the parts a synthesised kind adds around its kinematic core: the
//! screw jack's mount and attachment, and the struts that hold fixed pivots to the wing's
//! lower skin. Each is searched over a few candidates for the first that keeps clear of
//! the wing, the structure and the flap at sampled poses of the deployment (the
//! interference check then certifies the whole deployment); the designer may give any of
//! them instead.

use nalgebra::{Isometry2, Point2};

use crate::shared::geometry::turn_about;
use crate::shared::objective::LoadWeighing;
use crate::shared::outline::StationOutline;
use crate::shared::rocker_drive::{mount_square_at_mid_travel, RockerDrive};

/// Poses sampled by the placement search.
pub const PLACEMENT_SAMPLES: usize = 16;

/// A screw's attachment on the turning body and its mount (stowed, m).
pub type AttachmentAndMount = (Point2<f64>, Point2<f64>);

/// What the screw jack's solids measure (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JackSize {
    /// Screw outer radius.
    pub screw_radius_m: f64,
    /// Nut radius.
    pub nut_radius_m: f64,
    /// Jack body length.
    pub body_length_m: f64,
    /// Jack body radius.
    pub body_radius_m: f64,
}

/// A screw jack turning a body about `pivot` by `rotation_rad`: of the (attachment, mount)
/// pairs of `attachments` x `standoffs` (mounts square at mid-travel, turned about the
/// attachment) whose drive keeps the transmission angle above `min_transmission_rad` and
/// whose screw (as long as the longest stroke plus the nut) and jack body keep `margin`
/// clear of `outline` with the flap at `flap_at(ψ)` for sampled body rotations ψ, the one
/// of least cost: the depth its lowest point reaches in flap chords, plus, with
/// `weighing`, its peak screw force under the load cases in reference forces
/// ([`LoadWeighing::cost`]); without, the shallowest. None when no pair is clear.
#[allow(clippy::too_many_arguments)]
pub fn screw_jack_placement(
    pivot: Point2<f64>,
    rotation_rad: f64,
    attachments: &[Point2<f64>],
    standoffs: &[f64],
    min_transmission_rad: f64,
    size: &JackSize,
    margin: f64,
    outline: &StationOutline,
    flap_at: &dyn Fn(f64) -> Option<Isometry2<f64>>,
    weighing: Option<&LoadWeighing>,
) -> Result<AttachmentAndMount, Option<AttachmentAndMount>> {
    let rotations: Vec<f64> = (0..=PLACEMENT_SAMPLES)
        .map(|k| rotation_rad * k as f64 / PLACEMENT_SAMPLES as f64)
        .collect();
    let flap_poses: Option<Vec<Isometry2<f64>>> = rotations.iter().map(|&psi| flap_at(psi)).collect();
    let flap_poses = flap_poses.ok_or(None)?;
    // What the load asks of the body, the same for every candidate.
    let flap_chord = outline.flap_chord().map_or(1.0, |(_, _, chord)| chord);
    let loading = weighing.map(|w| {
        let torques = w.body_torques(&rotations, rotation_rad, flap_at);
        (w, torques, w.reference_force_n(&flap_poses))
    });
    let mut fallback = None;
    let mut best: Option<(Point2<f64>, Point2<f64>, f64)> = None;
    // The screw square to the arm at mid-travel first, then turned either way about the
    // attachment (the ends' transmission angles shift by the turn) to reach below the wing;
    // up to 1.4 rad (80 deg) either way, where the transmission rule allows.
    const TURNS: [f64; 9] = [0.0, -0.35, 0.35, -0.7, 0.7, -1.05, 1.05, -1.4, 1.4];
    let mut candidates = Vec::new();
    for &attachment in attachments {
        for &standoff in standoffs {
            candidates.extend(TURNS.iter().map(|&turn| (attachment, standoff, turn)));
        }
    }
    for (attachment, standoff, turn) in candidates {
        {
            let square = mount_square_at_mid_travel(pivot, attachment, rotation_rad, standoff);
            let middle = turn_about(pivot, 0.5 * rotation_rad) * attachment;
            let mount = turn_about(middle, turn) * square;
            let Ok(drive) = RockerDrive::try_new(pivot, mount, attachment) else {
                continue;
            };
            let length = drive.stroke_at(0.0).max(drive.stroke_at(rotation_rad)) + size.nut_radius_m;
            let transmits = rotations.iter().all(|&psi| {
                drive
                    .state(drive.stroke_at(psi))
                    .is_ok_and(|state| state.transmission_angle_rad >= min_transmission_rad)
            });
            if !transmits {
                continue;
            }
            fallback = fallback.or(Some((attachment, mount)));
            let clear = rotations.iter().zip(&flap_poses).all(|(&psi, pose)| {
                let Ok(state) = drive.state(drive.stroke_at(psi)) else {
                    return false;
                };
                let along = (state.attachment - mount).normalize();
                let poses = std::slice::from_ref(pose);
                outline.capsule_clear(mount, mount + along * length, size.screw_radius_m, margin, poses)
                    && outline.capsule_clear(
                        mount - along * (0.5 * size.body_length_m),
                        mount + along * (0.5 * size.body_length_m),
                        size.body_radius_m,
                        margin,
                        poses,
                    )
            });
            if clear {
                // The shallowest: the lowest point of the jack body and of the screw's free
                // end over the deployment sets the fairing.
                let lowest = rotations
                    .iter()
                    .filter_map(|&psi| drive.state(drive.stroke_at(psi)).ok())
                    .map(|state| (mount + (state.attachment - mount).normalize() * length).y)
                    .fold(mount.y - size.body_radius_m - 0.5 * size.body_length_m, f64::min);
                let depth = pivot.y - lowest;
                let cost = match &loading {
                    Some((w, torques, reference)) => {
                        // The screw's force: the body's torque times dψ/ds.
                        let peak = rotations
                            .iter()
                            .zip(torques)
                            .map(|(&psi, torque)| {
                                let rate = drive
                                    .state(drive.stroke_at(psi))
                                    .map_or(f64::INFINITY, |state| state.rotation_per_stroke.abs());
                                torque.map_or(f64::INFINITY, |t| t * rate)
                            })
                            .fold(0.0, f64::max);
                        w.cost(depth, flap_chord, peak, *reference)
                    }
                    None => depth / flap_chord,
                };
                if best.is_none_or(|(_, _, c)| cost < c) {
                    best = Some((attachment, mount, cost));
                }
            }
        }
    }
    best.map(|(attachment, mount, _)| (attachment, mount)).ok_or(fallback)
}

/// The first attachment fraction a screw-jack search tries: the arm's middle.
pub const DEFAULT_ATTACHMENT_FRACTION: f64 = 0.5;

/// How a kind's screw jack is placed: the designer's choices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewJackChoice {
    /// The arm the screw pushes, from its fraction 0 end to its fraction 1 end (stowed).
    pub arm: (Point2<f64>, Point2<f64>),
    /// Where on the arm the screw takes hold: the designer's fraction (the only one
    /// tried), or `None` for a search from [`DEFAULT_ATTACHMENT_FRACTION`] on.
    pub attachment_fraction: Option<f64>,
    /// The search's further candidates when the first is not clear; outside [0, 1] on a
    /// horn beyond an end of the arm (a horn beyond the pivot moves the other way, so its
    /// screw can sit on the other side). Not tried when the designer gives the fraction.
    pub other_fractions: &'static [f64],
    /// The mount, if the designer gives it.
    pub mount: Option<Point2<f64>>,
    /// Base distance from the attachment's mid-travel position to a default mount (m).
    pub standoff_m: f64,
    /// Smallest transmission angle (rad).
    pub min_transmission_rad: f64,
}

/// The screw jack of a body turning by `rotation_rad` about `pivot`: the designer's mount,
/// or the least costly clear candidate of [`screw_jack_placement`] over attachments (the
/// designer's `choice.attachment_fraction` alone, or [`DEFAULT_ATTACHMENT_FRACTION`] then
/// `choice.other_fractions` of the arm) and standoffs 1, 1.6, 2.4 and 0.7 times
/// `choice.standoff_m`; when none is clear, the first that transmits well enough (or the
/// first candidate) and `false`.
/// Returns (attachment, mount, clear).
#[allow(clippy::too_many_arguments)]
pub fn place_screw_jack(
    pivot: Point2<f64>,
    rotation_rad: f64,
    choice: &ScrewJackChoice,
    size: &JackSize,
    margin: f64,
    outline: &StationOutline,
    flap_at: &dyn Fn(f64) -> Option<Isometry2<f64>>,
    weighing: Option<&LoadWeighing>,
) -> (Point2<f64>, Point2<f64>, bool) {
    let (from, to) = choice.arm;
    let on_arm = |fraction: f64| from + (to - from) * fraction;
    let first = on_arm(choice.attachment_fraction.unwrap_or(DEFAULT_ATTACHMENT_FRACTION));
    if let Some(mount) = choice.mount {
        return (first, mount, true);
    }
    let others: &[f64] = if choice.attachment_fraction.is_some() {
        &[]
    } else {
        choice.other_fractions
    };
    let attachments: Vec<Point2<f64>> = std::iter::once(first)
        .chain(others.iter().copied().map(on_arm))
        .collect();
    let standoffs: Vec<f64> = [1.0, 1.6, 2.4, 0.7].iter().map(|k| k * choice.standoff_m).collect();
    match screw_jack_placement(
        pivot,
        rotation_rad,
        &attachments,
        &standoffs,
        choice.min_transmission_rad,
        size,
        margin,
        outline,
        flap_at,
        weighing,
    ) {
        Ok((attachment, mount)) => (attachment, mount, true),
        Err(Some((attachment, mount))) => (attachment, mount, false),
        Err(None) => (
            first,
            mount_square_at_mid_travel(pivot, first, rotation_rad, choice.standoff_m),
            false,
        ),
    }
}

/// A strut from the fixed point `from` up to the wing's lower skin: the first top of the
/// candidates (lower-skin points `ahead` flap chords ahead of the cove, in order) whose
/// strut keeps `margin` clear of the structure and of the flap at every pose of
/// `flap_poses`, and that is not `avoid`. None when no candidate is clear.
pub fn strut_top(
    outline: &StationOutline,
    from: Point2<f64>,
    ahead: &[f64],
    radius: f64,
    margin: f64,
    flap_poses: &[Isometry2<f64>],
    avoid: Option<Point2<f64>>,
) -> Option<Point2<f64>> {
    let lip = outline.cove_lower_lip_x()?;
    let (_, _, flap_chord) = outline.flap_chord()?;
    ahead.iter().find_map(|&k| {
        let top = outline.wing_lower_point(lip + k * flap_chord)?;
        let distinct = avoid.is_none_or(|p| (p - top).norm() > 0.04 * flap_chord);
        // The strut ends on the skin by design: it must not cross the wing short of its top.
        let short = top + (from - top).normalize() * (radius + margin);
        let clear = distinct
            && outline.structure.segment_clear_by(from, top, radius + margin)
            && !outline.wing.segment_meets(from, short)
            && flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                outline.flap.segment_clear_by(back * from, back * top, radius + margin)
            });
        clear.then_some(top)
    })
}

impl JackSize {
    /// The solids of `hardware` with a screw of mean radius `mean_radius_m` (thread depth
    /// a quarter of it).
    pub fn new(hardware: &crate::shared::flap_load::LinkHardware, mean_radius_m: f64) -> Self {
        Self {
            screw_radius_m: 1.25 * mean_radius_m,
            nut_radius_m: hardware.nut_radius_m,
            body_length_m: hardware.jack_body_length_m,
            body_radius_m: hardware.jack_body_radius_m,
        }
    }
}

/// The flap's poses of a turn by `rotation_rad` about `pivot`, sampled.
pub fn turning_flap(pivot: Point2<f64>, rotation_rad: f64) -> Vec<Isometry2<f64>> {
    (0..=PLACEMENT_SAMPLES)
        .map(|k| turn_about(pivot, rotation_rad * k as f64 / PLACEMENT_SAMPLES as f64))
        .collect()
}
