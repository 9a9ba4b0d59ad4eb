//! Draws the thesis case-study station (`000_...`, Chapter 5, Table 2) from hard-coded
//! demo geometry and writes `station.svg`, `plots.svg` and a PNG of each.
//!
//! Run: `cargo run -p flapwright-drawing --example station_drawing -- [OUT_DIR]`
//! (default `target/drawing-demo`).
//!
//! The mechanism: circular slots b1 = 350 mm and c1 = 300 mm about A0, B0 at
//! a1 = 275 mm / alpha0 = 65 deg, crank a2 = 240 mm, flap rotation beta3 = 35 deg. The
//! flap is a NACA 2412-like polygon of 560 mm chord; wing, spar and torque tube are
//! illustrative shapes, and the loads are the thesis landing scenario halved per jack,
//! for the picture only (the real numbers come from flapwright-mechanism/sizing).

use flapwright_drawing::{
    render_plots_svg, render_station_svg, Dimension, Joint, Link, MechanismSnapshot, PartStyle, Plot, SectionOutline,
    Series, SlotArc, StationDrawing,
};
use nalgebra::Vector2;
use std::path::{Path, PathBuf};

mod geometry;

use flapwright_drawing::convex_hull;
use geometry::{circle, clearance, flap_outline, mm, rotate, wing_skin, P};

/// The thesis Table 2 mechanism, positions in the station frame.
struct Demo {
    b0: P,
    crank_stowed: P,
    slot_b_stowed: P,
    slot_c_stowed: P,
    centre_of_mass: P,
    screw_length_m: f64,
}

impl Demo {
    fn new() -> Self {
        let (a1, a2, alpha0, beta3) = (0.275, 0.240, 65f64.to_radians(), 35f64.to_radians());
        let b0 = P::new(a1 * alpha0.cos(), a1 * alpha0.sin());
        // Thesis section 4.2 step 8: s34,i = sqrt(a1^2 - a2^2 cos^2(beta3/2)) - a2 sin(beta3/2).
        let h = a2 * (beta3 / 2.0).cos();
        let s34_initial = (a1 * a1 - h * h).sqrt() - a2 * (beta3 / 2.0).sin();
        // Screw direction: B0, A_i and A_f collinear, A_f = A_i turned by beta3 about A0.
        let direction = alpha0 - (h / a1).asin() + std::f64::consts::PI;
        let crank_stowed = b0 + s34_initial * Vector2::new(direction.cos(), direction.sin());
        assert!(
            (crank_stowed.coords.norm() - a2).abs() < 1e-9,
            "A_i must lie on the crank circle"
        );
        Demo {
            b0,
            crank_stowed,
            slot_b_stowed: P::new(0.350 * 40f64.to_radians().cos(), 0.350 * 40f64.to_radians().sin()),
            slot_c_stowed: P::new(0.300 * 60f64.to_radians().cos(), 0.300 * 60f64.to_radians().sin()),
            centre_of_mass: mm(-30.0, 340.0),
            screw_length_m: 0.250,
        }
    }

    /// (A, G, F, D, screw end) at deflection `deg`.
    fn pose(&self, deg: f64) -> [P; 5] {
        let a = rotate(&self.crank_stowed, deg);
        let screw_end = self.b0 + self.screw_length_m * (a - self.b0).normalize();
        [
            a,
            rotate(&self.slot_b_stowed, deg),
            rotate(&self.slot_c_stowed, deg),
            rotate(&self.centre_of_mass, deg),
            screw_end,
        ]
    }

    fn snapshot(&self, label: &str, deg: f64) -> MechanismSnapshot {
        let [a, g, f, d, screw_end] = self.pose(deg);
        MechanismSnapshot {
            label: label.to_owned(),
            deflection_deg: deg,
            flap_outline: vec![flap_outline().iter().map(|p| rotate(p, deg)).collect()],
            links: vec![
                Link {
                    name: "flap bracket".into(),
                    points: vec![d, a, g, f, d],
                },
                Link {
                    name: "screw jack".into(),
                    points: vec![self.b0, screw_end],
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
                    at: self.b0,
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
                Joint {
                    name: "F".into(),
                    at: f,
                    fixed: false,
                },
            ],
        }
    }
}

fn build_drawing(demo: &Demo) -> StationDrawing {
    let wing = wing_skin();
    let stowed = demo.pose(0.0);
    // Envelope: hull of the bracket and screw over the deployment (1 deg steps).
    let swept: Vec<P> = (0..=35)
        .flat_map(|deg| demo.pose(f64::from(deg)))
        .chain([demo.b0])
        .collect();
    let envelope = convex_hull(swept);
    // Fairing: the envelope's lower side (hull vertices from the leftmost to the
    // rightmost, counter-clockwise), 20 mm lower, joined to the wing and flap skins.
    let leftmost = (0..envelope.len())
        .min_by(|a, b| envelope[*a].x.total_cmp(&envelope[*b].x))
        .unwrap_or(0);
    let rightmost = (0..envelope.len())
        .max_by(|a, b| envelope[*a].x.total_cmp(&envelope[*b].x))
        .unwrap_or(0);
    let mut fairing = vec![mm(420.0, 284.0)];
    let mut i = rightmost;
    let mut lower = Vec::new();
    while i != leftmost {
        lower.push(envelope[i] - Vector2::new(0.0, 0.020));
        i = (i + envelope.len() - 1) % envelope.len();
    }
    lower.push(envelope[leftmost] - Vector2::new(0.010, 0.020));
    fairing.extend(lower);
    fairing.push(mm(envelope[leftmost].x * 1000.0 - 60.0, 305.0));
    let flap_spar_x = 160.0 - 0.2 * 560.0;
    StationDrawing {
        title: "Station demo - thesis case study (Table 2)".into(),
        subtitle: "Circular-arc slots b1 = 350 mm, c1 = 300 mm; screw jack from B0; flap rotation 35\u{b0} about A0"
            .into(),
        sections: vec![
            SectionOutline {
                part: "wing skin".into(),
                kind: PartStyle::WingSkin,
                polygons: vec![wing],
            },
            SectionOutline {
                part: "rear spar".into(),
                kind: PartStyle::Spar,
                polygons: vec![vec![
                    mm(600.0, 282.0),
                    mm(612.0, 282.0),
                    mm(612.0, 440.0),
                    mm(600.0, 440.0),
                ]],
            },
            SectionOutline {
                part: "torque tube".into(),
                kind: PartStyle::TorqueTube,
                polygons: vec![circle(mm(450.0, 330.0), 0.022)],
            },
            SectionOutline {
                part: "flap spar".into(),
                kind: PartStyle::Spar,
                polygons: vec![vec![
                    mm(flap_spar_x - 3.0, 306.0),
                    mm(flap_spar_x + 3.0, 306.0),
                    mm(flap_spar_x + 3.0, 366.0),
                    mm(flap_spar_x - 3.0, 366.0),
                ]],
            },
        ],
        settings: vec![
            demo.snapshot("stowed", 0.0),
            demo.snapshot("takeoff", 15.0),
            demo.snapshot("landing", 35.0),
        ],
        slots: vec![
            SlotArc {
                name: "slot b1".into(),
                centre: P::origin(),
                radius_m: 0.350,
                start_rad: 40f64.to_radians(),
                end_rad: 75f64.to_radians(),
            },
            SlotArc {
                name: "slot c1".into(),
                centre: P::origin(),
                radius_m: 0.300,
                start_rad: 60f64.to_radians(),
                end_rad: 95f64.to_radians(),
            },
        ],
        envelope: vec![envelope],
        fairing_line: Some(fairing),
        dimensions: vec![
            Dimension::new("a1", P::origin(), demo.b0),
            Dimension::new("a2", P::origin(), stowed[0]),
            Dimension::new("b1", P::origin(), stowed[1]),
            Dimension::new("c1", P::origin(), stowed[2]),
            Dimension::new("s34,i", demo.b0, stowed[0]),
            Dimension::new("a3", demo.b0, stowed[4]),
        ],
        ..Default::default()
    }
}

fn build_plots(demo: &Demo) -> Vec<Plot> {
    let wing = wing_skin();
    let (a2, r, lead, friction) = (0.240, 0.016, 0.008, 0.1);
    let mut deflection = Vec::new();
    let mut transmission = Vec::new();
    let mut force = (Vec::new(), Vec::new());
    let mut torque = (Vec::new(), Vec::new());
    let mut gap = Vec::new();
    for step in 0..=70 {
        let deg = 0.5 * f64::from(step);
        let [a, ..] = demo.pose(deg);
        let s_mm = (a - demo.b0).norm() * 1000.0;
        let mu = (a.coords.normalize().dot(&(a - demo.b0).normalize()))
            .acos()
            .to_degrees();
        let mu = mu.min(180.0 - mu);
        deflection.push((s_mm, deg));
        transmission.push((s_mm, mu));
        // Moment per jack: landing 110 -> 325 N m (thesis 220/650 halved), cruise 375 N m.
        for (moment, (f_series, t_series)) in [
            (110.0 + 215.0 * deg / 35.0, (&mut force.0, &mut torque.0)),
            (375.0, (&mut force.1, &mut torque.1)),
        ] {
            let f = moment / (a2 * mu.to_radians().sin());
            // Raising torque of a power screw: T = F r (l + 2 pi f r) / (2 pi r - f l).
            let t =
                f * r * (lead + std::f64::consts::TAU * friction * r) / (std::f64::consts::TAU * r - friction * lead);
            f_series.push((s_mm, f));
            t_series.push((s_mm, t));
        }
        let flap: Vec<P> = flap_outline().iter().map(|p| rotate(p, deg)).collect();
        gap.push((s_mm, clearance(&flap, &wing) * 1000.0));
    }
    let x_label = "nut travel s34 [mm]".to_owned();
    let plot = |title: &str, y_label: &str, series: Vec<Series>| Plot {
        title: title.into(),
        x_label: x_label.clone(),
        y_label: y_label.into(),
        series,
    };
    let limit = 0.5 * (180.0 - 35.0);
    let limit_line = vec![
        (transmission[0].0, limit),
        (transmission[transmission.len() - 1].0, limit),
    ];
    vec![
        plot(
            "Flap deflection",
            "deflection \u{3b4} [deg]",
            vec![Series {
                name: "flap".into(),
                points: deflection,
            }],
        ),
        plot(
            "Transmission angle",
            "transmission angle \u{3bc} [deg]",
            vec![
                Series {
                    name: "\u{3bc}".into(),
                    points: transmission,
                },
                Series {
                    name: "\u{3bc}min = (180\u{b0} - \u{3b2}3)/2".into(),
                    points: limit_line,
                },
            ],
        ),
        plot(
            "Actuator force",
            "screw force F [N]",
            vec![
                Series {
                    name: "landing".into(),
                    points: force.0,
                },
                Series {
                    name: "cruise".into(),
                    points: force.1,
                },
            ],
        ),
        plot(
            "Screw torque (raising)",
            "torque T [N\u{b7}m]",
            vec![
                Series {
                    name: "landing".into(),
                    points: torque.0,
                },
                Series {
                    name: "cruise".into(),
                    points: torque.1,
                },
            ],
        ),
        plot(
            "Flap-to-wing clearance",
            "clearance [mm]",
            vec![Series {
                name: "flap vs wing skin".into(),
                points: gap,
            }],
        ),
    ]
}

/// Renders `svg` to a PNG beside it; returns the number of non-white pixels.
fn write_png(svg: &str, path: &Path) -> usize {
    let mut options = resvg::usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let tree = resvg::usvg::Tree::from_str(svg, &options).expect("the SVG parses");
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).expect("non-zero size");
    resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    pixmap.save_png(path).expect("the PNG is written");
    pixmap
        .pixels()
        .iter()
        .filter(|p| p.red() < 250 || p.green() < 250 || p.blue() < 250)
        .count()
}

fn main() {
    let out: PathBuf = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/drawing-demo"));
    std::fs::create_dir_all(&out).expect("output folder");
    let demo = Demo::new();
    let station = render_station_svg(&build_drawing(&demo)).expect("station drawing");
    let plots = render_plots_svg(
        "Station demo - against nut travel s34 (demo loads)",
        &build_plots(&demo),
    )
    .expect("plots");
    std::fs::write(out.join("station.svg"), &station).expect("station.svg");
    std::fs::write(out.join("plots.svg"), &plots).expect("plots.svg");
    let inked_station = write_png(&station, &out.join("station.png"));
    let inked_plots = write_png(&plots, &out.join("plots.png"));
    println!(
        "wrote {} (station: {inked_station} inked px, plots: {inked_plots} inked px)",
        out.display()
    );
    for label in ["setting-stowed", "setting-takeoff", "setting-landing"] {
        assert!(station.contains(label), "{label} missing from the drawing");
    }
    assert!(inked_station > 10_000 && inked_plots > 10_000, "renderings look blank");
}
