//! Rod sizing: Euler buckling and strength against hand-computed cases, and warnings.

use approx::assert_relative_eq;
use flapwright_sizing::{
    bending_radius_m, buckling_radius_m, euler_critical_load_n, size_rod, BendingLoad, GoverningCase, Material,
    RodInput, SectionShape, SizingWarning,
};
use std::f64::consts::PI;

/// Hand case: solid r = 10 mm, E = 70 GPa, L = 0.5 m.
/// I = pi r^4 / 4 = pi x 1e-8 / 4 = 7.853981634e-9 m^4.
/// K = 1: P_cr = pi^2 E I / L^2 = 9.869604401 x 7e10 x 7.853981634e-9 / 0.25 = 21704.394 N.
/// K = 2: (K L)^2 = 1 m^2, P_cr = 21704.394 / 4 = 5426.098 N.
#[test]
fn euler_critical_load_hand_case() {
    let i = SectionShape::Solid.second_moment_m4(0.01);
    assert_relative_eq!(i, 7.853_981_633_974_483e-9, max_relative = 1e-12);
    assert_relative_eq!(
        euler_critical_load_n(70e9, i, 1.0, 0.5).unwrap(),
        21_704.393_676_209_87,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        euler_critical_load_n(70e9, i, 2.0, 0.5).unwrap(),
        5_426.098_419_052_468,
        max_relative = 1e-12
    );
}

/// Hand case: P = 10 kN, L = 1 m, K = 1, E = 200 GPa, solid.
/// r^4 = 4 P (K L)^2 / (pi^3 E) = 4e4 / (31.00627668 x 2e11) = 6.450306887e-9 m^4,
/// r = 6.450306887e-9^(1/4) = 8.961796839e-3 m.
#[test]
fn buckling_radius_hand_case() {
    let r = buckling_radius_m(1e4, 1.0, 1.0, 200e9, SectionShape::Solid).unwrap();
    assert_relative_eq!(r, 8.961_796_839_422_65e-3, max_relative = 1e-12);
    // Round trip: the critical load at that radius is the load.
    let p_cr = euler_critical_load_n(200e9, SectionShape::Solid.second_moment_m4(r), 1.0, 1.0).unwrap();
    assert_relative_eq!(p_cr, 1e4, max_relative = 1e-12);
}

/// Strength hand case: P = 50 kN tension, sigma = 500 MPa: A = 1e-4 m^2,
/// r = sqrt(1e-4 / pi) = 5.641895835e-3 m. Short rod (L = 0.1 m), no compression:
/// tension governs. Mass = A L rho = 1e-4 x 0.1 x 7850 = 0.0785 kg.
#[test]
fn tension_governs_hand_case() {
    let material = Material::try_new("steel", 7850.0, 500e6, 300e6, 200e9).unwrap();
    let sized = size_rod(&RodInput::new("s1", "link", 0.1, 5e4, 0.0), &material).unwrap();
    assert_eq!(sized.governing, GoverningCase::Tension);
    assert_relative_eq!(sized.radius_m, 5.641_895_835_477_563e-3, max_relative = 1e-12);
    assert_relative_eq!(sized.mass_kg, 0.0785, max_relative = 1e-12);
    assert!(sized.warnings.is_empty());
}

/// Long compressed rod: buckling governs (r_b = 8.96 mm > r_c = sqrt(1e4 / (pi 500e6)) = 2.52 mm).
#[test]
fn buckling_governs_long_rod() {
    let material = Material::try_new("steel", 7850.0, 500e6, 300e6, 200e9).unwrap();
    let sized = size_rod(&RodInput::new("s1", "strut", 1.0, 2e3, 1e4), &material).unwrap();
    assert_eq!(sized.governing, GoverningCase::Buckling);
    assert_relative_eq!(sized.radius_m, 8.961_796_839_422_65e-3, max_relative = 1e-12);
    assert_relative_eq!(sized.critical_load_n, 1e4, max_relative = 1e-12);
}

/// Tube: I = pi r^4 (1 - k^4) / 4, so r_tube = r_solid / (1 - k^4)^(1/4).
#[test]
fn tubular_buckling_radius() {
    let shape = SectionShape::try_tube(0.8).unwrap();
    let solid = buckling_radius_m(1e4, 1.0, 1.0, 200e9, SectionShape::Solid).unwrap();
    let tube = buckling_radius_m(1e4, 1.0, 1.0, 200e9, shape).unwrap();
    assert_relative_eq!(tube, solid / (1.0f64 - 0.8f64.powi(4)).powf(0.25), max_relative = 1e-12);
}

/// A rod that would need to be fatter than its station allows and than it is long:
/// 5 MN over 0.05 m of aluminium needs r = sqrt(5e6 / (pi 503e6)) = 56.2 mm.
#[test]
fn absurd_rod_is_warned_with_numbers() {
    let mut rod = RodInput::new("outboard", "drive link", 0.05, 5e6, 0.0);
    rod.max_outer_radius_m = Some(0.02);
    let sized = size_rod(&rod, &Material::aluminium_7075_t6()).unwrap();
    let r = sized.radius_m;
    assert_relative_eq!(r, (5e6 / (std::f64::consts::PI * 503e6)).sqrt(), max_relative = 1e-12);
    assert!(sized.warnings.contains(&SizingWarning::RodExceedsEnvelope {
        station: "outboard".into(),
        rod: "drive link".into(),
        required_outer_radius_m: r,
        allowed_outer_radius_m: 0.02,
    }));
    assert!(sized.warnings.contains(&SizingWarning::RodNotSlender {
        station: "outboard".into(),
        rod: "drive link".into(),
        outer_diameter_m: 2.0 * r,
        length_m: 0.05,
    }));
    let text = sized.warnings[0].to_string();
    assert!(text.contains("56.25 mm") && text.contains("20.00 mm"), "{text}");
}

#[test]
fn unloaded_rod_is_warned() {
    let sized = size_rod(&RodInput::new("s", "idle", 1.0, 0.0, 0.0), &Material::steel_4340()).unwrap();
    assert_eq!(sized.governing, GoverningCase::Unloaded);
    assert_eq!(sized.radius_m, 0.0);
    assert_eq!(sized.warnings.len(), 1);
}

/// Combined stress |N| / A + M / (Z (1 - P_c / P_cr)) of a round section at outer radius r.
fn combined_stress(load: BendingLoad, r: f64, shape: SectionShape, e: f64, kl: f64) -> f64 {
    let i = shape.second_moment_m4(r);
    let euler = PI * PI * e * i / (kl * kl);
    let compression = (-load.axial_n).max(0.0);
    load.axial_n.abs() / shape.area_m2(r) + load.bending_moment_nm * r / (i * (1.0 - compression / euler))
}

/// Special cases of the combined requirement: no moment gives the strength (or buckling)
/// radius; tension with bending lands exactly on the allowable, above either alone; a tube
/// needs a larger outer radius than a bar for the same moment, by (1 - k^4)^(-1/3).
#[test]
fn bending_radius_reduces_to_the_single_requirements() {
    let steel = Material::steel_4340();
    let (e, sigma) = (steel.youngs_modulus_pa, steel.allowable_tensile_pa);
    let solid = SectionShape::Solid;
    let tension_only = BendingLoad {
        axial_n: 2e4,
        bending_moment_nm: 0.0,
    };
    let r = bending_radius_m(&[tension_only], 0.4, 1.0, e, sigma, solid).unwrap();
    assert_relative_eq!(r, (2e4 / (PI * sigma)).sqrt(), max_relative = 1e-12);
    let both = BendingLoad {
        axial_n: 2e4,
        bending_moment_nm: 150.0,
    };
    let r = bending_radius_m(&[both], 0.4, 1.0, e, sigma, solid).unwrap();
    assert_relative_eq!(combined_stress(both, r, solid, e, 0.4), sigma, max_relative = 1e-11);
    assert!(r > (4.0 * 150.0 / (PI * sigma)).cbrt() && r > (2e4 / (PI * sigma)).sqrt());
    let tube = SectionShape::try_tube(0.8).unwrap();
    let moment_only = BendingLoad {
        axial_n: 0.0,
        bending_moment_nm: 150.0,
    };
    let bar = bending_radius_m(&[moment_only], 0.4, 1.0, e, sigma, solid).unwrap();
    let hollow = bending_radius_m(&[moment_only], 0.4, 1.0, e, sigma, tube).unwrap();
    assert_relative_eq!(
        hollow / bar,
        (1.0 - 0.8f64.powi(4)).powf(-1.0 / 3.0),
        max_relative = 1e-11
    );
}

/// Compression amplifies the moment: the radius meets the amplified stress exactly, grows
/// with the length (the Euler load falls), and exceeds the radius the same load needs
/// without the amplification.
#[test]
fn compression_amplifies_the_bending_moment() {
    let aluminium = Material::aluminium_7075_t6();
    let (e, sigma) = (aluminium.youngs_modulus_pa, aluminium.allowable_tensile_pa);
    let solid = SectionShape::Solid;
    let load = BendingLoad {
        axial_n: -3e4,
        bending_moment_nm: 400.0,
    };
    let short = bending_radius_m(&[load], 0.2, 1.0, e, sigma, solid).unwrap();
    let long = bending_radius_m(&[load], 1.5, 1.0, e, sigma, solid).unwrap();
    assert_relative_eq!(combined_stress(load, long, solid, e, 1.5), sigma, max_relative = 1e-11);
    assert!(long > short, "{long} <= {short}");
    let unamplified = |r: f64| 3e4 / solid.area_m2(r) + 400.0 * r / solid.second_moment_m4(r);
    assert!(
        unamplified(long) < sigma * (1.0 - 1e-6),
        "amplification made a difference"
    );
    // Several poses: the worst governs.
    let mild = BendingLoad {
        axial_n: 1e3,
        bending_moment_nm: 10.0,
    };
    let both = bending_radius_m(&[mild, load], 1.5, 1.0, e, sigma, solid).unwrap();
    assert_eq!(both, long);
}

/// A member that bends is sized for the combined case, named as governing, with its mass
/// from the bending radius, and warned when the kind's solid is thinner.
#[test]
fn a_member_that_bends_is_sized_for_the_combined_stress() {
    let steel = Material::steel_4340();
    let mut rod = RodInput::new("ib-inner", "crank", 0.3, 5e3, 2e3);
    rod.max_outer_radius_m = Some(0.01);
    rod.bending = vec![
        BendingLoad {
            axial_n: 5e3,
            bending_moment_nm: 900.0,
        },
        BendingLoad {
            axial_n: -2e3,
            bending_moment_nm: 300.0,
        },
    ];
    let sized = size_rod(&rod, &steel).unwrap();
    assert_eq!(sized.governing, GoverningCase::Bending);
    let r = sized.bending_radius_m.unwrap();
    assert_eq!(sized.radius_m, r);
    assert!(r > sized.tension_radius_m && r > sized.buckling_radius_m);
    assert_relative_eq!(
        sized.mass_kg,
        PI * r * r * 0.3 * steel.density_kg_m3,
        max_relative = 1e-12
    );
    assert!(sized
        .warnings
        .iter()
        .any(|w| matches!(w, SizingWarning::RodExceedsEnvelope { rod, .. } if rod == "crank")));
    // A negative moment is refused with the field's name.
    rod.bending[1].bending_moment_nm = -1.0;
    let error = size_rod(&rod, &steel).unwrap_err().to_string();
    assert!(
        error.contains("crank") && error.contains("bending[1].bending_moment_nm"),
        "{error}"
    );
}
