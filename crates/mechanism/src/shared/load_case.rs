//! Load cases, shared by every kind: the external moment on the flap, an aerodynamic
//! normal force from a flight condition, the load factor, and whether the flap's inertia
//! joins the quasi-static balance. Every kind's [`crate::seam::FlapMechanism::kinetostatics`]
//! takes a [`LoadCase`], so it lives here rather than in one kind's files (it was in the
//! circular-arc track's `kinetostatics.rs` until issue 36); the named thesis cases
//! ([`LoadCase::thesis_cruise`], [`LoadCase::thesis_landing`]) stay beside the type.

use serde::{Deserialize, Serialize};

/// The external (aerodynamic) moment M12 on the flap about the hinge A0, positive when it
/// tends to close the flap (clockwise in the station frame), N m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum ExternalMoment {
    /// Same moment at every deflection (thesis cruise scenario).
    Constant(f64),
    /// Linear between the stowed and the fully deployed value, interpolated over the nut
    /// stroke fraction (s34 - s34,i)/Δs. This is the reading that reproduces the thesis
    /// spreadsheet (Appendix C, Fig. 48): its M12 column steps by ΔM·10 mm/Δs per 10 mm
    /// row (14 895.6 N mm), not by ΔM·Δθ12/β3.
    Linear {
        /// M12 with the flap closed (N m).
        stowed_nm: f64,
        /// M12 with the flap fully deployed (N m).
        deployed_nm: f64,
    },
}

impl ExternalMoment {
    /// M12 (N m) at stroke fraction `stroke_fraction` = (s34 - s34,i)/Δs in [0, 1].
    pub fn at(&self, stroke_fraction: f64) -> f64 {
        match *self {
            Self::Constant(moment) => moment,
            Self::Linear { stowed_nm, deployed_nm } => {
                stowed_nm + (deployed_nm - stowed_nm) * stroke_fraction.clamp(0.0, 1.0)
            }
        }
    }
}

/// A named load case for one mechanism.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LoadCase {
    /// Name, e.g. `cruise` or `landing`.
    pub name: String,
    /// External moment on the flap share this mechanism carries.
    pub external_moment: ExternalMoment,
    /// Add the flap's inertia (d'Alembert: m a_D and I_D α12) to the quasi-static balance.
    #[serde(default)]
    pub include_inertia: bool,
    /// An aerodynamic normal force on the flap from a flight condition (absent: the external
    /// moment alone). Kinds synthesised from the flap settings take it; the thesis track's
    /// statics (thesis eqs. 3.4.x) have a moment and the weight only and refuse it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flap_normal_force: Option<FlapNormalForce>,
    /// Load factor n on the flap's weight (and, through [`FlapNormalForce`], its air load):
    /// `003_...` eq. 1 scales the normal force by n, and the weight of a manoeuvring flap
    /// is n m g as well. 1 in level flight and in the thesis cases.
    #[serde(default = "unit_load_factor")]
    pub load_factor: f64,
}

fn unit_load_factor() -> f64 {
    1.0
}

/// The normal force a flight condition puts on the flap share of one station: `C_N(δ)`
/// times `newtons_per_coefficient` (dynamic pressure x load factor x the station's share
/// of the flap area, `003_...` eq. 1 summed over the spanwise elements the station
/// carries), normal to the flap's chord (`003_...` eq. 1: "the normal force ... normal to
/// the flap chord"; the stowed chord's upward normal turned with the flap), at a point
/// fixed to the flap (the quarter chord).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FlapNormalForce {
    /// (deflection rad, C_N) rows, deflection increasing; linear between, held beyond.
    pub coefficients: Vec<(f64, f64)>,
    /// N per unit C_N.
    pub newtons_per_coefficient: f64,
    /// Where it acts on the stowed flap (station frame, m).
    pub at_stowed_m: nalgebra::Point2<f64>,
    /// The unit upward normal of the stowed flap's chord line (station frame): the chord
    /// from the trailing edge to the leading edge turned a quarter turn counter-clockwise
    /// (a flap with its own incidence has it tilted from the station's +y).
    pub normal_stowed: nalgebra::Vector2<f64>,
}

impl FlapNormalForce {
    /// The normal force (N) at deflection `deflection_rad`.
    pub fn at(&self, deflection_rad: f64) -> f64 {
        let rows = &self.coefficients;
        let coefficient = match rows.iter().position(|&(d, _)| d >= deflection_rad) {
            None => rows.last().map_or(0.0, |r| r.1),
            Some(0) => rows[0].1,
            Some(k) => {
                let ((d0, c0), (d1, c1)) = (rows[k - 1], rows[k]);
                c0 + (c1 - c0) * (deflection_rad - d0) / (d1 - d0)
            }
        };
        coefficient * self.newtons_per_coefficient
    }
}

impl LoadCase {
    /// Thesis cruise scenario (section 5.2): 750 N m on the flap, shared by its two screw
    /// jacks, so M12 = 375 N m per mechanism. The thesis halves the aerodynamic moment but
    /// NOT the flap weight (each mechanism carries the full 12 kg in Appendix C): that is
    /// the reading that reproduces Table 3.
    pub fn thesis_cruise() -> Self {
        Self {
            name: "cruise".to_owned(),
            external_moment: ExternalMoment::Constant(0.5 * 750.0),
            include_inertia: false,
            flap_normal_force: None,
            load_factor: 1.0,
        }
    }

    /// Thesis landing scenario (section 5.2): 220 N m closed, 650 N m fully deployed,
    /// halved for two jacks (110 N m → 325 N m), linear over the stroke.
    pub fn thesis_landing() -> Self {
        Self {
            name: "landing".to_owned(),
            external_moment: ExternalMoment::Linear {
                stowed_nm: 0.5 * 220.0,
                deployed_nm: 0.5 * 650.0,
            },
            include_inertia: false,
            flap_normal_force: None,
            load_factor: 1.0,
        }
    }
}
