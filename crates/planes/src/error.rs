//! The one error type of `flapwright-planes`.

/// Everything that can go wrong while building stations, frames and section cuts.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A direction that must have length (axis, normal, skew direction) is (nearly) zero.
    #[error("{quantity} has length {norm} (< {limit}): direction undefined")]
    ZeroLengthDirection {
        /// Which direction (e.g. "hinge axis", "skew direction").
        quantity: &'static str,
        /// Its length before normalisation (in its own unit, usually m or 1).
        norm: f64,
        /// The smallest accepted length.
        limit: f64,
    },
    /// A station frame needs an x axis perpendicular to gravity in the plane; impossible
    /// when the plane normal is (nearly) vertical.
    #[error("plane normal {normal_ac:?} is within {sine_limit} (sine) of gravity: station x axis undefined")]
    NormalAlongGravity {
        /// The plane normal in the aircraft frame.
        normal_ac: [f64; 3],
        /// Smallest accepted sine of the angle between normal and vertical.
        sine_limit: f64,
    },
    /// The hinge axis (nearly) lies in the plane it should cross (thesis step 1).
    #[error("hinge axis is parallel to the {plane} plane (|cos| = {cosine} < {limit})")]
    AxisParallelToPlane {
        /// Which plane ("inner flap side").
        plane: &'static str,
        /// |axis . normal|.
        cosine: f64,
        /// Smallest accepted |axis . normal|.
        limit: f64,
    },
    /// An input quantity is NaN or infinite.
    #[error("{quantity} is not finite ({value})")]
    NotFinite {
        /// Which input.
        quantity: &'static str,
        /// Its value.
        value: f64,
    },
    /// A deployment needs at least one setting and at least two samples.
    #[error("{quantity} = {value} is below the minimum {minimum}")]
    TooFew {
        /// What was counted ("flap settings", "deployment samples").
        quantity: &'static str,
        /// How many were given.
        value: usize,
        /// How many are needed.
        minimum: usize,
    },
    /// A triangle refers to a vertex the mesh does not have.
    #[error("part {part_name}: triangle {triangle} refers to vertex {index} of {vertex_count}")]
    VertexIndexOutOfRange {
        /// Part being cut.
        part_name: String,
        /// Triangle index.
        triangle: usize,
        /// Offending vertex index.
        index: u32,
        /// Number of vertices in the mesh.
        vertex_count: usize,
    },
    /// The cut of a mesh did not close: the mesh has a hole or a non-manifold edge there.
    #[error("part {part_name}: section does not close at mesh edge ({edge_start}, {edge_end})")]
    OpenSection {
        /// Part being cut.
        part_name: String,
        /// First vertex of the edge where the chain broke.
        edge_start: u32,
        /// Second vertex of that edge.
        edge_end: u32,
    },
    /// The stowed flap section does not reach behind the wing section's nose, so there is
    /// no local chord to measure gap and overlap against.
    #[error("local chord = {chord_m} m (wing nose to stowed flap trailing edge): the flap is not behind the wing")]
    FlapNotBehindWing {
        /// Wing nose x less flap trailing edge x, station frame (m).
        chord_m: f64,
    },
    /// No flap position gives the asked gap at this deflection and overlap.
    #[error("no flap position behind the wing gives a gap of {gap_m} m with an overlap of {overlap_m} m at {deflection_deg} deg (the smallest gap reachable is {smallest_gap_m} m)")]
    GapUnreachable {
        /// Asked gap (m).
        gap_m: f64,
        /// Asked overlap (m).
        overlap_m: f64,
        /// Deflection (deg).
        deflection_deg: f64,
        /// Smallest gap found over the search (m).
        smallest_gap_m: f64,
    },
    /// A row of the boundary CSV could not be read.
    #[error("boundary CSV line {line}: column {column} is missing or not a number")]
    BoundaryCsvField {
        /// 1-based line number.
        line: usize,
        /// Column name.
        column: &'static str,
    },
}

/// Result with this crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Returns `value` if finite, else [`Error::NotFinite`].
pub(crate) fn finite(quantity: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { quantity, value })
    }
}
