//! The four-bar (`003_...` section 3, Figs. 6 and 8) as a scene table: synthesised from the
//! flap's stowed, take-off and landing settings; the moving pivots are searched unless
//! given.

use std::sync::Arc;

use flapwright_kinds::four_bar::FollowStation;
use flapwright_kinds::{FourBar, FourBarSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::Point2;
use serde::Deserialize;

use super::dropped_hinge::default_transmission;
use super::{check_synthesised, check_trade_index, KindScene, ScrewDriveScene, SynthesisContext};
use crate::scene::KeyChecker;

/// `[station.mechanism]` with `kind = "four-bar"` (station frame, m).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FourBarScene {
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Flap centre of mass (stowed); absent: the flap section's centroid.
    pub flap_centre_of_mass_m: Option<[f64; 2]>,
    /// The crank's moving pivot A1 on the flap (stowed); absent: searched.
    pub forward_pivot_m: Option<[f64; 2]>,
    /// The rocker's moving pivot A2 on the flap (stowed); absent: searched.
    pub aft_pivot_m: Option<[f64; 2]>,
    /// Smallest transmission angle over the deployment, of the loop and the screw, deg.
    #[serde(default = "default_transmission")]
    pub min_transmission_angle_deg: f64,
    /// Where the screw takes hold of the crank: 0 at its fixed pivot, 1 at the flap, the
    /// only attachment tried; absent: searched (0.5 first, then 0.35, 0.7, 0.9 and a horn
    /// beyond the fixed pivot at -0.4 and -0.7) for the first whose screw keeps clear.
    pub actuator_attachment_fraction: Option<f64>,
    /// The screw's mount; absent: square to the crank at mid-travel, half a flap chord off.
    pub actuator_mount_m: Option<[f64; 2]>,
    /// The screw jack's thread and the shared drive.
    #[serde(default)]
    pub screw: ScrewDriveScene,
    /// Take this candidate of the screw jack placement's trade (the report's
    /// `details.synthesis.jack_trade`, from 0) instead of the one the weights choose, for
    /// every linkage the search builds; absent: theirs.
    pub trade_index: Option<usize>,
}

fn point(p: [f64; 2]) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

impl KindScene for FourBarScene {
    fn gives_actuator_mount(&self) -> bool {
        self.actuator_mount_m.is_some()
    }

    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        check_synthesised(
            checker,
            path,
            self.flap_mass_kg,
            self.flap_centre_of_mass_m.as_ref(),
            self.min_transmission_angle_deg,
            Some(&self.screw),
        );
        check_trade_index(
            checker,
            path,
            self.trade_index,
            flapwright_mechanism::shared::placement::JACK_TRADE_CANDIDATES,
        );
        for (key, pivot) in [
            ("forward_pivot_m", &self.forward_pivot_m),
            ("aft_pivot_m", &self.aft_pivot_m),
            ("actuator_mount_m", &self.actuator_mount_m),
        ] {
            if let Some(p) = pivot {
                checker.point_within(&format!("{path}.{key}"), p);
            }
        }
        if let Some(fraction) = self.actuator_attachment_fraction {
            checker.in_range(
                &format!("{path}.actuator_attachment_fraction"),
                fraction,
                0.05,
                1.0,
                false,
            );
        }
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        None
    }

    /// Crank, rocker, bracket, screw, jack body and nut move; two struts are fixed.
    fn flap_mass_kg(&self) -> f64 {
        self.flap_mass_kg
    }

    fn moving_parts(&self) -> usize {
        8
    }

    /// Measured on `transport-flap`'s stations (0.31 s, 4.2 s and 8.3 s a station at 60, 1000 and 2000 points).
    fn synthesis_cost_s(&self, airfoil_points_per_side: usize) -> f64 {
        0.1 + 4.2e-3 * airfoil_points_per_side as f64
    }

    fn synthesise(&self, context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        let flap = context.station_flap(self.flap_mass_kg, self.flap_centre_of_mass_m)?;
        let spec = FourBarSpec {
            takeoff: flap.takeoff,
            landing: flap.landing,
            forward_pivot: self.forward_pivot_m.map(point),
            aft_pivot: self.aft_pivot_m.map(point),
            follow: None,
            min_transmission_angle_rad: self.min_transmission_angle_deg.to_radians(),
            actuator_attachment_fraction: self.actuator_attachment_fraction,
            actuator_mount: self.actuator_mount_m.map(point),
            actuator_standoff_m: 0.5 * flap.flap_chord_m,
            flap_mass: flap.mass,
            screw_drive: context.screw_drive(self.screw.drive()),
            hardware: flap.hardware,
            outline: flap.outline.clone(),
            design_loads: context.design_loads.clone(),
            load_weight: context.actuator_load_weight,
            load_cap: context.four_bar_actuator_load_cap,
            mass_weighing: context.mass_weighing,
            trade_index: self.trade_index,
        };
        // Follow the flap's first station (where the scene fixes neither moving pivot): the
        // same points of the flap section and the nearest motion at every station move the
        // rigid flap alike; where none builds here, this station searches. The first station
        // synthesised again follows the second's motion from the second's pivots
        // (`FollowedMotion::attachments`), so that the two meet between their paths.
        let follow = match (&context.followed, &context.companion) {
            (Some(followed), companion) if followed.attachments.len() == 2 => {
                let mut points = followed.attachments.clone();
                points.sort_by(|a, b| b.x.total_cmp(&a.x));
                Some(FollowStation {
                    pivots: [points[0], points[1]],
                    deflections_rad: companion
                        .as_ref()
                        .map(|c| c.deflections_rad.clone())
                        .unwrap_or_default(),
                    motion: Some(followed.clone()),
                })
            }
            (_, Some(c)) => {
                let mut points: Vec<_> = c
                    .attachments
                    .iter()
                    .filter_map(|&a| flap.outline.flap_point(a))
                    .collect();
                points.sort_by(|a, b| b.x.total_cmp(&a.x));
                (points.len() == 2 && c.attachments.len() == 2).then(|| FollowStation {
                    pivots: [points[0], points[1]],
                    deflections_rad: c.deflections_rad.clone(),
                    motion: None,
                })
            }
            _ => None,
        };
        let spec = FourBarSpec { follow, ..spec };
        FourBar::synthesise(spec)
            .map(|m| Arc::new(m) as Arc<dyn FlapMechanism>)
            .map_err(|e| format!("cannot be synthesised: {e}"))
    }

    fn follows_motion(&self) -> bool {
        true
    }

    fn geometry_keys(&self) -> &'static str {
        "the flap settings, forward_pivot_m, aft_pivot_m, actuator_attachment_fraction, actuator_mount_m and trade_index"
    }
}
