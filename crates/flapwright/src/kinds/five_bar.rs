//! The five-bar double-slotted flap (`001_...` section 2, Fig. 1) as a scene table: its
//! link lengths and fixed pivots in the document's plane (origin at the crank's pivot O,
//! x aft, y up), the crank's travel, and the two flaps' masses and aerodynamic data.
//! Nothing is synthesised: the document gives the mechanism; Flapwright assembles it on the
//! branch nearest stowed and checks it over the travel.

use std::sync::Arc;

use flapwright_kinds::{DoubleFlapLoads, FiveBarDimensions, FiveBarDoubleFlap, FiveBarKind, LoadedFiveBar};
use flapwright_mechanism::FlapMechanism;
use serde::Deserialize;

use super::{KindScene, RotaryDriveScene, SynthesisContext, GRAVITY_MPS2};
use crate::scene::limits::{FLAP_MASS_KG, MECHANISM_LENGTH_M};
use crate::scene::KeyChecker;

/// `[station.mechanism]` with `kind = "five-bar"` (m, in `001_...`'s plane: origin at the
/// crank pivot O, x aft, y up; the document's letter in brackets).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FiveBarScene {
    /// |A - O|, the crank (a).
    pub crank_m: f64,
    /// |G - A|, the drive link (b).
    pub drive_link_m: f64,
    /// |G - C|, the main flap's arm from its hinge (c).
    pub main_arm_m: f64,
    /// The main flap's hinge C (l, -r).
    pub main_hinge_m: [f64; 2],
    /// The rocker's fixed pivot B (C - (s - i t)).
    pub rocker_pivot_m: [f64; 2],
    /// |D - B|, the rocker (d).
    pub rocker_m: f64,
    /// |G - D| (p).
    pub flap_link_m: f64,
    /// |E - G|, the flap link's extension beyond G (g; the listing's q).
    pub flap_link_extension_m: f64,
    /// |H - E|, the secondary link (h).
    pub secondary_link_m: f64,
    /// |H - F|, the secondary flap's arm from its pivot (z).
    pub secondary_arm_m: f64,
    /// Main flap chord c₁.
    pub main_chord_m: f64,
    /// Secondary flap chord c₂.
    pub secondary_chord_m: f64,
    /// Crank angle with the flaps stowed, deg (counter-clockwise from +x).
    pub crank_stowed_deg: f64,
    /// Crank angle fully deployed, deg.
    pub crank_deployed_deg: f64,
    /// Main flap mass, kg.
    pub main_flap_mass_kg: f64,
    /// Main flap moment of inertia about its centre of mass, kg m².
    pub main_flap_inertia_kgm2: f64,
    /// Secondary flap mass, kg.
    pub secondary_flap_mass_kg: f64,
    /// Secondary flap moment of inertia about its centre of mass, kg m².
    pub secondary_flap_inertia_kgm2: f64,
    /// The flaps' aerodynamic data (linearised, `001_...` section 3.1).
    pub aero: AeroScene,
    /// The gearing between the drive and the crank.
    #[serde(default)]
    pub rotary: RotaryDriveScene,
}

/// `aero = { ... }`: lift linear in each flap's deflection at its quarter chord, a constant
/// pitching moment (positive nose up), at one flight condition.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AeroScene {
    /// Air speed, m/s.
    pub speed_mps: f64,
    /// Air density, kg/m³.
    pub density_kgpm3: f64,
    /// Main flap area, m².
    pub main_area_m2: f64,
    /// Secondary flap area, m².
    pub secondary_area_m2: f64,
    /// Main flap lift slope per radian of its deflection.
    pub main_lift_slope_per_rad: f64,
    /// Secondary flap lift slope per radian of its deflection.
    pub secondary_lift_slope_per_rad: f64,
    /// Main flap pitching-moment coefficient about its quarter chord.
    pub main_moment_coefficient: f64,
    /// Secondary flap pitching-moment coefficient about its quarter chord.
    pub secondary_moment_coefficient: f64,
}

/// Crank angles a scene may give, deg.
const CRANK_DEG: (f64, f64) = (-720.0, 720.0);
/// Air speeds, m/s; densities, kg/m³; areas, m²; coefficients.
const SPEED_MPS: (f64, f64) = (0.0, 400.0);
const DENSITY_KGPM3: (f64, f64) = (0.0, 2.0);
const AREA_M2: (f64, f64) = (0.0, 1e3);
const COEFFICIENT: (f64, f64) = (-10.0, 10.0);
const INERTIA_KGM2: (f64, f64) = (0.0, 1e6);

impl FiveBarScene {
    fn dimensions(&self) -> FiveBarDimensions {
        let [cx, cy] = self.main_hinge_m;
        let [bx, by] = self.rocker_pivot_m;
        FiveBarDimensions {
            a: self.crank_m,
            b: self.drive_link_m,
            c: self.main_arm_m,
            l: cx,
            r: -cy,
            d: self.rocker_m,
            p: self.flap_link_m,
            s: cx - bx,
            t: by - cy,
            g: self.flap_link_extension_m,
            h: self.secondary_link_m,
            z: self.secondary_arm_m,
            main_chord: self.main_chord_m,
            secondary_chord: self.secondary_chord_m,
        }
    }

    fn loads(&self) -> DoubleFlapLoads {
        let a = &self.aero;
        let q = 0.5 * a.density_kgpm3 * a.speed_mps * a.speed_mps;
        DoubleFlapLoads {
            main_mass_kg: self.main_flap_mass_kg,
            main_inertia_kgm2: self.main_flap_inertia_kgm2,
            secondary_mass_kg: self.secondary_flap_mass_kg,
            secondary_inertia_kgm2: self.secondary_flap_inertia_kgm2,
            main_lift_per_rad_n: q * a.main_area_m2 * a.main_lift_slope_per_rad,
            secondary_lift_per_rad_n: q * a.secondary_area_m2 * a.secondary_lift_slope_per_rad,
            main_moment_nm: q * a.main_area_m2 * self.main_chord_m * a.main_moment_coefficient,
            secondary_moment_nm: q * a.secondary_area_m2 * self.secondary_chord_m * a.secondary_moment_coefficient,
            gravity_mps2: GRAVITY_MPS2,
        }
    }
}

/// Least angle between the two links of any dyad over the crank travel, deg: closer to a
/// toggle the five-bar's rates and loads grow without bound.
const MIN_TOGGLE_DISTANCE_DEG: f64 = 1.0;

impl KindScene for FiveBarScene {
    fn models_own_dynamics(&self) -> bool {
        true
    }

    fn check(&self, checker: &mut dyn KeyChecker, path: &str) {
        let (lo, hi) = MECHANISM_LENGTH_M;
        for (key, value) in [
            ("crank_m", self.crank_m),
            ("drive_link_m", self.drive_link_m),
            ("main_arm_m", self.main_arm_m),
            ("rocker_m", self.rocker_m),
            ("flap_link_m", self.flap_link_m),
            ("flap_link_extension_m", self.flap_link_extension_m),
            ("secondary_link_m", self.secondary_link_m),
            ("secondary_arm_m", self.secondary_arm_m),
            ("main_chord_m", self.main_chord_m),
            ("secondary_chord_m", self.secondary_chord_m),
        ] {
            checker.in_range(&format!("{path}.{key}"), value, lo, hi, false);
        }
        for (key, point) in [
            ("main_hinge_m", &self.main_hinge_m),
            ("rocker_pivot_m", &self.rocker_pivot_m),
        ] {
            checker.point_within(&format!("{path}.{key}"), point);
        }
        let (lo, hi) = CRANK_DEG;
        for (key, value) in [
            ("crank_stowed_deg", self.crank_stowed_deg),
            ("crank_deployed_deg", self.crank_deployed_deg),
        ] {
            checker.in_range(&format!("{path}.{key}"), value, lo, hi, false);
        }
        if self.crank_stowed_deg == self.crank_deployed_deg {
            checker.fail(
                &format!("{path}.crank_deployed_deg"),
                "equals crank_stowed_deg: the crank must turn".into(),
            );
        }
        let (mass_lo, mass_hi) = FLAP_MASS_KG;
        let (inertia_lo, inertia_hi) = INERTIA_KGM2;
        for (key, value, (lo, hi)) in [
            ("main_flap_mass_kg", self.main_flap_mass_kg, (mass_lo, mass_hi)),
            (
                "secondary_flap_mass_kg",
                self.secondary_flap_mass_kg,
                (mass_lo, mass_hi),
            ),
            (
                "main_flap_inertia_kgm2",
                self.main_flap_inertia_kgm2,
                (inertia_lo, inertia_hi),
            ),
            (
                "secondary_flap_inertia_kgm2",
                self.secondary_flap_inertia_kgm2,
                (inertia_lo, inertia_hi),
            ),
        ] {
            checker.in_range(&format!("{path}.{key}"), value, lo, hi, false);
        }
        let a = &self.aero;
        for (key, value, (lo, hi)) in [
            ("speed_mps", a.speed_mps, SPEED_MPS),
            ("density_kgpm3", a.density_kgpm3, DENSITY_KGPM3),
            ("main_area_m2", a.main_area_m2, AREA_M2),
            ("secondary_area_m2", a.secondary_area_m2, AREA_M2),
            ("main_lift_slope_per_rad", a.main_lift_slope_per_rad, COEFFICIENT),
            (
                "secondary_lift_slope_per_rad",
                a.secondary_lift_slope_per_rad,
                COEFFICIENT,
            ),
            ("main_moment_coefficient", a.main_moment_coefficient, COEFFICIENT),
            (
                "secondary_moment_coefficient",
                a.secondary_moment_coefficient,
                COEFFICIENT,
            ),
        ] {
            checker.in_range(&format!("{path}.aero.{key}"), value, lo, hi, false);
        }
        self.rotary.check(checker, path);
    }

    fn deflection_range(&self) -> Option<(f64, &'static str)> {
        None
    }

    fn moving_parts(&self) -> usize {
        7
    }

    /// Dimensioned by hand: nothing is searched.
    fn synthesis_cost_s(&self, _airfoil_points_per_side: usize) -> f64 {
        0.0
    }

    fn flap_mass_kg(&self) -> f64 {
        self.main_flap_mass_kg + self.secondary_flap_mass_kg
    }

    fn aft_element_mass_kg(&self) -> f64 {
        self.secondary_flap_mass_kg
    }

    fn synthesise(&self, _context: &SynthesisContext) -> Result<Arc<dyn FlapMechanism>, String> {
        let mechanism = FiveBarDoubleFlap::assemble(
            self.dimensions(),
            self.crank_stowed_deg.to_radians(),
            self.crank_deployed_deg.to_radians(),
        )
        .map_err(|e| format!("does not assemble: {e}"))?;
        // Every crank angle of the travel must assemble on the same branch.
        let samples = 181;
        let mut deflections = (0.0, 0.0);
        let mut nearest_toggle: Option<(f64, f64)> = None;
        for k in 0..samples {
            let fraction = k as f64 / (samples - 1) as f64;
            let alpha =
                mechanism.stowed_crank_rad + fraction * (mechanism.deployed_crank_rad - mechanism.stowed_crank_rad);
            let pose = mechanism
                .pose(alpha)
                .map_err(|e| format!("does not reach crank_deployed_deg on its stowed branch: {e}"))?;
            if k == 0 {
                deflections.0 = pose.main_deflection.value;
            }
            deflections.1 = pose.main_deflection.value;
            if nearest_toggle.is_none_or(|(sine, _)| pose.toggle_sine < sine) {
                nearest_toggle = Some((pose.toggle_sine, alpha));
            }
        }
        // A dyad at a toggle has no rate to give: the dynamics' equation of motion is
        // singular there (the integrator's step shrank to nothing with the rocker pivot at
        // y = -1), and the statics' loads grow without bound.
        if let Some((sine, alpha)) = nearest_toggle {
            let angle_deg = sine.clamp(-1.0, 1.0).abs().asin().to_degrees();
            if angle_deg < MIN_TOGGLE_DISTANCE_DEG {
                return Err(format!(
                    "passes {angle_deg:.2} deg from a toggle (two links of a dyad in line) at crank angle {:.1} deg; keep every dyad at least {MIN_TOGGLE_DISTANCE_DEG} deg from one over the travel: change {}",
                    alpha.to_degrees(),
                    self.geometry_keys()
                ));
            }
        }
        // The crank deploys the main flap: its trailing edge goes down (δ grows). A layout
        // that turns it up has no deployment (the drawings' and the report's deflection
        // range runs from 0 to a negative angle: the main hinge at y = 0 did so).
        let turn_deg = (deflections.1 - deflections.0).to_degrees();
        if turn_deg.is_nan() || turn_deg <= 0.0 {
            return Err(format!(
                "turns the main flap {:.1} deg trailing edge up from crank_stowed_deg to crank_deployed_deg: a deployment turns it down; change {}",
                -turn_deg,
                self.geometry_keys()
            ));
        }
        let actuator = self
            .rotary
            .drive()
            .actuator_for(mechanism.deployed_crank_rad - mechanism.stowed_crank_rad);
        let loaded = LoadedFiveBar {
            mechanism,
            loads: self.loads(),
        };
        FiveBarKind::new(loaded, actuator)
            .map(|m| Arc::new(m) as Arc<dyn FlapMechanism>)
            .map_err(|e| format!("cannot be built: {e}"))
    }

    fn geometry_keys(&self) -> &'static str {
        "the link lengths, main_hinge_m, rocker_pivot_m, crank_stowed_deg and crank_deployed_deg"
    }

    fn takes_normal_force(&self) -> bool {
        false
    }
}
