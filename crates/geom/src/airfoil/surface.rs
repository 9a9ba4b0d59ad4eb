//! One side of an airfoil as an arc-length parameterised polyline (leading edge to trailing edge).

use nalgebra::Point2;

/// A polyline with cumulative arc length, unit-chord airfoil coordinates.
#[derive(Debug, Clone)]
pub(crate) struct SurfaceLine {
    points: Vec<Point2<f64>>,
    cumulative: Vec<f64>,
}

impl SurfaceLine {
    /// Builds from at least two points (leading edge first).
    pub(crate) fn new(points: Vec<Point2<f64>>) -> Self {
        let mut cumulative = Vec::with_capacity(points.len());
        let mut total = 0.0;
        cumulative.push(0.0);
        for w in points.windows(2) {
            total += (w[1] - w[0]).norm();
            cumulative.push(total);
        }
        Self { points, cumulative }
    }

    /// Total arc length.
    pub(crate) fn length(&self) -> f64 {
        *self.cumulative.last().unwrap_or(&0.0)
    }

    /// Point at arc length `s` (clamped to the line).
    pub(crate) fn point_at_arc(&self, s: f64) -> Point2<f64> {
        let s = s.clamp(0.0, self.length());
        let i = self
            .cumulative
            .partition_point(|&c| c <= s)
            .clamp(1, self.points.len() - 1);
        let (s0, s1) = (self.cumulative[i - 1], self.cumulative[i]);
        let t = if s1 > s0 { (s - s0) / (s1 - s0) } else { 0.0 };
        self.points[i - 1] + (self.points[i] - self.points[i - 1]) * t
    }

    /// Arc length where the line first reaches abscissa `x` (walking from the leading edge),
    /// `None` when it never does.
    pub(crate) fn arc_at_x(&self, x: f64) -> Option<f64> {
        for (i, w) in self.points.windows(2).enumerate() {
            let (x0, x1) = (w[0].x, w[1].x);
            if (x0 - x).abs() <= 0.0 {
                return Some(self.cumulative[i]);
            }
            if (x0 < x && x <= x1) || (x1 <= x && x < x0) {
                let t = (x - x0) / (x1 - x0);
                return Some(self.cumulative[i] + t * (self.cumulative[i + 1] - self.cumulative[i]));
            }
        }
        None
    }

    /// `count` points between arc lengths `s_start` and `s_end` with cosine spacing
    /// `s_i = s_start + (s_end - s_start) (1 - cos(pi i / (count - 1))) / 2` (both ends included).
    pub(crate) fn sample_cosine(&self, s_start: f64, s_end: f64, count: usize) -> Vec<Point2<f64>> {
        (0..count)
            .map(|i| {
                let beta = std::f64::consts::PI * i as f64 / (count - 1) as f64;
                let s = s_start + (s_end - s_start) * 0.5 * (1.0 - beta.cos());
                if i == 0 {
                    self.point_at_arc(s_start)
                } else if i + 1 == count {
                    self.point_at_arc(s_end)
                } else {
                    self.point_at_arc(s)
                }
            })
            .collect()
    }
}
