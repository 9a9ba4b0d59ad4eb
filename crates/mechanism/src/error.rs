//! The crate's one error type.

use serde::Serialize;

/// Result with this crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Why a mechanism cannot be synthesised, assembled, posed or loaded.
///
/// Every variant names the condition and carries the values that triggered it
/// (SI units: metres, radians, newtons).
#[derive(Debug, Clone, PartialEq, Serialize, thiserror::Error)]
pub enum Error {
    /// A dimension is not finite or not strictly positive.
    #[error("dimension `{name}` = {value:e} must be finite and > 0")]
    InvalidDimension {
        /// Field name of the dimension.
        name: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// An angle, ratio or other parameter lies outside its admissible range.
    #[error("parameter `{name}` = {value:e} is outside [{min:e}, {max:e}]")]
    ParameterOutOfRange {
        /// Field name of the parameter.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Lowest admissible value.
        min: f64,
        /// Highest admissible value.
        max: f64,
    },
    /// Thesis section 5.3 red cell 2: the inner slot radius c1 must be smaller than the outer b1.
    #[error("inner slot radius {:.3} mm is not smaller than outer slot radius {:.3} mm", .inner_radius_m * 1e3, .outer_radius_m * 1e3)]
    SlotRadiiOrder {
        /// c1 (m).
        inner_radius_m: f64,
        /// b1 (m).
        outer_radius_m: f64,
    },
    /// Thesis step 8: no screw line through B0 can hold both end positions of A, because
    /// a1 <= a2 cos(β3/2) (the base pivot B0 lies inside the chord A_i A_f's foot circle).
    #[error(
        "no screw line through B0 holds both end positions: base distance {:.3} mm <= crank {:.3} mm x cos(half the rotation range) = {:.3} mm",
        .base_distance_m * 1e3, .crank_length_m * 1e3, .chord_distance_m * 1e3
    )]
    CollinearityImpossible {
        /// a1 (m).
        base_distance_m: f64,
        /// a2 (m).
        crank_length_m: f64,
        /// h = a2 cos(β3/2) (m), distance from A0 to the screw line.
        chord_distance_m: f64,
    },
    /// Thesis section 5.3 red cell 3: the screw is shorter than the largest slider travel s34,f.
    #[error("screw length {:.3} mm is shorter than the largest nut travel s34,f = {:.3} mm", .screw_length_m * 1e3, .required_m * 1e3)]
    ScrewTooShort {
        /// a3 (m).
        screw_length_m: f64,
        /// s34,f = s34,i + Δs (m).
        required_m: f64,
    },
    /// The nut would start on (or behind) the screw pivot B0: s34,i is below the shortest
    /// screw link that is not degenerate.
    #[error(
        "the nut starts {:.3} mm from the screw pivot B0 (s34,i; at least {:.3} mm): a zero-length or inverted screw link",
        .stroke_start_m * 1e3, .minimum_m * 1e3
    )]
    NutOnScrewPivot {
        /// s34,i (m).
        stroke_start_m: f64,
        /// The shortest accepted s34,i (m).
        minimum_m: f64,
    },
    /// Thesis section 5.3 red cell 1: the input would drive the pins out of their slots
    /// (s34 < s34,i or Δθ12 > β3).
    #[error(
        "input {:.3} mm is outside the slot range [{:.3}, {:.3}] mm",
        .input_m * 1e3, .min_input_m * 1e3, .max_input_m * 1e3
    )]
    OutOfSlot {
        /// Requested input s34 (m).
        input_m: f64,
        /// s34,i (m).
        min_input_m: f64,
        /// s34,f (m).
        max_input_m: f64,
    },
    /// The loop cannot close: the triangle A0 B0 A does not exist for this input.
    #[error(
        "cannot assemble at input {:.3} mm: reachable range is [{:.3}, {:.3}] mm",
        .input_m * 1e3, .min_input_m * 1e3, .max_input_m * 1e3
    )]
    CannotAssemble {
        /// Requested input (m).
        input_m: f64,
        /// Smallest input that assembles, |a1 - a2| (m).
        min_input_m: f64,
        /// Largest input that assembles, a1 + a2 (m).
        max_input_m: f64,
    },
    /// A dyad of a closed-form loop does not assemble: its two circles do not meet, or its
    /// links are aligned (a toggle).
    #[error("the five-bar's dyad {dyad} does not assemble at crank angle {:.3} deg", .crank_rad.to_degrees())]
    LoopOpen {
        /// Which dyad (its joint and loop).
        dyad: &'static str,
        /// Crank angle (rad).
        crank_rad: f64,
    },
    /// The mechanism is at (or within the tolerance of) a toggle (dead-centre) position:
    /// the transmission angle vanishes and the velocity Jacobian is singular.
    #[error(
        "toggle at input {:.3} mm: transmission angle {:.3} deg is below {:.3} deg",
        .input_m * 1e3, .transmission_angle_rad.to_degrees(), .tolerance_rad.to_degrees()
    )]
    Toggle {
        /// Input value at which the toggle was met (m).
        input_m: f64,
        /// Transmission angle μ there (rad).
        transmission_angle_rad: f64,
        /// The toggle tolerance in force (rad).
        tolerance_rad: f64,
    },
    /// An arc cosine argument fell outside [-1, 1] by more than rounding can explain.
    #[error("acos of `{quantity}`: cosine {cosine} exceeds 1 by more than {tolerance}")]
    AcosOutOfRange {
        /// What the angle is.
        quantity: &'static str,
        /// The offending cosine.
        cosine: f64,
        /// The rounding tolerance that was exceeded.
        tolerance: f64,
    },
    /// The two slot pins lie on one line through the hinge, so their radial reactions
    /// cannot balance a tangential load (the Cramer determinant sin(θF - θG) vanishes).
    #[error("slot reactions indeterminate: sin(θF - θG) = {determinant}")]
    SlotReactionsIndeterminate {
        /// sin(θF - θG).
        determinant: f64,
    },
    /// The screw cannot raise any load: 2πr - f l <= 0 in thesis eq. 3.6.9.
    #[error("screw cannot raise: 2πr - f·l = {denominator_m} m <= 0")]
    ScrewJammed {
        /// 2πr - f l (m).
        denominator_m: f64,
    },
    /// A sweep needs at least two samples.
    #[error("a sweep needs at least 2 samples, got {samples}")]
    TooFewSamples {
        /// Requested sample count.
        samples: usize,
    },
    /// A computed quantity came out non-finite (never returned silently).
    #[error("`{quantity}` is not finite at input {input_m:e}")]
    NonFinite {
        /// Which quantity.
        quantity: &'static str,
        /// Input value at which it happened.
        input_m: f64,
    },
    /// The general model's constraint count does not match its coordinates (3 per moving
    /// body): it is under- or over-constrained.
    #[error("model has {coordinates} coordinates but {constraints} constraint equations")]
    ConstraintCountMismatch {
        /// 3 × number of moving bodies.
        coordinates: usize,
        /// Joint equations plus the driver.
        constraints: usize,
    },
    /// A joint or the driver refers to a body that does not exist.
    #[error("body index {body} out of range (model has {bodies} bodies including ground)")]
    UnknownBody {
        /// Offending index.
        body: usize,
        /// Number of bodies, ground included.
        bodies: usize,
    },
    /// Newton's method did not reach the residual tolerance.
    #[error("no assembly at input {input}: residual {residual} after {iterations} Newton steps")]
    NotConverged {
        /// Input value (m or rad).
        input: f64,
        /// Final residual norm.
        residual: f64,
        /// Steps taken.
        iterations: usize,
    },
    /// The constraint Jacobian is singular (toggle or locked configuration).
    #[error("singular constraint Jacobian at input {input} (condition number {condition_number})")]
    SingularJacobian {
        /// Input value (m or rad).
        input: f64,
        /// 2-norm condition number.
        condition_number: f64,
    },
    /// A kind cannot be synthesised for its precision positions: which defect, and the
    /// numbers in words (mm and degrees).
    #[error("{kind}: {defect}: {detail}")]
    Synthesis {
        /// The kind's scene name.
        kind: &'static str,
        /// What went wrong.
        defect: SynthesisDefect,
        /// The numbers behind it.
        detail: String,
    },
    /// A candidate picked by its index in a search's trade (the non-dominated candidates the
    /// report lists) that the trade does not have.
    #[error("{kind}: trade_index = {index}: the search's trade has {count} candidates here (the report's `details.synthesis.trade`, from 0; without load cases it has none)")]
    NoSuchTradeCandidate {
        /// The kind's scene name.
        kind: &'static str,
        /// The index asked.
        index: usize,
        /// How many candidates the trade has.
        count: usize,
    },
    /// A kind's statics cannot take this load.
    #[error("the {kind} cannot take {load}")]
    LoadNotSupported {
        /// The kind.
        kind: &'static str,
        /// The load, in words.
        load: &'static str,
    },
}

/// Why a kind cannot move its flap through the precision positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, thiserror::Error)]
#[serde(rename_all = "kebab-case")]
pub enum SynthesisDefect {
    /// The positions need more than the kind has (a hinge for a pure translation, a
    /// circle through three points on one line).
    #[error("no real solution")]
    NoRealSolution,
    /// The mechanism would have to change assembly branch between positions, or reaches
    /// them out of order.
    #[error("branch or order defect")]
    BranchOrOrder,
    /// The mechanism passes a toggle (a transmission angle below the minimum) inside the
    /// deployment.
    #[error("toggle inside the deployment")]
    Toggle,
    /// A fixed pivot or the hinge lies where no support can hold it (inside the wing or
    /// flap section, or outside the fairing region).
    #[error("pivot outside the allowed region")]
    PivotOutsideRegion,
    /// A precision position is missing or not finite.
    #[error("precision positions missing")]
    MissingPositions,
}
