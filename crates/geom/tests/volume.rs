//! Volume of straight wings: exact for the section polygon, converging to the analytic
//! section area at second order.

use approx::assert_relative_eq;
use flapwright_geom::{
    Airfoil, MeshResolution, PanelSpec, SweepReference, TrailingEdge, WingModel, WingSectionSpec, WingSpec,
};
use nalgebra::{Isometry3, Point3, Vector3};
use proptest::prelude::*;

fn straight_wing(airfoil: Airfoil, chord_m: f64, span_m: f64, twist_deg: f64, panel: PanelSpec) -> WingSpec {
    WingSpec {
        root_leading_edge_ac: Point3::new(0.2, 0.0, 0.1),
        sections: vec![
            WingSectionSpec {
                y_m: 0.0,
                chord_m,
                twist_deg,
                airfoil: airfoil.clone(),
            },
            WingSectionSpec {
                y_m: span_m,
                chord_m,
                twist_deg,
                airfoil,
            },
        ],
        panels: vec![panel],
        sweep_reference: SweepReference::LeadingEdge,
        twist_axis_chord_fraction: 0.3,
    }
}

fn wing_volume(spec: WingSpec, points_per_side: usize) -> f64 {
    let model = WingModel::try_new(spec, vec![], vec![], None).unwrap();
    let parts = model
        .compute_parts(MeshResolution {
            points_per_side,
            spanwise_stations_per_m: 2.0,
            tube_segments: 8,
        })
        .unwrap();
    assert!(parts[0].mesh.compute_topology_check().is_watertight());
    parts[0].mesh.compute_signed_volume()
}

/// Area of NACA 00tt with the closed trailing edge: `2 * 5t * integral_0^1 of the eq. 6.2 polynomial`.
fn analytic_area(t: f64) -> f64 {
    10.0 * t * (0.2969 * 2.0 / 3.0 - 0.1260 / 2.0 - 0.3516 / 3.0 + 0.2843 / 4.0 - 0.1036 / 5.0)
}

#[test]
fn straight_wing_volume_is_polygon_area_times_span() {
    for (designation, te) in [("0012", TrailingEdge::Closed), ("4415", TrailingEdge::Open)] {
        let airfoil = Airfoil::naca(designation, 40, te).unwrap();
        let expected = airfoil.compute_area() * 1.5 * 1.5 * 3.0;
        let plain = wing_volume(
            straight_wing(
                airfoil.clone(),
                1.5,
                3.0,
                0.0,
                PanelSpec {
                    sweep_deg: 0.0,
                    dihedral_deg: 0.0,
                },
            ),
            40,
        );
        assert_relative_eq!(plain, expected, max_relative = 1e-12);
        // Sweep, dihedral and constant twist shear or rotate the sections: same volume (Cavalieri).
        let sheared = wing_volume(
            straight_wing(
                airfoil,
                1.5,
                3.0,
                6.0,
                PanelSpec {
                    sweep_deg: 35.0,
                    dihedral_deg: -8.0,
                },
            ),
            40,
        );
        assert_relative_eq!(sheared, expected, max_relative = 1e-12);
    }
}

#[test]
fn section_area_converges_at_second_order() {
    let exact = analytic_area(0.12);
    let errors: Vec<f64> = [20, 40, 80, 160]
        .iter()
        .map(|&n| (Airfoil::naca("0012", n, TrailingEdge::Closed).unwrap().compute_area() - exact).abs())
        .collect();
    for w in errors.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((1.8..2.3).contains(&order), "observed order {order}, errors {errors:?}");
    }
    // And the wing volume follows the section area.
    let volume = wing_volume(
        straight_wing(
            Airfoil::naca("0012", 80, TrailingEdge::Closed).unwrap(),
            1.0,
            2.0,
            0.0,
            PanelSpec {
                sweep_deg: 0.0,
                dihedral_deg: 0.0,
            },
        ),
        80,
    );
    assert_relative_eq!(volume, exact * 2.0, max_relative = 2e-3);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]
    #[test]
    fn volume_is_invariant_under_rigid_motion(rx in -3.0..3.0f64, ry in -3.0..3.0f64, rz in -3.0..3.0f64, t in -10.0..10.0f64) {
        let model = WingModel::try_new(straight_wing(Airfoil::naca("2412", 20, TrailingEdge::Open).unwrap(), 1.0, 2.0, 3.0, PanelSpec { sweep_deg: 20.0, dihedral_deg: 5.0 }), vec![], vec![], None).unwrap();
        let mesh = model.compute_parts(MeshResolution { points_per_side: 20, spanwise_stations_per_m: 1.0, tube_segments: 8 }).unwrap().remove(0).mesh;
        let pose = Isometry3::new(Vector3::new(t, -t, 2.0 * t), Vector3::new(rx, ry, rz));
        let moved = mesh.transformed(&pose);
        prop_assert!((moved.compute_signed_volume() - mesh.compute_signed_volume()).abs() <= 1e-12 * mesh.compute_signed_volume());
        prop_assert!(moved.compute_topology_check().is_watertight());
    }
}
