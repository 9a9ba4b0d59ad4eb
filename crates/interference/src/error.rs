//! Errors of the interference sweep.

/// Why a clearance sweep could not run.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A setting is outside its allowed range.
    #[error("{setting} = {value}: must be in {allowed}")]
    SettingOutOfRange {
        /// Setting name.
        setting: &'static str,
        /// Given value.
        value: f64,
        /// Allowed range, as text.
        allowed: &'static str,
    },
    /// The deployment range is empty or not finite.
    #[error("deployment range [{start}, {end}] must be finite with start < end")]
    BadRange {
        /// Range start.
        start: f64,
        /// Range end.
        end: f64,
    },
    /// A distance query failed.
    #[error("distance between {part_a} and {part_b} at deployment {parameter}")]
    Query {
        /// First part.
        part_a: String,
        /// Second part.
        part_b: String,
        /// Deployment parameter.
        parameter: f64,
        /// The geometry error.
        #[source]
        source: Box<flapwright_geom::Error>,
    },
    /// The mechanism could not be posed where the sweep asked.
    #[error("posing {part} at deployment {parameter}")]
    Pose {
        /// The part.
        part: String,
        /// Deployment parameter.
        parameter: f64,
        /// The mechanism's reason.
        #[source]
        source: flapwright_mechanism::Error,
    },
    /// A flap mesh was to follow a mechanism that has no flap body.
    #[error("flap {part}: its station's mechanism has no body with the flap role")]
    NoFlapBody {
        /// The flap part.
        part: String,
    },
    /// The stations carrying a flap cannot fix its rigid motion.
    #[error("flap {flap}: its stations' sections cannot fix a rigid motion")]
    FlapFit {
        /// The flap part.
        flap: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// A declared joint names a part the station does not have.
    #[error("joint {joint} names part {name}, which its station does not have")]
    UnknownPart {
        /// Part name.
        name: String,
        /// The joint.
        joint: String,
    },
    /// A station's mechanism has no solids to cut an opening for.
    #[error("station {station}: its mechanism has no solids, so no opening can be cut for it")]
    NoSolids {
        /// The station.
        station: String,
    },
    /// A part's speed bound is negative or not finite, so no certified bound can be given.
    #[error("part {part}: speed bound {value} m per unit deployment must be finite and >= 0")]
    BadSpeedBound {
        /// Part name.
        part: String,
        /// Given bound.
        value: f64,
    },
}

/// Result with this crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
