//! The hooked-track (`003_...` section 3, Figs. 6 and 10) as a scene table: synthesised from
//! the flap's stowed and landing settings (take-off's miss is reported); the carriage and
//! roller pins and the lead-in are searched unless given.

use std::sync::Arc;

use flapwright_kinds::{HookedTrack, HookedTrackSpec};
use flapwright_mechanism::FlapMechanism;
use nalgebra::Point2;
use serde::Deserialize;

use super::dropped_hinge::default_transmission;
use super::{check_synthesised, KindScene, ScrewDriveScene, SynthesisContext};
use crate::scene::KeyChecker;

/// `[station.mechanism]` with `kind = "hooked-track"` (station frame, m).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HookedTrackScene {
    /// Flap mass carried by this station, kg.
    pub flap_mass_kg: f64,
    /// Flap centre of mass (stowed); absent: the flap section's centroid.
    pub flap_centre_of_mass_m: Option<[f64; 2]>,
    /// The carriage's pin F on the flap (stowed); absent: searched.
    pub forward_attachment_m: Option<[f64; 2]>,
    /// The roller's pin G on the flap (stowed); absent: searched.
    pub aft_attachment_m: Option<[f64; 2]>,
    /// The lead-in's share of the stroke (the flap translates over it); absent: searched.
    pub lead_fraction: Option<f64>,
    /// Smallest transmission angle over the deployment, deg.
    #[serde(default = "default_transmission")]
    pub min_transmission_angle_deg: f64,
    /// The screw jack's thread and the shared drive.
    #[serde(default)]
    pub screw: ScrewDriveScene,
}

/// Lead-in fractions a scene may give: none up to nine tenths of the stroke.
const LEAD_FRACTION: (f64, f64) = (0.0, 0.9);

/// Shortest lead-in a scene may give besides none, fraction of the stroke: a lead-in of
/// 1e-300 of the stroke is a hook segment of no length, whose tube cannot be meshed (the
/// interference stage failed on it); 1 % (a millimetre on a 0.1 m stroke) meshes, and the
/// search's shortest is 5 %.
const MIN_LEAD_FRACTION: f64 = 0.01;

fn point([x, y]: [f64; 2]) -> Point2<f64> {
    Point2::new(x, y)
}

impl KindScene for HookedTrackScene {
    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        check_synthesised(
            checker,
            path,
            self.flap_mass_kg,
            self.flap_centre_of_mass_m.as_ref(),
            self.min_transmission_angle_deg,
            Some(&self.screw),
        );
        for (key, p) in [
            ("forward_attachment_m", &self.forward_attachment_m),
            ("aft_attachment_m", &self.aft_attachment_m),
        ] {
            if let Some(p) = p {
                checker.point_within(&format!("{path}.{key}"), p);
            }
        }
        if let Some(lead) = self.lead_fraction {
            let (lo, hi) = LEAD_FRACTION;
            if checker.in_range(&format!("{path}.lead_fraction"), lead, lo, hi, false)
                && lead > 0.0
                && lead < MIN_LEAD_FRACTION
            {
                checker.fail(
                    &format!("{path}.lead_fraction"),
                    format!(
                        "= {}: a lead-in this short is a hook segment of no length; give 0 (no lead-in) or at least {MIN_LEAD_FRACTION} of the stroke",
                        crate::scene::number(lead)
                    ),
                );
            }
        }
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        None
    }

    /// The flap's fitting and roller and the carriage move; the rail, hook, screw, jack
    /// body and struts are fixed.
    fn flap_mass_kg(&self) -> f64 {
        self.flap_mass_kg
    }

    fn moving_parts(&self) -> usize {
        3
    }

    /// Measured on `transport-flap`'s stations: 0.78 s a station at 60 points since the
    /// search keeps the wing-fixed solids clear of the moving flap (`ob-inner`, three
    /// syntheses of the sizing loop in 2.35 s; 0.10 s before); the growth with the points
    /// is the earlier measurement's (0.38 s at 1000 points then), not re-measured.
    fn synthesis_cost_s(&self, airfoil_points_per_side: usize) -> f64 {
        0.76 + 0.35e-3 * airfoil_points_per_side as f64
    }

    fn synthesise(&self, context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        let flap = context.station_flap(self.flap_mass_kg, self.flap_centre_of_mass_m)?;
        let spec = HookedTrackSpec {
            takeoff: flap.takeoff,
            landing: flap.landing,
            forward_attachment: self.forward_attachment_m.map(point),
            aft_attachment: self.aft_attachment_m.map(point),
            lead_fraction: self.lead_fraction,
            min_transmission_angle_rad: self.min_transmission_angle_deg.to_radians(),
            flap_mass: flap.mass,
            screw_drive: context.screw_drive(self.screw.drive()),
            hardware: flap.hardware,
            outline: flap.outline.clone(),
            design_loads: context.design_loads.clone(),
            follow: context.followed.clone(),
        };
        HookedTrack::synthesise(spec)
            .map(|m| Arc::new(m) as Arc<dyn FlapMechanism>)
            .map_err(|e| format!("cannot be synthesised: {e}"))
    }

    /// The rail and the hook shape the flap's path between stowed and landing: the flap's
    /// stations follow each other's motion.
    fn follows_motion(&self) -> bool {
        true
    }

    fn geometry_keys(&self) -> &'static str {
        "the flap settings, forward_attachment_m, aft_attachment_m and lead_fraction"
    }
}
