//! The crate's one error type.

use serde::Serialize;

/// Result with this crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Why a wing's mechanisms cannot be written as a URDF robot or a trajectory.
#[derive(Debug, Clone, PartialEq, Serialize, thiserror::Error)]
pub enum Error {
    /// A URDF name (station, flap, base link or mesh) is empty or uses characters outside
    /// ASCII letters, digits, `_` and `-` (or contains `--`, which XML comments forbid).
    #[error("URDF {what} name `{name}` must be non-empty ASCII letters, digits, '_' or '-' (no \"--\")")]
    InvalidUrdfName {
        /// What the name is for ("station", "flap", "base link", "mesh").
        what: &'static str,
        /// The rejected name.
        name: String,
    },
    /// Two links, joints or key-point groups of one URDF robot would share a name.
    #[error("URDF name `{name}` is used twice")]
    DuplicateUrdfName {
        /// The repeated name.
        name: String,
    },
    /// A flap must hang off exactly one station (`owns_flap`), found another count.
    #[error("flap `{flap}` is owned by {owners} stations; exactly one must own it")]
    FlapOwnership {
        /// Flap name.
        flap: String,
        /// Number of stations with `owns_flap` for it.
        owners: usize,
    },
    /// A flap mesh was given on a station that does not own the flap link.
    #[error("station `{station}` gives a flap mesh but does not own flap `{flap}`")]
    FlapMeshOnNonOwningStation {
        /// Station name.
        station: String,
        /// Flap name.
        flap: String,
    },
    /// A mesh filename is empty, absolute or a URI: URDF meshes must be relative to the file.
    #[error("mesh filename `{filename}` must be a non-empty path relative to the URDF file")]
    MeshPathNotRelative {
        /// The rejected filename.
        filename: String,
    },
    /// A station's placement `aircraft_from_station` has a non-finite entry.
    #[error("station `{station}`: aircraft_from_station is not finite")]
    NonFinitePlacement {
        /// Station name.
        station: String,
    },
    /// A moving body is joined to the rest only through slots: no URDF tree reaches it.
    #[error("station `{station}`: body `{body}` is reached by no revolute or prismatic joint, so the URDF tree cannot place it")]
    UrdfTreeIncomplete {
        /// Station name.
        station: String,
        /// Body name.
        body: String,
    },
    /// A URDF robot needs at least one station.
    #[error("a URDF robot needs at least one station")]
    NoStations,
    /// urdf-rs could not serialise the robot (its error text; the type is opaque).
    #[error("urdf-rs could not write the robot: {message}")]
    UrdfWrite {
        /// urdf-rs's message.
        message: String,
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
    /// A mechanism could not be posed or sampled (its own error, unchanged).
    #[error(transparent)]
    Mechanism(#[from] flapwright_mechanism::Error),
}
