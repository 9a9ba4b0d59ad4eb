//! The dropped hinge's screw jack: its mount and attachment on the forward arm (or a horn
//! below the hinge), the drive's triangle about the hinge, and the screw chosen from the
//! shared drive.

use nalgebra::Point2;
use serde::Serialize;

use super::{failure, mm, DroppedHingeSpec, TRANSMISSION_SAMPLES};
use flapwright_mechanism::shared::geometry::turn_about;
use flapwright_mechanism::shared::placement::{place_screw_jack, JackSize, JackTradeCandidate, ScrewJackChoice};
use flapwright_mechanism::shared::rocker_drive::{JackInstallation, RockerDrive};
use flapwright_mechanism::shared::screw_jack::{ScrewDrive, ScrewJack};
use flapwright_mechanism::{Result, SynthesisDefect};

/// The screw jack of a dropped hinge, as synthesis laid it out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DroppedHingeScrewJack {
    /// The screw's mount B0 (m).
    pub actuator_mount_m: Point2<f64>,
    /// False when no default place of the screw jack kept clear of the wing, the structure
    /// and the flap at the sampled poses (the interference check says where).
    pub actuator_clear: bool,
    /// The screw's attachment P on the forward arm, stowed (m).
    pub actuator_attachment_m: Point2<f64>,
    /// Stroke |P - B0| stowed and at landing (m).
    pub stroke_m: [f64; 2],
    /// Smallest transmission angle of the drive over the deployment (rad, sampled).
    pub min_transmission_angle_rad: f64,
    /// Its end pressure angles and its mount's turn from `004_...`'s installation.
    pub installation: JackInstallation,
    /// The placement's trade between the jack's depth and its load, the chosen one marked
    /// ([`flapwright_mechanism::shared::placement::PlacedJack::trade`]); a scene's
    /// `trade_index` picks another.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub trade: Vec<JackTradeCandidate>,
    /// The screw chosen from the drive: lead, radius, friction.
    pub screw: ScrewJack,
    /// Screw length (m): the longest stroke and the nut.
    pub screw_length_m: f64,
    /// Nominal nut speed (m/s).
    pub nominal_speed_mps: f64,
}

/// The screw jack's place (mount B0, attachment P), its drive's triangle, and the screw
/// chosen from the drive. Errors when B0, H and P lie on one line or the transmission angle
/// falls below the minimum (toggle).
pub(super) fn screw_jack_layout(
    spec: &DroppedHingeSpec,
    hinge: Point2<f64>,
    choice: &ScrewJackChoice,
    screw_drive: &ScrewDrive,
    margin: f64,
    trade_index: Option<usize>,
) -> Result<(RockerDrive, DroppedHingeScrewJack)> {
    let turn = spec.landing.deflection_rad;
    let hw = spec.hardware;
    let size = JackSize::new(&hw, screw_drive.mean_radius_m);
    let flap_at = |psi: f64| Some(turn_about(hinge, psi));
    let weighing = spec.weighing();
    let placed = place_screw_jack(
        hinge,
        turn,
        choice,
        &size,
        margin,
        &spec.outline,
        &flap_at,
        weighing.as_ref(),
    );
    let placed = placed.picked(super::KIND, trade_index)?;
    let (attachment, mount, actuator_clear, trade) = (placed.attachment, placed.mount, placed.clear, placed.trade);
    let drive = RockerDrive::try_new(hinge, mount, attachment).map_err(|_| {
        failure(
            SynthesisDefect::Toggle,
            format!(
                "the screw mount {}, the hinge {} and the screw's attachment {} lie on one line",
                mm(mount),
                mm(hinge),
                mm(attachment)
            ),
        )
    })?;
    let min_transmission = drive.min_transmission_rad(turn, TRANSMISSION_SAMPLES);
    if let Some(problem) = drive.transmission_problem(
        turn,
        spec.min_transmission_angle_rad,
        TRANSMISSION_SAMPLES,
        "forward arm",
    ) {
        return Err(failure(SynthesisDefect::Toggle, problem));
    }
    let stroke_m = [drive.stroke_at(0.0), drive.stroke_at(turn)];
    let (screw, nominal_speed_mps) = screw_drive.screw_for(stroke_m[1] - stroke_m[0]);
    // Long enough to carry the nut at the longest stroke, no longer: a screw's free end
    // beyond the nut would sweep into the flap.
    let screw_length_m = stroke_m[0].max(stroke_m[1]) + hw.nut_radius_m;
    let layout = DroppedHingeScrewJack {
        actuator_mount_m: mount,
        actuator_clear,
        actuator_attachment_m: attachment,
        stroke_m,
        min_transmission_angle_rad: min_transmission,
        installation: JackInstallation::of(&drive, turn),
        trade,
        screw,
        screw_length_m,
        nominal_speed_mps,
    };
    Ok((drive, layout))
}
