//! A section's polygons with their edges filed by x and by y, for the queries the
//! synthesis searches make millions of times: a vertical line, a horizontal ray or a short
//! segment meets only the edges filed where it lies, not the few hundred of a section.
//!
//! Each query applies the same per-edge test as the plain functions of the parent module
//! to a subset of the edges that holds every edge the test can pass, so the answers are
//! the same to the bit (the module's tests compare them).

use std::ops::{Deref, Range};
use std::sync::OnceLock;

use nalgebra::Point2;
use serde::{Serialize, Serializer};

use super::{crossing_at, edge_nearer_than, edge_segment_distance, ray_crosses, segments_cross};

/// Closed polygons (last point not repeated), with an index of their edges built on the
/// first query. Reads as the plain polygons (`Deref`), which the index does not change.
#[derive(Default, Clone)]
pub struct Polygons {
    rings: Vec<Vec<Point2<f64>>>,
    index: OnceLock<EdgeIndex>,
}

impl From<Vec<Vec<Point2<f64>>>> for Polygons {
    fn from(rings: Vec<Vec<Point2<f64>>>) -> Self {
        Self {
            rings,
            index: OnceLock::new(),
        }
    }
}

impl Deref for Polygons {
    type Target = [Vec<Point2<f64>>];
    fn deref(&self) -> &Self::Target {
        &self.rings
    }
}

impl PartialEq for Polygons {
    fn eq(&self, other: &Self) -> bool {
        self.rings == other.rings
    }
}

impl std::fmt::Debug for Polygons {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.rings.fmt(f)
    }
}

impl Serialize for Polygons {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.rings.serialize(serializer)
    }
}

impl Polygons {
    fn index(&self) -> &EdgeIndex {
        self.index.get_or_init(|| EdgeIndex::of(&self.rings))
    }

    /// True when `p` lies inside (even-odd rule), as [`super::inside`].
    pub fn inside(&self, p: Point2<f64>) -> bool {
        let index = self.index();
        let crossings = index
            .at(&index.by_y, p.y)
            .filter(|&(a, b)| ray_crosses(p, a, b))
            .count();
        crossings % 2 == 1
    }

    /// Lowest and highest y where the vertical line at `x` crosses the polygons, as
    /// [`super::vertical_span`].
    pub fn vertical_span(&self, x: f64) -> Option<(f64, f64)> {
        let index = self.index();
        index
            .at(&index.by_x, x)
            .filter_map(|(a, b)| crossing_at(a, b, x))
            .fold(None, |span, y| {
                Some(span.map_or((y, y), |(lo, hi): (f64, f64)| (lo.min(y), hi.max(y))))
            })
    }

    /// True when the segment `a`-`b` crosses an edge or lies inside, as
    /// [`super::segment_meets`].
    pub fn segment_meets(&self, a: Point2<f64>, b: Point2<f64>) -> bool {
        let index = self.index();
        index.any_within(&index.by_x, a.x.min(b.x), a.x.max(b.x), |c, d| {
            segments_cross(a, b, c, d)
        }) || self.inside(a)
            || self.inside(b)
    }

    /// True when the segment `a`-`b` stays farther than `reach` from the polygons, as
    /// `super::segment_distance(..) > reach`: only the edges filed where the segment's x
    /// extent widened by `reach` lies can come that near, and of those an edge whose box is
    /// already farther than `reach` from the segment's is let go before its distance.
    pub fn segment_clear_by(&self, a: Point2<f64>, b: Point2<f64>, reach: f64) -> bool {
        let finite = |p: Point2<f64>| p.x.is_finite() && p.y.is_finite();
        if self.rings.is_empty() || !reach.is_finite() || !finite(a) || !finite(b) {
            return super::segment_distance(&self.rings, a, b) > reach;
        }
        if self.segment_meets(a, b) {
            return 0.0 > reach;
        }
        let (low, high) = (a.inf(&b), a.sup(&b));
        let index = self.index();
        !index.any_within(&index.by_x, low.x - reach, high.x + reach, |c, d| {
            let off_x = (c.x.min(d.x) - high.x).max(low.x - c.x.max(d.x));
            let off_y = (c.y.min(d.y) - high.y).max(low.y - c.y.max(d.y));
            off_x <= reach && off_y <= reach && edge_segment_distance(c, d, a, b) <= reach
        })
    }

    /// True when an edge passes nearer than `near` to `p` (never for `near` <= 0).
    pub fn nearer_than(&self, p: Point2<f64>, near: f64) -> bool {
        if near.is_nan() || near <= 0.0 {
            return false;
        }
        let index = self.index();
        index.any_within(&index.by_x, p.x - near, p.x + near, |a, b| {
            edge_nearer_than(p, a, b, near)
        })
    }
}

/// The edges, and for each of a row of equal slots along an axis the edges whose extent
/// along it reaches into the slot.
#[derive(Debug, Clone)]
struct EdgeIndex {
    edges: Vec<(Point2<f64>, Point2<f64>)>,
    by_x: Slots,
    by_y: Slots,
}

#[derive(Debug, Clone)]
struct Slots {
    low: f64,
    width: f64,
    filed: Vec<Vec<u32>>,
}

impl Slots {
    /// Slots over the edges' extent along `along`, about four edges a slot.
    fn of(edges: &[(Point2<f64>, Point2<f64>)], along: impl Fn(Point2<f64>) -> f64) -> Slots {
        let (low, high) = edges
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (a, b)| {
                (lo.min(along(*a)).min(along(*b)), hi.max(along(*a)).max(along(*b)))
            });
        let count = (edges.len() / 4).clamp(1, 1024);
        let width = if high > low { (high - low) / count as f64 } else { 1.0 };
        let mut slots = Slots {
            low: if low.is_finite() { low } else { 0.0 },
            width,
            filed: vec![Vec::new(); count],
        };
        for (k, (a, b)) in edges.iter().enumerate() {
            let (from, to) = (along(*a).min(along(*b)), along(*a).max(along(*b)));
            for slot in slots.spanning(from, to) {
                slots.filed[slot].push(k as u32);
            }
        }
        slots
    }

    /// The slots that `[from, to]` reaches into; a value outside the row falls in its end
    /// slot, where no edge it could meet is missing (none reaches past the ends).
    fn spanning(&self, from: f64, to: f64) -> Range<usize> {
        let last = self.filed.len() - 1;
        let slot = |v: f64| {
            let k = ((v - self.low) / self.width).floor();
            if k.is_nan() || k <= 0.0 {
                0
            } else {
                (k as usize).min(last)
            }
        };
        let (first, end) = (slot(from), slot(to));
        first.min(end)..first.max(end) + 1
    }
}

impl EdgeIndex {
    fn of(rings: &[Vec<Point2<f64>>]) -> EdgeIndex {
        // In the plain functions' order: each polygon's closing edge first.
        let edges: Vec<(Point2<f64>, Point2<f64>)> = rings
            .iter()
            .flat_map(|ring| {
                ring.last()
                    .into_iter()
                    .chain(ring.iter())
                    .zip(ring.iter())
                    .map(|(a, b)| (*a, *b))
            })
            .collect();
        EdgeIndex {
            by_x: Slots::of(&edges, |p| p.x),
            by_y: Slots::of(&edges, |p| p.y),
            edges,
        }
    }

    /// The edges filed in the slot of `slots` where `v` lies.
    fn at<'a>(&'a self, slots: &'a Slots, v: f64) -> impl Iterator<Item = (Point2<f64>, Point2<f64>)> + 'a {
        let slot = slots.spanning(v, v).start;
        slots.filed[slot].iter().map(move |&k| self.edges[k as usize])
    }

    /// True when `test` holds for an edge filed in a slot of `slots` that `[from, to]`
    /// reaches into (an edge in several of them may be tested more than once).
    fn any_within(
        &self,
        slots: &Slots,
        from: f64,
        to: f64,
        mut test: impl FnMut(Point2<f64>, Point2<f64>) -> bool,
    ) -> bool {
        slots.filed[slots.spanning(from, to)].iter().flatten().any(|&k| {
            let (a, b) = self.edges[k as usize];
            test(a, b)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::{any_edge, boundary_distance, inside, segment_meets, vertical_span};
    use super::*;
    use proptest::prelude::*;

    /// Points on a quarter grid, so that queries land on vertices, on edges and on the
    /// slots' boundaries exactly.
    fn grid_point() -> impl Strategy<Value = Point2<f64>> {
        (-12i32..12, -12i32..12).prop_map(|(x, y)| Point2::new(x as f64 / 4.0, y as f64 / 4.0))
    }

    fn rings() -> impl Strategy<Value = Vec<Vec<Point2<f64>>>> {
        prop::collection::vec(prop::collection::vec(grid_point(), 0..40), 0..4)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// Every indexed query gives the plain function's answer, to the bit.
        #[test]
        fn indexed_queries_answer_as_the_plain_ones(
            rings in rings(),
            p in grid_point(),
            q in grid_point(),
            jitter in -0.3..0.3_f64,
            near in 0.0..2.0_f64,
        ) {
            let polygons = Polygons::from(rings.clone());
            for point in [p, Point2::new(p.x + jitter, p.y - jitter)] {
                prop_assert_eq!(polygons.inside(point), inside(&rings, point));
                prop_assert_eq!(polygons.vertical_span(point.x), vertical_span(&rings, point.x));
                prop_assert_eq!(polygons.segment_meets(point, q), segment_meets(&rings, point, q));
                prop_assert_eq!(polygons.segment_meets(point, point), segment_meets(&rings, point, point));
                let plain_near = any_edge(&rings, |a, b| edge_nearer_than(point, a, b, near));
                prop_assert_eq!(polygons.nearer_than(point, near), plain_near);
                let reach = near - 0.5;
                prop_assert_eq!(
                    polygons.segment_clear_by(point, q, reach),
                    super::super::segment_distance(&rings, point, q) > reach
                );
                let nearest = boundary_distance(&rings, point);
                if (nearest - near).abs() > 1e-9 {
                    prop_assert_eq!(plain_near, nearest < near);
                }
            }
        }
    }

    /// A segment with a coordinate that is not a number is measured as the plain test
    /// measures it (from its other end), not let through by a box of NaN.
    #[test]
    fn a_segment_with_a_nan_end_is_measured_as_the_plain_test_does() {
        let square = vec![vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
        ]];
        let polygons = Polygons::from(square.clone());
        let (a, b) = (Point2::new(1.1, 0.5), Point2::new(f64::NAN, 0.5));
        for (p, q) in [(a, b), (b, a)] {
            for reach in [0.05, 0.2] {
                assert_eq!(
                    polygons.segment_clear_by(p, q, reach),
                    super::super::segment_distance(&square, p, q) > reach
                );
            }
        }
    }

    #[test]
    fn empty_and_degenerate_polygons_answer_nothing() {
        let empty = Polygons::default();
        let origin = Point2::new(0.0, 0.0);
        assert!(!empty.inside(origin));
        assert_eq!(empty.vertical_span(0.0), None);
        assert!(!empty.segment_meets(origin, Point2::new(1.0, 1.0)));
        assert!(!empty.nearer_than(origin, 1.0));
        // A vertical sliver: every edge at x = 1, no width to file them by.
        let sliver = Polygons::from(vec![vec![
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(1.0, 1.0),
        ]]);
        assert!(!sliver.inside(Point2::new(1.0, 0.5)));
        assert!(sliver.segment_meets(Point2::new(0.0, 0.5), Point2::new(2.0, 0.5)));
        assert!(sliver.nearer_than(Point2::new(1.5, 0.5), 0.6));
        assert!(!sliver.nearer_than(Point2::new(1.5, 0.5), 0.4));
        assert!(!sliver.nearer_than(Point2::new(1.0, 0.5), 0.0));
    }
}
