//! The dropped hinge (`003_...` section 3, Figs. 6-7) as a scene table: synthesised from the
//! flap's stowed and landing settings, its free choices as keys with defaults.

use std::sync::Arc;

use flapwright_kinds::{DroppedHinge, DroppedHingeActuator, DroppedHingeSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::Point2;
use serde::Deserialize;

use super::{
    check_synthesised, check_trade_index, ActuatorChoice, KindScene, RotaryDriveScene, ScrewDriveScene,
    SynthesisContext,
};
use crate::scene::KeyChecker;

/// `[station.mechanism]` with `kind = "dropped-hinge"` (station frame, m).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DroppedHingeScene {
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Flap centre of mass (stowed); absent: the flap section's centroid.
    pub flap_centre_of_mass_m: Option<[f64; 2]>,
    /// The hinged structure's forward and aft attachments on the flap's lower surface, as
    /// fractions of the flap chord from its leading edge.
    #[serde(default = "default_attachments")]
    pub attachment_chord_fractions: [f64; 2],
    /// Where the screw takes hold of the forward arm: 0 at the flap, 1 at the hinge, the
    /// only attachment tried; absent: searched (0.5 first, then 0.65, 0.8, 0.35 and a horn
    /// below the hinge at 1.4 and 1.8) for the first whose screw keeps clear.
    pub actuator_attachment_fraction: Option<f64>,
    /// The screw's mount; absent: square to the arm at mid-travel, at the first of a few
    /// distances (from half a flap chord) and attachments that keep clear of the wing, the
    /// structure and the turning flap.
    pub actuator_mount_m: Option<[f64; 2]>,
    /// The support truss's attachments; absent: the first points of the wing's lower skin
    /// ahead of the cove whose members keep clear of the structure and the turning flap.
    pub support_points_m: Option<[[f64; 2]; 2]>,
    /// Smallest transmission angle of the screw over the deployment, deg.
    #[serde(default = "default_transmission")]
    pub min_transmission_angle_deg: f64,
    /// The actuator: `"screw-jack"` (default) or `"rotary"` (a geared rotary actuator on
    /// the hinge).
    #[serde(default)]
    pub actuator: ActuatorChoice,
    /// The screw jack's thread and the shared drive.
    #[serde(default)]
    pub screw: ScrewDriveScene,
    /// The rotary actuator's gearing and the shared drive.
    #[serde(default)]
    pub rotary: RotaryDriveScene,
    /// Take this candidate of the screw jack placement's trade (the report's
    /// `details.synthesis.trade`, from 0) instead of the one the weights choose; absent:
    /// theirs.
    pub trade_index: Option<usize>,
}

pub(super) fn default_attachments() -> [f64; 2] {
    [0.15, 0.5]
}

pub(super) fn default_transmission() -> f64 {
    30.0
}

fn point(p: [f64; 2]) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

impl KindScene for DroppedHingeScene {
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
        for (k, fraction) in self.attachment_chord_fractions.iter().enumerate() {
            checker.in_range(
                &format!("{path}.attachment_chord_fractions[{k}]"),
                *fraction,
                0.02,
                0.98,
                false,
            );
        }
        let [forward, aft] = self.attachment_chord_fractions;
        if forward.is_finite() && aft.is_finite() && aft - forward < 0.05 {
            checker.fail(
                &format!("{path}.attachment_chord_fractions"),
                format!("= [{forward}, {aft}]: the aft attachment must lie at least 5 % of the flap chord behind the forward one"),
            );
        }
        check_trade_index(
            checker,
            path,
            self.trade_index,
            flapwright_mechanism::shared::placement::JACK_TRADE_CANDIDATES,
        );
        if let Some(fraction) = self.actuator_attachment_fraction {
            checker.in_range(
                &format!("{path}.actuator_attachment_fraction"),
                fraction,
                0.05,
                0.95,
                false,
            );
        }
        if let Some(mount) = &self.actuator_mount_m {
            checker.point_within(&format!("{path}.actuator_mount_m"), mount);
            if self.actuator == ActuatorChoice::Rotary {
                checker.fail(
                    &format!("{path}.actuator_mount_m"),
                    "places a screw jack's mount, and actuator = \"rotary\" puts a geared rotary actuator on the hinge: remove it, or use actuator = \"screw-jack\"".into(),
                );
            }
        }
        self.rotary.check(checker, path);
        for (k, support) in self.support_points_m.iter().flatten().enumerate() {
            checker.point_within(&format!("{path}.support_points_m[{k}]"), support);
        }
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        None
    }

    /// Two arms, screw, jack body and nut move (a rotary actuator: the arms); two truss
    /// members are fixed.
    fn flap_mass_kg(&self) -> f64 {
        self.flap_mass_kg
    }

    fn moving_parts(&self) -> usize {
        7
    }

    /// Measured on `transport-flap`'s stations (0.03 s, 0.43 s and 0.87 s a station at 60, 1000 and 2000 points).
    fn synthesis_cost_s(&self, airfoil_points_per_side: usize) -> f64 {
        0.01 + 0.45e-3 * airfoil_points_per_side as f64
    }

    fn synthesise(&self, context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        let flap = context.station_flap(self.flap_mass_kg, self.flap_centre_of_mass_m)?;
        let attachment = |fraction: f64| {
            flap.outline
                .flap_lower_point(fraction)
                .ok_or(format!("no flap surface at {fraction} of the flap chord"))
        };
        let flap_attachments = [
            attachment(self.attachment_chord_fractions[0])?,
            attachment(self.attachment_chord_fractions[1])?,
        ];
        let spec = DroppedHingeSpec {
            landing: flap.landing,
            takeoff: Some(flap.takeoff),
            flap_attachments,
            actuator: match self.actuator {
                ActuatorChoice::ScrewJack => DroppedHingeActuator::ScrewJack {
                    attachment_fraction: self.actuator_attachment_fraction,
                    mount: self.actuator_mount_m.map(point),
                    standoff_m: 0.5 * flap.flap_chord_m,
                    drive: context.screw_drive(self.screw.drive()),
                    trade_index: self.trade_index,
                },
                ActuatorChoice::Rotary => DroppedHingeActuator::Rotary(self.rotary.drive()),
            },
            support_points: self.support_points_m.map(|[a, b]| [point(a), point(b)]),
            flap_mass: flap.mass,
            min_transmission_angle_rad: self.min_transmission_angle_deg.to_radians(),
            hardware: flap.hardware,
            outline: flap.outline.clone(),
            design_loads: context.design_loads.clone(),
            load_weight: context.actuator_load_weight,
            mass_weighing: context.mass_weighing,
        };
        DroppedHinge::synthesise(spec)
            .map(|m| Arc::new(m) as Arc<dyn FlapMechanism>)
            .map_err(|e| format!("cannot be synthesised: {e}"))
    }

    fn geometry_keys(&self) -> &'static str {
        "the flap's landing setting, attachment_chord_fractions, actuator, actuator_attachment_fraction, actuator_mount_m and trade_index"
    }
}
