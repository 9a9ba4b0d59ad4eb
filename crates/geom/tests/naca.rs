//! NACA thickness and camber against the published definitions written out here.

use approx::assert_relative_eq;
use flapwright_geom::{Airfoil, Naca, TrailingEdge};

use crate::fixture::data_path;

const STATIONS: [f64; 9] = [0.0, 0.0125, 0.05, 0.1, 0.25, 0.3, 0.5, 0.8, 1.0];

/// Abbott & von Doenhoff eq. 6.2, open trailing edge.
fn thickness(t: f64, x: f64) -> f64 {
    5.0 * t * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x.powi(2) + 0.2843 * x.powi(3) - 0.1015 * x.powi(4))
}

/// 4-digit mean line (Abbott & von Doenhoff section 6.4).
fn camber_four(m: f64, p: f64, x: f64) -> f64 {
    if m == 0.0 {
        0.0
    } else if x < p {
        m / p.powi(2) * (2.0 * p * x - x.powi(2))
    } else {
        m / (1.0 - p).powi(2) * ((1.0 - 2.0 * p) + 2.0 * p * x - x.powi(2))
    }
}

/// One row of `data/validation/naca_five_digit_mean_lines.csv`.
struct FiveDigitLine {
    p_digit: u32,
    reflexed: bool,
    r: f64,
    k1: f64,
    k2_over_k1: f64,
}

fn five_digit_table() -> Vec<FiveDigitLine> {
    let text = std::fs::read_to_string(data_path("validation/naca_five_digit_mean_lines.csv")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            FiveDigitLine {
                p_digit: f[0].parse().unwrap(),
                reflexed: f[1] == "1",
                r: f[2].parse().unwrap(),
                k1: f[3].parse().unwrap(),
                k2_over_k1: f[4].parse().unwrap(),
            }
        })
        .collect()
}

/// 5-digit mean line: standard `k1/6 (x^3 - 3 r x^2 + r^2 (3 - r) x)` ahead of r,
/// `k1 r^3 / 6 (1 - x)` behind; reflexed (NASA TM-4741)
/// `k1/6 ((x - r)^3 - k21 (1 - r)^3 x - r^3 x + r^3)` ahead, `k1/6 (k21 (x - r)^3 - k21 (1 - r)^3 x - r^3 x + r^3)` behind;
/// both scaled by c_l,i / 0.3 = L / 2.
fn camber_five(line: &FiveDigitLine, l_digit: u32, x: f64) -> f64 {
    let (r, k1, k21) = (line.r, line.k1, line.k2_over_k1);
    let y = if !line.reflexed {
        if x < r {
            k1 / 6.0 * (x.powi(3) - 3.0 * r * x.powi(2) + r.powi(2) * (3.0 - r) * x)
        } else {
            k1 * r.powi(3) / 6.0 * (1.0 - x)
        }
    } else if x < r {
        k1 / 6.0 * ((x - r).powi(3) - k21 * (1.0 - r).powi(3) * x - r.powi(3) * x + r.powi(3))
    } else {
        k1 / 6.0 * (k21 * (x - r).powi(3) - k21 * (1.0 - r).powi(3) * x - r.powi(3) * x + r.powi(3))
    };
    y * (0.15 * f64::from(l_digit)) / 0.3
}

#[test]
fn four_digit_thickness_and_camber_match_the_definition() {
    for (designation, m, p, t) in [
        ("0012", 0.0, 0.0, 0.12),
        ("2412", 0.02, 0.4, 0.12),
        ("4415", 0.04, 0.4, 0.15),
    ] {
        let naca = Naca::parse(designation, TrailingEdge::Open).unwrap();
        for x in STATIONS {
            assert_relative_eq!(naca.thickness(x), thickness(t, x), epsilon = 1e-12, max_relative = 1e-9);
            assert_relative_eq!(
                naca.camber(x),
                camber_four(m, p, x),
                epsilon = 1e-12,
                max_relative = 1e-9
            );
        }
    }
}

#[test]
fn five_digit_thickness_and_camber_match_the_definition() {
    let table = five_digit_table();
    assert_eq!(table.len(), 9, "all table rows read");
    for designation in ["23012", "23112", "24012", "21015", "25112"] {
        let d: Vec<u32> = designation.chars().map(|c| c.to_digit(10).unwrap()).collect();
        let line = table
            .iter()
            .find(|l| l.p_digit == d[1] && l.reflexed == (d[2] == 1))
            .unwrap();
        let naca = Naca::parse(designation, TrailingEdge::Open).unwrap();
        let t = f64::from(10 * d[3] + d[4]) / 100.0;
        for x in STATIONS {
            assert_relative_eq!(naca.thickness(x), thickness(t, x), epsilon = 1e-12, max_relative = 1e-9);
            assert_relative_eq!(
                naca.camber(x),
                camber_five(line, d[0], x),
                epsilon = 1e-12,
                max_relative = 1e-9
            );
        }
    }
}

#[test]
fn five_digit_table_puts_maximum_camber_at_p_over_20() {
    // Independent check of r and k1: the designation's second digit P means maximum camber
    // at x = P/20, so the mean-line slope must vanish there.
    for line in five_digit_table() {
        let designation = format!("2{}{}12", line.p_digit, u32::from(line.reflexed));
        let naca = Naca::parse(&designation, TrailingEdge::Open).unwrap();
        let x = f64::from(line.p_digit) / 20.0;
        let scale = naca.camber(x).abs().max(1e-3);
        assert!(
            naca.camber_slope(x).abs() < 0.02 * scale / x,
            "{designation}: slope {} at {x}",
            naca.camber_slope(x)
        );
    }
}

#[test]
fn camber_slope_matches_finite_differences() {
    for designation in ["2412", "4415", "23012", "23112"] {
        let naca = Naca::parse(designation, TrailingEdge::Open).unwrap();
        for x in [0.03, 0.1, 0.2, 0.35, 0.6, 0.9] {
            let h = 1e-6;
            let fd = (naca.camber(x + h) - naca.camber(x - h)) / (2.0 * h);
            assert_relative_eq!(naca.camber_slope(x), fd, epsilon = 1e-8, max_relative = 1e-6);
        }
    }
}

#[test]
fn generated_points_apply_thickness_normal_to_the_mean_line() {
    let n = 41;
    let airfoil = Airfoil::naca("4415", n, TrailingEdge::Closed).unwrap();
    let naca = Naca::parse("4415", TrailingEdge::Closed).unwrap();
    assert_eq!(airfoil.points.len(), 2 * n - 1);
    assert!(airfoil.has_closed_trailing_edge());
    for i in [3usize, 10, 25, 39] {
        let x = 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / (n - 1) as f64).cos());
        let theta = naca.camber_slope(x).atan();
        let upper = airfoil.points[n - 1 - i];
        let lower = airfoil.points[n - 1 + i];
        assert_relative_eq!(upper.x, x - naca.thickness(x) * theta.sin(), max_relative = 1e-12);
        assert_relative_eq!(
            upper.y,
            naca.camber(x) + naca.thickness(x) * theta.cos(),
            max_relative = 1e-12
        );
        assert_relative_eq!(
            lower.y,
            naca.camber(x) - naca.thickness(x) * theta.cos(),
            max_relative = 1e-12
        );
    }
}

#[test]
fn bad_designations_are_errors() {
    for bad in ["", "12", "0000", "40012", "23212", "2a12", "123456", "NACA 63-212"] {
        assert!(Naca::parse(bad, TrailingEdge::Open).is_err(), "{bad:?}");
    }
    assert!(Airfoil::naca("0012", 2, TrailingEdge::Open).is_err());
}
