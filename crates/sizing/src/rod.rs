//! Rods (two-force members) sized for tension, compression and Euler buckling, and
//! members that bend as well (a crank turned from between its pins, an arm cantilevered
//! from a hinge) sized for the combined stress.

use serde::Serialize;

use crate::check::{non_negative, positive};
use crate::material::Material;
use crate::section::SectionShape;
use crate::warning::SizingWarning;
use crate::{Error, Result};
use std::f64::consts::PI;

/// A rod to size: length, axial load envelope and section shape.
///
/// Loads are design loads (already multiplied by load and safety factors, see
/// [`crate::LoadCase::design_factor`]); tension and compression are magnitudes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RodInput {
    /// Station name (for reports and warnings).
    pub station: String,
    /// Rod name.
    pub name: String,
    /// Pin-to-pin length L, m.
    pub length_m: f64,
    /// Largest tensile axial force, N (>= 0).
    pub max_tension_n: f64,
    /// Largest compressive axial force (magnitude), N (>= 0).
    pub max_compression_n: f64,
    /// Euler effective-length (end-fixity) factor K: 1 pinned-pinned, 0.5 fixed-fixed,
    /// 0.699 fixed-pinned, 2 fixed-free. In (0, inf).
    pub end_fixity_factor: f64,
    /// Solid or tube with a fixed wall ratio.
    pub shape: SectionShape,
    /// Largest outer radius the station leaves room for, m (None: unlimited).
    pub max_outer_radius_m: Option<f64>,
    /// Bending loads, for a member that bends (empty for a two-force member): each an
    /// axial force with the bending moment at the same pose, design loads.
    pub bending: Vec<BendingLoad>,
}

/// One pose's design loads on a member that bends.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BendingLoad {
    /// Axial force, N, tension positive.
    pub axial_n: f64,
    /// Bending moment magnitude, N m (>= 0).
    pub bending_moment_nm: f64,
}

impl RodInput {
    /// A pinned-pinned (K = 1) solid rod with no envelope limit.
    pub fn new(
        station: impl Into<String>,
        name: impl Into<String>,
        length_m: f64,
        max_tension_n: f64,
        max_compression_n: f64,
    ) -> Self {
        Self {
            station: station.into(),
            name: name.into(),
            length_m,
            max_tension_n,
            max_compression_n,
            end_fixity_factor: 1.0,
            shape: SectionShape::Solid,
            max_outer_radius_m: None,
            bending: Vec::new(),
        }
    }
}

/// Which requirement set the radius.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GoverningCase {
    /// Tensile strength, P_t / A <= sigma_allow.
    Tension,
    /// Compressive strength, P_c / A <= sigma_allow.
    Compression,
    /// Euler buckling, P_c <= pi^2 E I / (K L)^2.
    Buckling,
    /// Axial force and bending moment together ([`bending_radius_m`]).
    Bending,
    /// No load: radius zero (a warning is raised).
    Unloaded,
}

/// Result of [`size_rod`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RodSizing {
    /// Station name.
    pub station: String,
    /// Rod name.
    pub name: String,
    /// Requirement that set the radius.
    pub governing: GoverningCase,
    /// Outer radius, m (largest of the three requirements).
    pub radius_m: f64,
    /// Inner radius, m (0 for solid).
    pub inner_radius_m: f64,
    /// Radius for tension alone, m.
    pub tension_radius_m: f64,
    /// Radius for compressive strength alone, m.
    pub compression_radius_m: f64,
    /// Radius for Euler buckling alone, m.
    pub buckling_radius_m: f64,
    /// Radius for axial force and bending together, m (members that bend only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bending_radius_m: Option<f64>,
    /// Euler critical load of the sized rod, N.
    pub critical_load_n: f64,
    /// Mass = A L rho, kg.
    pub mass_kg: f64,
    /// Warnings about this rod (also collected by the report).
    #[serde(skip)]
    pub warnings: Vec<SizingWarning>,
}

/// Outer radius carrying axial force P at stress sigma: A = P / sigma,
/// r = sqrt(P / (pi (1 - k^2) sigma)), m (N, Pa).
///
/// # Errors
/// [`Error::OutOfRange`] for a negative force, a non-positive stress or a bad shape.
pub fn strength_radius_m(force_n: f64, allowable_pa: f64, shape: SectionShape) -> Result<f64> {
    non_negative("force_n", force_n)?;
    positive("allowable_pa", allowable_pa)?;
    shape.validate()?;
    Ok((force_n / (PI * shape.area_factor() * allowable_pa)).sqrt())
}

/// Euler critical load P_cr = pi^2 E I / (K L)^2, N (Pa, m^4, m).
///
/// # Errors
/// [`Error::OutOfRange`] for E, K or L not positive, or I negative.
pub fn euler_critical_load_n(
    youngs_modulus_pa: f64,
    second_moment_m4: f64,
    end_fixity_factor: f64,
    length_m: f64,
) -> Result<f64> {
    positive("youngs_modulus_pa", youngs_modulus_pa)?;
    non_negative("second_moment_m4", second_moment_m4)?;
    positive("end_fixity_factor", end_fixity_factor)?;
    positive("length_m", length_m)?;
    Ok(PI * PI * youngs_modulus_pa * second_moment_m4 / (end_fixity_factor * length_m).powi(2))
}

/// Outer radius at which P_cr equals P: I = P (K L)^2 / (pi^2 E) with
/// I = pi r^4 (1 - k^4) / 4, so r = (4 P (K L)^2 / (pi^3 E (1 - k^4)))^(1/4), m.
///
/// # Errors
/// [`Error::OutOfRange`] for a negative force, L, K or E not positive, or a bad shape.
///
/// # Examples
/// ```
/// use flapwright_sizing::{buckling_radius_m, SectionShape};
/// // 10 kN over 1 m, pinned-pinned, E = 200 GPa: r = 8.96 mm.
/// let r = buckling_radius_m(1e4, 1.0, 1.0, 200e9, SectionShape::Solid)?;
/// assert!((r - 8.961_796_839e-3).abs() < 1e-12);
/// # Ok::<(), flapwright_sizing::Error>(())
/// ```
pub fn buckling_radius_m(
    force_n: f64,
    length_m: f64,
    end_fixity_factor: f64,
    youngs_modulus_pa: f64,
    shape: SectionShape,
) -> Result<f64> {
    non_negative("force_n", force_n)?;
    positive("length_m", length_m)?;
    positive("end_fixity_factor", end_fixity_factor)?;
    positive("youngs_modulus_pa", youngs_modulus_pa)?;
    shape.validate()?;
    let effective_length_m = end_fixity_factor * length_m;
    Ok(
        (4.0 * force_n * effective_length_m.powi(2) / (PI.powi(3) * youngs_modulus_pa * shape.inertia_factor()))
            .powf(0.25),
    )
}

/// Outer radius at which every load's combined stress reaches at most the allowable:
/// σ = |N| / A + M / (Z (1 - P_c / P_cr)) <= σ_allow, with Z = I / r the section modulus,
/// P_c = max(-N, 0) the compression and P_cr the Euler load of the member (K L): the
/// bending stress amplified by the approximate beam-column factor 1 / (1 - P_c / P_cr)
/// (Timoshenko & Gere, *Theory of Elastic Stability*, chapter 1, beam-columns), since
/// compression adds the member's own deflection to the moment's lever. σ falls
/// monotonically with r above the Euler radius of P_c, so bisection from the largest
/// single-requirement radius finds it, m.
///
/// # Errors
/// [`Error::OutOfRange`] for a non-finite axial force, a negative or non-finite moment,
/// L, K, E or σ_allow not positive, or a bad shape.
///
/// # Examples
/// ```
/// use flapwright_sizing::{bending_radius_m, BendingLoad, SectionShape};
/// // 100 N m on a solid round bar at 500 MPa: Z = π r^3 / 4 = M / σ, r = 6.339 mm.
/// let load = BendingLoad { axial_n: 0.0, bending_moment_nm: 100.0 };
/// let r = bending_radius_m(&[load], 0.3, 1.0, 200e9, 500e6, SectionShape::Solid)?;
/// assert!((r - (4.0 * 100.0 / (std::f64::consts::PI * 500e6)).cbrt()).abs() < 1e-12);
/// # Ok::<(), flapwright_sizing::Error>(())
/// ```
pub fn bending_radius_m(
    loads: &[BendingLoad],
    length_m: f64,
    end_fixity_factor: f64,
    youngs_modulus_pa: f64,
    allowable_pa: f64,
    shape: SectionShape,
) -> Result<f64> {
    positive("length_m", length_m)?;
    positive("end_fixity_factor", end_fixity_factor)?;
    positive("youngs_modulus_pa", youngs_modulus_pa)?;
    positive("allowable_pa", allowable_pa)?;
    shape.validate()?;
    let mut radius = 0.0_f64;
    for (i, load) in loads.iter().enumerate() {
        let axial = crate::check::finite(format!("bending[{i}].axial_n"), load.axial_n)?;
        let moment = non_negative(format!("bending[{i}].bending_moment_nm"), load.bending_moment_nm)?;
        let compression = (-axial).max(0.0);
        let stress = |r: f64| {
            let euler = euler_critical_load_n(
                youngs_modulus_pa,
                shape.second_moment_m4(r),
                end_fixity_factor,
                length_m,
            )
            .unwrap_or(0.0);
            let amplification = 1.0 - compression / euler;
            if amplification <= 0.0 {
                return f64::INFINITY;
            }
            axial.abs() / shape.area_m2(r) + moment * r / (shape.second_moment_m4(r) * amplification)
        };
        // Each requirement alone is met at its own radius; together they need more.
        let bending_alone = (4.0 * moment / (PI * shape.inertia_factor() * allowable_pa)).cbrt();
        let mut low = strength_radius_m(axial.abs(), allowable_pa, shape)?
            .max(buckling_radius_m(
                compression,
                length_m,
                end_fixity_factor,
                youngs_modulus_pa,
                shape,
            )?)
            .max(bending_alone);
        if low == 0.0 {
            continue;
        }
        let mut high = 2.0 * low;
        while stress(high) > allowable_pa {
            (low, high) = (high, 2.0 * high);
        }
        while high - low > 1e-13 * high {
            let mid = 0.5 * (low + high);
            if stress(mid) > allowable_pa {
                low = mid;
            } else {
                high = mid;
            }
        }
        radius = radius.max(high);
    }
    Ok(radius)
}

/// Largest tension and compression (magnitudes, N) of an axial-force history (N,
/// tension positive), e.g. a link force over the deployment.
///
/// # Errors
/// [`Error::Empty`] for no samples, [`Error::OutOfRange`] for a non-finite sample.
pub fn axial_envelope_n(axial_forces_n: &[f64]) -> Result<(f64, f64)> {
    if axial_forces_n.is_empty() {
        return Err(Error::Empty {
            what: "axial force history",
        });
    }
    let mut envelope = (0.0_f64, 0.0_f64);
    for (i, &f) in axial_forces_n.iter().enumerate() {
        crate::check::finite(format!("axial_forces_n[{i}]"), f)?;
        envelope = (envelope.0.max(f), envelope.1.max(-f));
    }
    Ok(envelope)
}

/// Sizes a rod: the outer radius is the largest of the tension, compression-strength
/// and Euler-buckling radii (`003_...` section 4.1: A = pi r^2, I = pi r^4 / 4 for solid
/// rods; tubes use the wall ratio). Suspicious sizes are returned with warnings.
///
/// # Errors
/// [`Error::InvalidMaterial`], [`Error::OutOfRange`] for bad lengths, loads, K, shape or
/// envelope.
pub fn size_rod(rod: &RodInput, material: &Material) -> Result<RodSizing> {
    material.validate()?;
    rod.shape.validate()?;
    let field = |what: &str| format!("rod {}/{}: {what}", rod.station, rod.name);
    let length_m = positive(field("length_m"), rod.length_m)?;
    let tension_n = non_negative(field("max_tension_n"), rod.max_tension_n)?;
    let compression_n = non_negative(field("max_compression_n"), rod.max_compression_n)?;
    let fixity = positive(field("end_fixity_factor"), rod.end_fixity_factor)?;
    if let Some(limit) = rod.max_outer_radius_m {
        positive(field("max_outer_radius_m"), limit)?;
    }
    let e = material.youngs_modulus_pa;
    let sigma = material.allowable_tensile_pa;
    let tension_radius_m = strength_radius_m(tension_n, sigma, rod.shape)?;
    let compression_radius_m = strength_radius_m(compression_n, sigma, rod.shape)?;
    let buckling_radius_m = buckling_radius_m(compression_n, length_m, fixity, e, rod.shape)?;
    let bending_radius_m = if rod.bending.is_empty() {
        None
    } else {
        for (i, load) in rod.bending.iter().enumerate() {
            crate::check::finite(field(&format!("bending[{i}].axial_n")), load.axial_n)?;
            non_negative(
                field(&format!("bending[{i}].bending_moment_nm")),
                load.bending_moment_nm,
            )?;
        }
        Some(bending_radius_m(&rod.bending, length_m, fixity, e, sigma, rod.shape)?)
    };
    let mut governing = GoverningCase::Unloaded;
    let mut radius_m = 0.0;
    for (case, r) in [
        (GoverningCase::Tension, tension_radius_m),
        (GoverningCase::Compression, compression_radius_m),
        (GoverningCase::Buckling, buckling_radius_m),
        (GoverningCase::Bending, bending_radius_m.unwrap_or(0.0)),
    ] {
        if r > radius_m {
            (governing, radius_m) = (case, r);
        }
    }
    let mut warnings = Vec::new();
    let names = || (rod.station.clone(), rod.name.clone());
    if governing == GoverningCase::Unloaded {
        let (station, rod) = names();
        warnings.push(SizingWarning::UnloadedRod { station, rod });
    }
    if let Some(allowed) = rod.max_outer_radius_m.filter(|&a| radius_m > a) {
        let (station, rod) = names();
        warnings.push(SizingWarning::RodExceedsEnvelope {
            station,
            rod,
            required_outer_radius_m: radius_m,
            allowed_outer_radius_m: allowed,
        });
    }
    if 2.0 * radius_m > length_m {
        let (station, rod) = names();
        warnings.push(SizingWarning::RodNotSlender {
            station,
            rod,
            outer_diameter_m: 2.0 * radius_m,
            length_m,
        });
    }
    if governing == GoverningCase::Buckling {
        let slenderness = fixity * length_m / rod.shape.radius_of_gyration_m(radius_m);
        let transition = PI * (2.0 * e / sigma).sqrt();
        if slenderness < transition {
            let (station, rod) = names();
            warnings.push(SizingWarning::IntermediateColumn {
                station,
                rod,
                slenderness_ratio: slenderness,
                transition_slenderness_ratio: transition,
            });
        }
    }
    let second_moment = rod.shape.second_moment_m4(radius_m);
    Ok(RodSizing {
        station: rod.station.clone(),
        name: rod.name.clone(),
        governing,
        radius_m,
        inner_radius_m: rod.shape.inner_radius_m(radius_m),
        tension_radius_m,
        compression_radius_m,
        buckling_radius_m,
        bending_radius_m,
        critical_load_n: euler_critical_load_n(e, second_moment, fixity, length_m)?,
        mass_kg: rod.shape.area_m2(radius_m) * length_m * material.density_kg_m3,
        warnings,
    })
}
