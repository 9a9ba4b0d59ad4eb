//! One small chart of a plot page: frame, grid, nice ticks, axis labels, series and a
//! legend placed in the emptiest corner.

use crate::plot::Plot;
use crate::style::{css_name, line, num, points_attribute, series_style, text, text_width, Anchor, INK};
use crate::ticks::{format_tick, padded_ticks};
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
    let x_ticks = padded_ticks(x_min, x_max, X_TICKS, PAD_FRACTION);
    let y_ticks = padded_ticks(y_min, y_max, Y_TICKS, PAD_FRACTION);
    let (area_left, area_top) = (left + LEFT_PX, top + TOP_PX);
    let (area_width, area_height) = (
        CHART_WIDTH_PX - LEFT_PX - RIGHT_PX,
        CHART_HEIGHT_PX - TOP_PX - BOTTOM_PX,
    );
    let to_page = |x: f64, y: f64| {
        (
            area_left + (x - x_ticks.axis_min) / (x_ticks.axis_max - x_ticks.axis_min) * area_width,
            area_top + (y_ticks.axis_max - y) / (y_ticks.axis_max - y_ticks.axis_min) * area_height,
        )
    };
    let (area_right, area_bottom) = (area_left + area_width, area_top + area_height);

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
    if plot.series.len() > 1 {
        group = group.add(legend(
            plot,
            &page_points,
            (area_left, area_top, area_right, area_bottom),
        ));
    }
    group
}

/// Legend box in the corner of the plot area holding the fewest data points.
fn legend(plot: &Plot, page_points: &[(f64, f64)], area: (f64, f64, f64, f64)) -> Group {
    let (area_left, area_top, area_right, area_bottom) = area;
    let widest = plot
        .series
        .iter()
        .map(|s| text_width(&s.name, LEGEND_FONT_PX))
        .fold(0.0, f64::max);
    let (box_width, box_height) = (widest + 50.0, 18.0 * plot.series.len() as f64 + 8.0);
    let inset = 6.0;
    let corners = [
        (area_right - inset - box_width, area_top + inset),
        (area_left + inset, area_top + inset),
        (area_right - inset - box_width, area_bottom - inset - box_height),
        (area_left + inset, area_bottom - inset - box_height),
    ];
    let crowding = |(x, y): (f64, f64)| {
        page_points
            .iter()
            .filter(|(px, py)| {
                *px >= x - 4.0 && *px <= x + box_width + 4.0 && *py >= y - 4.0 && *py <= y + box_height + 4.0
            })
            .count()
    };
    let (x, y) = corners
        .iter()
        .copied()
        .min_by_key(|c| crowding(*c))
        .unwrap_or(corners[0]);
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
