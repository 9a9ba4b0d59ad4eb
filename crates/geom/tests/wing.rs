//! Sweep, dihedral and twist checked by transforming known points.

use approx::assert_relative_eq;
use flapwright_geom::{
    Airfoil, Error, PanelSpec, Surface, SweepReference, TrailingEdge, Wing, WingSectionSpec, WingSpec,
};
use nalgebra::{Point3, Rotation3, Vector3};

fn two_section_wing(
    chords: (f64, f64),
    twists_deg: (f64, f64),
    panel: PanelSpec,
    reference: SweepReference,
) -> WingSpec {
    let airfoil = Airfoil::naca("2412", 30, TrailingEdge::Closed).unwrap();
    WingSpec {
        root_leading_edge_ac: Point3::new(0.3, 0.5, -0.1),
        sections: vec![
            WingSectionSpec {
                y_m: 0.5,
                chord_m: chords.0,
                twist_deg: twists_deg.0,
                airfoil: airfoil.clone(),
            },
            WingSectionSpec {
                y_m: 4.5,
                chord_m: chords.1,
                twist_deg: twists_deg.1,
                airfoil,
            },
        ],
        panels: vec![panel],
        sweep_reference: reference,
        twist_axis_chord_fraction: 0.25,
    }
}

#[test]
fn leading_edge_sweep_and_dihedral_move_the_leading_edge() {
    let panel = PanelSpec {
        sweep_deg: 30.0,
        dihedral_deg: -7.0,
    };
    let wing = Wing::try_new(two_section_wing(
        (2.0, 1.0),
        (0.0, 0.0),
        panel,
        SweepReference::LeadingEdge,
    ))
    .unwrap();
    for y in [0.5, 1.7, 4.5] {
        let le = wing.chord_point_ac(y, 0.0).unwrap();
        let dy = y - 0.5;
        assert_relative_eq!(le.x, 0.3 + dy * 30f64.to_radians().tan(), max_relative = 1e-12);
        assert_relative_eq!(le.z, -0.1 + dy * (-7f64).to_radians().tan(), max_relative = 1e-12);
        assert_relative_eq!(le.y, y, max_relative = 1e-15);
    }
}

#[test]
fn quarter_chord_sweep_moves_the_quarter_chord_line() {
    let panel = PanelSpec {
        sweep_deg: 25.0,
        dihedral_deg: 0.0,
    };
    let wing = Wing::try_new(two_section_wing(
        (2.0, 0.8),
        (0.0, 0.0),
        panel,
        SweepReference::QuarterChord,
    ))
    .unwrap();
    let root = wing.chord_point_ac(0.5, 0.25).unwrap();
    let tip = wing.chord_point_ac(4.5, 0.25).unwrap();
    assert_relative_eq!(
        (tip.x - root.x) / (tip.y - root.y),
        25f64.to_radians().tan(),
        max_relative = 1e-12
    );
    // Unswept quarter chord with taper: the leading edge sweeps forward... aft by (c_r - c_t)/4.
    let unswept = Wing::try_new(two_section_wing(
        (2.0, 0.8),
        (0.0, 0.0),
        PanelSpec {
            sweep_deg: 0.0,
            dihedral_deg: 0.0,
        },
        SweepReference::QuarterChord,
    ))
    .unwrap();
    assert_relative_eq!(
        unswept.chord_point_ac(4.5, 0.0).unwrap().x - 0.3,
        0.25 * (2.0 - 0.8),
        max_relative = 1e-12
    );
}

#[test]
fn twist_rotates_about_the_twist_axis_nose_up() {
    let panel = PanelSpec {
        sweep_deg: 10.0,
        dihedral_deg: 4.0,
    };
    let wing = Wing::try_new(two_section_wing(
        (1.5, 1.5),
        (8.0, 8.0),
        panel,
        SweepReference::LeadingEdge,
    ))
    .unwrap();
    let untwisted = Wing::try_new(two_section_wing(
        (1.5, 1.5),
        (0.0, 0.0),
        panel,
        SweepReference::LeadingEdge,
    ))
    .unwrap();
    let y = 2.0;
    let axis = untwisted.chord_point_ac(y, 0.25).unwrap();
    let rotation = Rotation3::from_axis_angle(&Vector3::y_axis(), 8f64.to_radians());
    for (x, surface) in [
        (0.0, Surface::Upper),
        (0.5, Surface::Upper),
        (0.9, Surface::Lower),
        (1.0, Surface::Lower),
    ] {
        let plain = untwisted.point_ac(y, x, surface).unwrap();
        let expected = axis + rotation * (plain - axis);
        let twisted = wing.point_ac(y, x, surface).unwrap();
        assert_relative_eq!((twisted - expected).norm(), 0.0, epsilon = 1e-12);
    }
    // Nose up: the leading edge rises by 0.25 c sin(theta), the trailing edge drops by 0.75 c sin(theta).
    let le = wing.chord_point_ac(y, 0.0).unwrap();
    let te = wing.chord_point_ac(y, 1.0).unwrap();
    assert_relative_eq!(
        le.z - axis.z,
        0.25 * 1.5 * 8f64.to_radians().sin(),
        max_relative = 1e-12
    );
    assert_relative_eq!(
        te.z - axis.z,
        -0.75 * 1.5 * 8f64.to_radians().sin(),
        max_relative = 1e-12
    );
}

#[test]
fn kinked_wing_places_the_second_panel_from_the_kink() {
    let spec = crate::fixture::wing_spec();
    let wing = Wing::try_new(spec).unwrap();
    let kink = wing.section_leading_edges_ac()[1];
    let tip = wing.section_leading_edges_ac()[2];
    assert_relative_eq!(kink.x, 2.5 * 2f64.to_radians().tan(), max_relative = 1e-12);
    assert_relative_eq!(tip.x - kink.x, 3.5 * 15f64.to_radians().tan(), max_relative = 1e-12);
    assert_relative_eq!(tip.z - kink.z, 3.5 * 5f64.to_radians().tan(), max_relative = 1e-12);
    // Blending: half way along the outer panel the section is the mean of its neighbours.
    let section = wing.section_at(4.25).unwrap();
    let a = Airfoil::naca("23012", 50, TrailingEdge::Closed).unwrap();
    let b = Airfoil::naca("2412", 50, TrailingEdge::Closed).unwrap();
    for i in [0, 20, 49, 70] {
        assert_relative_eq!(
            section.airfoil.points[i],
            nalgebra::center(&a.points[i], &b.points[i]),
            epsilon = 1e-15
        );
    }
    assert_relative_eq!(section.chord_m, 1.25, max_relative = 1e-12);
    assert_relative_eq!(section.twist_rad, (-1.5f64).to_radians(), max_relative = 1e-12);
}

#[test]
fn invalid_wings_are_errors() {
    let panel = PanelSpec {
        sweep_deg: 0.0,
        dihedral_deg: 0.0,
    };
    let good = two_section_wing((1.0, 1.0), (0.0, 0.0), panel, SweepReference::LeadingEdge);
    let mut s = good.clone();
    s.sections.swap(0, 1);
    s.root_leading_edge_ac.y = 4.5;
    assert!(matches!(
        Wing::try_new(s),
        Err(Error::SectionsOutOfOrder { index: 1, .. })
    ));
    let mut s = good.clone();
    s.sections[1].chord_m = -1.0;
    assert!(matches!(
        Wing::try_new(s),
        Err(Error::OutOfRange {
            what: "wing section chord_m",
            ..
        })
    ));
    let mut s = good.clone();
    s.sections[0].twist_deg = f64::NAN;
    assert!(Wing::try_new(s).is_err());
    let mut s = good.clone();
    s.panels.clear();
    assert!(matches!(Wing::try_new(s), Err(Error::PanelCount { .. })));
    let mut s = good.clone();
    s.root_leading_edge_ac.y = 0.0;
    assert!(matches!(Wing::try_new(s), Err(Error::RootLeadingEdgeMismatch { .. })));
    let wing = Wing::try_new(good).unwrap();
    assert!(matches!(wing.section_at(5.0), Err(Error::OutsideSpan { .. })));
    assert!(wing.point_ac(1.0, 1.5, Surface::Upper).is_err());
}
