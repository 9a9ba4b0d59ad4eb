//! Plot pages: parse, render, size, legends, refusal of non-finite samples.

use crate::fixtures::plots;
use crate::raster::{declared_size, inked, render};
use flapwright_drawing::{plots_page_size_px, render_plots_svg, Error};

#[test]
fn renders_a_grid_of_the_declared_size() {
    let plots = plots();
    let svg = render_plots_svg("Fixture plots", &plots).expect("renders");
    let (width, height) = plots_page_size_px(plots.len());
    assert_eq!(declared_size(&svg), (width as u32, height as u32));
    let pixmap = render(&svg, true);
    assert_eq!((pixmap.width(), pixmap.height()), (width as u32, height as u32));
    let total = (pixmap.width() * pixmap.height()) as usize;
    assert!(inked(&pixmap) > total / 100, "plot page looks blank");
    assert!(inked(&render(&svg, false)) > 5_000, "lines missing without fonts");
}

#[test]
fn axis_labels_and_legend_are_written() {
    let svg = render_plots_svg("Fixture plots", &plots()).expect("renders");
    assert!(svg.contains("nut travel s34 [mm]"));
    assert!(svg.contains("force [N]"));
    // Only the two-series plot has a legend.
    assert_eq!(svg.matches("class=\"legend\"").count(), 1);
    assert!(svg.lines().any(|line| line.trim() == "cruise"), "legend entry missing");
}

#[test]
fn non_finite_sample_is_refused_with_series_and_index() {
    let mut plots = plots();
    plots[1].series[1].points[7].1 = f64::INFINITY;
    match render_plots_svg("Fixture plots", &plots) {
        Err(Error::NonFiniteSample {
            plot, series, index, ..
        }) => {
            assert_eq!((plot.as_str(), series.as_str(), index), ("Force", "cruise", 7));
        }
        other => panic!("expected NonFiniteSample, got {other:?}"),
    }
}
