//! Error of the NACA 0012 (closed trailing edge) section area and of a straight wing's
//! volume against the analytic value, versus airfoil points per side and build time.
//! Checks itself: the observed order of convergence must be 2 (cosine spacing).
//!
//! Run: `cargo run --release -p flapwright-geom --example volume_convergence`

use std::time::Instant;

use flapwright_geom::{
    Airfoil, MeshResolution, PanelSpec, SweepReference, TrailingEdge, WingModel, WingSectionSpec, WingSpec,
};
use nalgebra::Point3;

/// Analytic area of NACA 00tt with the closed trailing edge (Abbott & von Doenhoff eq. 6.2
/// integrated): `10 t (0.2969 * 2/3 - 0.1260/2 - 0.3516/3 + 0.2843/4 - 0.1036/5)`.
fn analytic_area(t: f64) -> f64 {
    10.0 * t * (0.2969 * 2.0 / 3.0 - 0.1260 / 2.0 - 0.3516 / 3.0 + 0.2843 / 4.0 - 0.1036 / 5.0)
}

fn main() -> Result<(), flapwright_geom::Error> {
    let (chord_m, span_m) = (1.2, 3.0);
    let exact_volume = analytic_area(0.12) * chord_m * chord_m * span_m;
    println!(
        "{:>8} {:>10} {:>14} {:>8} {:>12}",
        "points", "triangles", "volume error", "order", "build (ms)"
    );
    let mut previous: Option<f64> = None;
    let mut orders = Vec::new();
    for points_per_side in [10, 20, 40, 80, 160, 320] {
        let airfoil = Airfoil::naca("0012", points_per_side, TrailingEdge::Closed)?;
        let spec = WingSpec {
            root_leading_edge_ac: Point3::origin(),
            sections: vec![
                WingSectionSpec {
                    y_m: 0.0,
                    chord_m,
                    twist_deg: 0.0,
                    airfoil: airfoil.clone(),
                },
                WingSectionSpec {
                    y_m: span_m,
                    chord_m,
                    twist_deg: 0.0,
                    airfoil,
                },
            ],
            panels: vec![PanelSpec {
                sweep_deg: 0.0,
                dihedral_deg: 0.0,
            }],
            sweep_reference: SweepReference::LeadingEdge,
            twist_axis_chord_fraction: 0.25,
        };
        let start = Instant::now();
        let model = WingModel::try_new(spec, vec![], vec![], None)?;
        let parts = model.compute_parts(MeshResolution {
            points_per_side,
            spanwise_stations_per_m: 1.0,
            tube_segments: 8,
        })?;
        let elapsed_ms = start.elapsed().as_secs_f64() * 1e3;
        let error = (parts[0].mesh.compute_signed_volume() - exact_volume).abs() / exact_volume;
        let order = previous.map(|p| (p / error).log2());
        if let Some(order) = order {
            orders.push(order);
        }
        println!(
            "{points_per_side:>8} {:>10} {error:>14.3e} {:>8} {elapsed_ms:>12.3}",
            parts[0].mesh.triangles.len(),
            order.map_or("-".to_owned(), |o| format!("{o:.2}"))
        );
        previous = Some(error);
    }
    for order in &orders[1..] {
        assert!((1.8..2.3).contains(order), "observed order {order} is not 2");
    }
    println!("second-order convergence confirmed");
    Ok(())
}
