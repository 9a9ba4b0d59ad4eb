//! The check's clearances against an independent exact distance, for one part of every
//! body role against its station's opened skin (issue 17): the parts are posed from the
//! mechanism seam here (not through the check's motions) and the distance is brute force
//! over triangles, segments and points (Ericson, Real-Time Collision Detection, 5.1.5 and
//! 5.1.9), without parry.
//!
//! What must hold for the pair's sweep (`min_clearance_m` d at `at_parameter` τ*, residual
//! bound r): the exact distance at τ* is d, and on a grid of the deployment the exact
//! distance never falls below d - r (the certified lower bound).

use std::path::Path;

use flapwright_geom::reference::{segment_triangle, triangle_triangle};
use flapwright_geom::TriMesh;
use flapwright_interference::{sweep_pair, Part};
use flapwright_mechanism::seam::{posed_shape, BodyRole, PlanarShape};
use flapwright_mechanism::spanwise::spanwise_layout;
use nalgebra::{Isometry3, Point3};

use super::{assembly, MeshPart, StationRecord};
use crate::pipeline::{geometry, mechanisms, stations};
use crate::scene::Scene;

/// Grid of the deployment on which the certified bound is checked.
const GRID: usize = 41;

/// How closely the check's distance must equal the exact one at the same pose (m): parry's
/// GJK distance from a capsule to a triangle stops within about 1e-8 m (5.4e-9 m seen on
/// the transport's crank at 0.80 m).
const AGREEMENT_M: f64 = 1e-7;

fn triangles(mesh: &TriMesh) -> Vec<[Point3<f64>; 3]> {
    mesh.triangles
        .iter()
        .map(|t| t.map(|i| mesh.vertices[i as usize]))
        .collect()
}

/// Exact distance from the segments (thickened by `radius`) to the sheet's triangles.
fn segments_to_sheet(segments: &[(Point3<f64>, Point3<f64>)], radius: f64, sheet: &[[Point3<f64>; 3]]) -> f64 {
    let mut best = f64::INFINITY;
    for (p, q) in segments {
        for t in sheet {
            best = best.min(segment_triangle(p, q, t));
        }
    }
    (best - radius).max(0.0)
}

/// A part's solid at drive fraction τ, posed from the seam: the segments of its skeleton
/// and its radius (a capsule chain), or its triangles (a track's tube mesh, fixed).
enum Posed {
    Round(Vec<(Point3<f64>, Point3<f64>)>, f64),
    Mesh(Vec<[Point3<f64>; 3]>),
}

fn posed(record: &StationRecord, body: usize, solid: &str, part: &Part, fraction: f64) -> Posed {
    let mechanism = record.mechanism.as_ref();
    let shape = &mechanism.bodies()[body]
        .solids
        .iter()
        .find(|s| format!("{}.{}", record.station, s.name) == part.name)
        .expect("the part's solid")
        .shape;
    if let PlanarShape::Tube { .. } = shape {
        assert!(!mechanism.bodies()[body].is_moving(), "{solid}: tracks are fixed");
        return Posed::Mesh(triangles(&part.shape.compute_surface_mesh()));
    }
    let pose = mechanism
        .pose(mechanism.input_range().at_fraction(fraction))
        .expect("poses");
    let frame: &Isometry3<f64> = record
        .placed
        .as_ref()
        .expect("placed")
        .station
        .frame
        .aircraft_from_station();
    // Its spanwise layer, as the seam lays the station out.
    let solid_index = mechanism.bodies()[body]
        .solids
        .iter()
        .position(|s| format!("{}.{}", record.station, s.name) == part.name)
        .expect("the part's solid");
    let z = spanwise_layout(mechanism).expect("a layout")[body][solid_index]; // 33 poses: cheap next to the brute force
    let skeleton: Vec<Point3<f64>> = posed_shape(shape, &pose.bodies[body])
        .skeleton()
        .iter()
        .map(|p| frame * Point3::new(p.x, p.y, z))
        .collect();
    let segments = match skeleton.as_slice() {
        [only] => vec![(*only, *only)],
        many => many.windows(2).map(|w| (w[0], w[1])).collect(),
    };
    Posed::Round(segments, shape.radius_m())
}

/// The sheet's triangles that can hold the closest point to `solid`: those whose box lies
/// within an upper bound of the distance (from one point of the solid to the nearest sheet
/// vertex) of the solid's box. Exact: every other triangle is farther than that bound.
fn near(solid: &Posed, sheet: &[[Point3<f64>; 3]]) -> Vec<[Point3<f64>; 3]> {
    let (points, radius): (Vec<Point3<f64>>, f64) = match solid {
        Posed::Round(segments, radius) => (segments.iter().flat_map(|(p, q)| [*p, *q]).collect(), *radius),
        Posed::Mesh(triangles) => (triangles.iter().flatten().copied().collect(), 0.0),
    };
    let upper = sheet
        .iter()
        .flatten()
        .map(|v| (v - points[0]).norm())
        .fold(f64::INFINITY, f64::min);
    let margin = upper + radius;
    let (mut lo, mut hi) = (points[0], points[0]);
    for p in &points {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    sheet
        .iter()
        .filter(|t| {
            let (mut tlo, mut thi) = (t[0], t[0]);
            for v in &t[1..] {
                tlo = tlo.inf(v);
                thi = thi.sup(v);
            }
            let gap = (0..3)
                .map(|k| (tlo[k] - hi[k]).max(lo[k] - thi[k]).max(0.0).powi(2))
                .sum::<f64>()
                .sqrt();
            gap <= margin
        })
        .copied()
        .collect()
}

fn exact_distance(solid: &Posed, sheet: &[[Point3<f64>; 3]]) -> f64 {
    let sheet = &near(solid, sheet)[..];
    match solid {
        Posed::Round(segments, radius) => segments_to_sheet(segments, *radius, sheet),
        Posed::Mesh(triangles) => triangles
            .iter()
            .flat_map(|a| sheet.iter().map(move |b| triangle_triangle(a, b)))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The scene's stations up to synthesis, as `design` runs them.
fn synthesised(text: &str, dir: &Path) -> (Scene, Vec<MeshPart>, Vec<StationRecord>) {
    let scene = Scene::from_file_text(text, "test scene", &crate::scene::Folder::new(dir)).expect("valid scene");
    let wing = scene.wing.as_ref().expect("a wing");
    let model = geometry::build_model(&scene, wing, &crate::scene::Folder::new(dir)).expect("model");
    let meshed = geometry::mesh_parts(&model, &scene.resolution).expect("meshes");
    let placed = stations::place_all(&scene, &model, &meshed).expect("planes");
    let placed = stations::apply_flap_motion(&scene, &model, &meshed, placed).expect("flap motion");
    let records = mechanisms::synthesise_all(&scene, None, placed, &[]).expect("synthesis");
    (scene, meshed, records)
}

/// One part of each role in `roles` against its station's opened skin: returns the roles
/// checked.
fn agree_for_roles(text: &str, roles: &[BodyRole]) -> Vec<BodyRole> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes");
    let (scene, meshed, records) = synthesised(text, &dir);
    let (assembly, _, settings) =
        assembly(&scene, &meshed, &records, &crate::pipeline::WingCache::default()).expect("assembly");
    let mut checked = Vec::new();
    for &role in roles {
        let Some((station, part)) = assembly
            .stations
            .iter()
            .find_map(|s| s.parts.iter().find(|p| p.role == role).map(|p| (s, p)))
        else {
            continue;
        };
        let record = records.iter().find(|r| r.station == station.station).unwrap();
        let skin = &station.opened_skins[0];
        let sheet = triangles(&skin.shape.compute_surface_mesh());
        let sweep = sweep_pair(&part.part, skin, 0.0, 1.0, &settings).expect("sweeps");
        let solid = |fraction: f64| posed(record, part.body, &part.part.name, &part.part, fraction);
        let at = exact_distance(&solid(sweep.at_parameter), &sheet);
        // parry's distance from a capsule to a triangle converges (GJK) to about 1e-8 m.
        assert!(
            (at - sweep.min_clearance_m).abs() <= AGREEMENT_M,
            "{role:?} {}: exact {at} m at τ = {}, check {} m",
            part.part.name,
            sweep.at_parameter,
            sweep.min_clearance_m
        );
        let bound = sweep.min_clearance_m - sweep.residual_bound_m;
        for k in 0..GRID {
            let fraction = k as f64 / (GRID - 1) as f64;
            let exact = exact_distance(&solid(fraction), &sheet);
            assert!(
                exact >= bound - AGREEMENT_M,
                "{role:?} {}: exact {exact} m at τ = {fraction} under the certified {bound} m",
                part.part.name
            );
        }
        eprintln!(
            "{role:?} {} against {}: {:.6} m at τ = {:.3} (exact {at:.9} m), residual bound {:.2e} m",
            part.part.name, skin.name, sweep.min_clearance_m, sweep.at_parameter, sweep.residual_bound_m
        );
        checked.push(role);
    }
    checked
}

#[test]
fn default_scene_clearances_agree_with_brute_force_for_flap_actuator_and_track() {
    let roles = [BodyRole::Flap, BodyRole::Actuator, BodyRole::Track];
    assert_eq!(agree_for_roles(crate::scene::DEFAULT_SCENE_TOML, &roles), roles);
}

#[test]
fn transport_clearances_agree_with_brute_force_for_links_supports_and_carriages() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes");
    let text = std::fs::read_to_string(dir.join("transport-flap.toml")).unwrap();
    // Four-bars (links, supports), and hooked tracks at the outboard flap (carriages).
    let text = text.replace("kind = \"dropped-hinge\"", "kind = \"hooked-track\"");
    let roles = [BodyRole::Link, BodyRole::Support, BodyRole::Carriage];
    assert_eq!(agree_for_roles(&text, &roles), roles);
}
