//! Deployment sweeps: pose and forces at evenly spaced nut positions, with diagnostics,
//! stopping (not failing) at the first input where the mechanism cannot move.

use serde::Serialize;

use super::synthesis::CircularArcTrack;
use flapwright_mechanism::shared::load_case::LoadCase;
use flapwright_mechanism::{Error, Result};

/// Reactions at the named joints (N, thesis signs); serialises keyed by joint name.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JointReactions {
    /// Revolute A (nut 4 on flap 2): F42 along the screw, = F_input.
    #[serde(rename = "A")]
    pub nut_pivot_a_n: f64,
    /// Revolute B0 (screw 3 on ground 1): G13, axial, = F_input (F43y' = 0, eq. 3.4.14).
    #[serde(rename = "B0")]
    pub screw_mount_b0_n: f64,
    /// Pin-in-slot G (inner slot, radius c1): G12G, radial.
    #[serde(rename = "G")]
    pub inner_pin_g_n: f64,
    /// Pin-in-slot F (outer slot, radius b1): G12F, radial.
    #[serde(rename = "F")]
    pub outer_pin_f_n: f64,
}

/// One sample of a sweep: the report.json row of issue 4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepSample {
    /// Nut position s34 (m).
    pub input_m: f64,
    /// Flap deflection θ12 - θ12,i (deg), trailing edge down positive.
    pub deflection_deg: f64,
    /// Transmission angle μ (deg).
    pub transmission_angle_deg: f64,
    /// F_input (N), eq. 3.4.16.
    pub actuator_force_n: f64,
    /// T_R (N m), eq. 3.6.9.
    pub raise_torque_nm: f64,
    /// T_L (N m), eq. 3.6.10.
    pub lower_torque_nm: f64,
    /// Joint reactions by joint name (N).
    pub joint_reactions_n: JointReactions,
    /// Loop-closure residual (m).
    pub closure_residual_m: f64,
    /// Position Jacobian condition number.
    pub jacobian_condition_number: f64,
    /// Distance to toggle (deg).
    pub distance_to_toggle_deg: f64,
    /// |F_virtual_work - F_equilibrium| / max(|F|, 1 N): cross-check of eqs. 3.4.16/3.5.1.
    pub force_cross_check_relative: f64,
}

/// Where and why a sweep stopped early.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepStop {
    /// Index of the first sample that failed.
    pub sample_index: usize,
    /// Its input s34 (m).
    pub input_m: f64,
    /// The reason (names the input again inside).
    pub reason: Error,
}

/// A deployment sweep under one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sweep {
    /// Load case name.
    pub load_case: String,
    /// Samples up to (not including) the stop, if any.
    pub samples: Vec<SweepSample>,
    /// Set when the sweep could not reach the end.
    pub stopped: Option<SweepStop>,
}

impl CircularArcTrack {
    /// `samples` evenly spaced nut positions from s34,i to s34,f (both included) at the
    /// spec's nominal speed and acceleration, under `load`.
    ///
    /// Errors: [`Error::TooFewSamples`] for fewer than 2 samples. A pose or force failure
    /// does not error: the sweep stops there and says why in [`Sweep::stopped`].
    pub fn sweep(&self, samples: usize, load: &LoadCase) -> Result<Sweep> {
        let inputs = self.evenly_spaced_inputs(samples)?;
        Ok(self.sweep_at(inputs, load))
    }

    /// `samples` evenly spaced nut positions from s34,i to s34,f, the last exactly s34,f.
    pub(crate) fn evenly_spaced_inputs(&self, samples: usize) -> Result<impl ExactSizeIterator<Item = f64> + '_> {
        if samples < 2 {
            return Err(Error::TooFewSamples { samples });
        }
        let (start, stroke) = (self.synthesis.stroke_start_m, self.synthesis.stroke_m);
        let last = (samples - 1) as f64;
        let end = self.synthesis.stroke_end_m;
        Ok((0..samples).map(move |i| {
            if i + 1 == samples {
                end
            } else {
                start + stroke * i as f64 / last
            }
        }))
    }

    /// Sweep at the given nut positions (m), e.g. the spreadsheet's 10 mm rows.
    pub fn sweep_at(&self, inputs: impl IntoIterator<Item = f64>, load: &LoadCase) -> Sweep {
        let inputs = inputs.into_iter();
        let mut sweep = Sweep {
            load_case: load.name.clone(),
            samples: Vec::with_capacity(inputs.size_hint().0),
            stopped: None,
        };
        for (sample_index, input_m) in inputs.enumerate() {
            match self.sample(input_m, load) {
                Ok(sample) => sweep.samples.push(sample),
                Err(reason) => {
                    sweep.stopped = Some(SweepStop {
                        sample_index,
                        input_m,
                        reason,
                    });
                    break;
                }
            }
        }
        sweep
    }

    fn sample(&self, input_m: f64, load: &LoadCase) -> Result<SweepSample> {
        let pose = self.pose(
            input_m,
            self.spec.nominal_input_speed_mps,
            self.spec.nominal_input_accel_mps2,
        )?;
        let forces = self.forces(&pose, load)?;
        let force = forces.actuator_force_n;
        Ok(SweepSample {
            input_m,
            deflection_deg: pose.deflection_rad.to_degrees(),
            transmission_angle_deg: pose.diagnostics.transmission_angle_rad.to_degrees(),
            actuator_force_n: force,
            raise_torque_nm: forces.screw.raise_torque_nm,
            lower_torque_nm: forces.screw.lower_torque_nm,
            joint_reactions_n: JointReactions {
                nut_pivot_a_n: force,
                screw_mount_b0_n: force,
                inner_pin_g_n: forces.inner_slot_reaction_n,
                outer_pin_f_n: forces.outer_slot_reaction_n,
            },
            closure_residual_m: pose.diagnostics.closure_residual_m,
            jacobian_condition_number: pose.diagnostics.jacobian_condition_number,
            distance_to_toggle_deg: pose.diagnostics.distance_to_toggle_rad.to_degrees(),
            force_cross_check_relative: (forces.actuator_force_virtual_work_n - force).abs() / force.abs().max(1.0),
        })
    }
}
