//! The equation of motion of a one-input mechanism in its input q, by the work-energy
//! theorem dT/dt = Π (`001_...` section 3.1, written for any kind):
//!
//! T = ½ J(q) q̇², J(q) = Σ_b (m_b |c_b'|² + I_b φ_b'²), with c_b the centre of mass and φ_b
//! the angle of body b and ' = d/dq (the kinematic coefficients); Π = τ q̇ + Q(q) q̇, Q the
//! generalised force of the loads and weights (their power per unit input rate). Hence
//!
//! J(q) q̈ + ½ J'(q) q̇² = τ + Q(q),
//!
//! and at a constant input rate ω the driving torque τ = ½ J' ω² - Q. The integrator's
//! Jacobian also needs J'' and Q', which need the third derivatives of the centres: the
//! kinds give [`PointJet`]s to third order.
//!
//! Loads (`001_...` section 3.1, linearised aerodynamics): each aerodynamic surface has a
//! lift L = L_δ δ normal to its chord at its aerodynamic centre, n = (sin δ, cos δ) for a
//! chord along e^{-iδ} (x aft, y up, δ trailing edge down), and a constant pitching moment
//! M, positive nose up, so that its power is M δ̇. Weights act along -y.

use serde::Serialize;

use crate::error::Result;

use crate::jet::{AngleJet, PointJet};

/// A body with mass, where it stands at one input (with the derivatives of its centre and
/// angle with respect to the input).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertialBody {
    /// Body name.
    pub name: &'static str,
    /// Mass (kg).
    pub mass_kg: f64,
    /// Moment of inertia about the centre of mass (kg m²).
    pub inertia_kgm2: f64,
    /// Centre of mass (m) and its derivatives.
    pub centre: PointJet,
    /// The body's angle (rad, counter-clockwise) and its derivatives.
    pub angle: AngleJet,
}

/// A lifting surface: lift linear in its deflection, a constant pitching moment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AeroSurface {
    /// Surface name.
    pub name: &'static str,
    /// Aerodynamic centre (m) and its derivatives.
    pub aerodynamic_centre: PointJet,
    /// Deflection δ (rad, trailing edge down) and its derivatives.
    pub deflection: AngleJet,
    /// Lift per radian of deflection (N/rad).
    pub lift_per_rad_n: f64,
    /// Pitching moment (N m, positive nose up, in the sense of δ).
    pub pitching_moment_nm: f64,
}

/// The generalised inertia and force at one input, and their slopes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Generalised {
    /// J(q) (kg m² for an angle input).
    pub inertia: f64,
    /// dJ/dq.
    pub inertia_slope: f64,
    /// d²J/dq².
    pub inertia_curvature: f64,
    /// Q(q), the loads' and weights' power per unit input rate (N m for an angle input).
    pub force: f64,
    /// dQ/dq.
    pub force_slope: f64,
}

impl Generalised {
    /// The driving torque (or force) that holds the input rate constant at `rate`:
    /// τ = ½ J' ω² - Q.
    pub fn torque_at_constant_rate(&self, rate: f64) -> f64 {
        0.5 * self.inertia_slope * rate * rate - self.force
    }

    /// The input acceleration under driving torque `torque` at input rate `rate`:
    /// q̈ = (τ + Q - ½ J' q̇²) / J.
    pub fn acceleration(&self, torque: f64, rate: f64) -> f64 {
        (torque + self.force - 0.5 * self.inertia_slope * rate * rate) / self.inertia
    }
}

/// J, Q and their slopes from the bodies with mass, the surfaces and gravity (m/s², along
/// -y), by the formulas of the module doc.
pub fn generalise(bodies: &[InertialBody], surfaces: &[AeroSurface], gravity_mps2: f64) -> Generalised {
    let mut out = Generalised {
        inertia: 0.0,
        inertia_slope: 0.0,
        inertia_curvature: 0.0,
        force: 0.0,
        force_slope: 0.0,
    };
    for body in bodies {
        let (c, w) = (&body.centre, &body.angle);
        out.inertia += body.mass_kg * c.d1.norm_squared() + body.inertia_kgm2 * w.d1 * w.d1;
        out.inertia_slope += 2.0 * (body.mass_kg * c.d1.dot(&c.d2) + body.inertia_kgm2 * w.d1 * w.d2);
        out.inertia_curvature += 2.0
            * (body.mass_kg * (c.d2.norm_squared() + c.d1.dot(&c.d3))
                + body.inertia_kgm2 * (w.d2 * w.d2 + w.d1 * w.d3));
        out.force -= body.mass_kg * gravity_mps2 * c.d1.y;
        out.force_slope -= body.mass_kg * gravity_mps2 * c.d2.y;
    }
    for surface in surfaces {
        let (ac, delta) = (&surface.aerodynamic_centre, &surface.deflection);
        let (sin, cos) = delta.value.sin_cos();
        let normal = nalgebra::Vector2::new(sin, cos);
        let normal_slope = nalgebra::Vector2::new(cos, -sin) * delta.d1;
        let lift = surface.lift_per_rad_n * delta.value;
        let lift_slope = surface.lift_per_rad_n * delta.d1;
        out.force += lift * normal.dot(&ac.d1) + surface.pitching_moment_nm * delta.d1;
        out.force_slope += lift_slope * normal.dot(&ac.d1)
            + lift * (normal_slope.dot(&ac.d1) + normal.dot(&ac.d2))
            + surface.pitching_moment_nm * delta.d2;
    }
    out
}

/// A one-input mechanism with its loads, as the equation of motion sees it: the dynamics
/// stage is written against this, never against a kind.
pub trait OneInputDynamics: Send + Sync {
    /// The input with the flap stowed and fully deployed (rad for a crank).
    fn input_travel(&self) -> (f64, f64);

    /// J, Q and their slopes at `input`.
    fn generalised_at(&self, input: f64) -> Result<Generalised>;
}
