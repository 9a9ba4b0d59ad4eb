//! `.dat` reading and writing (Selig and Lednicer).

use flapwright_geom::{Airfoil, TrailingEdge};

use crate::fixture::{data_path, n63212};

#[test]
fn selig_round_trip_is_exact() {
    let airfoil = Airfoil::naca("23012", 37, TrailingEdge::Open).unwrap();
    let mut bytes = Vec::new();
    airfoil.write_dat(&mut bytes).unwrap();
    let back = Airfoil::from_dat(bytes.as_slice()).unwrap();
    assert_eq!(back, airfoil);
}

#[test]
fn lednicer_round_trip_is_exact() {
    let airfoil = n63212();
    let mut bytes = Vec::new();
    airfoil.write_dat_lednicer(&mut bytes).unwrap();
    let back = Airfoil::from_dat(bytes.as_slice()).unwrap();
    assert_eq!(back, airfoil);
}

#[test]
fn handwritten_lednicer_file_reads_in_selig_order() {
    let text = "TEST LEDNICER\n3. 3.\n\n0.0 0.0\n0.5 0.06\n1.0 0.0\n\n0.0 0.0\n0.5 -0.04\n1.0 0.0\n";
    let airfoil = Airfoil::from_dat(text.as_bytes()).unwrap();
    let xy: Vec<(f64, f64)> = airfoil.points.iter().map(|p| (p.x, p.y)).collect();
    assert_eq!(xy, vec![(1.0, 0.0), (0.5, 0.06), (0.0, 0.0), (0.5, -0.04), (1.0, 0.0)]);
    approx::assert_relative_eq!(airfoil.compute_area(), 0.5 * 0.1, max_relative = 1e-12);
}

#[test]
fn every_shipped_airfoil_file_reads() {
    let mut count = 0;
    for entry in std::fs::read_dir(data_path("airfoils")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "dat") {
            let airfoil = Airfoil::from_dat(std::fs::File::open(&path).unwrap()).unwrap();
            assert!(airfoil.compute_area() > 0.05, "{path:?}");
            count += 1;
        }
    }
    assert!(count >= 6);
    assert_eq!(n63212().points.len(), 51);
}

#[test]
fn malformed_files_are_errors_not_panics() {
    for text in [
        "",
        "NAME\n",
        "NAME\n1 2 3\n",
        "NAME\n0 0\nx y\n",
        "L\n3. 3.\n0 0\n1 0\n",
        "NAME\n1 0\n0 0\n1 0\n",
        "N\nNaN 0\n0 0\n1 0\n0.5 -1\n1 0\n",
    ] {
        assert!(Airfoil::from_dat(text.as_bytes()).is_err(), "{text:?}");
    }
}
