//! The crate's error type: every variant names the condition and carries the offending
//! value with the allowed range.

/// Result with this crate's [`enum@Error`] as the default error type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong while sizing. Variants name the condition and carry the
/// field, the value and the allowed range; none carries a free-form message.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A material property is outside its physical range (zero allowable stress,
    /// negative density, ...).
    #[error("material `{material}`: {field} = {value} is outside the allowed range {allowed}")]
    InvalidMaterial {
        /// Material name.
        material: String,
        /// Field name, e.g. `allowable_tensile_pa`.
        field: &'static str,
        /// Value given.
        value: f64,
        /// Allowed range in words, e.g. `(0, inf) Pa`.
        allowed: &'static str,
    },
    /// A sizing input (length, load, factor, ratio, ...) is not finite or out of range.
    #[error("{field} = {value} is outside the allowed range {allowed}")]
    OutOfRange {
        /// Field name with its context, e.g. `rods[2].length_m`.
        field: String,
        /// Value given.
        value: f64,
        /// Allowed range in words.
        allowed: &'static str,
    },
    /// A gearbox (or other) mechanical efficiency is not in (0, 1].
    #[error("{field} = {value} is not an efficiency: allowed range (0, 1]")]
    EfficiencyOutOfRange {
        /// Field name.
        field: String,
        /// Value given.
        value: f64,
    },
    /// A normal-force coefficient table has fewer than two rows.
    #[error("normal-force coefficient table needs at least 2 rows, got {rows}")]
    TableTooShort {
        /// Rows given.
        rows: usize,
    },
    /// Deflections of a normal-force table do not strictly increase.
    #[error("normal-force table deflections must strictly increase; row {row} does not")]
    TableNotIncreasing {
        /// First offending row (0-based).
        row: usize,
    },
    /// A deflection outside the normal-force table was requested (no extrapolation).
    #[error("deflection {deflection_rad} rad is outside the table range [{min_rad}, {max_rad}] rad")]
    DeflectionOutsideTable {
        /// Deflection requested, rad.
        deflection_rad: f64,
        /// First table deflection, rad.
        min_rad: f64,
        /// Last table deflection, rad.
        max_rad: f64,
    },
    /// Two lists that must pair up have different lengths.
    #[error("{what}: lengths differ ({first} vs {second})")]
    LengthMismatch {
        /// Which lists.
        what: &'static str,
        /// Length of the first list.
        first: usize,
        /// Length of the second list.
        second: usize,
    },
    /// Too few support stations for the load distribution.
    #[error("at least {required} support stations are needed, got {found}")]
    TooFewStations {
        /// Minimum number.
        required: usize,
        /// Number given.
        found: usize,
    },
    /// Station (or sample) positions do not strictly increase.
    #[error("{what} must strictly increase; entry {index} ({value}) does not")]
    NotIncreasing {
        /// Which list.
        what: &'static str,
        /// First offending index (0-based).
        index: usize,
        /// Offending value.
        value: f64,
    },
    /// The screw thread's lead angle exceeds the friction limit in the raise direction
    /// (thesis `000` eq 3.6.9 denominator `2 pi r - f l` is not positive): the screw
    /// jams and cannot raise any load.
    #[error("screw thread jams when raising: 2 pi r - f l = {denominator_m} m is not positive")]
    ScrewJamsWhenRaising {
        /// Denominator of eq 3.6.9, m.
        denominator_m: f64,
    },
    /// An empty list was given where at least one entry is required.
    #[error("{what} is empty")]
    Empty {
        /// Which list.
        what: &'static str,
    },
}
