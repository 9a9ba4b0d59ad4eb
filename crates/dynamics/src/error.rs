//! The crate's one error type.

/// Result with this crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Why a dynamics run cannot start or finish.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A parameter lies outside its admissible range.
    #[error("`{name}` = {value:e} is outside ({min:e}, {max:e}]")]
    OutOfRange {
        /// The parameter's name, as in the scene (`motor.inductance_h`).
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Bound below (exclusive).
        min: f64,
        /// Bound above (inclusive).
        max: f64,
    },
    /// The mechanism could not be posed during the run.
    #[error("mechanism at input {input:.6}: {source}")]
    Mechanism {
        /// The input where it failed.
        input: f64,
        /// What the mechanism said.
        source: flapwright_mechanism::Error,
    },
    /// The ODE solver failed (step size collapse, Newton failure, ...).
    #[error("the {method} integrator failed at t = {time_s:.6} s: {message}")]
    Solver {
        /// Which method.
        method: &'static str,
        /// Time reached (s).
        time_s: f64,
        /// The solver's message.
        message: String,
    },
    /// The generalised inertia is not positive: the input cannot be accelerated.
    #[error("generalised inertia {inertia:e} is not positive at input {input:.6}")]
    NoInertia {
        /// Input.
        input: f64,
        /// J(q) plus the reflected rotor inertia.
        inertia: f64,
    },
}
