//! The default scene (`data/scenes/small-aircraft.toml`) built from the Rust API: a NACA
//! 63-215 wing from a `.dat` file with an own-section NACA 63-212 flap, a chord fraction
//! tapering 0.283 -> 0.2715, a 40 mm side gap and a two-point hinge. Regression: at fine
//! airfoil resolution the cove-cut wing skin caps failed to triangulate.

use flapwright_geom::{
    Airfoil, FlapSectionSpec, FlapSpec, HingeSpec, MeshResolution, PanelSpec, SparSpec, SweepReference, TorqueTubeSpec,
    WingModel, WingSectionSpec, WingSpec,
};
use nalgebra::Point3;

use crate::fixture::data_path;

/// An airfoil file from `data/airfoils`, resampled as the CLI does.
fn dat_airfoil(file: &str, points_per_side: usize) -> Airfoil {
    let path = data_path(&format!("airfoils/{file}"));
    Airfoil::from_dat(std::fs::File::open(path).unwrap())
        .unwrap()
        .resampled(points_per_side)
        .unwrap()
}

/// The default scene's wing model with its airfoils resampled to `points_per_side`.
pub fn scene_model(points_per_side: usize) -> WingModel {
    let wing_airfoil = dat_airfoil("n63215.dat", points_per_side);
    let section = |y_m: f64, chord_m: f64, twist_deg: f64| WingSectionSpec {
        y_m,
        chord_m,
        twist_deg,
        airfoil: wing_airfoil.clone(),
    };
    let wing = WingSpec {
        root_leading_edge_ac: Point3::new(0.0, 0.6, 0.0),
        sections: vec![section(0.6, 2.1, 0.0), section(5.5, 1.2, -2.0)],
        panels: vec![PanelSpec {
            sweep_deg: 3.0,
            dihedral_deg: 5.0,
        }],
        sweep_reference: SweepReference::LeadingEdge,
        twist_axis_chord_fraction: 0.25,
    };
    let flap = FlapSpec {
        name: "flap".into(),
        y_inboard_m: 0.8,
        y_outboard_m: 3.0,
        chord_fraction_inboard: 0.283,
        chord_fraction_outboard: 0.2715,
        hinge: HingeSpec::Points {
            inboard_ac: Point3::new(1.6609, 0.8, -0.3025),
            outboard_ac: Point3::new(1.4530, 3.0, -0.1200),
        },
        section: FlapSectionSpec::OwnSection {
            airfoil: dat_airfoil("n63212.dat", points_per_side),
        },
        side_gap_m: Some(0.040),
        shroud_chord_fraction: 0.0,
        aft_element: None,
    };
    let spar = |name: &str, chord_fraction: f64| SparSpec {
        name: name.into(),
        chord_fraction,
        thickness_m: 0.006,
        y_start_m: 0.6,
        y_end_m: 5.5,
    };
    let tube = TorqueTubeSpec {
        path_ac: vec![Point3::new(1.4017, 0.8, 0.0196), Point3::new(1.2960, 3.0, 0.2594)],
        radius_m: 0.020,
    };
    WingModel::try_new(
        wing,
        vec![flap],
        vec![spar("front-spar", 0.20), spar("rear-spar", 0.64)],
        Some(tube),
    )
    .unwrap()
}

#[test]
fn scene_meshes_watertight_at_every_resolution() {
    // Part volumes (m^3) at the finest resolution, to check the coarser ones converge to.
    let mut finest: Vec<f64> = Vec::new();
    for points_per_side in [240, 160, 120, 60, 20] {
        let resolution = MeshResolution {
            points_per_side,
            ..MeshResolution::default()
        };
        let parts = scene_model(points_per_side)
            .compute_parts(resolution)
            .unwrap_or_else(|e| panic!("{points_per_side} points per side: {e}"));
        for part in &parts {
            let check = part.mesh.compute_topology_check();
            assert!(check.is_watertight(), "{points_per_side}: {}: {check:?}", part.name);
            assert!(
                part.mesh.compute_signed_volume() > 0.0,
                "{points_per_side}: {}",
                part.name
            );
        }
        let volumes: Vec<f64> = parts.iter().map(|p| p.mesh.compute_signed_volume()).collect();
        if finest.is_empty() {
            finest = volumes;
        } else {
            // A cap with missing or overlapping triangles would change the volume by far more.
            for (v, f) in volumes.iter().zip(&finest) {
                approx::assert_relative_eq!(*v, *f, max_relative = 2e-2);
            }
        }
    }
}
