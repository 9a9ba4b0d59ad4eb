//! A rigid flap carried by several stations: its 3D pose at each drive fraction is the
//! least-squares rigid motion of its sections as the stations' mechanisms move them
//! (`flapwright_geom::fit_rigid_motion`).
//!
//! Each station's mechanism moves the flap's section in its own plane. The stations of a
//! tapered flap ask for a conical motion (the sections move by amounts that grow with the
//! local chord, and their planes are parallel), which no single planar motion lifted into
//! 3D gives: following one station would carry the flap through the wing at the others.
//! The fit follows all of them; what it cannot follow (the stations disagreeing with any
//! rigid motion, and the in-plane mechanisms against the flap's out-of-plane motion) is
//! its residual, reported by [`FittedFlapMotion::fit_at`] for the attachments' joints to
//! take up.

use std::sync::Arc;

use flapwright_geom::{fit_rigid_motion, FitSpeedGain, RigidFit};
use flapwright_mechanism::seam::FlapMechanism;
use nalgebra::{Isometry3, Point2, Point3};

use crate::error::{Error, Result};
use crate::part::Motion;
use crate::station::{lift, FlapElement};

/// Largest number of section points a carrier contributes to the fit (evenly picked):
/// enough to weigh the whole section, few enough for a pose in microseconds.
pub const FIT_POINTS_PER_CARRIER: usize = 24;

/// The linearised speed gain of the fit ([`FitSpeedGain`]) holds exactly for an exact fit;
/// the Procrustes derivative of an inexact one differs by about the residual over the
/// section's size (millimetres over metres here). This margin covers residuals up to a
/// tenth of the sections' size; `rigid_fit`'s and this module's tests check it against
/// finite differences.
pub const FIT_SPEED_MARGIN: f64 = 1.25;

/// One station carrying the flap.
#[derive(Clone)]
pub struct FlapCarrier {
    /// Station name.
    pub station: String,
    /// The station frame in the aircraft frame.
    pub aircraft_from_station: Isometry3<f64>,
    /// Its mechanism (its flap displacement moves the section).
    pub mechanism: Arc<dyn FlapMechanism>,
    /// Points of the stowed flap section in the station plane (station frame, m): the
    /// section's outline thinned by [`fit_points`].
    pub section_st: Vec<Point2<f64>>,
}

impl std::fmt::Debug for FlapCarrier {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FlapCarrier")
            .field("station", &self.station)
            .field("kind", &self.mechanism.kind())
            .field("section_points", &self.section_st.len())
            .finish()
    }
}

/// The flap's rigid motion fitted to every carrier's section over the drive fraction τ.
#[derive(Debug, Clone)]
pub struct FittedFlapMotion {
    carriers: Vec<FlapCarrier>,
    /// Each carrier's body that moves the element ([`FlapElement::carrier`]).
    carrier_bodies: Vec<usize>,
    /// The fitted points stowed, aircraft frame, in carrier order.
    stowed_ac: Vec<Point3<f64>>,
    /// m per unit τ, for the `query` points given at construction.
    speed_bound: f64,
    /// Root mean square of the fitted points' speed bounds (m per unit τ): the speed gain
    /// at a point times this (and the margin) bounds the fitted field there.
    root_mean_square: f64,
}

impl FittedFlapMotion {
    /// The motion of the flap (its main or aft `element`) carried by `carriers` (two or
    /// more stations, each with a section of that element), with a speed bound valid for
    /// `query_ac` (the element's vertices, stowed).
    ///
    /// # Errors
    /// [`Error::NoFlapBody`] when a carrier's mechanism has no flap body,
    /// [`Error::FlapFit`] when the sections cannot fix a rigid motion (fewer than three
    /// points in all, or all on one line).
    pub fn try_new(
        flap: &str,
        element: FlapElement,
        carriers: Vec<FlapCarrier>,
        query_ac: &[Point3<f64>],
    ) -> Result<Self> {
        let fit_error = |source| Error::FlapFit {
            flap: flap.to_string(),
            source,
        };
        let stowed_ac: Vec<Point3<f64>> = carriers
            .iter()
            .flat_map(|c| c.section_st.iter().map(|p| lifted(&c.aircraft_from_station, p)))
            .collect();
        // How fast the fitted points move: each its station's flap body bound at its radius;
        // the gain bounds the fitted body by their root mean square.
        let (mut sum_squares, mut count) = (0.0_f64, 0usize);
        let mut carrier_bodies = Vec::with_capacity(carriers.len());
        for carrier in &carriers {
            let (index, body) = element
                .carrier(carrier.mechanism.as_ref())
                .ok_or_else(|| Error::NoFlapBody { part: flap.to_string() })?;
            carrier_bodies.push(index);
            let travel = carrier.mechanism.input_range().travel().abs();
            for p in &carrier.section_st {
                let reach = (p - body.speed_bound.reference).norm();
                sum_squares += (body.speed_bound.within(reach) * travel).powi(2);
                count += 1;
            }
        }
        let gain = FitSpeedGain::compute(&stowed_ac, query_ac).map_err(fit_error)?.gain;
        let root_mean_square = (sum_squares / count.max(1) as f64).sqrt();
        // The fit itself must be well posed at the stowed end.
        fit_rigid_motion(&stowed_ac, &stowed_ac).map_err(fit_error)?;
        Ok(Self {
            carriers,
            carrier_bodies,
            stowed_ac,
            speed_bound: FIT_SPEED_MARGIN * gain * root_mean_square,
            root_mean_square,
        })
    }

    /// The carriers, in the order given.
    pub fn carriers(&self) -> &[FlapCarrier] {
        &self.carriers
    }

    /// The fit at drive fraction `fraction`: the flap's pose (maps stowed aircraft-frame
    /// points to their positions) and how far the carriers' sections are from it.
    pub fn fit_at(&self, fraction: f64) -> std::result::Result<RigidFit, flapwright_mechanism::Error> {
        self.fit_of(&self.moved_sections(fraction)?, fraction)
    }

    /// The fit of the stowed points to `moved` (at `fraction`, for the error).
    fn fit_of(
        &self,
        moved: &[Vec<Point3<f64>>],
        fraction: f64,
    ) -> std::result::Result<RigidFit, flapwright_mechanism::Error> {
        // The stowed points were fitted at construction, so only a non-finite pose fails.
        fit_rigid_motion(&self.stowed_ac, &moved.concat()).map_err(|_| flapwright_mechanism::Error::NonFinite {
            quantity: "fitted flap pose",
            input_m: fraction,
        })
    }

    /// Each carrier's section points (aircraft frame) as its own mechanism moves them at
    /// drive fraction `fraction`.
    fn moved_sections(&self, fraction: f64) -> std::result::Result<Vec<Vec<Point3<f64>>>, flapwright_mechanism::Error> {
        self.carriers
            .iter()
            .zip(&self.carrier_bodies)
            .map(|(carrier, &body)| {
                let mechanism = &carrier.mechanism;
                let pose = mechanism.pose(mechanism.input_range().at_fraction(fraction))?;
                let moved = carrier.aircraft_from_station * lift(&FlapElement::displacement(body, &pose));
                Ok(carrier
                    .section_st
                    .iter()
                    .map(|p| moved * Point3::new(p.x, p.y, 0.0))
                    .collect())
            })
            .collect()
    }

    /// The fit at drive fraction `fraction` and, per carrier (in the order given), the
    /// largest distance (m) of its section points, as its own mechanism moves them, from
    /// where the fitted motion puts them: how far each station pulls the flap off the
    /// rigid motion its attachments must take up.
    pub fn carrier_misses_at(
        &self,
        fraction: f64,
    ) -> std::result::Result<(RigidFit, Vec<f64>), flapwright_mechanism::Error> {
        let moved = self.moved_sections(fraction)?;
        let fit = self.fit_of(&moved, fraction)?;
        let mut stowed = self.stowed_ac.iter();
        let misses = moved
            .iter()
            .map(|section| {
                section
                    .iter()
                    .zip(stowed.by_ref())
                    .map(|(moved_ac, stowed_ac)| (moved_ac - fit.motion * stowed_ac).norm())
                    .fold(0.0, f64::max)
            })
            .collect();
        Ok((fit, misses))
    }
}

impl Motion for FittedFlapMotion {
    fn pose_ac(&self, t: f64) -> std::result::Result<Isometry3<f64>, flapwright_mechanism::Error> {
        Ok(self.fit_at(t)?.motion)
    }

    fn speed_bound(&self) -> f64 {
        self.speed_bound
    }

    /// The local frame is the stowed aircraft frame, where the fitted points are: the gain
    /// at the query points ([`FitSpeedGain`] is convex in the point: a corner of their hull
    /// bounds it) times the fitted points' root mean square speed, with the margin.
    fn field_speed_bound(&self, local_points: &[Point3<f64>]) -> Option<f64> {
        let gain = FitSpeedGain::compute(&self.stowed_ac, local_points).ok()?.gain;
        Some(FIT_SPEED_MARGIN * gain * self.root_mean_square)
    }
}

fn lifted(aircraft_from_station: &Isometry3<f64>, p: &Point2<f64>) -> Point3<f64> {
    aircraft_from_station * Point3::new(p.x, p.y, 0.0)
}

/// At most [`FIT_POINTS_PER_CARRIER`] points of a section's polygons, spread evenly
/// along them: what a carrier contributes to the fit.
pub fn fit_points(polygons: &[Vec<Point2<f64>>]) -> Vec<Point2<f64>> {
    let all: Vec<Point2<f64>> = polygons.iter().flatten().copied().collect();
    if all.len() <= FIT_POINTS_PER_CARRIER {
        return all;
    }
    (0..FIT_POINTS_PER_CARRIER)
        .map(|k| all[k * all.len() / FIT_POINTS_PER_CARRIER])
        .collect()
}
