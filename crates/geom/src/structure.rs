//! Spars (plates between the skins) and the torque tube (a cylinder along a polyline).

use nalgebra::{Point2, Point3, Unit, Vector3};

use crate::airfoil::{Airfoil, Surface};
use crate::error::{require_finite, require_range, Error, Result};
use crate::loft::loft_closed;
use crate::mesh::TriMesh;

/// Largest accepted bend between consecutive torque-tube segments (deg): larger bends would
/// fold the mitred joint onto itself.
pub const MAX_TUBE_BEND_DEG: f64 = 60.0;

/// A spar: a plate of constant thickness normal to the chord line at a chord fraction,
/// reaching from the lower to the upper skin, between two spanwise stations.
#[derive(Debug, Clone, PartialEq)]
pub struct SparSpec {
    /// Name (unique among the spars).
    pub name: String,
    /// Chord fraction of the plate's mid-plane, (0, 1).
    pub chord_fraction: f64,
    /// Plate thickness along the chord (m), > 0.
    pub thickness_m: f64,
    /// Inboard end y (m).
    pub y_start_m: f64,
    /// Outboard end y (m).
    pub y_end_m: f64,
}

/// A torque tube: a circular cylinder of `radius_m` along a polyline, mitred at the bends.
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueTubeSpec {
    /// Path points, aircraft frame (m); at least two, no repeats, bends <= [`MAX_TUBE_BEND_DEG`].
    pub path_ac: Vec<Point3<f64>>,
    /// Outer radius (m), > 0.
    pub radius_m: f64,
}

impl SparSpec {
    /// Checks finite values and ranges (the spanwise range against the wing is checked by
    /// [`crate::WingModel::try_new`]).
    pub fn validate(&self) -> Result<()> {
        require_range("spar chord_fraction", self.chord_fraction, 0.0, 1.0)?;
        require_range("spar thickness_m", self.thickness_m, f64::MIN_POSITIVE, f64::MAX)?;
        require_finite("spar y_start_m", self.y_start_m)?;
        require_finite("spar y_end_m", self.y_end_m)?;
        if self.y_end_m <= self.y_start_m {
            return Err(Error::OutOfRange {
                what: "spar y_end_m (must exceed y_start_m)",
                value: self.y_end_m,
                minimum: self.y_start_m,
                maximum: f64::MAX,
            });
        }
        Ok(())
    }

    /// Four-corner section of the plate in unit-chord section coordinates for a section of
    /// `chord_m` and shape `airfoil`: fore lower, aft lower, aft upper, fore upper.
    pub(crate) fn outline(&self, airfoil: &Airfoil, chord_m: f64) -> Result<Vec<Point2<f64>>> {
        let half = 0.5 * self.thickness_m / chord_m;
        let (fore, aft) = (self.chord_fraction - half, self.chord_fraction + half);
        require_range("spar plate chordwise extent (chord fraction)", fore, 0.0, 1.0)?;
        require_range("spar plate chordwise extent (chord fraction)", aft, 0.0, 1.0)?;
        Ok(vec![
            Point2::new(fore, airfoil.surface_y(fore, Surface::Lower)?),
            Point2::new(aft, airfoil.surface_y(aft, Surface::Lower)?),
            Point2::new(aft, airfoil.surface_y(aft, Surface::Upper)?),
            Point2::new(fore, airfoil.surface_y(fore, Surface::Upper)?),
        ])
    }
}

impl TorqueTubeSpec {
    /// Checks the path and radius.
    pub fn validate(&self) -> Result<()> {
        if self.path_ac.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "torque tube path",
                count: self.path_ac.len(),
                minimum: 2,
            });
        }
        for p in &self.path_ac {
            for v in p.iter() {
                require_finite("torque tube path coordinate (m)", *v)?;
            }
        }
        require_range("torque tube radius_m", self.radius_m, f64::MIN_POSITIVE, f64::MAX)?;
        let directions = self.directions()?;
        for (i, w) in directions.windows(2).enumerate() {
            let bend_deg = w[0].dot(&w[1]).clamp(-1.0, 1.0).acos().to_degrees();
            if bend_deg > MAX_TUBE_BEND_DEG {
                return Err(Error::TubePath {
                    index: i + 1,
                    bend_deg,
                    max_bend_deg: MAX_TUBE_BEND_DEG,
                });
            }
        }
        Ok(())
    }

    fn directions(&self) -> Result<Vec<Unit<Vector3<f64>>>> {
        self.path_ac
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                Unit::try_new(w[1] - w[0], 1e-12 * (1.0 + w[0].coords.norm())).ok_or(Error::TubePath {
                    index: i + 1,
                    bend_deg: 0.0,
                    max_bend_deg: MAX_TUBE_BEND_DEG,
                })
            })
            .collect()
    }

    /// Rings of `segments` points round the path: a circle at the start normal to the first
    /// segment, carried along each segment to the mitre (bisector) plane at each bend and to
    /// the end plane, so the tube is exactly a union of cylinders with mitred joints.
    /// Between mitres, rings are added so that no generator is longer than
    /// `max_ring_spacing_m`: the surface is the same, but collision queries prune far
    /// better on short triangles than on slivers as long as the tube.
    pub(crate) fn rings(&self, segments: usize, max_ring_spacing_m: f64) -> Result<Vec<Vec<Point3<f64>>>> {
        self.validate()?;
        let directions = self.directions()?;
        let first = directions[0];
        let helper = if first.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::z()
        };
        let e1 = first.cross(&helper).normalize();
        let e2 = first.cross(&e1);
        let mut ring: Vec<Point3<f64>> = (0..segments)
            .map(|i| {
                let angle = std::f64::consts::TAU * i as f64 / segments as f64;
                self.path_ac[0] + (e1 * angle.cos() + e2 * angle.sin()) * self.radius_m
            })
            .collect();
        let mut rings = vec![ring.clone()];
        for (k, direction) in directions.iter().enumerate() {
            let vertex = self.path_ac[k + 1];
            let plane_normal = match directions.get(k + 1) {
                Some(next) => (direction.into_inner() + next.into_inner()).normalize(),
                None => direction.into_inner(),
            };
            let next_ring: Vec<Point3<f64>> = ring
                .iter()
                .map(|p| {
                    let s = (vertex - p).dot(&plane_normal) / direction.dot(&plane_normal);
                    p + direction.into_inner() * s
                })
                .collect();
            let longest = ring
                .iter()
                .zip(&next_ring)
                .map(|(p, q)| (q - p).norm())
                .fold(0.0, f64::max);
            let pieces = (longest / max_ring_spacing_m).ceil().max(1.0) as usize;
            for j in 1..pieces {
                let f = j as f64 / pieces as f64;
                rings.push(ring.iter().zip(&next_ring).map(|(p, q)| p + (q - p) * f).collect());
            }
            ring = next_ring;
            rings.push(ring.clone());
        }
        Ok(rings)
    }
}

/// A closed round tube of `radius_m` along the polyline `path_ac` (bends up to
/// [`MAX_TUBE_BEND_DEG`] each, mitred), `segments` points round, rings at most
/// `max_ring_spacing_m` apart: the torque tube's loft, for any swept round solid (slot
/// tracks follow their arcs with it).
pub fn tube_mesh(path_ac: &[Point3<f64>], radius_m: f64, segments: usize, max_ring_spacing_m: f64) -> Result<TriMesh> {
    let spec = TorqueTubeSpec {
        path_ac: path_ac.to_vec(),
        radius_m,
    };
    loft_closed(&spec.rings(segments, max_ring_spacing_m)?, "tube")
}
