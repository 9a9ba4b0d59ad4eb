//! Newton position solution with the analytic Jacobian, then velocities and accelerations
//! from the differentiated constraints (Φ_q q̇ = ν, Φ_q q̈ = γ) for a [`PlanarModel`].

use nalgebra::{DMatrix, DVector, Vector2};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::planar::{perp, BodyPoint, Driver, Frames, Joint, PlanarModel};

/// Newton stops when every constraint residual is below this (m, m² or rad).
const NEWTON_TOLERANCE: f64 = 1e-13;
/// Newton gives up after this many steps.
const NEWTON_MAX_ITERATIONS: usize = 60;
/// Largest angle change per Newton step (rad), so the solution stays on its branch.
const NEWTON_MAX_ANGLE_STEP_RAD: f64 = 0.25;
/// A Jacobian with a larger condition number is treated as singular (toggle).
const SINGULAR_CONDITION_NUMBER: f64 = 1e12;

/// One assembled configuration with its rates.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanarSolution {
    /// Input value (m for a distance driver, rad for an angle driver).
    pub input: f64,
    /// (x, y, φ) of each moving body, in body order (m, m, rad).
    pub coordinates: Vec<f64>,
    /// Time derivatives of `coordinates` (m/s, rad/s).
    pub rates: Vec<f64>,
    /// Second time derivatives (m/s², rad/s²).
    pub accelerations: Vec<f64>,
    /// Largest constraint residual after Newton.
    pub closure_residual: f64,
    /// 2-norm condition number of the constraint Jacobian.
    pub jacobian_condition_number: f64,
    /// Newton steps taken.
    pub iterations: usize,
}

struct Assembled {
    residual: DVector<f64>,
    jacobian: DMatrix<f64>,
    velocity_rhs: DVector<f64>,
    acceleration_rhs: DVector<f64>,
}

/// Adds `sign * weight · ∂P/∂q` of a body point to a Jacobian row.
fn add_point(row: &mut [f64], weight: Vector2<f64>, point: &BodyPoint, rotated: Vector2<f64>, sign: f64) {
    if point.body == 0 {
        return;
    }
    let i = 3 * (point.body - 1);
    row[i] += sign * weight.x;
    row[i + 1] += sign * weight.y;
    row[i + 2] += sign * weight.dot(&perp(rotated));
}

impl PlanarModel {
    /// Number of coordinates (3 per moving body).
    pub fn coordinate_count(&self) -> usize {
        3 * self.bodies.len().saturating_sub(1)
    }

    /// Checks body indices and that joints plus driver give exactly one equation per
    /// coordinate (Errors: [`Error::UnknownBody`], [`Error::ConstraintCountMismatch`]).
    pub fn validate(&self) -> Result<()> {
        let bodies = self.bodies.len();
        let check = |p: &BodyPoint| {
            if p.body < bodies {
                Ok(())
            } else {
                Err(Error::UnknownBody { body: p.body, bodies })
            }
        };
        for joint in &self.joints {
            match joint {
                Joint::Revolute { a, b, .. } | Joint::Prismatic { a, b, .. } => {
                    check(a)?;
                    check(b)?;
                }
                Joint::PinInCircularSlot { pin, centre, .. } => {
                    check(pin)?;
                    check(centre)?;
                }
                Joint::PinInStraightSlot { pin, slot_point, .. } => {
                    check(pin)?;
                    check(slot_point)?;
                }
            }
        }
        match &self.driver {
            Driver::Distance { a, b } | Driver::RelativeAngle { a, b, .. } => {
                check(a)?;
                check(b)?;
            }
        }
        let constraints = self.joints.iter().map(Joint::equation_count).sum::<usize>() + 1;
        if constraints != self.coordinate_count() {
            return Err(Error::ConstraintCountMismatch {
                coordinates: self.coordinate_count(),
                constraints,
            });
        }
        Ok(())
    }

    fn assemble(&self, q: &[f64], qd: &[f64], input: [f64; 3]) -> Assembled {
        let n = self.coordinate_count();
        let frames = Frames {
            coordinates: q,
            rates: qd,
        };
        let mut residual = DVector::zeros(n);
        let mut jacobian = DMatrix::zeros(n, n);
        let mut velocity_rhs = DVector::zeros(n);
        let mut acceleration_rhs = DVector::zeros(n);
        let mut row = vec![0.0; n];
        let mut k = 0;
        let mut push = |k: &mut usize, value: f64, row: &mut Vec<f64>, nu: f64, gamma: f64| {
            residual[*k] = value;
            for (j, entry) in row.iter_mut().enumerate() {
                jacobian[(*k, j)] = *entry;
                *entry = 0.0;
            }
            velocity_rhs[*k] = nu;
            acceleration_rhs[*k] = gamma;
            *k += 1;
        };
        // Quadratic-velocity part of a point's acceleration: -R p ω².
        let centripetal = |rotated: Vector2<f64>, rate: f64| -rotated * (rate * rate);
        // n · (P_b - P_a) with n on `guide`'s body: value, Jacobian, γ.
        let normal_distance = |row: &mut Vec<f64>, a: &BodyPoint, axis: Vector2<f64>, b: &BodyPoint| {
            let normal = frames.direction(a.body, perp(axis));
            let (ra, pa, wa) = frames.point(a);
            let (rb, pb, wb) = frames.point(b);
            let d = pb - pa;
            add_point(row, normal, b, rb, 1.0);
            add_point(row, normal, a, ra, -1.0);
            if a.body != 0 {
                row[3 * (a.body - 1) + 2] += perp(normal).dot(&d);
            }
            let d_rate = frames.velocity(b) - frames.velocity(a);
            let quad = centripetal(rb, wb) - centripetal(ra, wa);
            let gamma = -(-normal.dot(&d) * wa * wa + 2.0 * wa * perp(normal).dot(&d_rate) + normal.dot(&quad));
            (normal.dot(&d), gamma)
        };
        // θ_a - θ_b (the ground's angle is 0): value and Jacobian; linear, so ν = γ = 0.
        let relative_angle = |row: &mut Vec<f64>, a: usize, b: usize| {
            let mut angle = |body: usize, sign: f64| {
                if body == 0 {
                    return 0.0;
                }
                row[3 * (body - 1) + 2] += sign;
                q[3 * (body - 1) + 2]
            };
            angle(a, 1.0) - angle(b, -1.0)
        };
        // ½(|P_a - P_b|² - ρ²): value, Jacobian, γ.
        let half_square = |row: &mut Vec<f64>, a: &BodyPoint, b: &BodyPoint, radius: f64| {
            let (ra, pa, wa) = frames.point(a);
            let (rb, pb, wb) = frames.point(b);
            let e = pa - pb;
            add_point(row, e, a, ra, 1.0);
            add_point(row, e, b, rb, -1.0);
            let e_rate = frames.velocity(a) - frames.velocity(b);
            let quad = centripetal(ra, wa) - centripetal(rb, wb);
            (
                0.5 * (e.norm_squared() - radius * radius),
                -(e_rate.norm_squared() + e.dot(&quad)),
            )
        };
        for joint in &self.joints {
            match joint {
                Joint::Revolute { a, b, .. } => {
                    let (ra, pa, wa) = frames.point(a);
                    let (rb, pb, wb) = frames.point(b);
                    let gamma = -(centripetal(ra, wa) - centripetal(rb, wb));
                    for axis in 0..2 {
                        let unit = if axis == 0 { Vector2::x() } else { Vector2::y() };
                        add_point(&mut row, unit, a, ra, 1.0);
                        add_point(&mut row, unit, b, rb, -1.0);
                        push(&mut k, pa[axis] - pb[axis], &mut row, 0.0, gamma[axis]);
                    }
                }
                Joint::Prismatic {
                    a,
                    axis_local,
                    b,
                    angle_offset_rad,
                    ..
                } => {
                    let value = relative_angle(&mut row, a.body, b.body) - angle_offset_rad;
                    push(&mut k, value, &mut row, 0.0, 0.0);
                    let (value, gamma) = normal_distance(&mut row, a, *axis_local, b);
                    push(&mut k, value, &mut row, 0.0, gamma);
                }
                Joint::PinInCircularSlot {
                    pin, centre, radius_m, ..
                } => {
                    let (value, gamma) = half_square(&mut row, pin, centre, *radius_m);
                    push(&mut k, value, &mut row, 0.0, gamma);
                }
                Joint::PinInStraightSlot {
                    pin,
                    slot_point,
                    axis_local,
                    ..
                } => {
                    let (value, gamma) = normal_distance(&mut row, slot_point, *axis_local, pin);
                    push(&mut k, value, &mut row, 0.0, gamma);
                }
            }
        }
        let [s, s_rate, s_accel] = input;
        match &self.driver {
            Driver::Distance { a, b } => {
                let (value, gamma) = half_square(&mut row, a, b, s);
                push(
                    &mut k,
                    value,
                    &mut row,
                    s * s_rate,
                    gamma + s_rate * s_rate + s * s_accel,
                );
            }
            Driver::RelativeAngle { a, b, offset_rad } => {
                let value = relative_angle(&mut row, a.body, b.body) - offset_rad - s;
                push(&mut k, value, &mut row, s_rate, s_accel);
            }
        }
        Assembled {
            residual,
            jacobian,
            velocity_rhs,
            acceleration_rhs,
        }
    }

    /// Assembles at `input` (m or rad) starting from `guess` (the previous sample's
    /// coordinates, or the stowed configuration: this picks and tracks the branch), then
    /// solves rates and accelerations for the input's rate and acceleration.
    ///
    /// Errors: [`Error::NotConverged`] (cannot assemble), [`Error::SingularJacobian`]
    /// (toggle), plus [`PlanarModel::validate`]'s.
    pub fn solve(&self, input: f64, input_rate: f64, input_accel: f64, guess: &[f64]) -> Result<PlanarSolution> {
        self.validate()?;
        let n = self.coordinate_count();
        let mut q = DVector::from_column_slice(&guess[..n.min(guess.len())]);
        if q.len() != n {
            return Err(Error::ConstraintCountMismatch {
                coordinates: n,
                constraints: guess.len(),
            });
        }
        let zeros = vec![0.0; n];
        let drive = [input, input_rate, input_accel];
        let mut iterations = 0;
        let mut system = self.assemble(q.as_slice(), &zeros, drive);
        while system.residual.amax() > NEWTON_TOLERANCE {
            if iterations == NEWTON_MAX_ITERATIONS {
                return Err(Error::NotConverged {
                    input,
                    residual: system.residual.amax(),
                    iterations,
                });
            }
            let step = system
                .jacobian
                .clone()
                .lu()
                .solve(&system.residual)
                .ok_or(Error::SingularJacobian {
                    input,
                    condition_number: f64::INFINITY,
                })?;
            let largest_turn = (0..n / 3).map(|b| step[3 * b + 2].abs()).fold(0.0, f64::max);
            let scale = if largest_turn > NEWTON_MAX_ANGLE_STEP_RAD {
                NEWTON_MAX_ANGLE_STEP_RAD / largest_turn
            } else {
                1.0
            };
            q -= step * scale;
            iterations += 1;
            system = self.assemble(q.as_slice(), &zeros, drive);
            if !system.residual.amax().is_finite() {
                return Err(Error::NotConverged {
                    input,
                    residual: f64::INFINITY,
                    iterations,
                });
            }
        }
        let singular = system.jacobian.clone().singular_values();
        let condition_number = singular.max() / singular.min();
        if condition_number.is_nan() || condition_number >= SINGULAR_CONDITION_NUMBER {
            return Err(Error::SingularJacobian {
                input,
                condition_number,
            });
        }
        let lu = system.jacobian.clone().lu();
        let rates = lu.solve(&system.velocity_rhs).ok_or(Error::SingularJacobian {
            input,
            condition_number,
        })?;
        let with_rates = self.assemble(q.as_slice(), rates.as_slice(), drive);
        let accelerations = lu.solve(&with_rates.acceleration_rhs).ok_or(Error::SingularJacobian {
            input,
            condition_number,
        })?;
        Ok(PlanarSolution {
            input,
            coordinates: q.as_slice().to_vec(),
            rates: rates.as_slice().to_vec(),
            accelerations: accelerations.as_slice().to_vec(),
            closure_residual: system.residual.amax(),
            jacobian_condition_number: condition_number,
            iterations,
        })
    }

    /// Solves at each input in turn, each from the previous solution (the first from
    /// `stowed`), so the assembly branch of the stowed configuration is tracked. Stops at
    /// the first failure and returns it beside the samples solved so far; the error names
    /// the input value.
    pub fn sweep(
        &self,
        inputs: &[f64],
        input_rate: f64,
        input_accel: f64,
        stowed: &[f64],
    ) -> (Vec<PlanarSolution>, Option<Error>) {
        let mut solutions: Vec<PlanarSolution> = Vec::with_capacity(inputs.len());
        for &input in inputs {
            let guess = solutions.last().map_or(stowed, |s| s.coordinates.as_slice());
            match self.solve(input, input_rate, input_accel, guess) {
                Ok(solution) => solutions.push(solution),
                Err(error) => return (solutions, Some(error)),
            }
        }
        (solutions, None)
    }
}
