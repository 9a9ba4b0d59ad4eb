//! The five-bar double-slotted flap of `001_...` (Politecnico di Milano MSD project,
//! section 2, Fig. 1): a crank O-A turned by the motor drives, through the link A-G, the
//! main flap about its fixed hinge C; the rocker B-D and the link D-G-E, pinned to the main
//! flap at G, swing E, and the link E-H turns the secondary flap about its pivot F at the
//! main flap's trailing edge.
//!
//! # Frame and angles (as `001_...`)
//!
//! Gauss plane of the station: O (the crank's pivot) at the origin, x aft, y up, angles
//! counter-clockwise from +x. C = l - i r and B = C - (s - i t) are fixed. The main flap's
//! deflection δ and the secondary flap's θ are positive trailing edge down:
//! G - C = i c e^{-iδ}, F - C = c₁ e^{-iδ} (F at the end of the main chord, perpendicular to
//! C G), H - F = i z e^{-iθ}, L - F = c₂ e^{-iθ} (L the secondary trailing edge).
//!
//! # Position, closed form
//!
//! Each of the three loop equations of `001_...` is one RRR dyad once the earlier ones are
//! solved, so no Newton iteration is needed (the document solves each by Newton-Raphson):
//! 1. (A - O) + (G - A) = (C - O) + (G - C): G on the circles (A, b) and (C, c);
//! 2. (D - B) + (G - D) = (C - B) + (G - C): D on (B, d) and (G, p); E = G + g (G - D)/p;
//! 3. (G - C) + (E - G) + (H - E) = (F - C) + (H - F): H on (E, h) and (F, z).
//!
//! Each dyad keeps its branch (the side of the line between its two centres), fixed by the
//! assembly at the start of the deployment; a branch can only change through a toggle,
//! which [`FiveBarPose::toggle_sine`] measures. The velocities and accelerations are the
//! derivatives of the same closed form, carried along by [`flapwright_mechanism::jet`] (derived here, not taken
//! from the document's section 2.1-2.3, whose printed forms carry the typos listed in
//! `data/validation/001-five-bar-defects.md`; tests compare with finite differences and
//! with the corrected printed forms).

mod seam;

use nalgebra::Vector2;
use serde::Serialize;

use flapwright_mechanism::generalised::{generalise, AeroSurface, Generalised, InertialBody, OneInputDynamics};
use flapwright_mechanism::jet::{dyad_to_order, AngleJet, PointJet};
use flapwright_mechanism::{Error, Result};
pub use seam::FiveBarKind;

/// The link lengths and fixed points of the five-bar (m), named as in `001_...` section 2
/// (its Matlab listing, section 4, calls g `q`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FiveBarDimensions {
    /// |A - O|, the crank.
    pub a: f64,
    /// |G - A|, the link from the crank to the main flap.
    pub b: f64,
    /// |G - C|, the main flap's arm from its hinge.
    pub c: f64,
    /// Re(C - O).
    pub l: f64,
    /// -Im(C - O).
    pub r: f64,
    /// |D - B|, the rocker.
    pub d: f64,
    /// |G - D|.
    pub p: f64,
    /// Re(C - B).
    pub s: f64,
    /// -Im(C - B).
    pub t: f64,
    /// |E - G|, the extension of the link D-G beyond G.
    pub g: f64,
    /// |H - E|, the link to the secondary flap.
    pub h: f64,
    /// |H - F|, the secondary flap's arm from its pivot.
    pub z: f64,
    /// c₁, the main flap's chord |F - C|.
    pub main_chord: f64,
    /// c₂, the secondary flap's chord |L - F|.
    pub secondary_chord: f64,
}

impl FiveBarDimensions {
    /// The data set of `001_...` section 4 (a 1/17 model of a Boeing 747 flap, K = 17),
    /// with the document's chords c₁ = 1 m, c₂ = 0.5 m.
    pub fn polimi_case_study() -> Self {
        let k = 17.0;
        Self {
            a: 3.5 / k,
            b: 9.0 / k,
            c: 5.0 / k,
            l: 9.0 / k,
            r: 6.5 / k,
            d: 9.0 / k,
            p: 2.25 / k,
            s: 7.0 / k,
            t: 8.0 / k,
            g: 3.0 / k,
            h: 17.75 / k,
            z: 4.0 / k,
            main_chord: 1.0,
            secondary_chord: 0.5,
        }
    }

    fn check(&self) -> Result<()> {
        let lengths = [
            ("a", self.a),
            ("b", self.b),
            ("c", self.c),
            ("d", self.d),
            ("p", self.p),
            ("g", self.g),
            ("h", self.h),
            ("z", self.z),
            ("main_chord", self.main_chord),
            ("secondary_chord", self.secondary_chord),
        ];
        for (name, value) in lengths {
            if !(value.is_finite() && value > 0.0) {
                return Err(Error::InvalidDimension { name, value });
            }
        }
        for (name, value) in [("l", self.l), ("r", self.r), ("s", self.s), ("t", self.t)] {
            if !value.is_finite() {
                return Err(Error::InvalidDimension { name, value });
            }
        }
        Ok(())
    }
}

/// Which intersection each dyad takes: the sign of (Q - P) x (X - P) for the dyad's
/// centres P, Q and joint X, in the order G (about A and C), D (about B and G), H (about
/// E and F).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FiveBarBranches {
    /// Branch of G.
    pub g: f64,
    /// Branch of D.
    pub d: f64,
    /// Branch of H.
    pub h: f64,
}

/// Mass properties and aerodynamic data of the two flaps (`001_...` sections 3.1 and 4):
/// centres of mass at half chord, aerodynamic centres at quarter chord, lift normal to the
/// chord and linear in the flap's deflection, a constant pitching moment (positive nose up,
/// that is in the sense of δ: `001_...` writes its power as M_AC δ̇).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DoubleFlapLoads {
    /// Main flap mass (kg).
    pub main_mass_kg: f64,
    /// Main flap moment of inertia about its centre of mass (kg m²).
    pub main_inertia_kgm2: f64,
    /// Secondary flap mass (kg).
    pub secondary_mass_kg: f64,
    /// Secondary flap moment of inertia about its centre of mass (kg m²).
    pub secondary_inertia_kgm2: f64,
    /// Main flap lift per radian of δ, ½ ρ U² S₁ C_L/δ (N/rad).
    pub main_lift_per_rad_n: f64,
    /// Secondary flap lift per radian of θ (N/rad).
    pub secondary_lift_per_rad_n: f64,
    /// Main flap pitching moment, ½ ρ U² S₁ c₁ C_MAC₁ (N m).
    pub main_moment_nm: f64,
    /// Secondary flap pitching moment (N m).
    pub secondary_moment_nm: f64,
    /// Gravitational acceleration (m/s², along -y).
    pub gravity_mps2: f64,
}

impl DoubleFlapLoads {
    /// The data of `001_...` section 4: landing speed 240 km/h at sea level, S = 1.5 c,
    /// M = 20 kg, m = 10 kg, J_M = M c₁ 3.5/K, J_m = m c₂ 2.5/K, C_L/δ = 1.4, C_L/θ = 1.3,
    /// C_MAC = -0.3 for both.
    pub fn polimi_case_study(dimensions: &FiveBarDimensions) -> Self {
        let k = 17.0;
        let dynamic_pressure = 0.5 * 1.225 * (240.0_f64 / 3.6).powi(2);
        let (c1, c2) = (dimensions.main_chord, dimensions.secondary_chord);
        let (s1, s2) = (1.5 * c1, 1.5 * c2);
        Self {
            main_mass_kg: 20.0,
            main_inertia_kgm2: 20.0 * c1 * 3.5 / k,
            secondary_mass_kg: 10.0,
            secondary_inertia_kgm2: 10.0 * c2 * 2.5 / k,
            main_lift_per_rad_n: dynamic_pressure * s1 * 1.4,
            secondary_lift_per_rad_n: dynamic_pressure * s2 * 1.3,
            main_moment_nm: dynamic_pressure * s1 * c1 * -0.3,
            secondary_moment_nm: dynamic_pressure * s2 * c2 * -0.3,
            gravity_mps2: 9.81,
        }
    }
}

/// The five-bar double flap, assembled.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FiveBarDoubleFlap {
    /// Link lengths and fixed points.
    pub dimensions: FiveBarDimensions,
    /// The dyads' branches.
    pub branches: FiveBarBranches,
    /// Crank angle α with both flaps stowed (rad).
    pub stowed_crank_rad: f64,
    /// Crank angle α fully deployed (rad).
    pub deployed_crank_rad: f64,
}

/// Every joint of the five-bar at one crank angle, with its derivatives with respect to α.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiveBarPose {
    /// Crank angle α (rad).
    pub crank_rad: f64,
    /// The crank pin A.
    pub a: PointJet,
    /// The main flap's pin G.
    pub g: PointJet,
    /// The rocker's pin D.
    pub d: PointJet,
    /// The end E of the link D-G-E.
    pub e: PointJet,
    /// The secondary flap's pivot F, the main flap's trailing edge.
    pub f: PointJet,
    /// The secondary flap's pin H.
    pub h: PointJet,
    /// The secondary flap's trailing edge L.
    pub trailing_edge: PointJet,
    /// Main flap deflection δ (rad, trailing edge down).
    pub main_deflection: AngleJet,
    /// Secondary flap deflection θ (rad, trailing edge down).
    pub secondary_deflection: AngleJet,
    /// The smallest |sin| of the angle between the two links of a dyad: 0 at a toggle.
    pub toggle_sine: f64,
}

impl FiveBarDoubleFlap {
    /// The five-bar with `dimensions`, its branches taken from the assembly whose flaps
    /// are nearest stowed at crank angle `stowed_crank_rad` (of the eight, the one that
    /// assembles there with the smallest |δ| + |θ|), deployed at `deployed_crank_rad`.
    pub fn assemble(dimensions: FiveBarDimensions, stowed_crank_rad: f64, deployed_crank_rad: f64) -> Result<Self> {
        dimensions.check()?;
        for (name, value) in [
            ("stowed_crank_rad", stowed_crank_rad),
            ("deployed_crank_rad", deployed_crank_rad),
        ] {
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    quantity: name,
                    input_m: value,
                });
            }
        }
        let mut best: Option<(f64, FiveBarBranches)> = None;
        for g in [1.0, -1.0] {
            for d in [1.0, -1.0] {
                for h in [1.0, -1.0] {
                    let candidate = Self {
                        dimensions,
                        branches: FiveBarBranches { g, d, h },
                        stowed_crank_rad,
                        deployed_crank_rad,
                    };
                    let Ok(pose) = candidate.pose(stowed_crank_rad) else {
                        continue;
                    };
                    let stowedness = pose.main_deflection.value.abs() + pose.secondary_deflection.value.abs();
                    if best.is_none_or(|(b, _)| stowedness < b) {
                        best = Some((stowedness, candidate.branches));
                    }
                }
            }
        }
        let Some((_, branches)) = best else {
            return Err(Error::LoopOpen {
                dyad: "any",
                crank_rad: stowed_crank_rad,
            });
        };
        Ok(Self {
            dimensions,
            branches,
            stowed_crank_rad,
            deployed_crank_rad,
        })
    }

    /// The `001_...` case study: the section 4 data over its crank range 275-320 deg.
    pub fn polimi_case_study() -> Result<Self> {
        Self::assemble(
            FiveBarDimensions::polimi_case_study(),
            275f64.to_radians(),
            320f64.to_radians(),
        )
    }

    /// The fixed hinge C of the main flap.
    pub fn hinge_c(&self) -> Vector2<f64> {
        Vector2::new(self.dimensions.l, -self.dimensions.r)
    }

    /// The rocker's fixed pivot B.
    pub fn pivot_b(&self) -> Vector2<f64> {
        self.hinge_c() - Vector2::new(self.dimensions.s, -self.dimensions.t)
    }

    /// The mechanism at crank angle `crank_rad`, with every derivative to third order.
    pub fn pose(&self, crank_rad: f64) -> Result<FiveBarPose> {
        self.pose_to_order::<3>(crank_rad)
    }

    /// Positions and rates only (the second and third derivatives left 0): what a sweep
    /// of the deployment's kinematics needs, in half the time.
    pub fn pose_and_rates(&self, crank_rad: f64) -> Result<FiveBarPose> {
        self.pose_to_order::<1>(crank_rad)
    }

    #[inline]
    fn pose_to_order<const ORDER: usize>(&self, crank_rad: f64) -> Result<FiveBarPose> {
        let dims = &self.dimensions;
        let open = |dyad: &'static str| Error::LoopOpen { dyad, crank_rad };
        let alpha = AngleJet::input(crank_rad);
        let a = PointJet::polar(dims.a, alpha);
        let c = PointJet::fixed(self.hinge_c());
        let b = PointJet::fixed(self.pivot_b());
        let g_dyad =
            dyad_to_order::<ORDER>(&a, dims.b, &c, dims.c, self.branches.g).ok_or_else(|| open("G (loop 1)"))?;
        let g = g_dyad.point;
        let d_dyad =
            dyad_to_order::<ORDER>(&b, dims.d, &g, dims.p, self.branches.d).ok_or_else(|| open("D (loop 2)"))?;
        let d = d_dyad.point;
        let e = g + (g - d) * (dims.g / dims.p);
        // G - C = i c e^{-iδ}: the chord direction e^{-iδ} = -i (G - C)/c, and F - C is
        // c₁ along it.
        let main_chord_direction = (g - c).perp() * (-1.0 / dims.c);
        let f = c + main_chord_direction * dims.main_chord;
        let h_dyad =
            dyad_to_order::<ORDER>(&e, dims.h, &f, dims.z, self.branches.h).ok_or_else(|| open("H (loop 3)"))?;
        let h = h_dyad.point;
        let secondary_chord_direction = (h - f).perp() * (-1.0 / dims.z);
        let trailing_edge = f + secondary_chord_direction * dims.secondary_chord;
        let pose = FiveBarPose {
            crank_rad,
            a,
            g,
            d,
            e,
            f,
            h,
            trailing_edge,
            main_deflection: main_chord_direction.angle_to_order::<ORDER>().negated(),
            secondary_deflection: secondary_chord_direction.angle_to_order::<ORDER>().negated(),
            toggle_sine: [g_dyad, d_dyad, h_dyad]
                .iter()
                .map(|j| j.sine_between_links.abs())
                .fold(f64::INFINITY, f64::min),
        };
        // Every derivative computed (the ones beyond ORDER are 0): a NaN anywhere shows.
        let finite = |angle: &AngleJet| (angle.value + angle.d1 + angle.d2 + angle.d3).is_finite();
        if !finite(&pose.secondary_deflection) || !finite(&pose.main_deflection) {
            return Err(Error::NonFinite {
                quantity: "five-bar derivatives",
                input_m: crank_rad,
            });
        }
        Ok(pose)
    }

    /// The largest violation of the three loop equations of `001_...` section 2, written
    /// with the link angles measured from the solved points (m): what the closed form
    /// leaves to rounding.
    pub fn closure_residual(&self, pose: &FiveBarPose) -> f64 {
        let dims = &self.dimensions;
        let polar = |length: f64, angle: f64| Vector2::new(angle.cos(), angle.sin()) * length;
        let direction = |v: Vector2<f64>| v.y.atan2(v.x);
        let (beta, phi, psi, xi) = (
            direction(pose.g.p - pose.a.p),
            direction(pose.d.p - self.pivot_b()),
            direction(pose.g.p - pose.d.p),
            direction(pose.h.p - pose.e.p),
        );
        let (delta, theta) = (pose.main_deflection.value, pose.secondary_deflection.value);
        // i c e^{-iδ} = c (sin δ, cos δ); (ic - c₁) e^{-iδ} = (c sin δ - c₁ cos δ, c cos δ + c₁ sin δ).
        let arm = |length: f64, angle: f64| Vector2::new(angle.sin(), angle.cos()) * length;
        let loop1 = polar(dims.a, pose.crank_rad) + polar(dims.b, beta) - self.hinge_c() - arm(dims.c, delta);
        let loop2 = polar(dims.d, phi) + polar(dims.p, psi) - (self.hinge_c() - self.pivot_b()) - arm(dims.c, delta);
        let loop3 = arm(dims.c, delta) - polar(dims.main_chord, -delta) + polar(dims.g, psi) + polar(dims.h, xi)
            - arm(dims.z, theta);
        loop1.norm().max(loop2.norm()).max(loop3.norm())
    }

    /// The bodies with mass and the aerodynamic surfaces at `pose`, for the equation of
    /// motion (`001_...` section 3.1: the links are massless).
    pub fn inertial_model(&self, pose: &FiveBarPose, loads: &DoubleFlapLoads) -> (Vec<InertialBody>, Vec<AeroSurface>) {
        let dims = &self.dimensions;
        let c = PointJet::fixed(self.hinge_c());
        let main_direction = (pose.f - c) * (1.0 / dims.main_chord);
        let secondary_direction = (pose.trailing_edge - pose.f) * (1.0 / dims.secondary_chord);
        let main_at = |fraction: f64| c + main_direction * (fraction * dims.main_chord);
        let secondary_at = |fraction: f64| pose.f + secondary_direction * (fraction * dims.secondary_chord);
        let bodies = vec![
            InertialBody {
                name: "main-flap",
                mass_kg: loads.main_mass_kg,
                inertia_kgm2: loads.main_inertia_kgm2,
                centre: main_at(0.5),
                angle: pose.main_deflection.negated(),
            },
            InertialBody {
                name: "secondary-flap",
                mass_kg: loads.secondary_mass_kg,
                inertia_kgm2: loads.secondary_inertia_kgm2,
                centre: secondary_at(0.5),
                angle: pose.secondary_deflection.negated(),
            },
        ];
        let surfaces = vec![
            AeroSurface {
                name: "main-flap",
                aerodynamic_centre: main_at(0.25),
                deflection: pose.main_deflection,
                lift_per_rad_n: loads.main_lift_per_rad_n,
                pitching_moment_nm: loads.main_moment_nm,
            },
            AeroSurface {
                name: "secondary-flap",
                aerodynamic_centre: secondary_at(0.25),
                deflection: pose.secondary_deflection,
                lift_per_rad_n: loads.secondary_lift_per_rad_n,
                pitching_moment_nm: loads.secondary_moment_nm,
            },
        ];
        (bodies, surfaces)
    }
}

/// The five-bar with its flaps' mass and aerodynamic loads: a one-input system for the
/// equation of motion.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadedFiveBar {
    /// The mechanism.
    pub mechanism: FiveBarDoubleFlap,
    /// Masses, inertias and aerodynamic data of the two flaps.
    pub loads: DoubleFlapLoads,
}

impl LoadedFiveBar {
    /// The `001_...` case study with its section 4 loads.
    pub fn polimi_case_study() -> Result<Self> {
        let mechanism = FiveBarDoubleFlap::polimi_case_study()?;
        let loads = DoubleFlapLoads::polimi_case_study(&mechanism.dimensions);
        Ok(Self { mechanism, loads })
    }
}

impl OneInputDynamics for LoadedFiveBar {
    fn input_travel(&self) -> (f64, f64) {
        (self.mechanism.stowed_crank_rad, self.mechanism.deployed_crank_rad)
    }

    fn generalised_at(&self, input: f64) -> Result<Generalised> {
        let pose = self.mechanism.pose(input)?;
        let (bodies, surfaces) = self.mechanism.inertial_model(&pose, &self.loads);
        Ok(generalise(&bodies, &surfaces, self.loads.gravity_mps2))
    }
}
