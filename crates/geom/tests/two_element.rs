//! Two-element flaps: the aft element nested under the main element's trailing edge, the
//! main element cut for it as the wing is cut for the flap.

use flapwright_geom::flap::SHROUD_CLEARANCE_CHORD_FRACTION;
use flapwright_geom::parts::aft_element_name;
use flapwright_geom::{
    AftElementSpec, Airfoil, CollisionShape, Error, FlapSectionSpec, MeshResolution, PartKind, SectionOutline,
    TrailingEdge, WingModel,
};
use nalgebra::Point2;

use crate::fixture::{model, wing_spec};

const RESOLUTION: MeshResolution = MeshResolution {
    points_per_side: 30,
    spanwise_stations_per_m: 2.0,
    tube_segments: 16,
};

/// The fixture's inboard flap (its own NACA 63-212 section) with an aft element of
/// `chord_fraction` of its chord and a shroud of 4 % of it.
fn with_aft_element(chord_fraction: f64) -> Result<WingModel, Error> {
    let base = model();
    let mut flaps: Vec<_> = base.flaps().iter().map(|f| f.spec().clone()).collect();
    flaps[0].aft_element = Some(AftElementSpec {
        airfoil: Airfoil::naca("0009", 50, TrailingEdge::Closed).unwrap(),
        chord_fraction,
        shroud_chord_fraction: 0.04,
    });
    WingModel::try_new(wing_spec(), flaps, base.spars().to_vec(), base.torque_tube().cloned())
}

/// A section outline in its plane (aircraft x, z).
fn in_plane(outline: &SectionOutline) -> Vec<Point2<f64>> {
    outline.points_ac.iter().map(|p| Point2::new(p.x, p.z)).collect()
}

fn outline<'a>(outlines: &'a [SectionOutline], name: &str) -> &'a SectionOutline {
    outlines.iter().find(|o| o.name == name).unwrap()
}

fn extent_x(points: &[Point2<f64>]) -> (f64, f64) {
    points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(p.x), hi.max(p.x))
    })
}

/// Even-odd rule.
fn contains(polygon: &[Point2<f64>], p: &Point2<f64>) -> bool {
    let mut inside = false;
    for (a, b) in polygon.iter().zip(polygon.iter().cycle().skip(1)) {
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

fn segment_distance(p: &Point2<f64>, a: &Point2<f64>, b: &Point2<f64>) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
    (p - (a + ab * t)).norm()
}

/// Smallest distance from the vertices of each polygon to the edges of the other.
fn polygon_distance(first: &[Point2<f64>], second: &[Point2<f64>]) -> f64 {
    let one_way = |points: &[Point2<f64>], polygon: &[Point2<f64>]| {
        points
            .iter()
            .flat_map(|p| {
                polygon
                    .iter()
                    .zip(polygon.iter().cycle().skip(1))
                    .map(move |(a, b)| segment_distance(p, a, b))
            })
            .fold(f64::INFINITY, f64::min)
    };
    one_way(first, second).min(one_way(second, first))
}

#[test]
fn the_aft_element_is_a_part_of_its_own_nested_clear_of_the_main_element() {
    let parts = with_aft_element(0.35).unwrap().compute_parts(RESOLUTION).unwrap();
    let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names[..3], ["wing", "inboard-flap", "inboard-flap-aft"]);
    assert_eq!(parts[2].kind, PartKind::AftElement);
    assert_eq!(parts[2].flap_element(), Some(("inboard-flap", true)));
    assert_eq!(parts[1].flap_element(), Some(("inboard-flap", false)));
    for part in &parts[..3] {
        assert!(part.mesh.compute_topology_check().is_watertight(), "{}", part.name);
        assert!(part.mesh.compute_signed_volume() > 0.0, "{}", part.name);
    }
    // The elements and the wing keep clear of each other stowed, the slot between the two
    // elements a few millimetres at this 0.6 m flap chord.
    let shape = |k: usize| CollisionShape::from_mesh(&parts[k].mesh).unwrap();
    let identity = nalgebra::Isometry3::identity();
    let clearance = |a: usize, b: usize| {
        flapwright_geom::compute_clearance(&shape(a), &identity, &shape(b), &identity, 1e-3)
            .unwrap()
            .distance_m
    };
    let slot = clearance(1, 2);
    assert!(slot > 0.0 && slot < 0.02, "slot {slot} m");
    let behind_wing = clearance(0, 2);
    assert!(behind_wing > 0.0, "aft element against the wing: {behind_wing} m");
}

#[test]
fn the_section_splits_the_single_element_flap_where_the_aft_element_nests() {
    let y = 1.5;
    let single = model().compute_section_outlines(y, 30).unwrap();
    let split = with_aft_element(0.35).unwrap().compute_section_outlines(y, 30).unwrap();
    let whole = in_plane(outline(&single, "inboard-flap"));
    let main = in_plane(outline(&split, "inboard-flap"));
    let aft_outline = outline(&split, &aft_element_name("inboard-flap"));
    assert_eq!(aft_outline.kind, PartKind::AftElement);
    let aft = in_plane(aft_outline);
    let (whole_front, whole_back) = extent_x(&whole);
    let (main_front, main_back) = extent_x(&main);
    let (aft_front, aft_back) = extent_x(&aft);
    // The main element keeps the flap's nose; the aft element ends on the flap's trailing
    // edge (aircraft x aft).
    assert!((main_front - whole_front).abs() < 1e-9, "{main_front} {whole_front}");
    assert!((aft_back - whole_back).abs() < 1e-9, "{aft_back} {whole_back}");
    // Its chord is the asked share of the flap's (the two chord lines differ in incidence
    // by the flap mean line's slope, a few degrees: cosines within 1 %).
    let flap_chord = whole_back - whole_front;
    let ratio = (aft_back - aft_front) / flap_chord;
    assert!((ratio - 0.35).abs() < 0.35 * 0.01, "aft chord share {ratio}");
    // The main element reaches over the aft element's nose (the shroud), and not past the
    // flap's own trailing edge.
    assert!(
        main_back > aft_front && main_back < whole_back,
        "{main_back} {aft_front} {whole_back}"
    );
    // No point of one element lies inside the other, and the slot keeps at least part of
    // the shroud clearance (checked by the shroud at sampled stations only).
    assert!(aft.iter().all(|p| !contains(&main, p)));
    assert!(main.iter().all(|p| !contains(&aft, p)));
    let gap = polygon_distance(&main, &aft);
    assert!(
        gap >= 0.5 * SHROUD_CLEARANCE_CHORD_FRACTION * flap_chord,
        "slot {gap} m at flap chord {flap_chord} m"
    );
}

#[test]
fn an_aft_element_needs_the_flaps_own_section_and_a_sensible_chord() {
    assert!(matches!(
        with_aft_element(0.05),
        Err(Error::OutOfRange {
            what: "flap aft_element chord_fraction",
            ..
        })
    ));
    let base = model();
    let mut flaps: Vec<_> = base.flaps().iter().map(|f| f.spec().clone()).collect();
    assert_eq!(flaps[1].section, FlapSectionSpec::CutOut);
    flaps[1].aft_element = Some(AftElementSpec {
        airfoil: Airfoil::naca("0009", 50, TrailingEdge::Closed).unwrap(),
        chord_fraction: 0.3,
        shroud_chord_fraction: 0.0,
    });
    assert!(matches!(
        WingModel::try_new(wing_spec(), flaps, vec![], None),
        Err(Error::AftElementNeedsOwnSection { flap }) if flap == "outboard-flap"
    ));
}
