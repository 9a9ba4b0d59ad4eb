//! Rod sizing: Euler buckling and strength against hand-computed cases, and warnings.

use approx::assert_relative_eq;
use flapwright_sizing::{
    buckling_radius_m, euler_critical_load_n, size_rod, GoverningCase, Material, RodInput, SectionShape, SizingWarning,
};

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
