//! Position, velocity and acceleration of every named point of the track (thesis 3.1-3.4).

use nalgebra::{Point2, Vector2};
use serde::Serialize;

use super::synthesis::CircularArcTrack;
use flapwright_mechanism::shared::slider_crank::SliderCrankState;
use flapwright_mechanism::{Error, Result};

/// Relative slack on the slot ends attributed to rounding (red cell 1 check).
const SLOT_END_TOLERANCE: f64 = 1e-12;

/// Position (m), velocity (m/s) and acceleration (m/s²) of one point, station frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointKinematics {
    /// Position (m).
    pub position_m: Point2<f64>,
    /// Velocity (m/s).
    pub velocity_mps: Vector2<f64>,
    /// Acceleration (m/s²).
    pub acceleration_mps2: Vector2<f64>,
}

impl PointKinematics {
    /// A point at `offset` from the fixed pivot `pivot` on a body turning at `rate` (rad/s)
    /// with angular acceleration `accel` (rad/s²): v = ω k×r, a = α k×r - ω² r.
    fn on_rotating_body(pivot: Point2<f64>, offset: Vector2<f64>, rate: f64, accel: f64) -> Self {
        let perpendicular = Vector2::new(-offset.y, offset.x);
        Self {
            position_m: pivot + offset,
            velocity_mps: perpendicular * rate,
            acceleration_mps2: perpendicular * accel - offset * (rate * rate),
        }
    }
}

/// Health of one pose: how far it is from failing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PoseDiagnostics {
    /// Loop-closure residual (m).
    pub closure_residual_m: f64,
    /// Condition number of the position Jacobian ∂(loop)/∂(θ12, θ13).
    pub jacobian_condition_number: f64,
    /// Transmission angle μ (rad), acute angle between flap crank A0A and screw B0A.
    pub transmission_angle_rad: f64,
    /// Angular distance to the nearest toggle (rad); for the inverted slider-crank the
    /// toggle is μ = 0, so this equals μ.
    pub distance_to_toggle_rad: f64,
}

/// The whole track at one input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pose {
    /// θ12, θ13, ω12, ω13, α12, α13 and the input itself.
    pub linkage: SliderCrankState,
    /// Flap deflection θ12 - θ12,i (rad), trailing edge down positive.
    pub deflection_rad: f64,
    /// A: nut pivot on the flap.
    pub nut_pivot_a: PointKinematics,
    /// B: free end of the screw (B0 + a3 along the screw).
    pub screw_end_b: PointKinematics,
    /// D: flap centre of mass.
    pub centre_of_mass_d: PointKinematics,
    /// F: pin in the outer slot (radius b1).
    pub outer_pin_f: PointKinematics,
    /// G: pin in the inner slot (radius c1).
    pub inner_pin_g: PointKinematics,
    /// Closure residual, condition number, transmission angle, distance to toggle.
    pub diagnostics: PoseDiagnostics,
}

impl CircularArcTrack {
    /// Poses the track at nut position s34 = `input_m` (m), speed ṡ34 (m/s) and
    /// acceleration s̈34 (m/s²).
    ///
    /// Errors: [`Error::OutOfSlot`] when s34 is outside [s34,i, s34,f] (thesis 5.3 red
    /// cell 1), and the slider-crank's [`Error::CannotAssemble`] / [`Error::Toggle`].
    pub fn pose(&self, input_m: f64, input_speed_mps: f64, input_accel_mps2: f64) -> Result<Pose> {
        let synthesis = &self.synthesis;
        let slack = SLOT_END_TOLERANCE * synthesis.stroke_end_m;
        if !(input_m >= synthesis.stroke_start_m - slack && input_m <= synthesis.stroke_end_m + slack) {
            return Err(Error::OutOfSlot {
                input_m,
                min_input_m: synthesis.stroke_start_m,
                max_input_m: synthesis.stroke_end_m,
            });
        }
        let linkage = self.linkage.state(input_m, input_speed_mps, input_accel_mps2)?;
        Ok(self.pose_from_state(linkage))
    }

    pub(crate) fn pose_from_state(&self, linkage: SliderCrankState) -> Pose {
        let spec = &self.spec;
        let synthesis = &self.synthesis;
        // Unit vectors by complex products, to keep trigonometry to two sin_cos calls.
        let turn = |cos: f64, sin: f64, v: Vector2<f64>| Vector2::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y);
        let base = synthesis.screw_mount_m.coords / spec.base_distance_m;
        let (sin12, cos12) = linkage.crank_angle_rad.sin_cos();
        let (sin13, cos13) = linkage.slider_angle_rad.sin_cos();
        let crank_dir = turn(cos12, sin12, base);
        let screw_dir = turn(cos13, sin13, base);
        let stowed_dir = synthesis.nut_pivot_stowed_m.coords / spec.crank_length_m;
        // Rotation by the deflection θ12 - θ12,i, taking stowed_dir onto crank_dir.
        let (cos_defl, sin_defl) = (stowed_dir.dot(&crank_dir), stowed_dir.perp(&crank_dir));
        let (rate, accel) = (linkage.crank_rate_radps, linkage.crank_accel_radps2);
        let hinge = Point2::origin();
        let flap_point = |stowed: Point2<f64>| {
            PointKinematics::on_rotating_body(hinge, turn(cos_defl, sin_defl, stowed.coords), rate, accel)
        };
        Pose {
            linkage,
            deflection_rad: linkage.crank_angle_rad - synthesis.stowed_crank_angle_rad,
            nut_pivot_a: PointKinematics::on_rotating_body(hinge, crank_dir * spec.crank_length_m, rate, accel),
            screw_end_b: PointKinematics::on_rotating_body(
                synthesis.screw_mount_m,
                screw_dir * spec.screw_length_m,
                linkage.slider_rate_radps,
                linkage.slider_accel_radps2,
            ),
            centre_of_mass_d: flap_point(spec.centre_of_mass_stowed_m),
            outer_pin_f: flap_point(synthesis.outer_pin_stowed_m),
            inner_pin_g: flap_point(synthesis.inner_pin_stowed_m),
            diagnostics: PoseDiagnostics {
                closure_residual_m: linkage.closure_residual_m,
                jacobian_condition_number: linkage.jacobian_condition_number,
                transmission_angle_rad: linkage.transmission_angle_rad,
                distance_to_toggle_rad: linkage.transmission_angle_rad,
            },
        }
    }
}
