//! The circular-arc track with screw jack (thesis `000_...`, Chapters 3-5) as a scene
//! table: its keys, their checks and its synthesis.

use std::sync::Arc;

use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec, TrackHardware};
use flapwright_mechanism::{FlapMechanism, ScrewJack, DEFAULT_TOGGLE_TOLERANCE_RAD};
use nalgebra::Point2;
use serde::Deserialize;

use super::{KindScene, SynthesisContext};
use crate::scene::limits::{
    FLAP_MASS_KG, MECHANISM_LENGTH_M, MIN_SLOT_OFFSET_ANGLE_DEG, NUT_SPEED_MPS, SCREW_FRICTION, SCREW_LEAD_M,
    SCREW_MEAN_RADIUS_M,
};
use crate::scene::{number, KeyChecker};

/// Standard gravity used by the mechanism's weight term (m/s²), as the thesis (Table 2).
const GRAVITY_MPS2: f64 = 9.81;

/// Thesis step 9: "select a3 slightly greater than Δs + s34,i"; Table 2 has 250 mm for
/// 224.6 mm, so an unspecified screw is 10 % longer than the full stroke.
const SCREW_LENGTH_MARGIN: f64 = 1.10;

/// The flap rotation a track may give, deg: below a degree it is no flap setting (a typo
/// such as 1e-300 would otherwise pass); flap settings stay below 90 deg.
const ROTATION_RANGE_DEG: (f64, f64) = (1.0, 90.0);

/// The keys that place the screw line and the nut's travel.
const SCREW_GEOMETRY_KEYS: &str = "base_distance_m, base_angle_deg, crank_length_m and rotation_range_deg";

/// Dimensions of a circular-arc-track mechanism in the station frame (thesis Table 2 names
/// in the doc comments).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CircularArcTrackScene {
    /// a1 = |A0 B0|, m.
    pub base_distance_m: f64,
    /// α0, angle of A0B0 from the station x axis, deg.
    pub base_angle_deg: f64,
    /// a2 = |A0 A|, m.
    pub crank_length_m: f64,
    /// a3, screw length; absent: synthesised (step 9), m.
    pub screw_length_m: Option<f64>,
    /// b1, outer slot radius, m.
    pub outer_slot_radius_m: f64,
    /// c1, inner slot radius, m.
    pub inner_slot_radius_m: f64,
    /// β1, angle of the outer slot's stowed end, deg.
    pub slot_start_angle_deg: f64,
    /// β2, angle between the two slots' stowed ends, deg.
    pub slot_offset_angle_deg: f64,
    /// β3, flap rotation range, deg.
    pub rotation_range_deg: f64,
    /// Flap centre of mass D (stowed), station frame, m.
    pub flap_centre_of_mass_m: [f64; 2],
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Screw lead l, m.
    pub screw_lead_m: f64,
    /// Screw mean radius r, m.
    pub screw_mean_radius_m: f64,
    /// Thread friction coefficient f.
    pub screw_friction: f64,
    /// Nut speed along the screw, m/s.
    #[serde(default = "default_nut_speed")]
    pub nut_speed_mps: f64,
    /// Sizes of the solids that stand for the hardware (fittings, nut, tracks, jack body),
    /// m; each absent key keeps the default of `TrackHardware` (thesis small-aircraft sizes).
    #[serde(default)]
    pub hardware: TrackHardwareScene,
}

/// `[station.mechanism.hardware]` of a circular-arc track: every key optional (m).
#[derive(Debug, Clone, Default, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrackHardwareScene {
    pub fitting_radius_m: Option<f64>,
    pub nut_radius_m: Option<f64>,
    pub track_radius_m: Option<f64>,
    pub jack_body_length_m: Option<f64>,
    pub jack_body_radius_m: Option<f64>,
}

impl TrackHardwareScene {
    /// The sizes, defaults where absent.
    fn resolve(&self) -> TrackHardware {
        let default = TrackHardware::default();
        TrackHardware {
            fitting_radius_m: self.fitting_radius_m.unwrap_or(default.fitting_radius_m),
            nut_radius_m: self.nut_radius_m.unwrap_or(default.nut_radius_m),
            track_radius_m: self.track_radius_m.unwrap_or(default.track_radius_m),
            jack_body_length_m: self.jack_body_length_m.unwrap_or(default.jack_body_length_m),
            jack_body_radius_m: self.jack_body_radius_m.unwrap_or(default.jack_body_radius_m),
        }
    }

    /// The given keys with their values.
    fn given(&self) -> Vec<(&'static str, f64)> {
        [
            ("fitting_radius_m", self.fitting_radius_m),
            ("nut_radius_m", self.nut_radius_m),
            ("track_radius_m", self.track_radius_m),
            ("jack_body_length_m", self.jack_body_length_m),
            ("jack_body_radius_m", self.jack_body_radius_m),
        ]
        .into_iter()
        .filter_map(|(key, value)| value.map(|v| (key, v)))
        .collect()
    }
}

/// Hardware sizes (m): from a tenth of a millimetre to a metre.
const HARDWARE_SIZE_M: (f64, f64) = (1e-4, 1.0);

fn default_nut_speed() -> f64 {
    0.035
}

impl CircularArcTrackScene {
    fn spec(&self, screw_length_m: f64) -> CircularArcTrackSpec {
        CircularArcTrackSpec {
            base_distance_m: self.base_distance_m,
            crank_length_m: self.crank_length_m,
            screw_length_m,
            base_angle_rad: self.base_angle_deg.to_radians(),
            outer_slot_radius_m: self.outer_slot_radius_m,
            inner_slot_radius_m: self.inner_slot_radius_m,
            outer_slot_start_angle_rad: self.slot_start_angle_deg.to_radians(),
            inner_slot_offset_angle_rad: self.slot_offset_angle_deg.to_radians(),
            rotation_range_rad: self.rotation_range_deg.to_radians(),
            centre_of_mass_stowed_m: Point2::new(self.flap_centre_of_mass_m[0], self.flap_centre_of_mass_m[1]),
            flap_mass_kg: self.flap_mass_kg,
            flap_moment_of_inertia_kgm2: 0.0,
            gravity_mps2: GRAVITY_MPS2,
            screw: ScrewJack {
                lead_m: self.screw_lead_m,
                mean_radius_m: self.screw_mean_radius_m,
                friction_coefficient: self.screw_friction,
            },
            nominal_input_speed_mps: self.nut_speed_mps,
            nominal_input_accel_mps2: 0.0,
            toggle_tolerance_rad: DEFAULT_TOGGLE_TOLERANCE_RAD,
        }
    }

    fn track(&self) -> flapwright_mechanism::Result<CircularArcTrack> {
        let track = match self.screw_length_m {
            Some(length) => CircularArcTrack::synthesise(self.spec(length))?,
            None => {
                // Synthesise once with an unbounded screw to learn the stroke, then size it.
                let probe = CircularArcTrack::synthesise(self.spec(f64::MAX))?;
                let length = SCREW_LENGTH_MARGIN * probe.synthesis().stroke_end_m;
                CircularArcTrack::synthesise(self.spec(length))?
            }
        };
        Ok(track.with_hardware(self.hardware.resolve()))
    }
}

impl KindScene for CircularArcTrackScene {
    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        let m = self;
        let mut lengths = vec![
            ("base_distance_m", m.base_distance_m),
            ("crank_length_m", m.crank_length_m),
            ("outer_slot_radius_m", m.outer_slot_radius_m),
            ("inner_slot_radius_m", m.inner_slot_radius_m),
        ];
        lengths.extend(m.screw_length_m.map(|a3| ("screw_length_m", a3)));
        for (key, value, (min, max)) in lengths
            .into_iter()
            .map(|(key, value)| (key, value, MECHANISM_LENGTH_M))
            .chain([
                ("flap_mass_kg", m.flap_mass_kg, FLAP_MASS_KG),
                ("screw_lead_m", m.screw_lead_m, SCREW_LEAD_M),
                ("screw_mean_radius_m", m.screw_mean_radius_m, SCREW_MEAN_RADIUS_M),
                ("screw_friction", m.screw_friction, SCREW_FRICTION),
                ("nut_speed_mps", m.nut_speed_mps, NUT_SPEED_MPS),
            ])
        {
            checker.in_range(&format!("{path}.{key}"), value, min, max, false);
        }
        for (key, value) in [
            ("base_angle_deg", m.base_angle_deg),
            ("slot_start_angle_deg", m.slot_start_angle_deg),
            ("slot_offset_angle_deg", m.slot_offset_angle_deg),
        ] {
            checker.in_range(&format!("{path}.{key}"), value, -360.0, 360.0, false);
        }
        checker.in_range(
            &format!("{path}.rotation_range_deg"),
            m.rotation_range_deg,
            ROTATION_RANGE_DEG.0,
            ROTATION_RANGE_DEG.1,
            false,
        );
        let offset = m.slot_offset_angle_deg;
        if offset.is_finite() && offset.to_radians().sin().abs() < MIN_SLOT_OFFSET_ANGLE_DEG.to_radians().sin() {
            checker.fail(
                &format!("{path}.slot_offset_angle_deg"),
                format!(
                    "= {}: the two slot pins lie on one line through the hinge A0 and cannot hold the flap; keep it at least {MIN_SLOT_OFFSET_ANGLE_DEG} deg away from 0 and +-180 deg",
                    number(offset)
                ),
            );
        }
        checker.point_within(&format!("{path}.flap_centre_of_mass_m"), &m.flap_centre_of_mass_m);
        for (key, value) in m.hardware.given() {
            let (min, max) = HARDWARE_SIZE_M;
            checker.in_range(&format!("{path}.hardware.{key}"), value, min, max, false);
        }
        if m.inner_slot_radius_m.is_finite() && m.inner_slot_radius_m >= m.outer_slot_radius_m {
            // Thesis section 5.3, red-cell condition 2.
            checker.fail(
                &format!("{path}.inner_slot_radius_m"),
                format!(
                    "= {}: must be smaller than outer_slot_radius_m = {} (thesis 5.3, condition 2)",
                    number(m.inner_slot_radius_m),
                    number(m.outer_slot_radius_m)
                ),
            );
        }
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        Some((self.rotation_range_deg, "rotation_range_deg"))
    }

    /// Screw, jack body, nut and the three fittings move; the two tracks are fixed but
    /// counted, as the check pairs them too.
    fn flap_mass_kg(&self) -> f64 {
        self.flap_mass_kg
    }

    fn moving_parts(&self) -> usize {
        7
    }

    /// Dimensioned by hand: nothing is searched.
    fn synthesis_cost_s(&self, _airfoil_points_per_side: usize) -> f64 {
        0.0
    }

    /// From the table alone: the thesis kind is dimensioned by hand.
    fn synthesise(&self, _context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        match self.track() {
            Ok(track) => Ok(Arc::new(track)),
            Err(
                error @ (flapwright_mechanism::Error::NutOnScrewPivot { .. }
                | flapwright_mechanism::Error::CollinearityImpossible { .. }),
            ) => Err(format!("cannot be synthesised: {error}; change {SCREW_GEOMETRY_KEYS}")),
            Err(error) => Err(format!("cannot be synthesised: {error}")),
        }
    }

    fn geometry_keys(&self) -> &'static str {
        SCREW_GEOMETRY_KEYS
    }

    /// The thesis statics (eqs. 3.4.x) take a hinge moment and the weight only.
    fn takes_normal_force(&self) -> bool {
        false
    }
}
