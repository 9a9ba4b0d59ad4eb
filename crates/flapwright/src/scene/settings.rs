//! Settings tables: `[sizing]`, `[[materials]]`, `[interference]`, `[outputs]`,
//! `[resolution]`.

use serde::Deserialize;

/// `[sizing]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SizingScene {
    /// Material of the screws (sized as rods for strength and buckling): a preset
    /// (`steel-4340`, `aluminium-7075-t6`, `titanium-ti-6al-4v`) or a `[[materials]]` name.
    #[serde(default = "default_screw_material")]
    pub screw_material: String,
    /// Material of the torque tubes.
    #[serde(default = "default_tube_material")]
    pub torque_tube_material: String,
    /// Material of the mechanisms' two-force members (links, truss members), sized as
    /// pinned rods for strength and buckling.
    #[serde(default = "default_link_material")]
    pub link_material: String,
    /// Efficiency of each station gearbox, (0, 1].
    #[serde(default = "default_gearbox_efficiency")]
    pub gearbox_efficiency: f64,
    /// Torque tube inner / outer radius, [0, 1) (0: solid).
    #[serde(default = "default_wall_ratio")]
    pub torque_tube_inner_to_outer_ratio: f64,
    /// Euler end-fixity factor K of the screws (1: pinned-pinned).
    #[serde(default = "default_end_fixity")]
    pub screw_end_fixity_factor: f64,
}

fn default_screw_material() -> String {
    "steel-4340".into()
}
fn default_link_material() -> String {
    "steel-4340".into()
}
fn default_tube_material() -> String {
    "aluminium-7075-t6".into()
}
fn default_gearbox_efficiency() -> f64 {
    0.9
}
fn default_wall_ratio() -> f64 {
    0.8
}
fn default_end_fixity() -> f64 {
    1.0
}

impl Default for SizingScene {
    fn default() -> Self {
        Self {
            screw_material: default_screw_material(),
            torque_tube_material: default_tube_material(),
            link_material: default_link_material(),
            gearbox_efficiency: default_gearbox_efficiency(),
            torque_tube_inner_to_outer_ratio: default_wall_ratio(),
            screw_end_fixity_factor: default_end_fixity(),
        }
    }
}

/// `[interference]`: the clearance check (defaults chosen from the error-vs-time study in
/// `docs/report.md`).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct InterferenceScene {
    /// Smallest acceptable clearance between parts, m.
    #[serde(default = "default_clearance")]
    pub required_clearance_m: f64,
    /// Evenly spaced deployment samples before refinement.
    #[serde(default = "default_initial_samples")]
    pub initial_samples: usize,
    /// Refine until the certified bound is within this of the sampled minimum, m.
    #[serde(default = "default_tolerance")]
    pub tolerance_m: f64,
    /// Relative refinement tolerance: a clearance is located to the larger of
    /// `tolerance_m` and this fraction of itself.
    #[serde(default = "default_relative_tolerance")]
    pub relative_tolerance: f64,
    /// Distance evaluations per part pair at most.
    #[serde(default = "default_max_evaluations")]
    pub max_evaluations: usize,
    /// Largest separation allowed between parts joined by design (the nut on its screw,
    /// the fitting at the nut pivot), m.
    #[serde(default = "default_joint_play")]
    pub joint_play_m: f64,
    /// How far the openings cut in the skin and the flap for a station's mechanism reach
    /// beyond its swept solids, m; default twice the required clearance (a part passing
    /// through an opening then clears its edges by the requirement).
    #[serde(default)]
    pub opening_margin_m: Option<f64>,
    /// A station's parts need at least this share of the local flap chord as clearance
    /// (%), where that is more than `required_clearance_m`: scales the requirement with the
    /// wing (a 1/17 model and its full-size aircraft ask the same of their mechanisms).
    #[serde(default)]
    pub required_clearance_percent_flap_chord: Option<f64>,
    /// Refine each pair only until its verdict against its required clearance is certain
    /// (`flapwright_interference::SweepSettings::stop_at_verdict`), not until its minimum
    /// is located to the tolerance: the same certified pass or fail, with each pair's
    /// `min_clearance_m` then only its smallest sample (`residual_bound_m` says how much
    /// lower the minimum may be). The trade study sets it: it reads only the verdicts.
    #[serde(default)]
    pub stop_at_verdict: bool,
}

impl InterferenceScene {
    /// The opening margin, given or defaulted (m).
    pub fn opening_margin_m(&self) -> f64 {
        self.opening_margin_m.unwrap_or(2.0 * self.required_clearance_m)
    }
}

/// 0.5 mm: the radial play of a plain trunnion bearing of this size is tenths of a
/// millimetre; a nut that leaves its screw separates by far more.
fn default_joint_play() -> f64 {
    0.0005
}

fn default_clearance() -> f64 {
    0.003
}
fn default_initial_samples() -> usize {
    9
}
fn default_tolerance() -> f64 {
    0.001
}
fn default_relative_tolerance() -> f64 {
    0.01
}
fn default_max_evaluations() -> usize {
    400
}

impl Default for InterferenceScene {
    fn default() -> Self {
        Self {
            required_clearance_m: default_clearance(),
            initial_samples: default_initial_samples(),
            tolerance_m: default_tolerance(),
            relative_tolerance: default_relative_tolerance(),
            max_evaluations: default_max_evaluations(),
            joint_play_m: default_joint_play(),
            opening_margin_m: None,
            required_clearance_percent_flap_chord: None,
            stop_at_verdict: false,
        }
    }
}

/// `[[materials]]`: a custom material.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialScene {
    /// Name used in `[sizing]`.
    pub name: String,
    /// Density, kg/m^3.
    pub density_kg_m3: f64,
    /// Allowable tensile (and compressive) stress, Pa.
    pub allowable_tensile_pa: f64,
    /// Allowable shear stress, Pa.
    pub allowable_shear_pa: f64,
    /// Young's modulus, Pa.
    pub youngs_modulus_pa: f64,
}

/// `[design]`: what the mechanism searches weigh besides the fairing's depth
/// ([`flapwright_mechanism::shared::objective`]).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DesignScene {
    /// Weight of a screw jack's peak load, in reference loads (the largest force the load
    /// cases put on the flap), against the fairing's depth in flap chords (the dropped
    /// hinge's and the four-bar's jack placement); 0: the shallowest placement whatever
    /// its screw carries.
    #[serde(default = "default_actuator_load_weight")]
    pub actuator_load_weight: f64,
    /// Weight of a rotary actuator's peak torque, in reference torques (that force times
    /// the flap chord), against the fairing's depth in flap chords (the link-track's
    /// search); 0: the shallowest link whatever it needs. Default 1: five times the screw
    /// jacks' weight, since a rotary actuator carries about a fifth as many of its
    /// reference loads (`003_...` Table 1: 0.09 against 0.29-0.55).
    #[serde(default = "default_rotary_actuator_load_weight")]
    pub rotary_actuator_load_weight: f64,
    /// The four-bar's screw load, in reference loads, above which its placement trades
    /// steeply (each reference load over it worth two flap chords of fairing depth): the
    /// shallowest clear placement whose screw carries at most this; default 1, the whole
    /// air and inertia load on the flap.
    #[serde(default = "default_four_bar_actuator_load_cap")]
    pub four_bar_actuator_load_cap: f64,
    /// Weight of the mass a screw jack's placement adds (the screw and a horn beyond the
    /// body's pivot, sized from the `[sizing]` materials under the load cases times the
    /// safety factor), in the station's flap shares, against the fairing's depth in flap
    /// chords; 0: not weighed. Default 0.5: a kilogram worth about 5 mm of fairing depth on
    /// `transport-flap`, whose 1.6-1.8 m flaps' stations carry 150-180 kg each.
    #[serde(default = "default_mechanism_mass_weight")]
    pub mechanism_mass_weight: f64,
}

fn default_mechanism_mass_weight() -> f64 {
    flapwright_mechanism::shared::objective::DEFAULT_MASS_WEIGHT
}

fn default_four_bar_actuator_load_cap() -> f64 {
    flapwright_kinds::four_bar::DEFAULT_JACK_LOAD_CAP
}

fn default_actuator_load_weight() -> f64 {
    flapwright_mechanism::shared::objective::DEFAULT_LOAD_WEIGHT
}

fn default_rotary_actuator_load_weight() -> f64 {
    flapwright_mechanism::shared::objective::DEFAULT_ROTARY_LOAD_WEIGHT
}

impl Default for DesignScene {
    fn default() -> Self {
        Self {
            actuator_load_weight: default_actuator_load_weight(),
            rotary_actuator_load_weight: default_rotary_actuator_load_weight(),
            four_bar_actuator_load_cap: default_four_bar_actuator_load_cap(),
            mechanism_mass_weight: default_mechanism_mass_weight(),
        }
    }
}

/// `[outputs]`: which results to produce; a stage that no requested output needs is skipped.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OutputsScene {
    /// Binary STL of every part.
    #[serde(default = "yes")]
    pub stl: bool,
    /// Mechanism kinematics and forces.
    #[serde(default = "yes")]
    pub kinematics: bool,
    /// Rods, screw jacks, torque tubes, drive power, masses (needs kinematics).
    #[serde(default = "yes")]
    pub sizing: bool,
    /// Clearance check and fairing depth (needs a wing).
    #[serde(default = "yes")]
    pub interference: bool,
    /// URDF of the wing and its mechanisms, with a trajectory file (needs a wing; writes the
    /// STL files it refers to).
    #[serde(default = "yes")]
    pub urdf: bool,
    /// SVG drawing and plots per station.
    #[serde(default = "yes")]
    pub svg: bool,
    /// Animated binary glTF of the deployment (needs a wing).
    #[serde(default = "yes")]
    pub gltf: bool,
    /// Where the STL files show the flaps and mechanisms (`export --at`; not a scene key).
    #[serde(skip)]
    pub stl_setting: StlSetting,
}

/// The flap setting the STL files show (`flapwright export --stl --at SETTING`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StlSetting {
    /// Flaps stowed (the URDF's and glTF's rest pose).
    #[default]
    Stowed,
    /// Each flap at its take-off deflection.
    Takeoff,
    /// Each flap at its landing deflection.
    Landing,
}

fn yes() -> bool {
    true
}

impl Default for OutputsScene {
    fn default() -> Self {
        Self {
            stl: true,
            kinematics: true,
            sizing: true,
            interference: true,
            urdf: true,
            svg: true,
            gltf: true,
            stl_setting: StlSetting::Stowed,
        }
    }
}

/// `[resolution]`: discretisation knobs (defaults chosen from the error-vs-time tables in
/// `docs/report.md`).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ResolutionScene {
    /// Airfoil points per side (upper/lower).
    #[serde(default = "default_points_per_side")]
    pub airfoil_points_per_side: usize,
    /// Deployment samples per station sweep.
    #[serde(default = "default_samples")]
    pub deployment_samples: usize,
    /// Flap rotations at which the fairing depth is measured.
    #[serde(default = "default_fairing_samples")]
    pub fairing_samples: usize,
    /// Points along each round solid (capsule axis) at which the fairing depth is measured.
    #[serde(default = "default_fairing_points_per_capsule")]
    pub fairing_points_per_capsule: usize,
}

fn default_points_per_side() -> usize {
    60
}
fn default_samples() -> usize {
    51
}
fn default_fairing_samples() -> usize {
    21
}
fn default_fairing_points_per_capsule() -> usize {
    8
}

impl Default for ResolutionScene {
    fn default() -> Self {
        Self {
            airfoil_points_per_side: default_points_per_side(),
            deployment_samples: default_samples(),
            fairing_samples: default_fairing_samples(),
            fairing_points_per_capsule: default_fairing_points_per_capsule(),
        }
    }
}
