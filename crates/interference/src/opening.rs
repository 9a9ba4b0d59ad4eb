//! Openings: where a station's mechanism passes through the wing skin and through its
//! flap, cut out of those surfaces so that every part is checked against the rest of them.
//!
//! The skin of a real trailing edge is cut only where the mechanism passes: an opening in
//! the lower skin and the cove for the fairing, a slot in the flap's lower side and nose for
//! the tracks and fittings. The upper skin, the flap's upper side and the wing box ahead of
//! the rear spar are never cut. Here an opening is a box in the station frame (x forward,
//! y up, z outboard): spanwise the half width of the station's solids plus a margin,
//! chordwise (skin only) the extent of the solids swept over the deployment plus the same
//! margin, never ahead of the rear spar's aft face. Inside the box, the faces that do not
//! point up (outward normal within [`UPWARD_FACE_COS`] of station +y) are removed: the
//! lower skin, the cove wall and ceiling, the flap's lower side and nose. What is left is a
//! sheet ([`CollisionShape::from_surface`](flapwright_geom::collision::CollisionShape::from_surface)):
//! a part crossing it touches it and fails, a part inside the wing is clear of it by its
//! distance to the nearest skin.
//!
//! Fixed support structure is fastened to the wing: where a fixed solid ends on the lower
//! skin (within its radius plus the margin of the section's lower contour), the skin under
//! that end is its fitting's pad, cut like the opening but only about that end (it may lie
//! ahead of the rear spar: support struts are bolted to the wing box's lower skin).
//!
//! The margin keeps a part that passes through an opening at least the margin away from the
//! opening's edges, so it should be at least the required clearance (the scene's default is
//! twice it). The swept extent comes from samples of the deployment, widened by what any
//! solid can move between two samples (its speed bound times half the sample spacing), so
//! the box holds the whole sweep.

use flapwright_geom::TriMesh;
use flapwright_mechanism::seam::{BodyRole, FlapMechanism};
use flapwright_mechanism::shared::outline::{point_segment_distance, vertical_span};
use flapwright_mechanism::spanwise::spanwise_layout;
use nalgebra::{Isometry3, Point2, Point3, Vector3};
use serde::Serialize;

use crate::error::{Error, Result};
use crate::station::{joined_solids, planar_parts};

/// Faces whose outward normal makes less than 60 deg with the station's up axis
/// (cos 60 deg = 0.5) belong to the upper side of the skin or the flap and are never cut.
pub const UPWARD_FACE_COS: f64 = 0.5;

/// Deployment samples the swept extent is taken from (the allowance between them is added).
pub const OPENING_SAMPLES: usize = 33;

/// The openings cut for one station's mechanism, station frame (m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Opening {
    /// Station.
    pub station: String,
    /// Half the spanwise width of the skin's openings about the station plane: the widest
    /// solid's half width plus the margin (m).
    pub half_width_m: f64,
    /// Half the spanwise width of the flap's slot: the widest of the solids on the flap's
    /// bodies and those joined to them by design ([`crate::station::joined_solids`]), plus
    /// the margin (m). Only those pass through it; the station's other solids are checked
    /// against the whole flap.
    pub slot_half_width_m: f64,
    /// Chordwise extent of the skin's opening, station x (forward positive): the swept
    /// solids' extent widened by the margin, never ahead of the rear spar's aft face (m).
    pub chordwise_x_m: [f64; 2],
    /// Chordwise extents (station x) of the pads where fixed solids end on the lower skin
    /// (their fittings), each the end's radius plus the margin either side (m).
    pub pads_x_m: Vec<[f64; 2]>,
    /// How far the opening reaches beyond the swept solids (m).
    pub margin_m: f64,
    /// Area of skin removed (m^2): the fairing opening and the cove slots.
    pub skin_area_m2: f64,
    /// Area of the flap's surface removed (m^2): its slot (0 without a flap at the station).
    pub flap_area_m2: f64,
}

/// The station's opening before it is cut: its box (areas zero until [`cut_opening`]).
///
/// `forward_limit_x`: the station x of the rear spar's aft face, when the plane cuts one;
/// the skin ahead of it (the wing box) is never opened. `wing_section`: the main wing cut by
/// the station plane (station frame), for the pads of fixed solids ending on its lower skin.
pub fn station_opening(
    station: &str,
    mechanism: &dyn FlapMechanism,
    forward_limit_x: Option<f64>,
    wing_section: &[Vec<Point2<f64>>],
    margin_m: f64,
) -> Result<Opening> {
    if !(margin_m.is_finite() && margin_m >= 0.0) {
        return Err(Error::SettingOutOfRange {
            setting: "opening margin_m",
            value: margin_m,
            allowed: "[0, inf)",
        });
    }
    let travel = mechanism.input_range().travel().abs();
    // What a solid can move between two samples: its bound times half the spacing.
    let spacing = 1.0 / (OPENING_SAMPLES - 1) as f64;
    let allowance = mechanism
        .bodies()
        .iter()
        .flat_map(|body| body.solids.iter().map(|s| body.speed_bound.for_shape(&s.shape)))
        .fold(0.0, f64::max)
        * travel
        * spacing
        / 2.0;
    // Spanwise: every solid's layer and radius.
    let offsets = spanwise_layout(mechanism).map_err(|source| Error::Pose {
        part: format!("{station} (spanwise layout)"),
        parameter: 0.0,
        source,
    })?;
    let half_width = mechanism
        .bodies()
        .iter()
        .zip(&offsets)
        .flat_map(|(body, offsets)| {
            body.solids
                .iter()
                .zip(offsets)
                .map(|(s, z)| z.abs() + s.shape.radius_m())
        })
        .fold(0.0, f64::max);
    let is_flap = |b: usize| {
        mechanism
            .bodies()
            .get(b)
            .is_some_and(|body| matches!(body.role, BodyRole::Flap | BodyRole::AftFlap))
    };
    let joined = joined_solids(mechanism);
    let slot_half_width = mechanism
        .bodies()
        .iter()
        .enumerate()
        .flat_map(|(b, body)| {
            let (offsets, joined) = (&offsets[b], &joined[b]);
            body.solids
                .iter()
                .enumerate()
                .filter(move |&(s, _)| is_flap(b) || joined[s].iter().any(|&other| is_flap(other)))
                .map(move |(s, solid)| offsets[s].abs() + solid.shape.radius_m())
        })
        .fold(0.0, f64::max);
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..OPENING_SAMPLES {
        let capsules = planar_parts(mechanism, i as f64 * spacing).map_err(|source| Error::Pose {
            part: format!("{station} (opening)"),
            parameter: i as f64 * spacing,
            source,
        })?;
        for capsule in capsules {
            for end in [capsule.from, capsule.to] {
                low = low.min(end.x - capsule.radius_m);
                high = high.max(end.x + capsule.radius_m);
            }
        }
    }
    if !(low.is_finite() && high.is_finite()) {
        return Err(Error::NoSolids {
            station: station.to_string(),
        });
    }
    let mut pads_x_m = Vec::new();
    for body in mechanism.bodies().iter().filter(|b| !b.is_moving()) {
        for solid in &body.solids {
            let reach = solid.shape.radius_m() + margin_m;
            let skeleton = solid.shape.skeleton();
            let ends = [skeleton.first(), skeleton.last()];
            let on_lower_skin = |end: &Point2<f64>| {
                vertical_span(wing_section, end.x).is_some_and(|(lower, _)| (end.y - lower).abs() <= reach)
            };
            if ends.iter().flatten().any(|end| on_lower_skin(end)) {
                pads_x_m.extend(pad(wing_section, &skeleton, reach));
            }
        }
    }
    let reach = margin_m + allowance;
    let mut high = high + reach;
    if let Some(limit) = forward_limit_x {
        high = high.min(limit);
    }
    Ok(Opening {
        station: station.to_string(),
        half_width_m: half_width + margin_m,
        slot_half_width_m: slot_half_width + margin_m,
        chordwise_x_m: [low - reach, high.max(low - reach)],
        pads_x_m,
        margin_m,
        skin_area_m2: 0.0,
        flap_area_m2: 0.0,
    })
}

/// The chordwise extent of the lower contour of `wing_section` within `reach` of the
/// polyline `skeleton` (a fixed solid ending on the skin, however obliquely it meets it),
/// sampled every quarter of `reach` and widened by one step; `None` when none is.
fn pad(wing_section: &[Vec<Point2<f64>>], skeleton: &[Point2<f64>], reach: f64) -> Option<[f64; 2]> {
    let (low, high) = skeleton.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(p.x), hi.max(p.x))
    });
    let step = reach / 4.0;
    let steps = ((high - low + 2.0 * reach) / step).ceil() as usize;
    let segments: Vec<(Point2<f64>, Point2<f64>)> = match skeleton {
        [only] => vec![(*only, *only)],
        many => many.windows(2).map(|w| (w[0], w[1])).collect(),
    };
    let near = (0..=steps)
        .map(|k| low - reach + k as f64 * step)
        .filter(|&x| {
            vertical_span(wing_section, x).is_some_and(|(lower, _)| {
                let p = Point2::new(x, lower);
                segments.iter().any(|(a, b)| point_segment_distance(p, *a, *b) <= reach)
            })
        })
        .fold(None, |range: Option<[f64; 2]>, x| {
            Some(range.map_or([x, x], |[lo, hi]| [lo.min(x), hi.max(x)]))
        });
    near.map(|[lo, hi]| [lo - step, hi + step])
}

/// Which surface an opening is cut in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OpenedSurface {
    /// The wing skin: the box's full extent.
    WingSkin,
    /// The station's flap (stowed): its slot runs the flap's whole chord within the
    /// slot's spanwise width, since the flap moves along the parts that pass through it.
    Flap,
}

/// `mesh_ac` (aircraft frame) with the opening removed, and the area removed (m^2).
pub fn cut_opening(
    mesh_ac: &TriMesh,
    aircraft_from_station: &Isometry3<f64>,
    opening: &Opening,
    surface: OpenedSurface,
) -> (TriMesh, f64) {
    let station_from_aircraft = aircraft_from_station.inverse();
    let boxes: Vec<Option<[f64; 2]>> = match surface {
        OpenedSurface::WingSkin => std::iter::once(opening.chordwise_x_m)
            .chain(opening.pads_x_m.iter().copied())
            .map(Some)
            .collect(),
        OpenedSurface::Flap => vec![None],
    };
    // Only triangles reaching into a box are cut (a wing's skin has tens of thousands, a
    // station's boxes meet a few hundred); the others are kept as they are.
    let half_width = match surface {
        OpenedSurface::WingSkin => opening.half_width_m,
        OpenedSurface::Flap => opening.slot_half_width_m,
    };
    let reaches_a_box = |corners: &[Point3<f64>; 3]| {
        let (z_low, z_high) = span(corners.map(|p| p.z));
        let (x_low, x_high) = span(corners.map(|p| p.x));
        z_high >= -half_width
            && z_low <= half_width
            && boxes
                .iter()
                .any(|b| b.is_none_or(|[aft, fore]| x_high >= aft && x_low <= fore))
    };
    let station_vertices: Vec<Point3<f64>> = mesh_ac.vertices.iter().map(|v| station_from_aircraft * v).collect();
    let near_flags: Vec<bool> = mesh_ac
        .triangles
        .iter()
        .map(|t| reaches_a_box(&t.map(|i| station_vertices[i as usize])))
        .collect();
    let mut near = mesh_ac
        .select_triangles(|k| near_flags[k])
        .transformed(&station_from_aircraft);
    let mut removed_m2 = 0.0;
    for chordwise in boxes {
        let (left, removed) = cut_box(&near, half_width, chordwise);
        near = left;
        removed_m2 += removed;
    }
    // The kept triangles keep the mesh's own vertices (those they use).
    let mut kept = mesh_ac.select_triangles(|k| !near_flags[k]);
    kept.append(&near.transformed(aircraft_from_station));
    (kept, removed_m2)
}

/// The smallest and largest of three values.
fn span(values: [f64; 3]) -> (f64, f64) {
    (
        values[0].min(values[1]).min(values[2]),
        values[0].max(values[1]).max(values[2]),
    )
}

/// `mesh` (station frame) less its faces that do not point up inside the box
/// |z| <= `half_width`, x in `chordwise` (any x without), and the area removed.
fn cut_box(mesh: &TriMesh, half_width: f64, chordwise: Option<[f64; 2]>) -> (TriMesh, f64) {
    let mut planes = vec![
        (Point3::new(0.0, 0.0, -half_width), Vector3::z()),
        (Point3::new(0.0, 0.0, half_width), -Vector3::z()),
    ];
    if let Some([aft, fore]) = chordwise {
        planes.push((Point3::new(aft, 0.0, 0.0), Vector3::x()));
        planes.push((Point3::new(fore, 0.0, 0.0), -Vector3::x()));
    }
    // Peel off what lies outside each plane (behind its inward normal); what is left
    // lies in the box.
    let mut outside = TriMesh::default();
    let mut inside = mesh.clone();
    for (point, inward) in &planes {
        let [behind, ahead] = inside.split_by_plane(point, inward);
        outside.append(&behind);
        inside = ahead;
    }
    let mut removed = TriMesh::default();
    for (index, triangle) in inside.triangles.iter().enumerate() {
        let piece = TriMesh {
            vertices: triangle.map(|i| inside.vertices[i as usize]).to_vec(),
            triangles: vec![[0, 1, 2]],
        };
        if inside.triangle_normal(index).y >= UPWARD_FACE_COS {
            outside.append(&piece);
        } else {
            removed.append(&piece);
        }
    }
    (outside, removed.compute_area())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed box from (-1, -0.1, -1) to (1, 0.1, 1): top faces up, bottom down.
    fn slab() -> TriMesh {
        let mut vertices = Vec::new();
        for &x in &[-1.0, 1.0] {
            for &y in &[-0.1, 0.1] {
                for &z in &[-1.0, 1.0] {
                    vertices.push(Point3::new(x, y, z));
                }
            }
        }
        // Index = 4 ix + 2 iy + iz.
        let quads = [
            [0, 1, 3, 2], // x = -1
            [4, 6, 7, 5], // x = +1
            [0, 4, 5, 1], // y = -0.1
            [2, 3, 7, 6], // y = +0.1
            [0, 2, 6, 4], // z = -1
            [1, 5, 7, 3], // z = +1
        ];
        let triangles = quads
            .iter()
            .flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]])
            .collect();
        TriMesh { vertices, triangles }
    }

    #[test]
    fn only_the_lower_face_inside_the_box_is_cut() {
        let mesh = slab();
        assert!(mesh.compute_topology_check().is_watertight());
        assert!(mesh.compute_signed_volume() > 0.0);
        let opening = Opening {
            station: "s".into(),
            half_width_m: 0.1,
            slot_half_width_m: 0.1,
            chordwise_x_m: [-0.5, 0.25],
            pads_x_m: vec![[0.5, 0.6]],
            margin_m: 0.0,
            skin_area_m2: 0.0,
            flap_area_m2: 0.0,
        };
        let (kept, removed) = cut_opening(&mesh, &Isometry3::identity(), &opening, OpenedSurface::WingSkin);
        // The lower face loses 0.75 x 0.2 and a pad of 0.1 x 0.2; the upper face and the
        // sides keep everything.
        approx::assert_relative_eq!(removed, 0.85 * 0.2, max_relative = 1e-12);
        approx::assert_relative_eq!(kept.compute_area() + removed, mesh.compute_area(), max_relative = 1e-12);
        // A flap's slot has no chordwise limit: the whole lower face within the width, and
        // the faces at either end (they face fore and aft, like a nose).
        let (_, removed) = cut_opening(&mesh, &Isometry3::identity(), &opening, OpenedSurface::Flap);
        approx::assert_relative_eq!(removed, 2.0 * 0.2 + 2.0 * 0.2 * 0.2, max_relative = 1e-12);
    }
}
