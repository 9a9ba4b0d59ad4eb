//! Dimensions of the circular-arc track with screw jack (thesis Chapter 3, Table 2).

use nalgebra::Point2;
use serde::{Deserialize, Serialize};

use flapwright_mechanism::shared::angle::DEFAULT_TOGGLE_TOLERANCE_RAD;
use flapwright_mechanism::shared::screw_jack::ScrewJack;

/// The designer's choices for one circular-arc-track station (thesis steps 4-7 and 10).
///
/// Frame: the thesis station frame, in SI (the thesis works in mm): origin A0 = the flap
/// hinge (remote centre of both slots), x towards the nose, y up, angles counter-clockwise
/// positive. With the flap aft of the hinge, counter-clockwise rotation (θ12 growing) moves
/// the trailing edge down: deflection = θ12 - θ12,i, trailing-edge-down positive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CircularArcTrackSpec {
    /// a1 = |A0 B0| (m): hinge to the screw's fixed pivot (thesis Fig. 11).
    pub base_distance_m: f64,
    /// a2 = |A0 A| (m): hinge to the nut pivot on the flap (thesis Fig. 11).
    pub crank_length_m: f64,
    /// a3 = |B0 B| (m): screw length (thesis step 9; red cell 3 if < s34,f).
    pub screw_length_m: f64,
    /// α0 = ∠x A0 B0 (rad).
    pub base_angle_rad: f64,
    /// b1 (m): radius of the outer (larger) slot, which carries pin F (thesis Fig. 12).
    pub outer_slot_radius_m: f64,
    /// c1 (m): radius of the inner (smaller) slot, which carries pin G (red cell 2 if >= b1).
    pub inner_slot_radius_m: f64,
    /// β1 = ∠x A0 F1,i (rad): stowed direction of pin F on the outer slot.
    pub outer_slot_start_angle_rad: f64,
    /// β2 = ∠F1,i A0 F2,i (rad): stowed pin G lies at β1 + β2 on the inner slot.
    pub inner_slot_offset_angle_rad: f64,
    /// β3 (rad): arc angle of both slots = full flap rotation.
    pub rotation_range_rad: f64,
    /// D stowed, (x_D, y_D) (m): flap centre of mass with the flap closed (thesis step 10).
    pub centre_of_mass_stowed_m: Point2<f64>,
    /// m_flap (kg): mass carried by this mechanism.
    pub flap_mass_kg: f64,
    /// I_D (kg m²): flap moment of inertia about its centre of mass D, used only by load
    /// cases with `include_inertia` (the thesis neglects inertia; its case has none).
    #[serde(default)]
    pub flap_moment_of_inertia_kgm2: f64,
    /// g (m/s²), acting along -y (thesis Appendix B small-angle assumption).
    pub gravity_mps2: f64,
    /// The screw jack (l, r, f of thesis section 3.6).
    pub screw: ScrewJack,
    /// ṡ34 (m/s): nominal nut speed used by sweeps (Table 2: 35 mm/s).
    pub nominal_input_speed_mps: f64,
    /// s̈34 (m/s²): nominal nut acceleration used by sweeps (Table 2: 0).
    pub nominal_input_accel_mps2: f64,
    /// Transmission angles below this (rad) are toggles.
    pub toggle_tolerance_rad: f64,
}

impl CircularArcTrackSpec {
    /// The case study of Arslan (2022), "Development of kinetostatic design methodology for
    /// airplane flap mechanisms", MSc thesis, İzmir Institute of Technology, section 5.2 and
    /// Table 2 (yellow input cells), converted from mm to m:
    /// a1 = 275 mm, a2 = 240 mm, a3 = 250 mm, α0 = 65°, b1 = 350 mm, c1 = 300 mm, β1 = 40°,
    /// β2 = 20°, β3 = 35°, D = (-30, 340) mm, m = 12 kg, g = 9.81 m/s², l = 8 mm, r = 16 mm,
    /// f = 0.1, ṡ34 = 35 mm/s, s̈34 = 0. The computed green cells (s34,i, Δs, g2, p2, q2,
    /// α2) are outputs of [`crate::CircularArcTrack::synthesise`]. The same numbers are in
    /// `data/validation/thesis-table2.csv`.
    pub fn thesis_case_study() -> Self {
        Self {
            base_distance_m: 0.275,
            crank_length_m: 0.240,
            screw_length_m: 0.250,
            base_angle_rad: 65f64.to_radians(),
            outer_slot_radius_m: 0.350,
            inner_slot_radius_m: 0.300,
            outer_slot_start_angle_rad: 40f64.to_radians(),
            inner_slot_offset_angle_rad: 20f64.to_radians(),
            rotation_range_rad: 35f64.to_radians(),
            centre_of_mass_stowed_m: Point2::new(-0.030, 0.340),
            flap_mass_kg: 12.0,
            flap_moment_of_inertia_kgm2: 0.0,
            gravity_mps2: 9.81,
            screw: ScrewJack {
                lead_m: 0.008,
                mean_radius_m: 0.016,
                friction_coefficient: 0.1,
            },
            nominal_input_speed_mps: 0.035,
            nominal_input_accel_mps2: 0.0,
            toggle_tolerance_rad: DEFAULT_TOGGLE_TOLERANCE_RAD,
        }
    }
}
