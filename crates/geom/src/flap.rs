//! Trailing-edge flaps: spanwise extent, chord fraction, hinge axis and stowed section.
//!
//! Section coordinates here are the wing section's unit-chord (u aft, v up) coordinates
//! (see [`crate::wing`]). A flap at spanwise position y occupies u >= 1 - c_f(y), with the
//! flap chord fraction c_f varying linearly from the inboard to the outboard end. The main
//! wing keeps a closed cove: a straight wall at `u = (flap's foremost u) - COVE_GAP_CHORD_FRACTION`.

use nalgebra::{Point2, Point3, Rotation2, Unit, Vector2, Vector3};

use crate::airfoil::{Airfoil, Surface};
use crate::error::{require_finite, require_range, Error, Result};
use crate::wing::Wing;

/// Chordwise gap (fraction of the local wing chord) between the cove wall and the stowed flap.
pub const COVE_GAP_CHORD_FRACTION: f64 = 0.01;
/// Spanwise gap (fraction of the local wing chord) between each flap side and the wing.
pub const SIDE_GAP_CHORD_FRACTION: f64 = 0.005;
/// Smallest and largest accepted flap chord fraction.
pub const FLAP_CHORD_FRACTION_RANGE: (f64, f64) = (0.02, 0.8);
/// Shortest accepted hinge axis as a fraction of the flap span.
pub const MIN_HINGE_LENGTH_FRACTION: f64 = 1e-3;

/// How the flap rotation (hinge) axis is given.
#[derive(Debug, Clone, PartialEq)]
pub enum HingeSpec {
    /// Two points on the axis, aircraft frame (m), as in the thesis; the outboard one must
    /// lie further outboard (larger y).
    Points {
        /// Inboard point (m).
        inboard_ac: Point3<f64>,
        /// Outboard point (m).
        outboard_ac: Point3<f64>,
    },
    /// Through the section point at `chord_fraction` (from the wing leading edge) and
    /// `depth_below_chord_fraction` below the chord line (both fractions of the local
    /// chord) at each flap end.
    ChordFraction {
        /// Chordwise hinge position u_h (fraction of local chord).
        chord_fraction: f64,
        /// Hinge depth below the chord line (fraction of local chord, positive down).
        depth_below_chord_fraction: f64,
    },
}

/// Shape of the flap section.
#[derive(Debug, Clone, PartialEq)]
pub enum FlapSectionSpec {
    /// The wing section aft of u = 1 - c_f (flat front face); the main wing keeps a closed cove.
    CutOut,
    /// Its own section (e.g. NACA 63(1)-212 in the thesis, `000_...` Chapter 4), chord =
    /// c_f times the local wing chord, trailing edges coinciding, chord line pointing at the
    /// wing mean line at u = 1 - c_f, nested in the cove.
    OwnSection {
        /// Flap section, unit chord.
        airfoil: Airfoil,
    },
}

/// Everything that defines one flap.
#[derive(Debug, Clone, PartialEq)]
pub struct FlapSpec {
    /// Name (unique among the flaps).
    pub name: String,
    /// Inboard end of the cut-out, y (m).
    pub y_inboard_m: f64,
    /// Outboard end of the cut-out, y (m).
    pub y_outboard_m: f64,
    /// Flap chord fraction c_f at the inboard end.
    pub chord_fraction_inboard: f64,
    /// Flap chord fraction c_f at the outboard end.
    pub chord_fraction_outboard: f64,
    /// Rotation axis.
    pub hinge: HingeSpec,
    /// Section shape.
    pub section: FlapSectionSpec,
    /// Spanwise gap between each flap side and its cut-out (m); `None`:
    /// [`SIDE_GAP_CHORD_FRACTION`] of the local chord. A flap turning about a hinge line that
    /// is not perpendicular to its streamwise sides moves spanwise and needs more.
    pub side_gap_m: Option<f64>,
    /// How far (fraction of the local chord) the wing's upper skin reaches aft over the
    /// stowed flap's nose as a shroud; 0: no shroud, the cove is a straight wall (the
    /// flap's nose then sits behind the lip and a positive overlap is out of reach). The
    /// shroud stops short where its underside would come closer to the flap than
    /// [`SHROUD_CLEARANCE_CHORD_FRACTION`].
    pub shroud_chord_fraction: f64,
    /// The aft element of a two-element (double-slotted) flap, nested under the main
    /// element's trailing edge; None: a single-element flap.
    pub aft_element: Option<AftElementSpec>,
}

/// The aft element (second flap or vane) of a two-element flap. Its section is nested in
/// the flap's own section the way a flap is nested in the wing: trailing edges coinciding,
/// chord line pointing at the flap's mean line at `1 - chord_fraction` of the flap chord;
/// the main element is the flap's section cut by a cove wall ahead of it, with a shroud
/// over its nose. Both fractions are of the whole flap's chord.
#[derive(Debug, Clone, PartialEq)]
pub struct AftElementSpec {
    /// Aft element section, unit chord.
    pub airfoil: Airfoil,
    /// Aft element chord as a fraction of the flap chord.
    pub chord_fraction: f64,
    /// How far the main element's upper skin reaches aft over the aft element's nose
    /// (fraction of the flap chord); 0: a straight cove wall.
    pub shroud_chord_fraction: f64,
}

/// Smallest and largest accepted aft-element chord (fraction of the flap chord).
pub const AFT_ELEMENT_CHORD_FRACTION_RANGE: (f64, f64) = (0.1, 0.7);

/// A flap's stowed section split into its elements (wing-section unit-chord u, v), each a
/// closed polygon as [`Flap::stowed_outline`] gives one.
#[derive(Debug, Clone, PartialEq)]
pub struct FlapElementOutlines {
    /// The main element: the whole flap for a single-element flap.
    pub main: Vec<Point2<f64>>,
    /// The aft element of a two-element flap.
    pub aft: Option<Vec<Point2<f64>>>,
}

/// Skin thickness of a shroud at the cove wall (fraction of the local chord).
pub const SHROUD_THICKNESS_CHORD_FRACTION: f64 = 0.004;
/// Thickness of a shroud's trailing edge (fraction of the local chord): 0.5 mm at 1 m.
pub const SHROUD_TRAILING_EDGE_CHORD_FRACTION: f64 = 0.0005;
/// Smallest clearance between a shroud's underside and the stowed flap (fraction of the
/// local chord).
pub const SHROUD_CLEARANCE_CHORD_FRACTION: f64 = 0.003;
/// Largest shroud (fraction of the local chord).
pub const MAX_SHROUD_CHORD_FRACTION: f64 = 0.2;

/// A validated flap on a wing.
#[derive(Debug, Clone)]
pub struct Flap {
    spec: FlapSpec,
    hinge_point_ac: Point3<f64>,
    hinge_direction_ac: Unit<Vector3<f64>>,
}

impl Flap {
    /// Validates the flap against the wing and places its hinge axis.
    pub fn try_new(spec: FlapSpec, wing: &Wing) -> Result<Flap> {
        require_finite("flap y_inboard_m", spec.y_inboard_m)?;
        require_finite("flap y_outboard_m", spec.y_outboard_m)?;
        require_range(
            "flap shroud_chord_fraction",
            spec.shroud_chord_fraction,
            0.0,
            MAX_SHROUD_CHORD_FRACTION,
        )?;
        if let Some(gap) = spec.side_gap_m {
            let quarter_span = 0.25 * (spec.y_outboard_m - spec.y_inboard_m).abs();
            require_range("flap side_gap_m", gap, 0.0, quarter_span)?;
        }
        if spec.y_outboard_m <= spec.y_inboard_m {
            return Err(Error::FlapSpanConflict {
                flap: spec.name.clone(),
                other: spec.name.clone(),
                y_inboard_m: spec.y_inboard_m,
                y_outboard_m: spec.y_outboard_m,
            });
        }
        wing.locate(spec.y_inboard_m, &format!("flap {:?} inboard end", spec.name))?;
        wing.locate(spec.y_outboard_m, &format!("flap {:?} outboard end", spec.name))?;
        if let FlapSectionSpec::OwnSection { airfoil } = &spec.section {
            airfoil.validate()?;
        }
        if let Some(aft) = &spec.aft_element {
            if matches!(spec.section, FlapSectionSpec::CutOut) {
                return Err(Error::AftElementNeedsOwnSection {
                    flap: spec.name.clone(),
                });
            }
            aft.airfoil.validate()?;
            let (lo, hi) = AFT_ELEMENT_CHORD_FRACTION_RANGE;
            require_range("flap aft_element chord_fraction", aft.chord_fraction, lo, hi)?;
            require_range(
                "flap aft_element shroud_chord_fraction",
                aft.shroud_chord_fraction,
                0.0,
                MAX_SHROUD_CHORD_FRACTION,
            )?;
        }
        let (lo, hi) = FLAP_CHORD_FRACTION_RANGE;
        require_range("flap chord_fraction_inboard", spec.chord_fraction_inboard, lo, hi)?;
        require_range("flap chord_fraction_outboard", spec.chord_fraction_outboard, lo, hi)?;
        let (inboard_ac, outboard_ac) = match &spec.hinge {
            HingeSpec::Points {
                inboard_ac,
                outboard_ac,
            } => {
                for v in inboard_ac.iter().chain(outboard_ac.iter()) {
                    require_finite("flap hinge point coordinate (m)", *v)?;
                }
                (*inboard_ac, *outboard_ac)
            }
            HingeSpec::ChordFraction {
                chord_fraction,
                depth_below_chord_fraction,
            } => {
                require_range("flap hinge chord_fraction", *chord_fraction, -1.0, 2.0)?;
                require_range(
                    "flap hinge depth_below_chord_fraction",
                    *depth_below_chord_fraction,
                    -1.0,
                    1.0,
                )?;
                let at = |y: f64| -> Result<Point3<f64>> {
                    let section = wing.section_at(y)?;
                    Ok(wing.section_point_ac(&section, Point2::new(*chord_fraction, -depth_below_chord_fraction)))
                };
                (at(spec.y_inboard_m)?, at(spec.y_outboard_m)?)
            }
        };
        let axis = outboard_ac - inboard_ac;
        let span = spec.y_outboard_m - spec.y_inboard_m;
        if !(axis.norm() > MIN_HINGE_LENGTH_FRACTION * span && axis.y > 0.0) {
            return Err(Error::DegenerateHingeAxis {
                flap: spec.name.clone(),
                length_m: axis.norm(),
                spanwise_m: axis.y,
            });
        }
        Ok(Flap {
            hinge_point_ac: inboard_ac,
            hinge_direction_ac: Unit::new_normalize(axis),
            spec,
        })
    }

    /// The validated spec.
    pub fn spec(&self) -> &FlapSpec {
        &self.spec
    }

    /// The rotation axis: a point on it (the inboard axis point) and its unit direction,
    /// pointing outboard, aircraft frame.
    pub fn hinge_axis_ac(&self) -> (Point3<f64>, Unit<Vector3<f64>>) {
        (self.hinge_point_ac, self.hinge_direction_ac)
    }

    /// Flap chord fraction c_f at `y_m` (linear between the ends; clamped outside).
    pub fn chord_fraction_at(&self, y_m: f64) -> f64 {
        let s = &self.spec;
        let t = ((y_m - s.y_inboard_m) / (s.y_outboard_m - s.y_inboard_m)).clamp(0.0, 1.0);
        s.chord_fraction_inboard + (s.chord_fraction_outboard - s.chord_fraction_inboard) * t
    }

    /// Spanwise extent of the flap body itself (m): the cut-out less the side gaps.
    pub fn body_span_m(&self, wing: &Wing) -> Result<(f64, f64)> {
        let (_, chord_in, _) = wing.planform_at(self.spec.y_inboard_m)?;
        let (_, chord_out, _) = wing.planform_at(self.spec.y_outboard_m)?;
        let (gap_in, gap_out) = match self.spec.side_gap_m {
            Some(gap) => (gap, gap),
            None => (SIDE_GAP_CHORD_FRACTION * chord_in, SIDE_GAP_CHORD_FRACTION * chord_out),
        };
        Ok((self.spec.y_inboard_m + gap_in, self.spec.y_outboard_m - gap_out))
    }

    /// Stowed flap section outline at `y_m` as a closed polygon in wing-section unit-chord
    /// coordinates (u aft, v up), from the trailing edge along the upper side to the front
    /// and back along the lower side. `wing_airfoil` is the local wing section (already
    /// resampled to `points_per_side`).
    pub fn stowed_outline(&self, y_m: f64, wing_airfoil: &Airfoil, points_per_side: usize) -> Result<Vec<Point2<f64>>> {
        let chord_fraction = self.chord_fraction_at(y_m);
        let front_u = 1.0 - chord_fraction;
        match &self.spec.section {
            FlapSectionSpec::CutOut => {
                let upper = wing_airfoil.surface_line(Surface::Upper);
                let lower = wing_airfoil.surface_line(Surface::Lower);
                let front_upper = upper
                    .arc_at_x(front_u)
                    .ok_or_else(|| self.outline_error(wing_airfoil))?;
                let front_lower = lower
                    .arc_at_x(front_u)
                    .ok_or_else(|| self.outline_error(wing_airfoil))?;
                let mut outline: Vec<Point2<f64>> = upper
                    .sample_cosine(front_upper, upper.length(), points_per_side)
                    .into_iter()
                    .rev()
                    .collect();
                outline.extend(lower.sample_cosine(front_lower, lower.length(), points_per_side));
                Ok(outline)
            }
            FlapSectionSpec::OwnSection { airfoil } => {
                let flap = airfoil.resampled(points_per_side)?;
                let to_wing = NestedPlacement::new(wing_airfoil, chord_fraction)?;
                Ok(flap.points.iter().map(|p| to_wing.apply(p)).collect())
            }
        }
    }

    /// The stowed section at `y_m` split into its elements (wing-section unit-chord u, v):
    /// for a two-element flap, the main element cut at a cove ahead of the aft element, and
    /// the aft element nested under its trailing edge; otherwise the whole flap as the main
    /// element. Each element has the same point count at every y.
    pub fn element_outlines(
        &self,
        y_m: f64,
        wing_airfoil: &Airfoil,
        points_per_side: usize,
    ) -> Result<FlapElementOutlines> {
        let (Some(aft), FlapSectionSpec::OwnSection { airfoil }) = (&self.spec.aft_element, &self.spec.section) else {
            return Ok(FlapElementOutlines {
                main: self.stowed_outline(y_m, wing_airfoil, points_per_side)?,
                aft: None,
            });
        };
        let flap = airfoil.resampled(points_per_side)?;
        let aft_airfoil = aft.airfoil.resampled(points_per_side)?;
        let in_flap = NestedPlacement::new(&flap, aft.chord_fraction)?;
        let aft_in_flap: Vec<Point2<f64>> = aft_airfoil.points.iter().map(|p| in_flap.apply(p)).collect();
        let main_in_flap = cut_host_outline(&flap, &aft_in_flap, aft.shroud_chord_fraction, points_per_side)?;
        let to_wing = NestedPlacement::new(wing_airfoil, self.chord_fraction_at(y_m))?;
        Ok(FlapElementOutlines {
            main: main_in_flap.iter().map(|p| to_wing.apply(p)).collect(),
            aft: Some(aft_in_flap.iter().map(|p| to_wing.apply(p)).collect()),
        })
    }

    fn outline_error(&self, airfoil: &Airfoil) -> Error {
        Error::BadAirfoil {
            name: airfoil.name.clone(),
            reason: "flap cut-out station lies outside the wing section",
        }
    }
}

/// Where an element with its own section sits nested in its host (the flap in the wing, the
/// aft element in the flap): trailing edges coinciding, its chord (a `chord_fraction` of
/// the host's) pointing at the host's mean line at `1 - chord_fraction`. Maps the element's
/// unit-chord points (x from its leading edge) to the host's.
struct NestedPlacement {
    trailing_edge: Point2<f64>,
    rotation: Rotation2<f64>,
    chord_fraction: f64,
}

impl NestedPlacement {
    fn new(host: &Airfoil, chord_fraction: f64) -> Result<Self> {
        let trailing_edge = host.trailing_edge_midpoint();
        let front_u = 1.0 - chord_fraction;
        let front = Point2::new(front_u, host.mean_line_y(front_u)?);
        let direction: Vector2<f64> = (trailing_edge - front).normalize();
        Ok(Self {
            trailing_edge,
            rotation: Rotation2::new(direction.y.atan2(direction.x)),
            chord_fraction,
        })
    }

    /// The element's x = 1 sits on the host's trailing edge.
    fn apply(&self, p: &Point2<f64>) -> Point2<f64> {
        self.trailing_edge + self.rotation * (Vector2::new(p.x - 1.0, p.y) * self.chord_fraction)
    }
}

/// The main wing's section outline where `flap` cuts it at `y_m` (unit-chord u, v): the
/// airfoil back to the cove wall at the flap's foremost point less the cove gap, and, with a
/// shroud, the upper skin on aft over the flap's nose and its underside back to the wall.
/// Same point count at every y of one flap (the loft joins stations point by point).
pub(crate) fn cut_wing_outline(
    flap: &Flap,
    y_m: f64,
    airfoil: &Airfoil,
    points_per_side: usize,
) -> Result<Vec<Point2<f64>>> {
    let flap_outline = flap.stowed_outline(y_m, airfoil, points_per_side)?;
    cut_host_outline(airfoil, &flap_outline, flap.spec.shroud_chord_fraction, points_per_side)
}

/// A host section (`airfoil`, unit chord) cut for the element nested in it (`nested`, in
/// the host's coordinates): the airfoil back to a cove wall at the element's foremost point
/// less [`COVE_GAP_CHORD_FRACTION`], and, with a shroud of `fraction` of the host chord, the
/// upper skin on aft over the element's nose and its underside back to the wall. The wing
/// is cut so for its flap, a two-element flap's main element for its aft element.
fn cut_host_outline(
    airfoil: &Airfoil,
    nested: &[Point2<f64>],
    fraction: f64,
    points_per_side: usize,
) -> Result<Vec<Point2<f64>>> {
    let cove_u = cove_chord_fraction(nested);
    if fraction <= 0.0 {
        return crate::mesher::truncated_outline(airfoil, cove_u, points_per_side);
    }
    let front_u = cove_u + COVE_GAP_CHORD_FRACTION;
    // The skin tapers from its thickness at the cove wall to a thin trailing edge at the
    // tip, as a shroud's does: the lip is then one point, from which the gap is measured
    // (a blunt lip would leave the flap closer to its lower corner than the gap says).
    let thickness_at = |u: f64, tip: f64| {
        let along = ((u - cove_u) / (tip - cove_u)).clamp(0.0, 1.0);
        SHROUD_THICKNESS_CHORD_FRACTION
            + (SHROUD_TRAILING_EDGE_CHORD_FRACTION - SHROUD_THICKNESS_CHORD_FRACTION) * along
    };
    // The nested element's top at u: the highest crossing of its outline.
    let nested_top = |u: f64| {
        nested
            .iter()
            .zip(nested.iter().cycle().skip(1))
            .filter(|(a, b)| (a.x - u) * (b.x - u) <= 0.0 && a.x != b.x)
            .map(|(a, b)| a.y + (u - a.x) / (b.x - a.x) * (b.y - a.y))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let clear_to = |tip: f64| -> Result<bool> {
        for k in 0..=32 {
            let u = front_u + (tip - front_u) * k as f64 / 32.0;
            let underside = airfoil.surface_y(u, Surface::Upper)? - thickness_at(u, tip);
            if underside - nested_top(u) < SHROUD_CLEARANCE_CHORD_FRACTION {
                return Ok(false);
            }
        }
        Ok(true)
    };
    // The longest shroud up to the asked length that clears the flap, to 1e-4 chord.
    let mut tip = front_u + fraction;
    if !clear_to(tip)? {
        let (mut lo, mut hi) = (cove_u, tip);
        while hi - lo > 1e-4 {
            let mid = 0.5 * (lo + hi);
            if clear_to(mid)? {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        tip = lo;
    }
    // No length clears (the nested section reaches the host's upper skin at its nose): the
    // shroud's underside would stand on the cove wall and fold the outline onto itself.
    if tip <= front_u {
        return Err(Error::BadAirfoil {
            name: airfoil.name.clone(),
            reason: "no shroud clears the nested flap's nose (its section reaches the upper skin there): give the flap a thinner section, or no shroud",
        });
    }
    let upper = airfoil.surface_line(Surface::Upper);
    let lower = airfoil.surface_line(Surface::Lower);
    let bad = || Error::BadAirfoil {
        name: airfoil.name.clone(),
        reason: "flap shroud lies outside the wing section",
    };
    let s_tip = upper.arc_at_x(tip).ok_or_else(bad)?;
    let s_cove = lower.arc_at_x(cove_u).ok_or_else(bad)?;
    let mut outline: Vec<Point2<f64>> = upper
        .sample_cosine(0.0, s_tip, points_per_side)
        .into_iter()
        .rev()
        .collect();
    outline.extend(lower.sample_cosine(0.0, s_cove, points_per_side).into_iter().skip(1));
    // Up the cove wall, then aft along the shroud's underside to below its tip.
    let under = SHROUD_UNDERSIDE_POINTS;
    for k in 0..under {
        let u = cove_u + (tip - cove_u) * k as f64 / (under - 1) as f64;
        outline.push(Point2::new(
            u,
            airfoil.surface_y(u, Surface::Upper)? - thickness_at(u, tip),
        ));
    }
    Ok(outline)
}

/// Points along a shroud's underside.
const SHROUD_UNDERSIDE_POINTS: usize = 12;

/// Chord fraction of the cove wall for a stowed flap outline: its foremost u less the gap.
pub(crate) fn cove_chord_fraction(outline: &[Point2<f64>]) -> f64 {
    outline.iter().fold(f64::INFINITY, |m, p| m.min(p.x)) - COVE_GAP_CHORD_FRACTION
}
