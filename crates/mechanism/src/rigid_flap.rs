//! The equation of motion of any one-input kind from what every kind gives through the seam:
//! its flap's pose against the input and its statics. The flap is the one body with mass
//! (the links massless, as `001_...` section 1.1 and the kinds' statics take them), so
//! ([`crate::generalised`]'s work-energy form)
//!
//! J(q) = m |c'|² + I_c θ'²,   Q(q) = -F(q),
//!
//! with c the flap's centre of mass, θ its angle, ' = d/dq, and F the actuator load the kind's
//! statics give for the load case (its weight and flight load held quasi-statically: F is
//! the load's power per unit input rate, negated, by virtual work).
//!
//! The input q here is the actuator's drive-shaft angle from stowed (rad), increasing
//! towards deployed: a screw's stroke or a rotary actuator's output angle times
//! [`crate::seam::Actuator::shaft_angle_per_input`], so that every kind is driven the same way. Losses
//! of the actuator itself (thread friction, gear efficiency) are not in Q; the motor's
//! gearbox efficiency of the dynamics can carry them.
//!
//! The kinematic coefficients are differences of the kind's own poses: five-point stencils
//! (central, or one-sided within two steps of an end, so that no pose is asked for outside
//! the travel) with the step [`RELATIVE_STEP`] of the travel: truncation ~ h⁴ (on the test four-bar, J' agrees with an extrapolated
//! difference to 1e-6 of its scale; at a step of 2e-3 it was off by 3e-7 of itself),
//! rounding ~ ε/h; J'' (the integrator's Jacobian only) to 1e-4. A kind
//! with jets of its own (the five-bar) gives its equation of motion itself
//! ([`FlapMechanism::dynamics`]); this is for the others, written once for all of them.
//! Beyond the stops (where an integrator may step before it locates the stop) the values at
//! the stop are held.

use nalgebra::{Isometry2, Point2};

use crate::error::{Error, Result};
use crate::generalised::{Generalised, OneInputDynamics};
use crate::seam::FlapMechanism;
use crate::shared::flap_load::FlapMass;
use crate::shared::load_case::LoadCase;

/// The difference step, as a fraction of the input travel.
pub const RELATIVE_STEP: f64 = 5e-4;

/// A kind's flap as the one body with mass, driven through its actuator's shaft.
#[derive(Debug)]
pub struct RigidFlapDynamics<'a> {
    mechanism: &'a dyn FlapMechanism,
    mass: FlapMass,
    inertia_kgm2: f64,
    load: LoadCase,
    /// Shaft angle per unit input, signed so that deploying turns the shaft positively.
    shaft_per_input: f64,
    stowed_input: f64,
    travel: f64,
}

impl<'a> RigidFlapDynamics<'a> {
    /// The model of `mechanism`'s flap of `mass` and moment of inertia `inertia_kgm2` about
    /// its centre of mass, under `load` (quasi-static: its inertia flag is ignored).
    pub fn new(mechanism: &'a dyn FlapMechanism, mass: FlapMass, inertia_kgm2: f64, load: &LoadCase) -> Result<Self> {
        let range = mechanism.input_range();
        let direction = (range.deployed - range.stowed).signum();
        let shaft_per_input = mechanism.actuator().shaft_angle_per_input() * direction;
        let travel = (range.deployed - range.stowed) * shaft_per_input;
        for (name, value, least) in [
            ("flap mass", mass.mass_kg, 0.0),
            ("flap moment of inertia", inertia_kgm2, 0.0),
            ("shaft travel", travel, f64::MIN_POSITIVE),
        ] {
            if !value.is_finite() || value < least {
                return Err(Error::InvalidDimension { name, value });
            }
        }
        let load = LoadCase {
            include_inertia: false,
            ..load.clone()
        };
        Ok(Self {
            mechanism,
            mass,
            inertia_kgm2,
            load,
            shaft_per_input,
            stowed_input: range.stowed,
            travel,
        })
    }

    /// The kind's input at shaft angle `q`, held at the stops.
    fn input(&self, q: f64) -> f64 {
        self.stowed_input + q.clamp(0.0, self.travel) / self.shaft_per_input
    }

    /// The flap's displacement from stowed at shaft angle `q`.
    fn flap(&self, q: f64) -> Result<Isometry2<f64>> {
        Ok(self.mechanism.pose(self.input(q))?.flap)
    }

    /// The centre of mass and angle at `q`.
    fn centre_and_angle(&self, q: f64) -> Result<(Point2<f64>, f64)> {
        let flap = self.flap(q)?;
        Ok((flap * self.mass.centre_of_mass_stowed_m, flap.rotation.angle()))
    }

    /// J at `q`: m |c'|² + I θ'². The nested stencils of one evaluation fall on the grid
    /// `base + k h`: `poses` keeps what was posed there (k, centre, angle), so the 25 points
    /// of J's five values cost 9 poses.
    fn inertia(&self, q: f64, base: f64, poses: &mut Vec<(i64, Point2<f64>, f64)>) -> Result<f64> {
        let h = RELATIVE_STEP * self.travel;
        let samples = stencil_points(q, h, self.travel);
        let mut centres = [Point2::origin(); 5];
        let mut angles = [0.0; 5];
        for (k, &at) in samples.points.iter().enumerate() {
            let grid = ((at - base) / h).round() as i64;
            let posed = match poses.iter().find(|(g, _, _)| *g == grid) {
                Some(&(_, centre, angle)) => (centre, angle),
                None => {
                    let (centre, angle) = self.centre_and_angle(base + grid as f64 * h)?;
                    poses.push((grid, centre, angle));
                    (centre, angle)
                }
            };
            (centres[k], angles[k]) = posed;
        }
        // Differences from the point's own angle, wrapped to (-π, π]: no jump at the ±π cut.
        let turned = angles.map(|a| (a - angles[samples.at]).sin().atan2((a - angles[samples.at]).cos()));
        let angle_rate = samples.first(&turned);
        let velocity_x = samples.first(&centres.map(|c| c.x));
        let velocity_y = samples.first(&centres.map(|c| c.y));
        Ok(self.mass.mass_kg * (velocity_x * velocity_x + velocity_y * velocity_y)
            + self.inertia_kgm2 * angle_rate * angle_rate)
    }

    /// Q at `q`: the load's power per unit shaft rate.
    fn force(&self, q: f64) -> Result<f64> {
        let statics = self.mechanism.kinetostatics(self.input(q), &self.load)?;
        Ok(-statics.actuator_load / self.shaft_per_input)
    }
}

/// Five sample points about `q` within [0, travel] and the weights of the first and second
/// derivative there.
struct Stencil {
    points: [f64; 5],
    /// Which point is `q` itself.
    at: usize,
    first: [f64; 5],
    second: [f64; 5],
    step: f64,
}

impl Stencil {
    fn first(&self, values: &[f64; 5]) -> f64 {
        self.first.iter().zip(values).map(|(w, v)| w * v).sum::<f64>() / self.step
    }

    fn second(&self, values: &[f64; 5]) -> f64 {
        self.second.iter().zip(values).map(|(w, v)| w * v).sum::<f64>() / (self.step * self.step)
    }
}

/// The five-point stencil at `q` (held inside [0, travel]) with step `h`: central where two
/// steps fit on both sides, else one-sided from the nearer end. Weights: the fourth-order
/// finite-difference formulas (Fornberg 1988).
fn stencil_points(q: f64, h: f64, travel: f64) -> Stencil {
    let q = q.clamp(0.0, travel);
    const CENTRAL_FIRST: [f64; 5] = [1.0 / 12.0, -8.0 / 12.0, 0.0, 8.0 / 12.0, -1.0 / 12.0];
    const CENTRAL_SECOND: [f64; 5] = [-1.0 / 12.0, 16.0 / 12.0, -30.0 / 12.0, 16.0 / 12.0, -1.0 / 12.0];
    const FORWARD_FIRST: [f64; 5] = [-25.0 / 12.0, 48.0 / 12.0, -36.0 / 12.0, 16.0 / 12.0, -3.0 / 12.0];
    const FORWARD_SECOND: [f64; 5] = [35.0 / 12.0, -104.0 / 12.0, 114.0 / 12.0, -56.0 / 12.0, 11.0 / 12.0];
    if q - 2.0 * h >= 0.0 && q + 2.0 * h <= travel {
        Stencil {
            points: [-2.0, -1.0, 0.0, 1.0, 2.0].map(|k| q + k * h),
            at: 2,
            first: CENTRAL_FIRST,
            second: CENTRAL_SECOND,
            step: h,
        }
    } else if q - 2.0 * h < 0.0 {
        Stencil {
            points: [0.0, 1.0, 2.0, 3.0, 4.0].map(|k| q + k * h),
            at: 0,
            first: FORWARD_FIRST,
            second: FORWARD_SECOND,
            step: h,
        }
    } else {
        // Backward: the forward formulas mirrored (the first derivative changes sign).
        Stencil {
            points: [0.0, -1.0, -2.0, -3.0, -4.0].map(|k| q + k * h),
            at: 0,
            first: FORWARD_FIRST.map(|w| -w),
            second: FORWARD_SECOND,
            step: h,
        }
    }
}

impl OneInputDynamics for RigidFlapDynamics<'_> {
    fn input_travel(&self) -> (f64, f64) {
        (0.0, self.travel)
    }

    fn generalised_at(&self, q: f64) -> Result<Generalised> {
        let h = RELATIVE_STEP * self.travel;
        let outer = stencil_points(q, h, self.travel);
        let mut inertias = [0.0; 5];
        let mut forces = [0.0; 5];
        let base = outer.points[outer.at];
        let mut poses = Vec::with_capacity(9);
        for (k, &at) in outer.points.iter().enumerate() {
            inertias[k] = self.inertia(at, base, &mut poses)?;
            forces[k] = self.force(at)?;
        }
        let generalised = Generalised {
            inertia: inertias[outer.at],
            inertia_slope: outer.first(&inertias),
            inertia_curvature: outer.second(&inertias),
            force: forces[outer.at],
            force_slope: outer.first(&forces),
        };
        let finite = [
            generalised.inertia,
            generalised.inertia_slope,
            generalised.inertia_curvature,
            generalised.force,
            generalised.force_slope,
        ]
        .iter()
        .all(|v| v.is_finite());
        if !finite {
            return Err(Error::NonFinite {
                quantity: "rigid-flap generalised inertia or force",
                input_m: self.input(q),
            });
        }
        Ok(generalised)
    }
}
