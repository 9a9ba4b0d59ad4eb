//! Warnings: results that were computed but should not be trusted silently.

use serde::Serialize;

/// A sizing result that was computed but is suspicious; each names the part and carries
/// the numbers. Reports list them; the CLI decides whether they fail a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SizingWarning {
    /// The required outer radius exceeds what the station allows.
    RodExceedsEnvelope {
        /// Station name.
        station: String,
        /// Rod name.
        rod: String,
        /// Required outer radius, m.
        required_outer_radius_m: f64,
        /// Largest radius the station allows, m.
        allowed_outer_radius_m: f64,
    },
    /// The required diameter is not small against the length: not a rod, and Euler
    /// buckling and axial-only loading are meaningless.
    RodNotSlender {
        /// Station name.
        station: String,
        /// Rod name.
        rod: String,
        /// Required outer diameter, m.
        outer_diameter_m: f64,
        /// Rod length, m.
        length_m: f64,
    },
    /// Buckling governs but the slenderness K L / rho_g is below the Euler/Johnson
    /// transition pi sqrt(2 E / sigma_allow): Euler overestimates the critical load.
    IntermediateColumn {
        /// Station name.
        station: String,
        /// Rod name.
        rod: String,
        /// Slenderness ratio K L / rho_g.
        slenderness_ratio: f64,
        /// Transition slenderness pi sqrt(2 E / sigma_allow).
        transition_slenderness_ratio: f64,
    },
    /// Both tension and compression are zero: the rod has no size from loads.
    UnloadedRod {
        /// Station name.
        station: String,
        /// Rod name.
        rod: String,
    },
    /// The actuator (a screw jack, or a geared rotary actuator) is not self-locking: the
    /// lowering torque is not positive, so the load back-drives it and a brake is needed.
    NotSelfLocking {
        /// Station name.
        station: String,
        /// Actuator name (`screw-jack`, `rotary-actuator`). Written as `screw_jack`, the
        /// report's field name from before the rename (issue 36): the wire name stays.
        #[serde(rename = "screw_jack")]
        actuator: String,
        /// Lowering torque given, N m (thesis `000` eq 3.6.10 sign).
        lower_torque_nm: f64,
    },
    /// The required torque-tube radius exceeds what the structure allows.
    TorqueTubeExceedsEnvelope {
        /// Station (tube) name.
        station: String,
        /// Required outer radius, m.
        required_outer_radius_m: f64,
        /// Largest radius allowed, m.
        allowed_outer_radius_m: f64,
    },
}

impl std::fmt::Display for SizingWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::RodExceedsEnvelope { station, rod, required_outer_radius_m, allowed_outer_radius_m } => write!(
                f,
                "station {station}, rod {rod}: needs outer radius {:.2} mm, station allows {:.2} mm",
                required_outer_radius_m * 1e3,
                allowed_outer_radius_m * 1e3
            ),
            Self::RodNotSlender { station, rod, outer_diameter_m, length_m } => write!(
                f,
                "station {station}, rod {rod}: needs diameter {:.2} mm for a length of {:.2} mm",
                outer_diameter_m * 1e3,
                length_m * 1e3
            ),
            Self::IntermediateColumn { station, rod, slenderness_ratio, transition_slenderness_ratio } => write!(
                f,
                "station {station}, rod {rod}: slenderness {slenderness_ratio:.1} below Euler limit {transition_slenderness_ratio:.1}"
            ),
            Self::UnloadedRod { station, rod } => write!(f, "station {station}, rod {rod}: carries no load"),
            Self::NotSelfLocking { station, actuator, lower_torque_nm } => write!(
                f,
                "station {station}, {actuator}: not self-locking (lowering torque {lower_torque_nm:.3} N m on the drive shaft: the load back-drives it)"
            ),
            Self::TorqueTubeExceedsEnvelope { station, required_outer_radius_m, allowed_outer_radius_m } => write!(
                f,
                "torque tube at station {station}: needs outer radius {:.2} mm, allowed {:.2} mm",
                required_outer_radius_m * 1e3,
                allowed_outer_radius_m * 1e3
            ),
        }
    }
}
