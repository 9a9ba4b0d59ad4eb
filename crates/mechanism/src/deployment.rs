//! Deployment sweeps of any mechanism kind through the seam: kinetostatics at evenly
//! spaced actuator inputs, stopping (not failing) at the first input where the mechanism
//! cannot be posed or loaded. Kind-neutral: reactions are keyed by joint name, the
//! actuator load is a force or a torque as the kind's input is a stroke or an angle.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::seam::{FlapMechanism, MemberLoad};
use crate::shared::load_case::LoadCase;
use crate::shared::screw_jack::ScrewTorques;

/// One sample of a deployment: a row of the report's `samples[]`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeploymentSample {
    /// Actuator input (m for a stroke, rad for an angle).
    pub input: f64,
    /// Flap deflection (deg), trailing edge down positive.
    pub deflection_deg: f64,
    /// Transmission angle (deg).
    pub transmission_angle_deg: f64,
    /// Actuator force (N) or torque (N m) by equilibrium.
    pub actuator_load: f64,
    /// |virtual work - equilibrium| / max(|load|, 1): the cross-check of the two methods.
    pub actuator_load_cross_check_relative: f64,
    /// Reaction at each joint (N), by joint name.
    pub reactions_n: BTreeMap<String, f64>,
    /// Loop-closure residual (m).
    pub closure_residual_m: f64,
    /// Position Jacobian condition number.
    pub jacobian_condition_number: f64,
    /// Distance to the nearest toggle (deg).
    pub distance_to_toggle_deg: f64,
    /// Raise and lower torque of a screw-jack actuator (absent for others). Written as
    /// `screw_torques_nm`, the report's field name from before the rename (issue 36): the
    /// wire name stays.
    #[serde(rename = "screw_torques_nm", skip_serializing_if = "Option::is_none")]
    pub actuator_torques_nm: Option<ScrewTorques>,
    /// Axial force (N, tension positive) and largest bending moment (N m) of each member
    /// the kind sizes, by member name (absent for a kind that declares none).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub member_loads: BTreeMap<String, MemberLoad>,
    /// Gap and overlap of the flap behind the main wing here: filled by the caller that
    /// knows the wing section (absent without one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flap_position: Option<FlapGapOverlap>,
    /// A two-element flap's aft element moved by a body of its own (the five-bar's
    /// secondary flap): its deflection here, and the second slot where the caller knows
    /// the sections (absent for kinds without one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aft_element: Option<AftElementSample>,
}

/// The aft element of a two-element flap at one sample.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AftElementSample {
    /// Its rotation from stowed (deg), trailing edge down positive, as the main flap's
    /// `deflection_deg`.
    pub deflection_deg: f64,
    /// Its rotation relative to the main element from stowed (deg).
    pub relative_deflection_deg: f64,
    /// The second slot: gap and overlap of the aft element behind the main element's
    /// trailing edge (% of the chord to the aft element's trailing edge); filled by the
    /// caller that knows the sections.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slot: Option<FlapGapOverlap>,
}

/// Gap and overlap of the flap behind the main wing at one sample (`003_...` Fig. 3
/// definitions, measured in the station plane).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlapGapOverlap {
    /// Gap (m); negative when the wing's trailing edge lies inside the flap section.
    pub gap_m: f64,
    /// Gap, % of the local clean chord.
    pub gap_percent_chord: f64,
    /// Overlap (m); positive while the flap nose is ahead of the trailing edge.
    pub overlap_m: f64,
    /// Overlap, % of the local clean chord.
    pub overlap_percent_chord: f64,
}

/// Where and why a deployment stopped early.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeploymentStop {
    /// Index of the first sample that failed.
    pub sample_index: usize,
    /// Its input.
    pub input: f64,
    /// The reason.
    pub reason: Error,
}

/// A deployment under one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Deployment {
    /// Load case name.
    pub load_case: String,
    /// Samples up to (not including) the stop, if any.
    pub samples: Vec<DeploymentSample>,
    /// Set when the deployment could not reach the end.
    pub stopped: Option<DeploymentStop>,
}

/// `samples` evenly spaced inputs from stowed to deployed (both included) under `load`.
///
/// Errors: [`Error::TooFewSamples`] for fewer than 2 samples. A pose or load failure does
/// not error: the deployment stops there and says why in [`Deployment::stopped`].
pub fn sweep_deployment(mechanism: &dyn FlapMechanism, samples: usize, load: &LoadCase) -> Result<Deployment> {
    if samples < 2 {
        return Err(Error::TooFewSamples { samples });
    }
    let mut deployment = Deployment {
        load_case: load.name.clone(),
        samples: Vec::with_capacity(samples),
        stopped: None,
    };
    let aft_body = crate::seam::aft_flap_body(mechanism.bodies());
    for (sample_index, input) in mechanism.input_range().samples(samples).into_iter().enumerate() {
        let aft_element = match aft_body.map(|k| mechanism.pose(input).map(|pose| (pose, k))) {
            None => Ok(None),
            Some(Ok((pose, k))) => Ok(Some(AftElementSample {
                deflection_deg: (pose.deflection_rad + (pose.flap.inverse() * pose.bodies[k]).rotation.angle())
                    .to_degrees(),
                relative_deflection_deg: (pose.flap.inverse() * pose.bodies[k]).rotation.angle().to_degrees(),
                slot: None,
            })),
            Some(Err(reason)) => Err(reason),
        };
        match aft_element.and_then(|aft| Ok((mechanism.kinetostatics(input, load)?, aft))) {
            Ok((loads, aft_element)) => deployment.samples.push(DeploymentSample {
                input,
                deflection_deg: loads.deflection_rad.to_degrees(),
                transmission_angle_deg: loads.transmission_angle_rad.to_degrees(),
                actuator_load: loads.actuator_load,
                actuator_load_cross_check_relative: (loads.actuator_load_virtual_work - loads.actuator_load).abs()
                    / loads.actuator_load.abs().max(1.0),
                reactions_n: loads.reactions.into_iter().collect(),
                closure_residual_m: loads.health.closure_residual_m,
                jacobian_condition_number: loads.health.jacobian_condition_number,
                distance_to_toggle_deg: loads.health.distance_to_toggle_rad.to_degrees(),
                actuator_torques_nm: loads.actuator_torques,
                member_loads: loads.members.into_iter().collect(),
                flap_position: None,
                aft_element,
            }),
            Err(reason) => {
                deployment.stopped = Some(DeploymentStop {
                    sample_index,
                    input,
                    reason,
                });
                break;
            }
        }
    }
    Ok(deployment)
}
