//! A representative wing model shared by the tests and the bench: two panels (a kink),
//! taper, sweep, dihedral, twist, mixed airfoil sources (NACA analytic open and closed
//! trailing edges and the thesis flap file), an own-section flap with a two-point hinge, a
//! cut-out flap with a chord-fraction hinge, two spars and a bent torque tube.
#![allow(dead_code)] // each user of the fixture uses part of it

use flapwright_geom::{
    Airfoil, FlapSectionSpec, FlapSpec, HingeSpec, PanelSpec, SparSpec, SweepReference, TorqueTubeSpec, TrailingEdge,
    Wing, WingModel, WingSectionSpec, WingSpec,
};
use nalgebra::Point3;

/// Path of a file in the workspace `data/` folder.
pub fn data_path(relative: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data")
        .join(relative)
}

/// The thesis flap section NACA 63-212 from `data/airfoils/n63212.dat`.
pub fn n63212() -> Airfoil {
    Airfoil::from_dat(std::fs::File::open(data_path("airfoils/n63212.dat")).unwrap()).unwrap()
}

/// The wing of the representative model.
pub fn wing_spec() -> WingSpec {
    let section = |y_m: f64, chord_m: f64, twist_deg: f64, airfoil: Airfoil| WingSectionSpec {
        y_m,
        chord_m,
        twist_deg,
        airfoil,
    };
    WingSpec {
        root_leading_edge_ac: Point3::new(0.0, 0.0, 0.0),
        sections: vec![
            section(0.0, 2.0, 2.0, Airfoil::naca("4415", 50, TrailingEdge::Open).unwrap()),
            section(2.5, 1.6, 0.0, Airfoil::naca("23012", 50, TrailingEdge::Closed).unwrap()),
            section(6.0, 0.9, -3.0, Airfoil::naca("2412", 50, TrailingEdge::Closed).unwrap()),
        ],
        panels: vec![
            PanelSpec {
                sweep_deg: 2.0,
                dihedral_deg: 3.0,
            },
            PanelSpec {
                sweep_deg: 15.0,
                dihedral_deg: 5.0,
            },
        ],
        sweep_reference: SweepReference::LeadingEdge,
        twist_axis_chord_fraction: 0.25,
    }
}

/// The representative model.
pub fn model() -> WingModel {
    let spec = wing_spec();
    let wing = Wing::try_new(spec.clone()).unwrap();
    let tube_path = [0.3, 2.5, 4.5].map(|y| wing.chord_point_ac(y, 0.66).unwrap()).to_vec();
    let inboard_hinge = wing.chord_point_ac(0.4, 0.75).unwrap() + nalgebra::Vector3::new(0.0, 0.0, -0.12);
    let outboard_hinge = wing.chord_point_ac(2.5, 0.75).unwrap() + nalgebra::Vector3::new(0.0, 0.0, -0.10);
    let flaps = vec![
        FlapSpec {
            name: "inboard-flap".into(),
            y_inboard_m: 0.4,
            y_outboard_m: 2.5,
            chord_fraction_inboard: 0.3,
            chord_fraction_outboard: 0.3,
            hinge: HingeSpec::Points {
                inboard_ac: inboard_hinge,
                outboard_ac: outboard_hinge,
            },
            section: FlapSectionSpec::OwnSection { airfoil: n63212() },
            side_gap_m: None,
            shroud_chord_fraction: 0.0,
            aft_element: None,
        },
        FlapSpec {
            name: "outboard-flap".into(),
            y_inboard_m: 2.7,
            y_outboard_m: 4.8,
            chord_fraction_inboard: 0.3,
            chord_fraction_outboard: 0.26,
            hinge: HingeSpec::ChordFraction {
                chord_fraction: 0.78,
                depth_below_chord_fraction: 0.06,
            },
            section: FlapSectionSpec::CutOut,
            side_gap_m: None,
            shroud_chord_fraction: 0.0,
            aft_element: None,
        },
    ];
    let spars = vec![
        SparSpec {
            name: "front-spar".into(),
            chord_fraction: 0.15,
            thickness_m: 0.01,
            y_start_m: 0.0,
            y_end_m: 6.0,
        },
        SparSpec {
            name: "rear-spar".into(),
            chord_fraction: 0.6,
            thickness_m: 0.008,
            y_start_m: 0.0,
            y_end_m: 5.5,
        },
    ];
    WingModel::try_new(
        spec,
        flaps,
        spars,
        Some(TorqueTubeSpec {
            path_ac: tube_path,
            radius_m: 0.02,
        }),
    )
    .unwrap()
}
