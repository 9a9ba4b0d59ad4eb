//! Greedy label placement: each label takes the first candidate position around its
//! anchor whose box overlaps nothing placed before (labels, joint markers, lines), else
//! the candidate with the least weighted overlap. Labels and markers weigh
//! [`SOLID_WEIGHT`], lines [`LINE_WEIGHT`]: a label may cross a line (its white halo
//! keeps it readable) sooner than another label.

/// Cost weight of overlapping a label or a marker.
pub(crate) const SOLID_WEIGHT: f64 = 10.0;
/// Further cost weight of overlapping a placed label: a label takes any free place, then
/// any place over lines, markers or the frame's edge, before it covers another label.
const LABEL_WEIGHT: f64 = 1000.0;
/// Cost weight of overlapping a line.
pub(crate) const LINE_WEIGHT: f64 = 1.0;
/// Spacing of the obstacle boxes sampled along a line, px.
const LINE_SAMPLE_PX: f64 = 5.0;

/// Axis-aligned box on the page, px (y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PageBox {
    /// Left edge, px.
    pub left: f64,
    /// Top edge, px.
    pub top: f64,
    /// Right edge, px.
    pub right: f64,
    /// Bottom edge, px.
    pub bottom: f64,
}

impl PageBox {
    /// Box of half-size (`half_width`, `half_height`) around (`x`, `y`).
    pub fn centred(x: f64, y: f64, half_width: f64, half_height: f64) -> Self {
        PageBox {
            left: x - half_width,
            top: y - half_height,
            right: x + half_width,
            bottom: y + half_height,
        }
    }

    /// Area shared with `other`, px^2 (0 when apart).
    pub fn overlap(&self, other: &PageBox) -> f64 {
        let width = self.right.min(other.right) - self.left.max(other.left);
        let height = self.bottom.min(other.bottom) - self.top.max(other.top);
        if width > 0.0 && height > 0.0 {
            width * height
        } else {
            0.0
        }
    }

    /// The box as the `data-box` attribute of a label's text ("left top right bottom",
    /// px): readers of the drawing (the tests) check that no two labels overlap.
    pub fn attribute(&self) -> String {
        use crate::style::num;
        format!(
            "{} {} {} {}",
            num(self.left),
            num(self.top),
            num(self.right),
            num(self.bottom)
        )
    }

    /// Area outside `frame`, px^2.
    fn outside(&self, frame: &PageBox) -> f64 {
        let area = (self.right - self.left) * (self.bottom - self.top);
        area - self.overlap(frame)
    }
}

/// Boxes already taken on one page.
#[derive(Debug, Clone)]
pub(crate) struct LabelPlacer {
    taken: Vec<(PageBox, f64)>,
    /// The labels placed so far.
    labels: Vec<PageBox>,
    frame: PageBox,
}

impl LabelPlacer {
    /// An empty page; labels should stay inside `frame`.
    pub fn new(frame: PageBox) -> Self {
        LabelPlacer {
            taken: Vec::new(),
            labels: Vec::new(),
            frame,
        }
    }

    /// Marks `area` as taken (a marker, a legend) without placing a label.
    pub fn block(&mut self, area: PageBox) {
        self.taken.push((area, SOLID_WEIGHT));
    }

    /// Marks the page polyline `points` (closed when `closed`) as a light obstacle.
    pub fn block_line(&mut self, points: &[(f64, f64)], closed: bool) {
        let count = points.len();
        let segments = if closed { count } else { count.saturating_sub(1) };
        for i in 0..segments {
            let (x1, y1) = points[i];
            let (x2, y2) = points[(i + 1) % count];
            let length = ((x2 - x1).powi(2) + (y2 - y1).powi(2)).sqrt();
            let steps = (length / LINE_SAMPLE_PX).ceil().max(1.0) as usize;
            for k in 0..=steps {
                let t = k as f64 / steps as f64;
                let area = PageBox::centred(x1 + t * (x2 - x1), y1 + t * (y2 - y1), 1.5, 1.5);
                self.taken.push((area, LINE_WEIGHT));
            }
        }
    }

    /// Overlap of `candidate` with everything taken, plus a heavy charge for leaving
    /// the frame.
    pub fn cost(&self, candidate: &PageBox) -> f64 {
        let overlap: f64 = self.taken.iter().map(|(b, weight)| weight * b.overlap(candidate)).sum();
        let on_labels: f64 = self.labels.iter().map(|b| b.overlap(candidate)).sum();
        overlap + LABEL_WEIGHT * on_labels + 100.0 * candidate.outside(&self.frame)
    }

    /// Places a box of half-size (`half_width`, `half_height`) near (`x`, `y`): tries
    /// the 8 compass directions at growing distances and returns the centre chosen.
    pub fn place_near(&mut self, x: f64, y: f64, half_width: f64, half_height: f64, gap: f64) -> (f64, f64) {
        // Preferred order: upper right, right, upper left, left, up, down, lower right, lower left.
        const DIRECTIONS: [(f64, f64); 8] = [
            (1.0, -1.0),
            (1.0, 0.0),
            (-1.0, -1.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
        ];
        let candidates = [1.0, 2.0, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0, 28.0]
            .iter()
            .flat_map(|ring| {
                DIRECTIONS.iter().map(move |(dx, dy)| {
                    let distance = gap * ring;
                    (x + dx * (half_width + distance), y + dy * (half_height + distance))
                })
            });
        self.place_best(candidates, half_width, half_height).1
    }

    /// Places a box of the given half-size at the first of `candidates` (centres) that
    /// is free, or else at the one with the least overlap; returns the index of that
    /// candidate and its centre.
    pub fn place_best(
        &mut self,
        candidates: impl IntoIterator<Item = (f64, f64)>,
        half_width: f64,
        half_height: f64,
    ) -> (usize, (f64, f64)) {
        let mut best: Option<(usize, (f64, f64), f64)> = None;
        for (index, (cx, cy)) in candidates.into_iter().enumerate() {
            let candidate = PageBox::centred(cx, cy, half_width, half_height);
            let cost = self.cost(&candidate);
            if cost <= 0.0 {
                best = Some((index, (cx, cy), 0.0));
                break;
            }
            if best.is_none_or(|(_, _, c)| cost < c) {
                best = Some((index, (cx, cy), cost));
            }
        }
        let (index, (cx, cy), _) = best.unwrap_or((0, (self.frame.left, self.frame.top), 0.0));
        let placed = PageBox::centred(cx, cy, half_width, half_height);
        self.taken.push((placed, SOLID_WEIGHT));
        self.labels.push(placed);
        (index, (cx, cy))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn second_label_at_same_anchor_moves_away() {
        let frame = PageBox {
            left: 0.0,
            top: 0.0,
            right: 500.0,
            bottom: 500.0,
        };
        let mut placer = LabelPlacer::new(frame);
        let a = placer.place_near(250.0, 250.0, 10.0, 6.0, 4.0);
        let b = placer.place_near(250.0, 250.0, 10.0, 6.0, 4.0);
        let box_a = PageBox::centred(a.0, a.1, 10.0, 6.0);
        let box_b = PageBox::centred(b.0, b.1, 10.0, 6.0);
        assert_eq!(box_a.overlap(&box_b), 0.0);
    }

    #[test]
    fn labels_stay_in_frame_when_possible() {
        let frame = PageBox {
            left: 0.0,
            top: 0.0,
            right: 100.0,
            bottom: 100.0,
        };
        let mut placer = LabelPlacer::new(frame);
        // Anchor at the top-right corner: the upper-right candidate leaves the frame.
        let (x, y) = placer.place_near(98.0, 2.0, 10.0, 6.0, 4.0);
        let placed = PageBox::centred(x, y, 10.0, 6.0);
        assert!(placed.left >= 0.0 && placed.right <= 100.0 && placed.top >= 0.0);
    }
}
