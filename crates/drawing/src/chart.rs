//! One small chart of a plot page: frame, grid, nice ticks, axis labels, series and a
//! legend where no curve runs (above the data when the data leave no such place).

use crate::plot::Plot;
use crate::style::{css_name, line, num, points_attribute, series_style, text, text_width, Anchor, INK};
use crate::ticks::{format_tick, padded_ticks, Ticks};
use svg::node::element::{Circle, Group, Polyline, Rectangle};

/// Width of one chart cell, px.
pub(crate) const CHART_WIDTH_PX: f64 = 560.0;
/// Height of one chart cell, px.
pub(crate) const CHART_HEIGHT_PX: f64 = 350.0;
/// Space left of the plot area (tick labels and y label), px.
const LEFT_PX: f64 = 78.0;
/// Space right of the plot area, px.
const RIGHT_PX: f64 = 18.0;
/// Space above the plot area (title), px.
const TOP_PX: f64 = 34.0;
/// Space below the plot area (tick labels and x label), px.
const BOTTOM_PX: f64 = 56.0;
/// Tick label font size, px.
const TICK_FONT_PX: f64 = 12.0;
/// Axis label font size, px.
const AXIS_FONT_PX: f64 = 13.0;
/// Legend font size, px.
const LEGEND_FONT_PX: f64 = 12.0;
/// Share of the data span added at each end of an axis.
const PAD_FRACTION: f64 = 0.04;
/// Wanted number of x tick intervals.
const X_TICKS: usize = 8;
/// Wanted number of y tick intervals.
const Y_TICKS: usize = 6;

/// Chart number `index` of `plot` with its cell's top-left corner at (`left`, `top`).
///
/// The plot must have been validated (finite series, one with points at least).
pub(crate) fn chart(index: usize, plot: &Plot, left: f64, top: f64) -> Group {
    let all = || plot.series.iter().flat_map(|s| s.points.iter());
    let (x_min, x_max) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (x, _)| {
        (lo.min(*x), hi.max(*x))
    });
    let (y_min, y_max) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (_, y)| {
        (lo.min(*y), hi.max(*y))
    });
    let (area_left, area_top) = (left + LEFT_PX, top + TOP_PX);
    let (area_width, area_height) = (
        CHART_WIDTH_PX - LEFT_PX - RIGHT_PX,
        CHART_HEIGHT_PX - TOP_PX - BOTTOM_PX,
    );
    let (area_right, area_bottom) = (area_left + area_width, area_top + area_height);
    let area = (area_left, area_top, area_right, area_bottom);
    let x_ticks = padded_ticks(x_min, x_max, X_TICKS, PAD_FRACTION);
    let page_map = |y_ticks: &Ticks| {
        let (x_ticks, y_ticks) = (x_ticks.clone(), y_ticks.clone());
        move |x: f64, y: f64| {
            (
                area_left + (x - x_ticks.axis_min) / (x_ticks.axis_max - x_ticks.axis_min) * area_width,
                area_top + (y_ticks.axis_max - y) / (y_ticks.axis_max - y_ticks.axis_min) * area_height,
            )
        }
    };
    let series_on_page = |to_page: &dyn Fn(f64, f64) -> (f64, f64)| -> Vec<Vec<(f64, f64)>> {
        plot.series
            .iter()
            .map(|s| s.points.iter().map(|(x, y)| to_page(*x, *y)).collect())
            .collect()
    };
    // The legend where no curve runs and no point lies; where the data leave no such
    // place, the y axis grows upward until the band above the data holds it.
    let legend_size = (plot.series.len() > 1).then(|| legend_size(plot));
    let mut y_ticks = padded_ticks(y_min, y_max, Y_TICKS, PAD_FRACTION);
    let mut legend_at = None;
    if let Some(size) = legend_size {
        legend_at = free_legend_place(&series_on_page(&page_map(&y_ticks)), area, size);
        if legend_at.is_none() {
            let band = size.1 + 2.0 * LEGEND_INSET_PX + 6.0;
            // The axis as drawn, grown so that its top `band` px lie above it (rounding
            // the ticks and padding only widen the axis: the band stays free).
            let span = y_ticks.axis_max - y_ticks.axis_min;
            let grown = y_ticks.axis_max + span * band / (area_height - band).max(1.0);
            y_ticks = padded_ticks(y_ticks.axis_min, grown, Y_TICKS, PAD_FRACTION);
            legend_at = free_legend_place(&series_on_page(&page_map(&y_ticks)), area, size);
        }
    }
    let to_page = page_map(&y_ticks);

    let mut group = Group::new()
        .set("id", format!("plot-{index}-{}", css_name(&plot.title)))
        .set("class", "plot")
        .add(text(&plot.title, area_left, top + 20.0, 15.0, Anchor::Start, INK).set("font-weight", "bold"));
    // Grid and ticks.
    for &value in &x_ticks.values {
        let (x, _) = to_page(value, y_ticks.axis_min);
        group = group
            .add(line(x, area_top, x, area_bottom, "#e3e3e3", 1.0))
            .add(line(x, area_bottom, x, area_bottom + 5.0, INK, 1.0))
            .add(text(
                &format_tick(value, x_ticks.step),
                x,
                area_bottom + 19.0,
                TICK_FONT_PX,
                Anchor::Middle,
                INK,
            ));
    }
    for &value in &y_ticks.values {
        let (_, y) = to_page(x_ticks.axis_min, value);
        group = group
            .add(line(area_left, y, area_right, y, "#e3e3e3", 1.0))
            .add(line(area_left - 5.0, y, area_left, y, INK, 1.0))
            .add(text(
                &format_tick(value, y_ticks.step),
                area_left - 8.0,
                y + 4.0,
                TICK_FONT_PX,
                Anchor::End,
                INK,
            ));
    }
    group = group.add(
        Rectangle::new()
            .set("x", num(area_left))
            .set("y", num(area_top))
            .set("width", num(area_width))
            .set("height", num(area_height))
            .set("fill", "none")
            .set("stroke", INK)
            .set("stroke-width", "1.2"),
    );
    // Axis labels.
    let x_label_y = area_bottom + 44.0;
    let y_label_x = left + 18.0;
    let y_label_y = area_top + 0.5 * area_height;
    group = group
        .add(
            text(
                &plot.x_label,
                area_left + 0.5 * area_width,
                x_label_y,
                AXIS_FONT_PX,
                Anchor::Middle,
                INK,
            )
            .set("class", "x-label"),
        )
        .add(
            text(&plot.y_label, y_label_x, y_label_y, AXIS_FONT_PX, Anchor::Middle, INK)
                .set("class", "y-label")
                .set(
                    "transform",
                    format!("rotate(-90 {} {})", num(y_label_x), num(y_label_y)),
                ),
        );
    // Series.
    let mut page_points: Vec<(f64, f64)> = Vec::new();
    for (s, series) in plot.series.iter().enumerate() {
        let (colour, dash) = series_style(s);
        // A legend entry only: nothing to draw.
        if series.points.is_empty() {
            continue;
        }
        let points: Vec<(f64, f64)> = series.points.iter().map(|(x, y)| to_page(*x, *y)).collect();
        page_points.extend(points.iter().copied());
        let mut series_group = Group::new().set("class", format!("series series-{s}"));
        if points.len() == 1 {
            series_group = series_group.add(
                Circle::new()
                    .set("cx", num(points[0].0))
                    .set("cy", num(points[0].1))
                    .set("r", "3.5")
                    .set("fill", colour),
            );
        } else {
            let mut polyline = Polyline::new()
                .set("points", points_attribute(&points))
                .set("fill", "none")
                .set("stroke", colour)
                .set("stroke-width", "2")
                .set("stroke-linejoin", "round");
            if let Some(dash) = dash {
                polyline = polyline.set("stroke-dasharray", dash);
            }
            series_group = series_group.add(polyline);
        }
        group = group.add(series_group);
    }
    if let Some(size) = legend_size {
        // No free place even above the data (a plot too small for its legend): the
        // least crowded corner.
        let at = legend_at.unwrap_or_else(|| least_crowded_corner(&page_points, area, size));
        group = group.add(legend(plot, at, size));
    }
    group
}

/// Inset of the legend box from the plot area's frame, px.
const LEGEND_INSET_PX: f64 = 6.0;
/// Clearance kept between the legend box and a curve or point, px.
const LEGEND_CLEARANCE_PX: f64 = 4.0;

/// The legend box's width and height, px.
fn legend_size(plot: &Plot) -> (f64, f64) {
    let widest = plot
        .series
        .iter()
        .map(|s| text_width(&s.name, LEGEND_FONT_PX))
        .fold(0.0, f64::max);
    (widest + 50.0, 18.0 * plot.series.len() as f64 + 8.0)
}

/// The legend's places in the plot area in the order they are preferred: the corners
/// (upper right first), then along the top and bottom edges, then along the sides.
fn legend_places(area: (f64, f64, f64, f64), (width, height): (f64, f64)) -> Vec<(f64, f64)> {
    let (area_left, area_top, area_right, area_bottom) = area;
    let (left, right) = (area_left + LEGEND_INSET_PX, area_right - LEGEND_INSET_PX - width);
    let (top, bottom) = (area_top + LEGEND_INSET_PX, area_bottom - LEGEND_INSET_PX - height);
    let mut places = vec![(right, top), (left, top), (right, bottom), (left, bottom)];
    for k in 1..8 {
        let x = right + (left - right) * f64::from(k) / 8.0;
        places.extend([(x, top), (x, bottom)]);
    }
    for k in 1..4 {
        let y = top + (bottom - top) * f64::from(k) / 4.0;
        places.extend([(right, y), (left, y)]);
    }
    places
}

/// The first of [`legend_places`] where the box (with [`LEGEND_CLEARANCE_PX`] round it)
/// holds no point of any series and no curve crosses it.
fn free_legend_place(series: &[Vec<(f64, f64)>], area: (f64, f64, f64, f64), size: (f64, f64)) -> Option<(f64, f64)> {
    legend_places(area, size).into_iter().find(|&(x, y)| {
        let c = LEGEND_CLEARANCE_PX;
        let (left, top, right, bottom) = (x - c, y - c, x + size.0 + c, y + size.1 + c);
        series.iter().all(|points| match points.as_slice() {
            [] => true,
            [only] => !inside(*only, (left, top, right, bottom)),
            _ => points
                .windows(2)
                .all(|pair| !segment_meets_box(pair[0], pair[1], (left, top, right, bottom))),
        })
    })
}

/// True when `p` lies in the box (left, top, right, bottom).
fn inside((x, y): (f64, f64), (left, top, right, bottom): (f64, f64, f64, f64)) -> bool {
    (left..=right).contains(&x) && (top..=bottom).contains(&y)
}

/// True when the segment a-b meets the box: an end inside it, or the segment crossing one
/// of its sides (clipped against the box's slabs, Liang-Barsky).
pub(crate) fn segment_meets_box(a: (f64, f64), b: (f64, f64), bounds: (f64, f64, f64, f64)) -> bool {
    let (left, top, right, bottom) = bounds;
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - left),
        (dx, right - a.0),
        (-dy, a.1 - top),
        (dy, bottom - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// The corner of the plot area whose legend box holds the fewest points.
fn least_crowded_corner(page_points: &[(f64, f64)], area: (f64, f64, f64, f64), size: (f64, f64)) -> (f64, f64) {
    let corners = &legend_places(area, size)[..4];
    let crowding = |(x, y): (f64, f64)| {
        page_points
            .iter()
            .filter(|p| inside(**p, (x - 4.0, y - 4.0, x + size.0 + 4.0, y + size.1 + 4.0)))
            .count()
    };
    corners
        .iter()
        .copied()
        .min_by_key(|c| crowding(*c))
        .unwrap_or(corners[0])
}

/// The legend box with its top-left corner at `at`.
fn legend(plot: &Plot, (x, y): (f64, f64), (box_width, box_height): (f64, f64)) -> Group {
    let mut group = Group::new().set("class", "legend").add(
        Rectangle::new()
            .set("x", num(x))
            .set("y", num(y))
            .set("width", num(box_width))
            .set("height", num(box_height))
            .set("fill", "white")
            .set("fill-opacity", "0.9")
            .set("stroke", "#999999")
            .set("stroke-width", "0.8"),
    );
    for (s, series) in plot.series.iter().enumerate() {
        let (colour, dash) = series_style(s);
        let row_y = y + 14.0 + 18.0 * s as f64;
        // A one-point series is drawn as a marker: its legend sample is one too.
        if series.points.len() == 1 {
            group = group.add(
                Circle::new()
                    .set("cx", num(x + 22.0))
                    .set("cy", num(row_y - 4.0))
                    .set("r", "3.5")
                    .set("fill", colour),
            );
        } else {
            let mut sample = line(x + 6.0, row_y - 4.0, x + 38.0, row_y - 4.0, colour, 2.0);
            if let Some(dash) = dash {
                sample = sample.set("stroke-dasharray", dash);
            }
            group = group.add(sample);
        }
        group = group.add(text(&series.name, x + 44.0, row_y, LEGEND_FONT_PX, Anchor::Start, INK));
    }
    group
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::Series;

    #[test]
    fn a_segment_meets_a_box_it_crosses_or_ends_in_and_no_other() {
        let unit = (0.0, 0.0, 10.0, 10.0);
        assert!(segment_meets_box((-5.0, 5.0), (15.0, 5.0), unit), "straight across");
        assert!(segment_meets_box((5.0, 5.0), (50.0, 50.0), unit), "from inside");
        assert!(segment_meets_box((-5.0, 12.0), (12.0, -5.0), unit), "across a corner");
        assert!(!segment_meets_box((-5.0, 4.0), (4.0, -5.0), unit), "past a corner");
        assert!(!segment_meets_box((-5.0, -5.0), (-1.0, 20.0), unit), "beside it");
        assert!(!segment_meets_box((12.0, 3.0), (12.0, 8.0), unit), "parallel to a side");
    }

    /// The number after `name="` in `text`, from `at` on.
    fn attribute(text: &str, at: usize, name: &str) -> f64 {
        let start = text[at..].find(&format!("{name}=\"")).unwrap() + at + name.len() + 2;
        let end = start + text[start..].find('"').unwrap();
        text[start..end].parse().unwrap()
    }

    /// Two curves zigzagging over the whole plot area leave no free place in it: the y axis
    /// grows until the legend fits above them, and no curve crosses the legend.
    #[test]
    fn a_legend_the_data_leave_no_room_for_goes_above_them() {
        let zigzag = |phase: f64| -> Vec<(f64, f64)> {
            (0..=40)
                .map(|i| (f64::from(i), ((f64::from(i) + phase) % 2.0).min(1.0)))
                .collect()
        };
        let plot = Plot {
            title: "crowded".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            series: vec![
                Series {
                    name: "first curve".into(),
                    points: zigzag(0.0),
                },
                Series {
                    name: "second curve".into(),
                    points: zigzag(1.0),
                },
            ],
        };
        let svg = chart(0, &plot, 0.0, 0.0).to_string();
        let legend = svg.find("class=\"legend\"").expect("a legend");
        let (x, y) = (attribute(&svg, legend, "x"), attribute(&svg, legend, "y"));
        let (width, height) = (attribute(&svg, legend, "width"), attribute(&svg, legend, "height"));
        let mut searched = 0;
        while let Some(at) = svg[searched..].find("points=\"") {
            let start = searched + at + 8;
            let end = start + svg[start..].find('"').unwrap();
            let points: Vec<(f64, f64)> = svg[start..end]
                .split_whitespace()
                .map(|p| {
                    let (px, py) = p.split_once(',').unwrap();
                    (px.parse().unwrap(), py.parse().unwrap())
                })
                .collect();
            for pair in points.windows(2) {
                assert!(
                    !segment_meets_box(pair[0], pair[1], (x, y, x + width, y + height)),
                    "a curve crosses the legend"
                );
            }
            searched = end;
        }
        assert!(
            y < TOP_PX + 2.0 * LEGEND_INSET_PX,
            "the legend sits at the top, above the data"
        );
    }
}
