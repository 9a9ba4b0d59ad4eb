//! Plots against the deployment input: data types, checks and the page grid
//! (`render_plots_svg`). One chart is drawn by `chart`.

use crate::chart::{chart, CHART_HEIGHT_PX, CHART_WIDTH_PX};
use crate::error::{Error, Result};
use crate::style::{num, text, Anchor, FONT_FAMILY, INK};
use svg::node::element::Rectangle;
use svg::Document;

/// One named line of (x, y) samples, in the units of its plot's axis labels.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Name shown in the legend (when the plot has more than one series).
    pub name: String,
    /// Samples in drawing order; every value must be finite. None: a legend entry only (a
    /// series that has nothing to show, e.g. a study's kind that failed, keeps its style
    /// and its place in the legend), if another series of the plot has points.
    pub points: Vec<(f64, f64)>,
}

/// One small chart: title, axis labels (with units, e.g. `"nut travel s34 [mm]"`) and
/// series.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    /// Chart title.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// The lines; at least one with at least one point. Each takes its colour and dash by
    /// its place in this list, so a series that keeps its place keeps its style.
    pub series: Vec<Series>,
}

/// Number of chart columns on a plot page.
pub const PLOT_COLUMNS: usize = 2;
/// Page margin, px.
const MARGIN_PX: f64 = 20.0;
/// Height of the page header, px.
const HEADER_PX: f64 = 56.0;
/// Space between charts, px.
const GAP_PX: f64 = 20.0;

/// Checks one plot: has series, one with points at least, all finite.
fn validate_plot(plot: &Plot) -> Result<()> {
    if plot.series.is_empty() {
        return Err(Error::NoSeries {
            plot: plot.title.clone(),
        });
    }
    if plot.series.iter().all(|series| series.points.is_empty()) {
        return Err(Error::EmptySeries {
            plot: plot.title.clone(),
            series: plot.series[0].name.clone(),
        });
    }
    for series in &plot.series {
        if let Some(index) = series
            .points
            .iter()
            .position(|(x, y)| !(x.is_finite() && y.is_finite()))
        {
            let (x, y) = series.points[index];
            return Err(Error::NonFiniteSample {
                plot: plot.title.clone(),
                series: series.name.clone(),
                index,
                x,
                y,
            });
        }
    }
    Ok(())
}

/// Page size (width, height) in px of a grid of `count` charts.
pub fn plots_page_size_px(count: usize) -> (f64, f64) {
    let rows = count.div_ceil(PLOT_COLUMNS).max(1) as f64;
    let width = 2.0 * MARGIN_PX + PLOT_COLUMNS as f64 * CHART_WIDTH_PX + (PLOT_COLUMNS as f64 - 1.0) * GAP_PX;
    let height = HEADER_PX + rows * CHART_HEIGHT_PX + (rows - 1.0) * GAP_PX + MARGIN_PX;
    (width, height)
}

/// Renders `plots` as a grid of small charts, two per row, under `title`.
///
/// Each chart has ticks at round numbers (steps 1, 2 or 5 x 10^k), tick labels, both
/// axis labels as given (they should carry the unit) and a legend when it has more
/// than one series. Units are whatever the caller's labels say; nothing is converted.
///
/// # Errors
/// [`Error::NoPlots`], [`Error::NoSeries`], [`Error::EmptySeries`], and
/// [`Error::NonFiniteSample`] naming the plot, series and sample index of a NaN or
/// infinite value (such a point is never drawn).
///
/// # Example
/// ```
/// use flapwright_drawing::{render_plots_svg, Error, Plot, Series};
///
/// let plot = Plot {
///     title: "Flap deflection".into(),
///     x_label: "nut travel s34 [mm]".into(),
///     y_label: "deflection [deg]".into(),
///     series: vec![Series { name: "flap".into(), points: vec![(80.3, 0.0), (152.4, 17.5), (224.6, 35.0)] }],
/// };
/// assert!(render_plots_svg("Station 1", &[plot.clone()])?.contains("deflection [deg]"));
///
/// let mut broken = plot;
/// broken.series[0].points[1].1 = f64::NAN;
/// assert!(matches!(render_plots_svg("Station 1", &[broken]), Err(Error::NonFiniteSample { index: 1, .. })));
/// # Ok::<(), Error>(())
/// ```
pub fn render_plots_svg(title: &str, plots: &[Plot]) -> Result<String> {
    if plots.is_empty() {
        return Err(Error::NoPlots);
    }
    plots.iter().try_for_each(validate_plot)?;
    let (width, height) = plots_page_size_px(plots.len());
    let mut document = Document::new()
        .set("xmlns", "http://www.w3.org/2000/svg")
        .set("width", num(width))
        .set("height", num(height))
        .set("viewBox", format!("0 0 {} {}", num(width), num(height)))
        .set("font-family", FONT_FAMILY)
        .add(
            Rectangle::new()
                .set("width", "100%")
                .set("height", "100%")
                .set("fill", "white"),
        )
        .add(
            text(title, MARGIN_PX, 36.0, 20.0, Anchor::Start, INK)
                .set("font-weight", "bold")
                .set("id", "title"),
        );
    for (index, plot) in plots.iter().enumerate() {
        let column = (index % PLOT_COLUMNS) as f64;
        let row = (index / PLOT_COLUMNS) as f64;
        let left = MARGIN_PX + column * (CHART_WIDTH_PX + GAP_PX);
        let top = HEADER_PX + row * (CHART_HEIGHT_PX + GAP_PX);
        document = document.add(chart(index, plot, left, top));
    }
    Ok(document.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plot_with(points: Vec<(f64, f64)>) -> Plot {
        Plot {
            title: "deflection".into(),
            x_label: "s34 [mm]".into(),
            y_label: "deflection [deg]".into(),
            series: vec![Series {
                name: "flap".into(),
                points,
            }],
        }
    }

    #[test]
    fn nan_sample_is_refused_with_its_index() {
        let plot = plot_with(vec![(0.0, 0.0), (1.0, 1.0), (2.0, f64::NAN)]);
        match render_plots_svg("t", &[plot]) {
            Err(Error::NonFiniteSample {
                plot, series, index, ..
            }) => {
                assert_eq!((plot.as_str(), series.as_str(), index), ("deflection", "flap", 2));
            }
            other => panic!("expected NonFiniteSample, got {other:?}"),
        }
    }

    /// A series with no points is a legend entry that keeps its place (its style), if
    /// another series has points.
    #[test]
    fn a_series_without_points_is_a_legend_entry() {
        let mut plot = plot_with(vec![(0.0, 1.0), (1.0, 2.0)]);
        plot.series.insert(
            0,
            Series {
                name: "failed".into(),
                points: Vec::new(),
            },
        );
        let svg = render_plots_svg("t", &[plot]).unwrap();
        assert!(svg.contains("failed"), "in the legend");
        assert!(!svg.contains("series series-0"), "nothing drawn for it");
        assert!(
            svg.contains("series series-1"),
            "the other keeps its place, so its style"
        );
    }

    #[test]
    fn empty_inputs_are_refused() {
        assert_eq!(render_plots_svg("t", &[]), Err(Error::NoPlots));
        let mut plot = plot_with(vec![]);
        assert!(matches!(
            render_plots_svg("t", &[plot.clone()]),
            Err(Error::EmptySeries { .. })
        ));
        plot.series.clear();
        assert!(matches!(render_plots_svg("t", &[plot]), Err(Error::NoSeries { .. })));
    }

    #[test]
    fn page_grows_by_rows() {
        let (w1, h1) = plots_page_size_px(1);
        let (w3, h3) = plots_page_size_px(3);
        assert_eq!(w1, w3);
        assert!(h3 > h1);
        assert_eq!(plots_page_size_px(4), plots_page_size_px(3));
    }
}
