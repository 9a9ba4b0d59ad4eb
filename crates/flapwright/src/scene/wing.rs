//! The aircraft: `[wing]` with its sections and panels, `[[flap]]`, `[structure]`.

use serde::Deserialize;

/// Which reference line the panel sweep angles are measured on.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default, schemars::JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum SweepReferenceScene {
    /// Leading-edge sweep.
    #[default]
    LeadingEdge,
    /// Quarter-chord sweep.
    QuarterChord,
}

/// `[wing]`: sections root to tip and the panels between them.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WingScene {
    /// Leading edge of the root section, aircraft frame (x aft, y outboard, z up), m.
    #[serde(default)]
    pub root_leading_edge_m: [f64; 3],
    /// Line on which the panel sweep angles are measured.
    #[serde(default)]
    pub sweep_reference: SweepReferenceScene,
    /// Chord fraction about which sections are twisted (0 = leading edge).
    #[serde(default = "quarter")]
    pub twist_axis_chord_fraction: f64,
    /// Sections, root to tip (at least two).
    pub sections: Vec<WingSectionScene>,
    /// One panel between each pair of consecutive sections.
    pub panels: Vec<PanelScene>,
}

fn quarter() -> f64 {
    0.25
}

/// `[[wing.sections]]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WingSectionScene {
    /// Spanwise position (aircraft y), m.
    pub y_m: f64,
    /// Chord, m.
    pub chord_m: f64,
    /// Twist, positive nose up, deg.
    #[serde(default)]
    pub twist_deg: f64,
    /// `"NACA 2412"`, `"NACA 23012"` or a `.dat` file (Selig or Lednicer).
    pub airfoil: String,
}

/// `[[wing.panels]]`: the part of the wing between two consecutive sections.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PanelScene {
    /// Sweep angle on the wing's sweep reference line, deg.
    #[serde(default)]
    pub sweep_deg: f64,
    /// Dihedral angle, deg (negative: anhedral).
    #[serde(default)]
    pub dihedral_deg: f64,
}

/// `[[flap]]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FlapScene {
    /// Flap name; stations refer to it.
    pub name: String,
    /// Inboard end, aircraft y, m.
    pub y_inboard_m: f64,
    /// Outboard end, aircraft y, m.
    pub y_outboard_m: f64,
    /// Flap chord / local wing chord at the inboard end.
    pub chord_fraction_inboard: f64,
    /// Flap chord / local wing chord at the outboard end.
    pub chord_fraction_outboard: f64,
    /// Own flap section nested in the cove (`"n63212.dat"`); absent: the flap is cut out of
    /// the wing section.
    pub airfoil: Option<String>,
    /// Spanwise gap between each flap side and the wing, m (default: 0.5 % of the local
    /// chord). A hinge line that is not perpendicular to the streamwise flap sides moves
    /// the sides spanwise as the flap deploys.
    pub side_gap_m: Option<f64>,
    /// How far the wing's upper skin reaches aft over the stowed flap's nose (fraction of
    /// the local chord); absent: no shroud.
    pub shroud_chord_fraction: Option<f64>,
    /// The aft element of a two-element (double-slotted) flap, nested under the main
    /// element's trailing edge; absent: a single-element flap.
    pub aft_element: Option<AftElementScene>,
    /// The flap rotation axis.
    pub hinge: HingeScene,
    /// Flap settings, deg of rotation about the hinge axis (trailing edge down positive).
    #[serde(default)]
    pub settings: SettingsScene,
}

impl FlapScene {
    /// The names of the flap's parts: its own (the main element) and its aft element's.
    pub fn part_names(&self) -> Vec<String> {
        let mut names = vec![self.name.clone()];
        if self.aft_element.is_some() {
            names.push(flapwright_geom::parts::aft_element_name(&self.name));
        }
        names
    }

    /// Whether `part` is one of the flap's parts ([`FlapScene::part_names`]).
    pub fn owns_part(&self, part: &str) -> bool {
        part == self.name
            || (self.aft_element.is_some() && part == flapwright_geom::parts::aft_element_name(&self.name))
    }
}

/// `[flap.aft_element]`: the second element of a double-slotted flap, nested in the flap's
/// own section as the flap is in the wing (trailing edges together); the mechanism's
/// aft-flap body moves it, or it stays fixed to the main element when the kind has none.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AftElementScene {
    /// Its section (`"NACA 0009"`, a `.dat` file).
    pub airfoil: String,
    /// Its chord as a fraction of the flap chord.
    pub chord_fraction: f64,
    /// How far the main element's upper skin reaches aft over its nose (fraction of the
    /// flap chord); absent: no shroud.
    pub shroud_chord_fraction: Option<f64>,
}

/// `[flap.hinge]`: either two points or a chord fraction and depth.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HingeScene {
    /// Inboard axis point, aircraft frame, m.
    pub inboard_point_m: Option<[f64; 3]>,
    /// Outboard axis point, aircraft frame, m.
    pub outboard_point_m: Option<[f64; 3]>,
    /// Hinge at this fraction of the local wing chord ...
    pub chord_fraction: Option<f64>,
    /// ... and this far below the chord line, as a fraction of the local wing chord.
    pub depth_below_chord_fraction: Option<f64>,
}

/// `[flap.settings]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SettingsScene {
    /// Take-off deflection, deg.
    pub takeoff_deg: f64,
    /// Landing deflection (fully deployed), deg.
    pub landing_deg: f64,
    /// Target gap at take-off, % of the local chord (`003_...` Fig. 3); optional.
    pub takeoff_gap_percent: Option<f64>,
    /// Target overlap at take-off, % of the local chord; optional.
    pub takeoff_overlap_percent: Option<f64>,
    /// Target gap at landing, % of the local chord; optional.
    pub landing_gap_percent: Option<f64>,
    /// Target overlap at landing, % of the local chord; optional.
    pub landing_overlap_percent: Option<f64>,
    /// The gap the structure keeps where a setting asks for less (a sealed slot: a seal on
    /// the wing's trailing edge closes the rest), m; by default twice the required
    /// clearance of `[interference]` (the clearance, and as much again for the stations'
    /// compromise on a rigid flap).
    pub sealed_gap_m: Option<f64>,
}

impl SettingsScene {
    /// The target (gap, overlap) in % of the local chord of `setting` ("takeoff" or
    /// "landing"), each when the scene gives it.
    pub fn targets(&self, setting: &str) -> (Option<f64>, Option<f64>) {
        match setting {
            "takeoff" => (self.takeoff_gap_percent, self.takeoff_overlap_percent),
            "landing" => (self.landing_gap_percent, self.landing_overlap_percent),
            _ => (None, None),
        }
    }

    /// The structural gap of a sealed setting (m): `sealed_gap_m`, or three times
    /// `required_clearance_m`.
    pub fn sealed_gap_m(&self, required_clearance_m: f64) -> f64 {
        self.sealed_gap_m.unwrap_or(3.0 * required_clearance_m)
    }
}

impl Default for SettingsScene {
    fn default() -> Self {
        Self {
            takeoff_deg: 15.0,
            landing_deg: 35.0,
            takeoff_gap_percent: None,
            takeoff_overlap_percent: None,
            landing_gap_percent: None,
            landing_overlap_percent: None,
            sealed_gap_m: None,
        }
    }
}

/// `[structure]`.
#[derive(Debug, Clone, Deserialize, Default, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StructureScene {
    /// Spars as plates at a chord fraction.
    #[serde(default)]
    pub spars: Vec<SparScene>,
    /// The flap drive torque tube.
    pub torque_tube: Option<TorqueTubeScene>,
}

/// `[[structure.spars]]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SparScene {
    /// Part name.
    pub name: String,
    /// Chord fraction of the spar's mid-plane.
    pub chord_fraction: f64,
    /// Web thickness, m.
    pub thickness_m: f64,
    /// Inboard end, aircraft y, m.
    pub y_start_m: f64,
    /// Outboard end, aircraft y, m.
    pub y_end_m: f64,
}

/// `[structure.torque_tube]`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TorqueTubeScene {
    /// Polyline of the tube axis, aircraft frame, m (or give `chord_fraction`).
    pub path_m: Option<Vec<[f64; 3]>>,
    /// Or: the axis runs through this chord fraction of the wing sections (from the
    /// leading edge), so that a change of sweep, dihedral or twist carries it along.
    pub chord_fraction: Option<f64>,
    /// With `chord_fraction`: this fraction of the local chord below the chord line
    /// (negative: above). Default 0.
    pub depth_below_chord_fraction: Option<f64>,
    /// With `chord_fraction`: from here (aircraft y, m; default: the wing root).
    pub y_start_m: Option<f64>,
    /// With `chord_fraction`: to here (aircraft y, m; default: the outermost flap's
    /// outboard end).
    pub y_end_m: Option<f64>,
    /// Outer radius, m.
    pub radius_m: f64,
}
