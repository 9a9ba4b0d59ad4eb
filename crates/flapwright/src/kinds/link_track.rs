//! The link-track (`003_...` section 3, Figs. 6 and 9) as a scene table: synthesised from
//! the flap's stowed, take-off and landing settings; the link's fixed pivot and the track's
//! slope are searched unless given.

use std::sync::Arc;

use flapwright_kinds::{LinkTrack, LinkTrackSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::Point2;
use serde::Deserialize;

use super::dropped_hinge::default_transmission;
use super::{check_synthesised, check_trade_index, KindScene, RotaryDriveScene, SynthesisContext};
use crate::scene::KeyChecker;

/// `[station.mechanism]` with `kind = "link-track"` (station frame, m).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LinkTrackScene {
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Flap centre of mass (stowed); absent: the flap section's centroid.
    pub flap_centre_of_mass_m: Option<[f64; 2]>,
    /// The link's fixed pivot, where the rotary actuator sits; absent: searched.
    pub link_pivot_m: Option<[f64; 2]>,
    /// The track's slope below the aft direction, deg; absent: searched.
    pub track_slope_deg: Option<f64>,
    /// Smallest transmission angle of the loop over the deployment, deg.
    #[serde(default = "default_transmission")]
    pub min_transmission_angle_deg: f64,
    /// The rotary actuator's gearing and the shared drive.
    #[serde(default)]
    pub rotary: RotaryDriveScene,
    /// Take this candidate of the search's trade (the report's `details.synthesis.trade`,
    /// from 0) instead of the one the weights choose; absent: theirs.
    pub trade_index: Option<usize>,
}

/// Track slopes a scene may give, deg below aft: any direction (the search goes round the
/// circle, and a flap that mostly turns may want its carriage to run forward, at 130 deg).
const TRACK_SLOPE_DEG: (f64, f64) = (-180.0, 180.0);

impl KindScene for LinkTrackScene {
    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        check_synthesised(
            checker,
            path,
            self.flap_mass_kg,
            self.flap_centre_of_mass_m.as_ref(),
            self.min_transmission_angle_deg,
            None,
        );
        if let Some(p) = &self.link_pivot_m {
            checker.point_within(&format!("{path}.link_pivot_m"), p);
        }
        if let Some(slope) = self.track_slope_deg {
            let (lo, hi) = TRACK_SLOPE_DEG;
            checker.in_range(&format!("{path}.track_slope_deg"), slope, lo, hi, false);
        }
        check_trade_index(
            checker,
            path,
            self.trade_index,
            flapwright_kinds::link_track::TRADE_CANDIDATES,
        );
        self.rotary.check(checker, path);
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        None
    }

    /// The flap's fitting and carriage and the link move; the track, actuator and struts
    /// are fixed.
    fn flap_mass_kg(&self) -> f64 {
        self.flap_mass_kg
    }

    fn moving_parts(&self) -> usize {
        3
    }

    /// Measured on `transport-flap`'s stations (0.10 s and 0.45 s a station at 60 and 1000 points).
    fn synthesis_cost_s(&self, airfoil_points_per_side: usize) -> f64 {
        0.07 + 0.4e-3 * airfoil_points_per_side as f64
    }

    fn synthesise(&self, context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        let flap = context.station_flap(self.flap_mass_kg, self.flap_centre_of_mass_m)?;
        let spec = LinkTrackSpec {
            takeoff: flap.takeoff,
            landing: flap.landing,
            link_pivot: self.link_pivot_m.map(|[x, y]| Point2::new(x, y)),
            track_slope_rad: self.track_slope_deg.map(f64::to_radians),
            min_transmission_angle_rad: self.min_transmission_angle_deg.to_radians(),
            flap_mass: flap.mass,
            rotary: self.rotary.drive(),
            hardware: flap.hardware,
            outline: flap.outline.clone(),
            design_loads: context.design_loads.clone(),
            load_weight: context.rotary_actuator_load_weight,
            follow: context.followed.clone(),
            trade_index: self.trade_index,
        };
        LinkTrack::synthesise(spec)
            .map(|m| Arc::new(m) as Arc<dyn FlapMechanism>)
            .map_err(|e| format!("cannot be synthesised: {e}"))
    }

    fn geometry_keys(&self) -> &'static str {
        "the flap settings, link_pivot_m, track_slope_deg and trade_index"
    }

    fn follows_motion(&self) -> bool {
        true
    }
}
