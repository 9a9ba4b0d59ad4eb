//! Mapping from the station frame (m, y up) to the SVG page (px, y down) at one scale
//! for both axes.

use nalgebra::Point2;

/// Axis-aligned box in the station frame, metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bounds {
    /// Smallest x, m.
    pub min_x: f64,
    /// Smallest y, m.
    pub min_y: f64,
    /// Largest x, m.
    pub max_x: f64,
    /// Largest y, m.
    pub max_y: f64,
}

impl Bounds {
    /// The box around `points`, `None` when there are none.
    pub fn around<'a>(points: impl IntoIterator<Item = &'a Point2<f64>>) -> Option<Self> {
        points.into_iter().fold(None, |acc: Option<Bounds>, p| {
            Some(match acc {
                None => Bounds {
                    min_x: p.x,
                    min_y: p.y,
                    max_x: p.x,
                    max_y: p.y,
                },
                Some(b) => Bounds {
                    min_x: b.min_x.min(p.x),
                    min_y: b.min_y.min(p.y),
                    max_x: b.max_x.max(p.x),
                    max_y: b.max_y.max(p.y),
                },
            })
        })
    }

    /// Width, m.
    pub fn width(&self) -> f64 {
        self.max_x - self.min_x
    }

    /// Height, m.
    pub fn height(&self) -> f64 {
        self.max_y - self.min_y
    }

    /// The box grown by `margin` metres on every side.
    pub fn grown(&self, margin: f64) -> Self {
        Bounds {
            min_x: self.min_x - margin,
            min_y: self.min_y - margin,
            max_x: self.max_x + margin,
            max_y: self.max_y + margin,
        }
    }
}

/// Station frame -> page: `page = origin + scale * (x - min_x, max_y - y)`.
///
/// The nose (+x) is to the right and y up, as in the thesis figures; the viewer looks
/// from outboard (station z towards the viewer).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ScreenMap {
    /// The station-frame box shown.
    pub bounds: Bounds,
    /// Pixels per metre, both axes.
    pub px_per_m: f64,
    /// Page x of `bounds.min_x`.
    pub left_px: f64,
    /// Page y of `bounds.max_y`.
    pub top_px: f64,
}

impl ScreenMap {
    /// The largest equal-axis scale that fits `bounds` into `width_px` x `max_height_px`,
    /// centred horizontally, with its top at `top_px`.
    pub fn fit(bounds: Bounds, left_px: f64, top_px: f64, width_px: f64, max_height_px: f64) -> Self {
        let px_per_m = (width_px / bounds.width()).min(max_height_px / bounds.height());
        let used_width = bounds.width() * px_per_m;
        ScreenMap {
            bounds,
            px_per_m,
            left_px: left_px + 0.5 * (width_px - used_width),
            top_px,
        }
    }

    /// Page position of a station-frame point.
    pub fn page_point(&self, p: &Point2<f64>) -> (f64, f64) {
        (
            self.left_px + (p.x - self.bounds.min_x) * self.px_per_m,
            self.top_px + (self.bounds.max_y - p.y) * self.px_per_m,
        )
    }

    /// Page positions of several points.
    pub fn page_points(&self, points: &[Point2<f64>]) -> Vec<(f64, f64)> {
        points.iter().map(|p| self.page_point(p)).collect()
    }

    /// Height of the drawn box, px.
    pub fn height_px(&self) -> f64 {
        self.bounds.height() * self.px_per_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_scale_and_y_up() {
        let bounds = Bounds {
            min_x: -1.0,
            min_y: 0.0,
            max_x: 1.0,
            max_y: 0.5,
        };
        let map = ScreenMap::fit(bounds, 10.0, 20.0, 200.0, 1000.0);
        assert_eq!(map.px_per_m, 100.0);
        assert_eq!(map.page_point(&Point2::new(-1.0, 0.5)), (10.0, 20.0));
        assert_eq!(map.page_point(&Point2::new(1.0, 0.0)), (210.0, 70.0));
        // Height-limited: centred horizontally.
        let tall = ScreenMap::fit(bounds, 0.0, 0.0, 200.0, 25.0);
        assert_eq!(tall.px_per_m, 50.0);
        assert_eq!(tall.page_point(&Point2::new(-1.0, 0.5)), (50.0, 0.0));
    }
}
