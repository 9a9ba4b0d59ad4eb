//! Shared inputs: a small circular-slot station at three settings, and a plot set.

use flapwright_drawing::{
    Dimension, Joint, Link, MechanismSnapshot, PartStyle, Plot, SectionOutline, Series, SlotArc, StationDrawing,
};
use nalgebra::{Point2, Rotation2};

type P = Point2<f64>;

/// Station-frame point from millimetres.
pub fn mm(x: f64, y: f64) -> P {
    P::new(x / 1000.0, y / 1000.0)
}

fn rotate(p: &P, deg: f64) -> P {
    Rotation2::new(deg.to_radians()) * p
}

fn flap() -> Vec<P> {
    vec![
        mm(160.0, 330.0),
        mm(100.0, 365.0),
        mm(-100.0, 360.0),
        mm(-400.0, 332.0),
        mm(-100.0, 310.0),
        mm(100.0, 305.0),
    ]
}

fn snapshot(label: &str, deg: f64) -> MechanismSnapshot {
    let a = rotate(&mm(37.0, 237.0), deg);
    let g = rotate(&mm(268.0, 225.0), deg);
    let b0 = mm(116.0, 249.0);
    MechanismSnapshot {
        label: label.into(),
        deflection_deg: deg,
        flap_outline: vec![flap().iter().map(|p| rotate(p, deg)).collect()],
        links: vec![
            Link {
                name: "bracket".into(),
                points: vec![rotate(&mm(-30.0, 340.0), deg), a, g],
            },
            Link {
                name: "screw".into(),
                points: vec![b0, a],
            },
        ],
        joints: vec![
            Joint {
                name: "A0".into(),
                at: P::origin(),
                fixed: true,
            },
            Joint {
                name: "B0".into(),
                at: b0,
                fixed: true,
            },
            Joint {
                name: "A".into(),
                at: a,
                fixed: false,
            },
            Joint {
                name: "G".into(),
                at: g,
                fixed: false,
            },
        ],
    }
}

/// The fixture station with stowed (0 deg), takeoff (15 deg) and landing (35 deg).
pub fn station() -> StationDrawing {
    StationDrawing {
        title: "Fixture station".into(),
        subtitle: "circular-arc slots".into(),
        sections: vec![
            SectionOutline {
                part: "wing".into(),
                kind: PartStyle::WingSkin,
                polygons: vec![vec![
                    mm(60.0, 380.0),
                    mm(700.0, 440.0),
                    mm(700.0, 280.0),
                    mm(240.0, 290.0),
                    mm(230.0, 370.0),
                ]],
            },
            SectionOutline {
                part: "torque tube".into(),
                kind: PartStyle::TorqueTube,
                polygons: vec![vec![
                    mm(440.0, 320.0),
                    mm(460.0, 320.0),
                    mm(460.0, 340.0),
                    mm(440.0, 340.0),
                ]],
            },
        ],
        settings: vec![
            snapshot("stowed", 0.0),
            snapshot("takeoff", 15.0),
            snapshot("landing", 35.0),
        ],
        slots: vec![SlotArc {
            name: "slot b1".into(),
            centre: P::origin(),
            radius_m: 0.35,
            start_rad: 40f64.to_radians(),
            end_rad: 75f64.to_radians(),
        }],
        envelope: vec![vec![mm(-120.0, 180.0), mm(280.0, 200.0), mm(120.0, 360.0)]],
        fairing_line: Some(vec![
            mm(400.0, 284.0),
            mm(280.0, 170.0),
            mm(-150.0, 160.0),
            mm(-200.0, 300.0),
        ]),
        dimensions: vec![
            Dimension::new("a2", P::origin(), mm(37.0, 237.0)),
            Dimension::new("b1", P::origin(), mm(268.0, 225.0)),
        ],
        ..Default::default()
    }
}

/// Three plots, one with two series.
pub fn plots() -> Vec<Plot> {
    let s: Vec<f64> = (0..=20).map(|i| 80.0 + 7.2 * f64::from(i)).collect();
    let series = |name: &str, f: &dyn Fn(f64) -> f64| Series {
        name: name.into(),
        points: s.iter().map(|x| (*x, f(*x))).collect(),
    };
    vec![
        Plot {
            title: "Deflection".into(),
            x_label: "nut travel s34 [mm]".into(),
            y_label: "deflection [deg]".into(),
            series: vec![series("flap", &|x| (x - 80.0) * 35.0 / 144.0)],
        },
        Plot {
            title: "Force".into(),
            x_label: "nut travel s34 [mm]".into(),
            y_label: "force [N]".into(),
            series: vec![
                series("landing", &|x| 480.0 + 6.0 * (x - 80.0)),
                series("cruise", &|_| 1600.0),
            ],
        },
        Plot {
            title: "Clearance".into(),
            x_label: "nut travel s34 [mm]".into(),
            y_label: "clearance [mm]".into(),
            series: vec![series("flap vs wing", &|x| 0.02 * (x - 150.0).powi(2) + 5.0)],
        },
    ]
}
