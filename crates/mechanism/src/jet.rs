//! Points and angles with their first three derivatives with respect to the input: the
//! kinematic coefficients (velocity, acceleration and jerk analogues, as in `004_...`)
//! from which velocities and accelerations at any input rate follow:
//! v = p' q̇, a = p'' q̇² + p' q̈.
//!
//! Carrying the derivatives along with the positions (forward-mode differentiation done by
//! hand, one rule per operation) keeps the velocity and acceleration analysis in the same
//! few lines as the position analysis, instead of a separately derived linear system per
//! loop, which is where the printed equations of `001_...` section 2 go wrong (see
//! `data/validation/001-five-bar-defects.md`). The third derivative feeds the slope of the
//! generalised inertia, which the stiff integrator's Jacobian needs.

use std::ops::{Add, Mul, Sub};

use nalgebra::Vector2;

use crate::shared::geometry::cross;

/// A planar point (or vector) and its first three derivatives with respect to the input
/// (m, m per unit input, ...).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointJet {
    /// Position.
    pub p: Vector2<f64>,
    /// d/dq.
    pub d1: Vector2<f64>,
    /// d²/dq².
    pub d2: Vector2<f64>,
    /// d³/dq³.
    pub d3: Vector2<f64>,
}

/// An angle (rad) and its first three derivatives with respect to the input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleJet {
    /// The angle.
    pub value: f64,
    /// d/dq.
    pub d1: f64,
    /// d²/dq².
    pub d2: f64,
    /// d³/dq³.
    pub d3: f64,
}

impl PointJet {
    /// A point that does not move.
    pub fn fixed(p: Vector2<f64>) -> Self {
        Self {
            p,
            d1: Vector2::zeros(),
            d2: Vector2::zeros(),
            d3: Vector2::zeros(),
        }
    }

    /// The point at `radius` along angle `angle` from the origin, r (cos a, sin a): a crank
    /// turned by its input.
    pub fn polar(radius: f64, angle: AngleJet) -> Self {
        let (sin, cos) = angle.value.sin_cos();
        let u = Vector2::new(cos, sin);
        let n = Vector2::new(-u.y, u.x);
        let (w1, w2, w3) = (angle.d1, angle.d2, angle.d3);
        // d/dq u = w n, d/dq n = -w u.
        Self {
            p: u * radius,
            d1: n * (radius * w1),
            d2: (n * w2 - u * (w1 * w1)) * radius,
            d3: (n * (w3 - w1 * w1 * w1) - u * (3.0 * w1 * w2)) * radius,
        }
    }

    /// The vector turned by +90 deg (i times it in the Gauss plane).
    pub fn perp(&self) -> Self {
        let turn = |v: Vector2<f64>| Vector2::new(-v.y, v.x);
        Self {
            p: turn(self.p),
            d1: turn(self.d1),
            d2: turn(self.d2),
            d3: turn(self.d3),
        }
    }

    /// The direction angle of the vector (rad) with its derivatives: for a vector u,
    /// ω = (u x u') / |u|², and its derivatives by the quotient rule.
    pub fn angle(&self) -> AngleJet {
        self.angle_to_order::<3>()
    }

    /// [`PointJet::angle`] with only the first `ORDER` derivatives (1 to 3; the others 0):
    /// a sweep of positions and rates skips the higher ones.
    #[inline]
    pub fn angle_to_order<const ORDER: usize>(&self) -> AngleJet {
        let (u, u1, u2, u3) = (self.p, self.d1, self.d2, self.d3);
        let n = u.norm_squared();
        let w1 = cross(u, u1) / n;
        let mut jet = AngleJet {
            value: u.y.atan2(u.x),
            d1: w1,
            d2: 0.0,
            d3: 0.0,
        };
        if ORDER >= 2 {
            let n1 = 2.0 * u.dot(&u1);
            jet.d2 = (cross(u, u2) - w1 * n1) / n;
            if ORDER >= 3 {
                let n2 = 2.0 * (u1.norm_squared() + u.dot(&u2));
                let c2 = cross(u1, u2) + cross(u, u3);
                jet.d3 = (c2 - 2.0 * jet.d2 * n1 - w1 * n2) / n;
            }
        }
        jet
    }

    /// Dot product of two jets (the product rule to third order).
    pub fn dot(&self, other: &Self) -> [f64; 4] {
        let (a, b) = (self, other);
        [
            a.p.dot(&b.p),
            a.d1.dot(&b.p) + a.p.dot(&b.d1),
            a.d2.dot(&b.p) + 2.0 * a.d1.dot(&b.d1) + a.p.dot(&b.d2),
            a.d3.dot(&b.p) + 3.0 * a.d2.dot(&b.d1) + 3.0 * a.d1.dot(&b.d2) + a.p.dot(&b.d3),
        ]
    }
}

impl Add for PointJet {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self {
            p: self.p + o.p,
            d1: self.d1 + o.d1,
            d2: self.d2 + o.d2,
            d3: self.d3 + o.d3,
        }
    }
}

impl Sub for PointJet {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self {
            p: self.p - o.p,
            d1: self.d1 - o.d1,
            d2: self.d2 - o.d2,
            d3: self.d3 - o.d3,
        }
    }
}

impl Mul<f64> for PointJet {
    type Output = Self;
    fn mul(self, k: f64) -> Self {
        Self {
            p: self.p * k,
            d1: self.d1 * k,
            d2: self.d2 * k,
            d3: self.d3 * k,
        }
    }
}

impl AngleJet {
    /// The input itself: q, 1, 0, 0.
    pub fn input(q: f64) -> Self {
        Self {
            value: q,
            d1: 1.0,
            d2: 0.0,
            d3: 0.0,
        }
    }

    /// The negated angle.
    pub fn negated(&self) -> Self {
        Self {
            value: -self.value,
            d1: -self.d1,
            d2: -self.d2,
            d3: -self.d3,
        }
    }
}

/// Where a point at fixed distances from two moving points stands, with its derivatives:
/// one RRR dyad, in closed form.
///
/// Position: the intersection of the circles (P, `from_p`) and (Q, `from_q`) on the side
/// `branch` (the sign of (Q - P) x (X - P)). Derivatives: differentiating
/// |X - P|² = r² k times gives, with u = X - P and w = X' - P',
/// u · (X' - P') = 0, u · (X'' - P'') = -|w|², u · (X''' - P''') = -3 w · (X'' - P''),
/// and the same about Q: a 2 x 2 system per order with the matrix [u_P; u_Q], singular when
/// the two links are aligned (a toggle). Returns `None` when the circles do not meet or the
/// links are aligned; the caller names the loop.
pub fn dyad(p: &PointJet, from_p: f64, q: &PointJet, from_q: f64, branch: f64) -> Option<DyadJet> {
    dyad_to_order::<3>(p, from_p, q, from_q, branch)
}

/// [`dyad`] with only the first `ORDER` derivatives (1 to 3; the others 0). `ORDER` is a
/// constant so that a sweep of positions and rates compiles without the higher orders.
///
/// The position is written with the squared distance D² = |Q - P|² alone:
/// X = P + a (Q - P) + b h (Q - P)⊥ with a = (r_P² - r_Q² + D²) / (2 D²) and
/// h² = r_P² / D² - a², one division and one square root on the path to X, where the
/// textbook form (the distance, then the foot along the unit direction) takes two of each.
#[inline]
pub fn dyad_to_order<const ORDER: usize>(
    p: &PointJet,
    from_p: f64,
    q: &PointJet,
    from_q: f64,
    branch: f64,
) -> Option<DyadJet> {
    let pq = q.p - p.p;
    let distance_squared = pq.norm_squared();
    if distance_squared.is_nan() || distance_squared <= 0.0 {
        return None;
    }
    let inverse_distance_squared = 1.0 / distance_squared;
    let from_p_squared = from_p * from_p;
    let along = 0.5 * (from_p_squared - from_q * from_q + distance_squared) * inverse_distance_squared;
    let h2 = from_p_squared * inverse_distance_squared - along * along;
    if h2.is_nan() || h2 < 0.0 {
        return None;
    }
    let x = p.p + pq * along + Vector2::new(-pq.y, pq.x) * (branch * h2.sqrt());
    let (up, uq) = (x - p.p, x - q.p);
    let det = cross(up, uq);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // Solves up · v = bp, uq · v = bq by Cramer's rule.
    let inverse_det = 1.0 / det;
    let solve = |bp: f64, bq: f64| Vector2::new(bp * uq.y - bq * up.y, up.x * bq - uq.x * bp) * inverse_det;
    let d1 = solve(up.dot(&p.d1), uq.dot(&q.d1));
    let mut point = PointJet {
        p: x,
        d1,
        d2: Vector2::zeros(),
        d3: Vector2::zeros(),
    };
    if ORDER >= 2 {
        let (wp, wq) = (d1 - p.d1, d1 - q.d1);
        point.d2 = solve(up.dot(&p.d2) - wp.norm_squared(), uq.dot(&q.d2) - wq.norm_squared());
        if ORDER >= 3 {
            point.d3 = solve(
                up.dot(&p.d3) - 3.0 * wp.dot(&(point.d2 - p.d2)),
                uq.dot(&q.d3) - 3.0 * wq.dot(&(point.d2 - q.d2)),
            );
        }
    }
    Some(DyadJet {
        point,
        sine_between_links: det / (from_p * from_q),
    })
}

/// A dyad's solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DyadJet {
    /// The joint point with its derivatives.
    pub point: PointJet,
    /// sin of the angle between the two links at the joint (signed): the dyad's distance
    /// from its toggle, 0 when the links are aligned.
    pub sine_between_links: f64,
}
