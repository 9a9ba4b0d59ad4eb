//! Load distribution: eq 1 and equilibrium of the station and attachment loads.

use approx::assert_relative_eq;
use flapwright_sizing::{
    attachment_loads, distribute_to_stations, element_loads, station_attachment_loads, ElementLoad, FlapElement,
    LoadCase, NormalForceTable,
};
use proptest::prelude::*;

/// Eq 1 hand case: C_N = 0.9 (table 0.8 at 30 deg, 1.0 at 40 deg, read at 35 deg),
/// c = 1.2 m, b = 0.5 m, q = 4000 Pa: N = 0.9 x 1.2 x 0.5 x 4000 = 2160 N;
/// x n 2.0 x 1.5 = 6480 N.
#[test]
fn eq_1_hand_case() {
    let table = NormalForceTable::try_new(vec![30f64.to_radians(), 40f64.to_radians()], vec![0.8, 1.0]).unwrap();
    let element = FlapElement {
        span_start_m: 2.0,
        span_end_m: 2.5,
        chord_m: 1.2,
        quarter_chord_aft_of_hinge_m: 0.1,
        moment_coefficient: 0.0,
    };
    let loads = element_loads(
        &[element],
        &table,
        35f64.to_radians(),
        4000.0,
        &LoadCase::cs25_flaps_extended(),
    )
    .unwrap();
    assert_relative_eq!(loads[0].normal_force_n, 6480.0, max_relative = 1e-12);
    assert_relative_eq!(loads[0].span_position_m, 2.25, max_relative = 1e-15);
}

/// Two stations at 0 and 4 m, 1000 N at 1 m: R = 750 N and 250 N (simple beam).
#[test]
fn two_station_simple_beam() {
    let e = ElementLoad {
        span_position_m: 1.0,
        normal_force_n: 1000.0,
        chordwise_position_m: 0.0,
        pitching_moment_nm: 0.0,
    };
    let s = distribute_to_stations(&[e], &[0.0, 4.0]).unwrap();
    assert_relative_eq!(s[0].normal_force_n, 750.0, max_relative = 1e-12);
    assert_relative_eq!(s[1].normal_force_n, 250.0, max_relative = 1e-12);
}

fn element_strategy() -> impl Strategy<Value = ElementLoad> {
    (-1.0..11.0, -5e3..5e3, -0.3..0.6, -500.0..500.0).prop_map(|(y, n, s, m)| ElementLoad {
        span_position_m: y,
        normal_force_n: n,
        chordwise_position_m: s,
        pitching_moment_nm: m,
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Station loads balance the element loads: sum of forces, pitching moment about the
    /// hinge line, and rolling moment about y = 0 with each overhang's load taken at its end
    /// station (the overhang's own moment about it is not passed on: the tributary rule);
    /// every station carries at most the sum of the loads' magnitudes (relative 1e-9 of
    /// the load scale).
    #[test]
    fn station_equilibrium(elements in prop::collection::vec(element_strategy(), 1..12), n in 2usize..6) {
        let stations_m: Vec<f64> = (0..n).map(|i| 10.0 * i as f64 / (n - 1) as f64).collect();
        let s = distribute_to_stations(&elements, &stations_m).unwrap();
        let scale: f64 = elements.iter().map(|e| e.normal_force_n.abs() * 11.0 + e.pitching_moment_nm.abs()).sum::<f64>() + 1.0;
        let force: f64 = elements.iter().map(|e| e.normal_force_n).sum::<f64>() - s.iter().map(|x| x.normal_force_n).sum::<f64>();
        let roll: f64 = elements.iter().map(|e| e.normal_force_n * e.span_position_m.clamp(0.0, 10.0)).sum::<f64>()
            - s.iter().map(|x| x.normal_force_n * x.span_position_m).sum::<f64>();
        let magnitude: f64 = elements.iter().map(|e| e.normal_force_n.abs()).sum();
        for station in &s {
            prop_assert!(station.normal_force_n.abs() <= magnitude * (1.0 + 1e-12));
        }
        let pitch: f64 = elements.iter().map(|e| e.pitching_moment_nm - e.normal_force_n * e.chordwise_position_m).sum::<f64>()
            - s.iter().map(|x| x.moment_about_hinge_nm).sum::<f64>();
        prop_assert!(force.abs() <= 1e-9 * scale);
        prop_assert!(roll.abs() <= 1e-9 * scale);
        prop_assert!(pitch.abs() <= 1e-9 * scale);
    }

    /// Attachment loads sum to N and reproduce the moment about any reference point.
    #[test]
    fn attachment_equilibrium(n in -5e3..5e3f64, m in -500.0..500.0f64, x_n in -0.5..1.0f64,
                              x_f in -0.2..0.3f64, l in 0.05..0.8f64, x_ref in -2.0..2.0f64) {
        let a = attachment_loads(n, m, x_n, x_f, x_f + l).unwrap();
        let scale = n.abs() * 3.0 / l + m.abs() / l + 1.0;
        prop_assert!((a.forward_n + a.aft_n - n).abs() <= 1e-9 * scale);
        // Nose-up moment about x_ref of an upward force at x is F (x_ref - x).
        let applied = n * (x_ref - x_n) + m;
        let carried = a.forward_n * (x_ref - x_f) + a.aft_n * (x_ref - x_f - l);
        prop_assert!((applied - carried).abs() <= 1e-9 * scale * 3.0);
    }
}

/// A station load through the chain: the moment about the hinge goes to the aft
/// attachment as -M / l. Hand case: N = 1000 N, M = -200 N m (load 0.2 m aft), l = 0.5 m:
/// aft = 400 N, forward = 600 N.
#[test]
fn station_to_attachments_hand_case() {
    let e = ElementLoad {
        span_position_m: 0.0,
        normal_force_n: 1000.0,
        chordwise_position_m: 0.2,
        pitching_moment_nm: 0.0,
    };
    let s = distribute_to_stations(&[e], &[0.0, 1.0]).unwrap();
    let a = station_attachment_loads(&s[0], 0.5).unwrap();
    assert_relative_eq!(a.aft_n, 400.0, max_relative = 1e-12);
    assert_relative_eq!(a.forward_n, 600.0, max_relative = 1e-12);
}

/// n > 2 assumption (pinned flap segments between stations): uniform load w = 100 N/m
/// over 0..8 m in 8 elements, stations at 0, 4, 8 m: each 4 m segment carries 400 N,
/// half to each end, so the ends get 200 N and the middle 400 N (a continuous beam
/// would give 150 / 500 / 150 N by the three-moment equation).
#[test]
fn three_stations_pinned_segments() {
    let elements: Vec<ElementLoad> = (0..8)
        .map(|i| ElementLoad {
            span_position_m: f64::from(i) + 0.5,
            normal_force_n: 100.0,
            chordwise_position_m: 0.0,
            pitching_moment_nm: 0.0,
        })
        .collect();
    let s = distribute_to_stations(&elements, &[0.0, 4.0, 8.0]).unwrap();
    assert_relative_eq!(s[0].normal_force_n, 200.0, max_relative = 1e-12);
    assert_relative_eq!(s[1].normal_force_n, 400.0, max_relative = 1e-12);
    assert_relative_eq!(s[2].normal_force_n, 200.0, max_relative = 1e-12);
}

/// Overhangs go to their end station (issue 35 item 2): two stations 1 mm apart inside a
/// 10 m flap under 100 N/m share its 1000 N with no share negative or above the whole (the
/// rigid overhang over the 1 mm end span gave about +-2.5 MN); stations at 2 and 8 m take
/// their tributary spans, 0-5 m and 5-10 m.
#[test]
fn overhangs_go_to_their_end_station_and_no_share_leaves_zero_to_whole() {
    let elements: Vec<ElementLoad> = (0..100)
        .map(|i| ElementLoad {
            span_position_m: 0.1 * f64::from(i) + 0.05,
            normal_force_n: 10.0,
            chordwise_position_m: 0.0,
            pitching_moment_nm: 0.0,
        })
        .collect();
    let close = distribute_to_stations(&elements, &[4.0, 4.001]).unwrap();
    for s in &close {
        assert!(
            (0.0..=1000.0 + 1e-9).contains(&s.normal_force_n),
            "{}",
            s.normal_force_n
        );
    }
    assert_relative_eq!(
        close[0].normal_force_n + close[1].normal_force_n,
        1000.0,
        max_relative = 1e-12
    );
    let apart = distribute_to_stations(&elements, &[2.0, 8.0]).unwrap();
    assert_relative_eq!(apart[0].normal_force_n, 500.0, max_relative = 1e-12);
    assert_relative_eq!(apart[1].normal_force_n, 500.0, max_relative = 1e-12);
}
