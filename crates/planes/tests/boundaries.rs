//! The thesis Fig. 45 boundary table: polar/cartesian consistency of every row, and the
//! deviation measure used to compare section cuts with it.

use std::io::BufReader;

use approx::assert_relative_eq;
use flapwright_planes::{boundary_deviation, parse_boundary_csv, BoundaryPoint};
use nalgebra::{Point2, Vector2};

fn fig45() -> Vec<BoundaryPoint> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../data/validation/thesis-fig45-boundaries.csv"
    );
    let file = std::fs::File::open(path).expect("data/validation/thesis-fig45-boundaries.csv");
    parse_boundary_csv(BufReader::new(file)).unwrap()
}

#[test]
fn every_row_is_polar_cartesian_consistent() {
    let rows = fig45();
    assert!(rows.len() >= 80, "{} rows", rows.len());
    let mut checked = 0;
    let mut flagged = Vec::new();
    for row in &rows {
        if !row.polar_consistent {
            flagged.push(row);
            continue;
        }
        if let (Some(r), Some(theta_deg)) = (row.r_mm, row.theta_deg) {
            let theta = theta_deg.to_radians();
            // x, y are printed with 10 significant digits from r (0.1 mm), θ (0.1 deg).
            assert!((r * theta.cos() - row.x_mm).abs() < 1e-6, "{row:?}");
            assert!((r * theta.sin() - row.y_mm).abs() < 1e-6, "{row:?}");
            if let Some(theta_rad) = row.theta_rad {
                assert!((theta - theta_rad).abs() < 1e-8, "{row:?}");
            }
        } else if let Some(theta_rad) = row.theta_rad {
            assert!((row.y_mm.atan2(row.x_mm) - theta_rad).abs() < 1e-8, "{row:?}");
        }
        checked += 1;
    }
    assert!(checked >= 80);
    // The one inconsistent row of the source (inner wing-below-spar point 1) really is.
    assert_eq!(flagged.len(), 1);
    let row = flagged[0];
    assert_eq!(
        (row.plane.as_str(), row.boundary.as_str(), row.point),
        ("inner", "wing-below-spar", 1)
    );
    let (r, theta) = (row.r_mm.unwrap(), row.theta_deg.unwrap().to_radians());
    assert!((r * theta.cos() - row.x_mm).abs() > 40.0);
}

fn boundary(rows: &[BoundaryPoint], plane: &str, name: &str) -> Vec<Point2<f64>> {
    rows.iter()
        .filter(|r| r.plane == plane && r.boundary == name)
        .map(|r| Point2::new(r.x_mm, r.y_mm))
        .collect()
}

#[test]
fn free_space_chains_and_the_flap_close() {
    let rows = fig45();
    for (plane, chain) in [
        (
            "outer",
            ["spar-front", "wing-top", "flap-top", "flap-front", "wing-below-spar"],
        ),
        (
            "inner",
            ["spar-front", "wing-top", "flap-top", "flap-front", "wing-below-spar"],
        ),
    ] {
        let parts: Vec<Vec<Point2<f64>>> = chain.iter().map(|name| boundary(&rows, plane, name)).collect();
        for part in &parts {
            assert!(part.len() >= 2, "{plane}");
        }
    }
    // Outer plane: each boundary starts where the previous one ends; the chain closes.
    let outer: Vec<Vec<Point2<f64>>> = ["spar-front", "wing-top", "flap-top", "flap-front", "wing-below-spar"]
        .iter()
        .map(|n| boundary(&rows, "outer", n))
        .collect();
    for k in 0..outer.len() {
        let end = outer[k].last().unwrap();
        let start = outer[(k + 1) % outer.len()][0];
        assert!((end - start).norm() < 1e-9, "outer chain gap after {k}");
    }
    let flap = boundary(&rows, "outer", "flap");
    assert!((flap[0] - flap[flap.len() - 1]).norm() < 1e-9);
}

#[test]
fn deviation_of_a_shifted_outline_is_the_shift() {
    let rows = fig45();
    let flap_m: Vec<Point2<f64>> = rows
        .iter()
        .filter(|r| r.plane == "outer" && r.boundary == "flap")
        .map(|r| r.position_m())
        .collect();
    let same = boundary_deviation(std::slice::from_ref(&flap_m), &flap_m).unwrap();
    assert_eq!(same.max_m, 0.0);
    // Shift the polygon 1 mm up: points on near-horizontal edges are 1 mm off, the nose less.
    let shifted: Vec<Point2<f64>> = flap_m.iter().map(|p| p + Vector2::new(0.0, 1e-3)).collect();
    let deviation = boundary_deviation(&[shifted], &flap_m).unwrap();
    assert!(deviation.max_m <= 1e-3 + 1e-15);
    assert!(deviation.max_m > 0.9e-3);
    assert!(deviation.mean_m > 0.3e-3 && deviation.mean_m < 1e-3);
    assert_eq!(deviation.point_count, flap_m.len());
    assert_relative_eq!(flap_m[0].x, -0.3343671074, epsilon = 1e-12);
}

#[test]
fn bad_rows_name_line_and_column() {
    let text = "# comment\nplane,boundary,label,point,r_mm,theta_deg,theta_rad,x_mm,y_mm,polar_consistent\nouter,flap,\"a, b\",0,1,2,3,abc,5,true\n";
    let err = parse_boundary_csv(text.as_bytes()).unwrap_err();
    assert_eq!(
        err,
        flapwright_planes::Error::BoundaryCsvField {
            line: 3,
            column: "x_mm"
        }
    );
}
