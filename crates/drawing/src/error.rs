//! The one error type of `flapwright-drawing`.

/// Everything that can go wrong while turning geometry or plot data into SVG.
///
/// Every variant names the condition and carries the context a user needs to find the
/// offending input (which part, which series, which point index).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// The station drawing has nothing to draw (no sections, settings, slots, envelope,
    /// fairing line or dimensions).
    #[error("the station drawing is empty: nothing to draw")]
    EmptyDrawing,

    /// A coordinate or angle of the station drawing is NaN or infinite.
    #[error("non-finite value in {what} at index {index}")]
    NonFinitePoint {
        /// Which item holds the value (e.g. "section `wing` polygon 0").
        what: String,
        /// Index of the point (or of the scalar) inside that item.
        index: usize,
    },

    /// A polygon or polyline has fewer points than its kind needs.
    #[error("{what} has {count} points, at least {minimum} are needed")]
    TooFewPoints {
        /// Which item (e.g. "link `screw` of setting `landing`").
        what: String,
        /// Number of points given.
        count: usize,
        /// Minimum number of points for this kind of item.
        minimum: usize,
    },

    /// A slot arc has a radius that is not strictly positive.
    #[error("slot `{slot}` has radius {radius_m} m; it must be > 0")]
    NonPositiveRadius {
        /// Name of the slot.
        slot: String,
        /// The radius given, metres.
        radius_m: f64,
    },

    /// A dimension's two end points coincide, so it has no direction to be drawn along.
    #[error("dimension `{label}` has zero length")]
    ZeroLengthDimension {
        /// Label of the dimension.
        label: String,
    },

    /// All the geometry lies on a point: no scale can be chosen.
    #[error("drawing extent is degenerate: {width_m} m x {height_m} m")]
    DegenerateExtent {
        /// Width of the bounding box, metres.
        width_m: f64,
        /// Height of the bounding box, metres.
        height_m: f64,
    },

    /// `render_plots_svg` was given no plots.
    #[error("no plots to render")]
    NoPlots,

    /// A plot has no series.
    #[error("plot `{plot}` has no series")]
    NoSeries {
        /// Title of the plot.
        plot: String,
    },

    /// No series of a plot has points (the first named).
    #[error("series `{series}` of plot `{plot}` has no points, nor has any other of the plot")]
    EmptySeries {
        /// Title of the plot.
        plot: String,
        /// Name of the series.
        series: String,
    },

    /// A plot sample is NaN or infinite; it is refused, never drawn.
    #[error("series `{series}` of plot `{plot}`: point {index} is not finite ({x}, {y})")]
    NonFiniteSample {
        /// Title of the plot.
        plot: String,
        /// Name of the series.
        series: String,
        /// Index of the sample in the series.
        index: usize,
        /// The x value given.
        x: f64,
        /// The y value given.
        y: f64,
    },
}

/// Result with this crate's [`Error`] as the default error type.
pub type Result<T, E = Error> = std::result::Result<T, E>;
