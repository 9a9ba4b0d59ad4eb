//! The error type of `flapwright-geom`.

/// Result with the crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong while building geometry, reading airfoils or querying shapes.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A NACA designation that is not a supported 4- or 5-digit series.
    #[error("NACA designation {designation:?} is not a supported 4-digit or 5-digit section")]
    UnknownNacaDesignation {
        /// The designation as given.
        designation: String,
    },
    /// Too few points requested or present.
    #[error("{what}: {count} points given, at least {minimum} needed")]
    TooFewPoints {
        /// What the points describe.
        what: &'static str,
        /// Number given.
        count: usize,
        /// Smallest accepted number.
        minimum: usize,
    },
    /// A value that must be finite is NaN or infinite.
    #[error("{what} = {value} is not finite")]
    NotFinite {
        /// Name of the quantity.
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// A value outside its allowed range.
    #[error("{what} = {value} is outside the allowed range [{minimum}, {maximum}]")]
    OutOfRange {
        /// Name of the quantity (field name, with its unit).
        what: &'static str,
        /// The value.
        value: f64,
        /// Smallest accepted value.
        minimum: f64,
        /// Largest accepted value.
        maximum: f64,
    },
    /// A line of an airfoil `.dat` file that is not two numbers.
    #[error("airfoil file line {line}: cannot read {text:?} as two numbers")]
    DatSyntax {
        /// 1-based line number.
        line: usize,
        /// The offending text.
        text: String,
    },
    /// A Lednicer file whose point counts do not match its header.
    #[error("Lednicer airfoil file: header announces {upper} upper and {lower} lower points, {found} found")]
    LednicerCount {
        /// Announced upper points.
        upper: usize,
        /// Announced lower points.
        lower: usize,
        /// Points found.
        found: usize,
    },
    /// Reading or writing failed.
    #[error("input/output")]
    Io(#[from] std::io::Error),
    /// Airfoil points that are not a single loop from trailing edge round the nose and back.
    #[error("airfoil {name:?}: {reason}")]
    BadAirfoil {
        /// Airfoil name.
        name: String,
        /// Which condition failed.
        reason: &'static str,
    },
    /// Wing sections not in strictly increasing spanwise order.
    #[error("wing section {index}: y = {y_m} m is not greater than the previous section's {previous_y_m} m")]
    SectionsOutOfOrder {
        /// Index of the offending section.
        index: usize,
        /// Its spanwise position (m).
        y_m: f64,
        /// The previous section's spanwise position (m).
        previous_y_m: f64,
    },
    /// Number of panels is not the number of sections minus one.
    #[error("wing: {panels} panels given for {sections} sections (need sections - 1)")]
    PanelCount {
        /// Panels given.
        panels: usize,
        /// Sections given.
        sections: usize,
    },
    /// The root leading-edge point does not lie at the first section's spanwise position.
    #[error("wing: root leading edge y = {root_y_m} m differs from the first section's y = {section_y_m} m")]
    RootLeadingEdgeMismatch {
        /// y of `root_leading_edge_ac` (m).
        root_y_m: f64,
        /// y of the first section (m).
        section_y_m: f64,
    },
    /// A spanwise position outside the wing.
    #[error("{what}: y = {y_m} m is outside the wing span [{root_y_m}, {tip_y_m}] m")]
    OutsideSpan {
        /// What was asked for.
        what: String,
        /// Requested spanwise position (m).
        y_m: f64,
        /// Root section position (m).
        root_y_m: f64,
        /// Tip section position (m).
        tip_y_m: f64,
    },
    /// Points that do not span what the operation needs (collinear points for a rigid fit).
    #[error("{what}")]
    Degenerate {
        /// What is degenerate, in words.
        what: &'static str,
    },
    /// A hinge axis whose two points (nearly) coincide or that does not run outboard.
    #[error("flap {flap:?}: hinge axis length {length_m} m (spanwise run {spanwise_m} m) does not define an outboard direction")]
    DegenerateHingeAxis {
        /// Flap name.
        flap: String,
        /// Distance between the two axis points (m).
        length_m: f64,
        /// y(outboard) - y(inboard) (m).
        spanwise_m: f64,
    },
    /// An aft element on a flap cut out of the wing section (it needs the flap's own
    /// section to nest in).
    #[error(
        "flap {flap:?}: an aft element needs the flap's own section (section = an airfoil), not the wing's cut-out"
    )]
    AftElementNeedsOwnSection {
        /// Flap name.
        flap: String,
    },
    /// Two flaps overlapping in span, or a flap of zero span.
    #[error("flap {flap:?}: span [{y_inboard_m}, {y_outboard_m}] m is empty or overlaps flap {other:?}")]
    FlapSpanConflict {
        /// Flap name.
        flap: String,
        /// The other flap (or the same one when its span is empty).
        other: String,
        /// Inboard end (m).
        y_inboard_m: f64,
        /// Outboard end (m).
        y_outboard_m: f64,
    },
    /// A spar that reaches into a flap cove.
    #[error("spar {spar:?} at chord fraction {chord_fraction} reaches behind the cove of flap {flap:?} (cove wall at {cove_chord_fraction})")]
    SparBehindFlap {
        /// Spar name.
        spar: String,
        /// Spar chord fraction.
        chord_fraction: f64,
        /// Flap name.
        flap: String,
        /// Chord fraction of the cove wall where the spar meets it.
        cove_chord_fraction: f64,
    },
    /// A polygon that could not be triangulated (self-intersecting or degenerate).
    #[error("{what}: polygon of {count} points cannot be triangulated (self-intersecting or degenerate)")]
    Triangulation {
        /// What the polygon is.
        what: &'static str,
        /// Number of vertices.
        count: usize,
    },
    /// A torque-tube path with a repeated point or a bend sharper than allowed.
    #[error("torque tube: path point {index} gives a zero-length segment or a bend of {bend_deg} deg (max {max_bend_deg} deg)")]
    TubePath {
        /// Index of the path point.
        index: usize,
        /// Bend angle there (deg).
        bend_deg: f64,
        /// Largest accepted bend (deg).
        max_bend_deg: f64,
    },
    /// A mesh the collision library rejected, or an unsupported shape pair.
    #[error("collision shape: {reason}")]
    Collision {
        /// What failed.
        reason: String,
    },
    /// A built mesh that failed its own topology check (an internal bug, reported not panicked).
    #[error("part {part:?}: mesh is not closed and consistently oriented ({boundary} boundary, {non_manifold} non-manifold, {misoriented} misoriented edges, {degenerate} degenerate triangles)")]
    MeshNotWatertight {
        /// Part name.
        part: String,
        /// Boundary edges.
        boundary: usize,
        /// Non-manifold edges.
        non_manifold: usize,
        /// Inconsistently oriented edges.
        misoriented: usize,
        /// Degenerate triangles.
        degenerate: usize,
    },
}

/// Returns `Err(NotFinite)` when `value` is NaN or infinite.
pub(crate) fn require_finite(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { what, value })
    }
}

/// Returns `Err(OutOfRange)` unless `minimum <= value <= maximum` (and finite).
pub(crate) fn require_range(what: &'static str, value: f64, minimum: f64, maximum: f64) -> Result<f64> {
    require_finite(what, value)?;
    if value >= minimum && value <= maximum {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            what,
            value,
            minimum,
            maximum,
        })
    }
}
