//! Design steps 7-10 of the thesis: the collinearity rule, the flap link and the checks of
//! the spreadsheet's red cells (thesis Chapter 4 and section 5.3).

use std::f64::consts::PI;

use nalgebra::{Point2, Vector2};
use serde::Serialize;

use super::seam::{bodies_and_joints, TrackHardware};
use super::spec::CircularArcTrackSpec;
use flapwright_mechanism::seam::{Body, Joint};
use flapwright_mechanism::shared::angle::guarded_acos;
use flapwright_mechanism::shared::slider_crank::InvertedSliderCrank;
use flapwright_mechanism::{Error, Result};

/// Angles closer than this (rad) are taken as equal in consistency checks.
const ANGLE_CONSISTENCY_TOLERANCE_RAD: f64 = 1e-9;

/// Shortest accepted stowed screw link s34,i as a fraction of the crank a2: below it the
/// nut starts on the screw pivot B0, the screw direction is undefined and the Jacobian
/// condition number runs past 1e15 (a 1 % crank keeps a 1/17 model's millimetre links
/// and rejects the degenerate case; the thesis has s34,i = 0.33 a2).
pub const MIN_STROKE_START_CRANK_FRACTION: f64 = 0.01;

/// Everything design steps 7-10 compute from a [`CircularArcTrackSpec`] (thesis green cells).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrackSynthesis {
    /// s34,i (m): stowed slider length from the collinearity of B0, A_i, A_f (step 8):
    /// t = sqrt(a1² - a2² cos²(β3/2)), s34,i = t - a2 sin(β3/2).
    pub stroke_start_m: f64,
    /// Δs = 2 a2 sin(β3/2) (m), step 7.
    pub stroke_m: f64,
    /// s34,f = s34,i + Δs (m).
    pub stroke_end_m: f64,
    /// h = |A0 W| = a2 cos(β3/2) (m): depth of the hinge below the screw line (Fig. 23).
    pub chord_distance_m: f64,
    /// θ12,i (rad): stowed crank angle.
    pub stowed_crank_angle_rad: f64,
    /// θ13,i = θ13,f (rad): the screw's direction at both ends (equal by collinearity).
    pub end_slider_angle_rad: f64,
    /// μ_min = (π - β3)/2 (rad): transmission angle at both ends (step 8).
    pub minimum_transmission_angle_rad: f64,
    /// A_i (m), nut pivot stowed.
    pub nut_pivot_stowed_m: Point2<f64>,
    /// A_f (m), nut pivot fully deployed.
    pub nut_pivot_deployed_m: Point2<f64>,
    /// B0 (m), the screw's fixed pivot.
    pub screw_mount_m: Point2<f64>,
    /// r_D = |A0 D| (m).
    pub centre_of_mass_radius_m: f64,
    /// θD = atan2(y_D, x_D) (rad), stowed. (The thesis writes atan2(x_D; y_D): Excel's
    /// ATAN2 takes x first.)
    pub centre_of_mass_angle_stowed_rad: f64,
    /// g2 = |A D| (m), step 10.
    pub crank_to_centre_of_mass_m: f64,
    /// α2 = ∠D A0 A (rad), thesis section 3.4.
    pub centre_of_mass_offset_angle_rad: f64,
    /// σ = ±1: D lies counter-clockwise (+1) or clockwise (-1) of A0A (thesis 3.4.4).
    pub centre_of_mass_side: i8,
    /// p2 = |D G| (m), step 10 (G stowed at F2,i on the inner slot).
    pub centre_of_mass_to_inner_pin_m: f64,
    /// q2 = |D F| (m), step 10 (F stowed at F1,i on the outer slot).
    pub centre_of_mass_to_outer_pin_m: f64,
    /// β5 = ∠G A0 D (rad), law of cosines in triangle A0 D G.
    pub inner_pin_offset_angle_rad: f64,
    /// β6 = ∠F A0 D (rad), law of cosines in triangle A0 D F.
    pub outer_pin_offset_angle_rad: f64,
    /// θG,i = β1 + β2 (rad), stowed direction of pin G.
    pub inner_pin_angle_stowed_rad: f64,
    /// θF,i = β1 (rad), stowed direction of pin F.
    pub outer_pin_angle_stowed_rad: f64,
    /// G stowed = F2,i = c1 e^{i(β1+β2)} (m).
    pub inner_pin_stowed_m: Point2<f64>,
    /// F stowed = F1,i = b1 e^{iβ1} (m).
    pub outer_pin_stowed_m: Point2<f64>,
    /// Conditions worth a look that do not stop the design.
    pub warnings: Vec<SynthesisWarning>,
}

/// A design condition that is legal but deserves the designer's attention.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum SynthesisWarning {
    /// The screw back-drives under load (f <= tan λ): a brake is needed to hold the flap.
    ScrewNotSelfLocking {
        /// λ (rad).
        lead_angle_rad: f64,
        /// f (-).
        friction_coefficient: f64,
    },
    /// A pin is not clockwise of D, so the thesis's θG = θD - β5 / θF = θD - β6 would give
    /// the mirror angle; the crate uses θG = β1 + β2 and θF = β1 directly.
    ThesisPinAngleFormulaMirrored {
        /// Which pin ("G" or "F").
        pin: &'static str,
    },
}

impl std::fmt::Display for SynthesisWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::ScrewNotSelfLocking {
                lead_angle_rad,
                friction_coefficient,
            } => write!(
                f,
                "the screw thread is not self-locking: lead angle {:.2} deg >= friction angle {:.2} deg \
                 (f = {friction_coefficient:.3}); a load can back-drive it, so a brake must hold the flap",
                lead_angle_rad.to_degrees(),
                friction_coefficient.atan().to_degrees()
            ),
            Self::ThesisPinAngleFormulaMirrored { pin } => write!(
                f,
                "pin {pin} is not clockwise of the flap centre of mass D: the thesis angle formula would \
                 mirror it, so its stowed angle is taken from the slot angles directly"
            ),
        }
    }
}

/// A synthesised circular-arc track with screw jack, ready to pose and load.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CircularArcTrack {
    pub(crate) spec: CircularArcTrackSpec,
    pub(crate) linkage: InvertedSliderCrank,
    pub(crate) synthesis: TrackSynthesis,
    /// Sizes of the solids behind the seam.
    pub(crate) hardware: TrackHardware,
    /// Bodies behind the seam ([`flapwright_mechanism::FlapMechanism::bodies`]), built from the synthesis.
    #[serde(skip)]
    pub(crate) bodies: Vec<Body>,
    /// Joints behind the seam ([`flapwright_mechanism::FlapMechanism::joints`]).
    #[serde(skip)]
    pub(crate) joints: Vec<Joint>,
}

impl CircularArcTrack {
    /// Runs design steps 7-10 on `spec` and checks the section 5.3 red cells.
    ///
    /// Errors: [`Error::InvalidDimension`]/[`Error::ParameterOutOfRange`] for a bad field,
    /// [`Error::SlotRadiiOrder`] (red cell 2, c1 >= b1), [`Error::CollinearityImpossible`]
    /// (a1 <= a2 cos(β3/2)), [`Error::ScrewTooShort`] (red cell 3, a3 < s34,f),
    /// [`Error::ScrewJammed`]. Red cell 1 (s34 outside the slots) is checked per pose.
    pub fn synthesise(spec: CircularArcTrackSpec) -> Result<Self> {
        validate(&spec)?;
        let mut linkage = InvertedSliderCrank::try_new(spec.base_distance_m, spec.crank_length_m, spec.base_angle_rad)?;
        linkage.toggle_tolerance_rad = spec.toggle_tolerance_rad;
        let (a1, a2) = (spec.base_distance_m, spec.crank_length_m);
        let half = 0.5 * spec.rotation_range_rad;
        let chord_distance_m = a2 * half.cos();
        if a1 <= chord_distance_m {
            return Err(Error::CollinearityImpossible {
                base_distance_m: a1,
                crank_length_m: a2,
                chord_distance_m,
            });
        }
        let t = ((a1 - chord_distance_m) * (a1 + chord_distance_m)).sqrt();
        let stroke_m = 2.0 * a2 * half.sin();
        let stroke_start_m = t - 0.5 * stroke_m;
        let min_stroke_start_m = MIN_STROKE_START_CRANK_FRACTION * a2;
        if stroke_start_m.is_nan() || stroke_start_m < min_stroke_start_m {
            return Err(Error::NutOnScrewPivot {
                stroke_start_m,
                minimum_m: min_stroke_start_m,
            });
        }
        let stroke_end_m = stroke_start_m + stroke_m;
        if spec.screw_length_m < stroke_end_m {
            return Err(Error::ScrewTooShort {
                screw_length_m: spec.screw_length_m,
                required_m: stroke_end_m,
            });
        }
        let (crank_i, slider_i) = linkage.angles(stroke_start_m)?;
        let (crank_f, _) = linkage.angles(stroke_end_m)?;
        let alpha0 = spec.base_angle_rad;
        let polar = |radius: f64, angle: f64| Point2::new(radius * angle.cos(), radius * angle.sin());
        let nut_pivot_stowed_m = polar(a2, alpha0 + crank_i);
        let nut_pivot_deployed_m = polar(a2, alpha0 + crank_f);

        let d = spec.centre_of_mass_stowed_m;
        let r_d = d.coords.norm();
        if !(r_d.is_finite() && r_d > 0.0) {
            return Err(Error::InvalidDimension {
                name: "centre_of_mass_stowed_m",
                value: r_d,
            });
        }
        let theta_d = d.y.atan2(d.x);
        let g2 = (d - nut_pivot_stowed_m).norm();
        let alpha2 = guarded_acos((a2 * a2 + r_d * r_d - g2 * g2) / (2.0 * a2 * r_d), "alpha2")?;
        let sigma: i8 = if wrap(theta_d - (alpha0 + crank_i)) > 0.0 {
            1
        } else {
            -1
        };

        let (b1, c1) = (spec.outer_slot_radius_m, spec.inner_slot_radius_m);
        let theta_f = spec.outer_slot_start_angle_rad;
        let theta_g = theta_f + spec.inner_slot_offset_angle_rad;
        let p2 = (d - polar(c1, theta_g)).norm();
        let q2 = (d - polar(b1, theta_f)).norm();
        let beta5 = guarded_acos((r_d * r_d + c1 * c1 - p2 * p2) / (2.0 * r_d * c1), "beta5")?;
        let beta6 = guarded_acos((r_d * r_d + b1 * b1 - q2 * q2) / (2.0 * r_d * b1), "beta6")?;

        let mut warnings = Vec::new();
        if !spec.screw.is_self_locking() {
            warnings.push(SynthesisWarning::ScrewNotSelfLocking {
                lead_angle_rad: spec.screw.lead_angle_rad(),
                friction_coefficient: spec.screw.friction_coefficient,
            });
        }
        for (pin, offset, direct) in [("G", beta5, theta_g), ("F", beta6, theta_f)] {
            if wrap(theta_d - offset - direct).abs() > ANGLE_CONSISTENCY_TOLERANCE_RAD {
                warnings.push(SynthesisWarning::ThesisPinAngleFormulaMirrored { pin });
            }
        }

        let synthesis = TrackSynthesis {
            stroke_start_m,
            stroke_m,
            stroke_end_m,
            chord_distance_m,
            stowed_crank_angle_rad: crank_i,
            end_slider_angle_rad: slider_i,
            minimum_transmission_angle_rad: 0.5 * (PI - spec.rotation_range_rad),
            nut_pivot_stowed_m,
            nut_pivot_deployed_m,
            screw_mount_m: Point2::from(Vector2::new(a1 * alpha0.cos(), a1 * alpha0.sin())),
            centre_of_mass_radius_m: r_d,
            centre_of_mass_angle_stowed_rad: theta_d,
            crank_to_centre_of_mass_m: g2,
            centre_of_mass_offset_angle_rad: alpha2,
            centre_of_mass_side: sigma,
            centre_of_mass_to_inner_pin_m: p2,
            centre_of_mass_to_outer_pin_m: q2,
            inner_pin_offset_angle_rad: beta5,
            outer_pin_offset_angle_rad: beta6,
            inner_pin_angle_stowed_rad: theta_g,
            outer_pin_angle_stowed_rad: theta_f,
            inner_pin_stowed_m: polar(c1, theta_g),
            outer_pin_stowed_m: polar(b1, theta_f),
            warnings,
        };
        Ok(Self {
            spec,
            linkage,
            synthesis,
            hardware: TrackHardware::default(),
            bodies: Vec::new(),
            joints: Vec::new(),
        }
        .with_hardware(TrackHardware::default()))
    }

    /// The same track with its solids sized by `hardware`.
    pub fn with_hardware(mut self, hardware: TrackHardware) -> Self {
        let (bodies, joints) = bodies_and_joints(&self, &hardware);
        self.hardware = hardware;
        self.bodies = bodies;
        self.joints = joints;
        self
    }

    /// The sizes of the solids that stand for the hardware.
    pub fn hardware(&self) -> &TrackHardware {
        &self.hardware
    }

    /// The dimensions this track was synthesised from.
    pub fn spec(&self) -> &CircularArcTrackSpec {
        &self.spec
    }

    /// The computed design quantities (s34,i, Δs, g2, p2, q2, ...).
    pub fn synthesis(&self) -> &TrackSynthesis {
        &self.synthesis
    }

    /// The driving inverted slider-crank A0 B0 A.
    pub fn linkage(&self) -> &InvertedSliderCrank {
        &self.linkage
    }
}

/// Wraps an angle (rad) into (-π, π].
pub(crate) fn wrap(angle: f64) -> f64 {
    let wrapped = angle.rem_euclid(2.0 * PI);
    if wrapped > PI {
        wrapped - 2.0 * PI
    } else {
        wrapped
    }
}

fn validate(spec: &CircularArcTrackSpec) -> Result<()> {
    let lengths = [
        ("base_distance_m", spec.base_distance_m),
        ("crank_length_m", spec.crank_length_m),
        ("screw_length_m", spec.screw_length_m),
        ("outer_slot_radius_m", spec.outer_slot_radius_m),
        ("inner_slot_radius_m", spec.inner_slot_radius_m),
        ("toggle_tolerance_rad", spec.toggle_tolerance_rad),
    ];
    for (name, value) in lengths {
        if !(value.is_finite() && value > 0.0) {
            return Err(Error::InvalidDimension { name, value });
        }
    }
    let ranged = [
        ("rotation_range_rad", spec.rotation_range_rad, 0.0, PI),
        ("flap_mass_kg", spec.flap_mass_kg, 0.0, f64::MAX),
        (
            "flap_moment_of_inertia_kgm2",
            spec.flap_moment_of_inertia_kgm2,
            0.0,
            f64::MAX,
        ),
        ("gravity_mps2", spec.gravity_mps2, 0.0, f64::MAX),
        ("base_angle_rad", spec.base_angle_rad, -4.0 * PI, 4.0 * PI),
        (
            "outer_slot_start_angle_rad",
            spec.outer_slot_start_angle_rad,
            -4.0 * PI,
            4.0 * PI,
        ),
        (
            "inner_slot_offset_angle_rad",
            spec.inner_slot_offset_angle_rad,
            -2.0 * PI,
            2.0 * PI,
        ),
        (
            "nominal_input_speed_mps",
            spec.nominal_input_speed_mps,
            -f64::MAX,
            f64::MAX,
        ),
        (
            "nominal_input_accel_mps2",
            spec.nominal_input_accel_mps2,
            -f64::MAX,
            f64::MAX,
        ),
        (
            "centre_of_mass_x_m",
            spec.centre_of_mass_stowed_m.x,
            -f64::MAX,
            f64::MAX,
        ),
        (
            "centre_of_mass_y_m",
            spec.centre_of_mass_stowed_m.y,
            -f64::MAX,
            f64::MAX,
        ),
    ];
    for (name, value, min, max) in ranged {
        // `!(a <= b)` also rejects NaN.
        if !(value >= min && value <= max) || (name == "rotation_range_rad" && value == 0.0) {
            return Err(Error::ParameterOutOfRange { name, value, min, max });
        }
    }
    if spec.inner_slot_radius_m >= spec.outer_slot_radius_m {
        return Err(Error::SlotRadiiOrder {
            inner_radius_m: spec.inner_slot_radius_m,
            outer_radius_m: spec.outer_slot_radius_m,
        });
    }
    spec.screw.validate()
}
