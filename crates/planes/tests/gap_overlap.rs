//! Gap and overlap against closed-form cases: a disc-shaped flap turning about A0 behind a
//! box-shaped wing.

use flapwright_planes::{Error, FlapBehindWing};
use nalgebra::{Point2, Rotation2};

/// Wing section: x from `aft` to the nose at 2.0, y from 0 to 0.1, with the upper lip
/// `lean` further aft than the lower one (a leaning cove wall).
fn wing(aft: f64, lean: f64) -> Vec<Vec<Point2<f64>>> {
    vec![vec![
        Point2::new(aft + lean, 0.0),
        Point2::new(2.0, 0.0),
        Point2::new(2.0, 0.1),
        Point2::new(aft, 0.1),
    ]]
}

/// A regular `n`-gon of circumradius `r` round `centre` (counter-clockwise).
fn disc(centre: Point2<f64>, r: f64, n: usize) -> Vec<Vec<Point2<f64>>> {
    vec![(0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            centre + nalgebra::Vector2::new(a.cos(), a.sin()) * r
        })
        .collect()]
}

#[test]
fn disc_flap_gap_and_overlap_are_analytic_at_every_rotation() {
    let (centre, r, n) = (Point2::new(0.35, -0.1), 0.15, 720);
    let measure = FlapBehindWing::new(&wing(0.5, 0.0), &disc(centre, r, n)).unwrap();
    let te = Point2::new(0.5, 0.1);
    assert_eq!(measure.trailing_edge(), te);
    // Chord: wing nose 2.0 to the disc's aft-most point 0.2.
    assert!((measure.chord_m() - (2.0 - (centre.x - r))).abs() < 1e-12);
    // The polygon lies between its inscribed and circumscribed circles.
    let r_in = r * (std::f64::consts::PI / n as f64).cos();
    for k in 0..=40 {
        let t = -0.3 + 1.2 * f64::from(k) / 40.0;
        let c = Rotation2::new(t) * centre;
        let result = measure.at_rotation(t);
        let to_centre = (te - c).norm();
        let gap_bounds = if to_centre > r {
            (to_centre - r, to_centre - r_in)
        } else {
            (-(r - to_centre), -(r_in - to_centre))
        };
        assert!(
            result.gap_m >= gap_bounds.0 - 1e-12 && result.gap_m <= gap_bounds.1 + 1e-12,
            "t = {t}: gap {} outside {gap_bounds:?}",
            result.gap_m
        );
        let overlap = (c.x + r_in - te.x, c.x + r - te.x);
        assert!(result.overlap_m >= overlap.0 - 1e-12 && result.overlap_m <= overlap.1 + 1e-12);
        assert!((result.gap_percent_chord - 100.0 * result.gap_m / measure.chord_m()).abs() < 1e-12);
        assert!((result.overlap_percent_chord - 100.0 * result.overlap_m / measure.chord_m()).abs() < 1e-12);
    }
}

#[test]
fn trailing_edge_inside_the_flap_gives_a_negative_gap() {
    // Disc round the trailing edge itself, 20 mm radius: gap -20 mm.
    let te = Point2::new(0.5, 0.1);
    let measure = FlapBehindWing::new(&wing(0.5, 0.0), &disc(te, 0.02, 4000)).unwrap();
    let result = measure.at_rotation(0.0);
    assert!((result.gap_m + 0.02).abs() < 1e-6, "{}", result.gap_m);
}

#[test]
fn the_upper_lip_of_a_leaning_cove_wall_is_the_trailing_edge() {
    let flap = disc(Point2::new(0.3, 0.0), 0.1, 64);
    // Lower lip 5 mm further aft than the upper one: still the upper lip (within 1 % c).
    let leaning = FlapBehindWing::new(&wing(0.505, -0.005), &flap).unwrap();
    assert_eq!(leaning.trailing_edge(), Point2::new(0.505, 0.1));
    // A lower lip 0.2 m aft is a different wing: its aft-most point is the trailing edge.
    let long_lower = FlapBehindWing::new(&wing(0.7, -0.2), &flap).unwrap();
    assert_eq!(long_lower.trailing_edge(), Point2::new(0.7 - 0.2, 0.0));
}

#[test]
fn bad_sections_are_errors() {
    let flap = disc(Point2::new(0.3, 0.0), 0.1, 16);
    assert!(matches!(FlapBehindWing::new(&[], &flap), Err(Error::TooFew { .. })));
    assert!(matches!(
        FlapBehindWing::new(&wing(0.5, 0.0), &[]),
        Err(Error::TooFew { .. })
    ));
    let ahead = disc(Point2::new(3.0, 0.0), 0.1, 16);
    assert!(matches!(
        FlapBehindWing::new(&wing(0.5, 0.0), &ahead),
        Err(Error::FlapNotBehindWing { .. })
    ));
    let mut nan = flap.clone();
    nan[0][3].y = f64::NAN;
    assert!(matches!(
        FlapBehindWing::new(&wing(0.5, 0.0), &nan),
        Err(Error::NotFinite { .. })
    ));
}

/// A wing section whose upper skin rises forward, y = 0.1 + 0.08 (x - 0.5), sampled at
/// `n` points from the nose at x = 2 back to a cove wall at x = 0.5 (vertical, lower skin
/// on y = 0): its upper lip is (0.5, 0.1) exactly, whatever the sampling.
fn cambered_wing(n: usize) -> Vec<Point2<f64>> {
    let mut polygon = vec![Point2::new(0.5, 0.0), Point2::new(2.0, 0.0)];
    polygon.extend((0..=n).map(|i| {
        let x = 2.0 - 1.5 * i as f64 / n as f64;
        Point2::new(x, 0.1 + 0.08 * (x - 0.5))
    }));
    polygon
}

#[test]
fn the_cove_lip_of_a_cambered_upper_skin_is_found_at_any_resolution() {
    let flap = disc(Point2::new(0.3, 0.0), 0.1, 64);
    for n in [3, 20, 150, 1000] {
        let lip = FlapBehindWing::new(&[cambered_wing(n)], &flap).unwrap().trailing_edge();
        assert!((lip - Point2::new(0.5, 0.1)).norm() < 1e-15, "n = {n}: {lip}");
        // Clockwise input finds the same lip.
        let mut reversed = cambered_wing(n);
        reversed.reverse();
        let lip = FlapBehindWing::new(&[reversed], &flap).unwrap().trailing_edge();
        assert!(
            (lip - Point2::new(0.5, 0.1)).norm() < 1e-15,
            "n = {n}, clockwise: {lip}"
        );
    }
    // Turned as twist and skew turn a station's section (here -15 and 10 deg about the
    // hinge at the origin), the lip is the turned lip.
    for angle_deg in [-15.0_f64, 10.0] {
        let turn = Rotation2::new(angle_deg.to_radians());
        let wing: Vec<Point2<f64>> = cambered_wing(400).iter().map(|p| turn * p).collect();
        let flap: Vec<Vec<Point2<f64>>> = vec![flap[0].iter().map(|p| turn * p).collect()];
        let lip = FlapBehindWing::new(&[wing], &flap).unwrap().trailing_edge();
        assert!(
            (lip - turn * Point2::new(0.5, 0.1)).norm() < 1e-15,
            "{angle_deg} deg: {lip}"
        );
    }
}

#[test]
fn a_general_displacement_moves_the_flap_as_a_rigid_body() {
    // A disc flap moved aft and down without turning (a hooked track's first travel):
    // gap and overlap follow the disc's centre.
    let (centre, r, n) = (Point2::new(0.35, -0.1), 0.15, 720);
    let measure = FlapBehindWing::new(&wing(0.5, 0.0), &disc(centre, r, n)).unwrap();
    let te = Point2::new(0.5, 0.1);
    let r_in = r * (std::f64::consts::PI / n as f64).cos();
    for (dx, dy) in [(0.0, 0.0), (-0.05, -0.02), (-0.12, -0.08)] {
        let moved = nalgebra::Isometry2::translation(dx, dy);
        let result = measure.at_displacement(&moved);
        let c = centre + nalgebra::Vector2::new(dx, dy);
        let to_centre = (te - c).norm();
        assert!(result.gap_m >= to_centre - r - 1e-12 && result.gap_m <= to_centre - r_in + 1e-12);
        assert!(result.overlap_m >= c.x + r_in - te.x - 1e-12 && result.overlap_m <= c.x + r - te.x + 1e-12);
        assert_eq!(result.rotation_rad, 0.0);
    }
    // A turn about A0 is the displacement of that turn.
    for t in [0.1, 0.6] {
        assert_eq!(
            measure.at_rotation(t),
            measure.at_displacement(&nalgebra::Isometry2::rotation(t))
        );
    }
}

/// The precision position of a flap setting is its inverse: measured back, it gives the
/// asked deflection, gap and overlap; the flap sits under the lip (its centre below it), and
/// an overlap that leaves the nose too far from the lip is a typed error.
#[test]
fn setting_displacement_meets_the_asked_gap_and_overlap() {
    let measure = FlapBehindWing::new(&wing(0.5, 0.0), &disc(Point2::new(0.35, -0.1), 0.15, 360)).unwrap();
    let chord = measure.chord_m();
    for (deflection_deg, gap_percent, overlap_percent) in
        [(0.0, 1.0, 2.0), (15.0, 0.0, 3.0), (35.0, 2.0, 0.0), (40.0, 1.5, -0.5)]
    {
        let (gap, overlap) = (gap_percent * chord / 100.0, overlap_percent * chord / 100.0);
        let moved = measure
            .displacement_for_setting(f64::to_radians(deflection_deg), gap, overlap)
            .unwrap();
        let back = measure.at_displacement(&moved);
        assert!((back.rotation_rad - deflection_deg.to_radians()).abs() < 1e-12);
        assert!(
            (back.gap_m - gap).abs() < 1e-9,
            "{deflection_deg}: gap {} for {gap}",
            back.gap_m
        );
        assert!((back.overlap_m - overlap).abs() < 1e-12);
        let centre = moved * Point2::new(0.35, -0.1);
        assert!(centre.y < measure.trailing_edge().y, "the flap hangs under the lip");
    }
    assert!(matches!(
        measure.displacement_for_setting(0.5, 0.001, -0.2),
        Err(Error::GapUnreachable { .. })
    ));
    assert!(matches!(
        measure.displacement_for_setting(f64::NAN, 0.0, 0.0),
        Err(Error::NotFinite { .. })
    ));
}

/// A two-element flap: the gap and overlap stay the main element's, the chord runs to the
/// aft element's trailing edge.
#[test]
fn the_chord_runs_to_the_whole_flaps_trailing_edge() {
    let main = disc(Point2::new(0.35, -0.1), 0.15, 360);
    let aft = disc(Point2::new(0.1, -0.15), 0.05, 360);
    let whole: Vec<Vec<Point2<f64>>> = main.iter().chain(&aft).cloned().collect();
    let own = FlapBehindWing::new(&wing(0.5, 0.0), &main).unwrap();
    let measure = own.clone().with_chord_to(&whole).unwrap();
    // Wing nose 2.0 to the aft disc's aft-most point 0.05.
    assert!((measure.chord_m() - 1.95).abs() < 1e-12, "{}", measure.chord_m());
    let (a, b) = (own.at_rotation(0.3), measure.at_rotation(0.3));
    assert_eq!((a.gap_m, a.overlap_m), (b.gap_m, b.overlap_m));
    assert!((b.gap_percent_chord - a.gap_m / 1.95 * 100.0).abs() < 1e-12);
    // A "whole flap" that ends ahead of the element's own trailing edge changes nothing.
    let shorter = own
        .clone()
        .with_chord_to(&disc(Point2::new(0.4, -0.1), 0.01, 8))
        .unwrap();
    assert_eq!(shorter.chord_m(), own.chord_m());
    assert!(matches!(own.with_chord_to(&[]), Err(Error::TooFew { .. })));
}

/// A shroud ending in a blunt base 2.5 mm high (issue 35 item 4): the gap is measured from
/// the base's nearest point, here its lower corner, not from the upper corner; a cove wall
/// 5 %c deep (the box wing above) is no lip.
#[test]
fn the_gap_is_measured_from_the_nearest_point_of_a_blunt_lip() {
    let (upper, lower) = (Point2::new(0.5, 0.1), Point2::new(0.5, 0.0975));
    let wing = vec![vec![
        Point2::new(1.0, 0.0),
        Point2::new(2.0, 0.0),
        Point2::new(2.0, 0.12),
        upper,
        lower,
        Point2::new(1.0, 0.0975),
    ]];
    let (centre, r) = (Point2::new(0.45, 0.0), 0.05);
    let measure = FlapBehindWing::new(&wing, &disc(centre, r, 4000)).unwrap();
    assert_eq!(measure.trailing_edge(), upper);
    assert_eq!(measure.lip(), &[upper, lower]);
    let gap = measure.at_rotation(0.0).gap_m;
    let from_lower = (lower - centre).norm() - r;
    assert!((gap - from_lower).abs() < 1e-6, "{gap} against {from_lower}");
    assert!((upper - centre).norm() - r - gap > 2e-3);
    let boxed = FlapBehindWing::new(&self::wing(0.5, 0.0), &disc(centre, r, 64)).unwrap();
    assert_eq!(boxed.lip(), &[Point2::new(0.5, 0.1)]);
}
