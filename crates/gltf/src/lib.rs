//! Animated binary glTF (`.glb`) of rigid bodies, for viewers anyone can open (a browser
//! viewer, Blender) by drag and drop.
//!
//! # Overview
//! - [`Model`]: named [`Body`]s, each a triangle mesh where it stands at rest with its
//!   [`Material`], and, for a moving body, its displacement at every sample time.
//! - [`to_glb`] writes the model as one binary glTF 2.0 file: one node per body (named
//!   as the body, the name also in its `extras` as [`PART_EXTRAS_KEY`], which survives
//!   three.js's node-name sanitising; a moving body's under its pose node, see
//!   Precision), all under one root node that turns the aircraft frame into
//!   glTF's +Y-up frame ([`gltf_from_aircraft`]), and one animation (`deployment`) with
//!   a translation and a rotation channel per moving body, linear interpolation between
//!   samples (glTF's `LINEAR`: translations interpolated linearly, rotations spherically).
//! - [`interpolated_displacement`] is what a viewer shows between two samples, so a caller
//!   can bound the interpolation error against its own poses.
//!
//! The JSON is built with `gltf-json` and wrapped by `gltf`'s GLB writer: nothing of the
//! format is written by hand but the byte layout of the buffer.
//!
//! # Units and frames
//! Metres, seconds. Meshes and displacements are given in the aircraft frame (x aft,
//! y starboard, z up). A body's node sits at its anchor, the centre of its mesh's box at
//! rest: vertices are stored relative to it (so their 32-bit floats keep sub-micrometre
//! detail), and at sample k the node's translation is D_k(anchor) and its rotation D_k's,
//! for the displacement D_k from rest.
//!
//! # Precision
//! glTF stores vertices and keyframes as 32-bit floats (2^-24 |t|: 0.6 um at 10 m). So that
//! the file carries the poses to double precision all the same, a moving part's node (its
//! name, its mesh) hangs under a pose node (`<name>#pose`, [`pose_node_name`]): the pose
//! node's keyframes are the pose rounded to 32 bits, the part node's the small remainder,
//! T(t_c) R_c T(t_f) R_f = T(t) R, which rounds to about 1e-15 m and rad. A reader that
//! composes the two in 64 bits gets the poses back to about 1e-14 m; a viewer drawing in 32
//! bits sees the coarse pose, as it would anyway. Vertices are relative to the anchor, so
//! their 32 bits keep sub-micrometre detail.
//!
//! ```
//! use flapwright_geom::TriMesh;
//! use flapwright_gltf::{to_glb, Body, Material, Model};
//! use nalgebra::{Isometry3, Point3, Vector3};
//!
//! let triangle = TriMesh {
//!     vertices: vec![Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0)],
//!     triangles: vec![[0, 1, 2]],
//! };
//! let model = Model {
//!     times_s: vec![0.0, 1.0],
//!     materials: vec![Material { name: "part".into(), rgba: [0.8, 0.3, 0.1, 1.0] }],
//!     bodies: vec![Body {
//!         name: "flap".into(),
//!         mesh: triangle,
//!         material: 0,
//!         displacements: Some(vec![Isometry3::identity(), Isometry3::translation(0.0, 0.0, -0.2)]),
//!     }],
//! };
//! let glb = to_glb(&model)?;
//! assert_eq!(&glb[..4], b"glTF");
//! # Ok::<(), flapwright_gltf::Error>(())
//! ```

use std::borrow::Cow;
use std::collections::BTreeMap;

use flapwright_geom::TriMesh;
use gltf_json as json;
use json::validation::Checked::Valid;
use json::validation::USize64;
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

/// The glTF frame seen from the aircraft frame: a quarter turn about x, so that the
/// aircraft's z (up) becomes glTF's +Y and its y (starboard) glTF's -Z; x (aft) stays +X.
pub fn gltf_from_aircraft() -> UnitQuaternion<f64> {
    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), -std::f64::consts::FRAC_PI_2)
}

/// Name of the root node that carries [`gltf_from_aircraft`].
pub const ROOT_NODE: &str = "aircraft-frame";

/// Name of the one animation.
pub const ANIMATION: &str = "deployment";

/// Everything that keeps a model from being written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// The model has no body.
    #[error("the model has no body to show")]
    NoBodies,
    /// Sample times are fewer than two, not finite or not strictly increasing.
    #[error("sample times must be at least two, finite and strictly increasing (got {count})")]
    BadTimes {
        /// How many were given.
        count: usize,
    },
    /// A moving body has a number of displacements other than the number of times.
    #[error("body `{body}` has {given} displacements for {times} sample times")]
    SampleCount {
        /// The body.
        body: String,
        /// Displacements given.
        given: usize,
        /// Sample times.
        times: usize,
    },
    /// A body's mesh has no triangle, an index out of range or a non-finite vertex.
    #[error("body `{body}`: {reason}")]
    BadMesh {
        /// The body.
        body: String,
        /// What is wrong.
        reason: String,
    },
    /// A displacement is not finite.
    #[error("body `{body}` has a non-finite displacement at sample {sample}")]
    NonFiniteDisplacement {
        /// The body.
        body: String,
        /// The sample.
        sample: usize,
    },
    /// A body names a material that does not exist.
    #[error("body `{body}` names material {material}, of {count}")]
    NoSuchMaterial {
        /// The body.
        body: String,
        /// Index given.
        material: usize,
        /// Materials there are.
        count: usize,
    },
    /// The file would exceed the 4 GiB a GLB can hold, or serialisation failed.
    #[error("cannot write the GLB: {0}")]
    Write(String),
}

/// Result of this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// A surface colour: PBR metallic-roughness with this base colour; alpha below 1 blends.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Name.
    pub name: String,
    /// Linear RGBA, each in [0, 1].
    pub rgba: [f32; 4],
}

/// A rigid body.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Node name (the report's part name).
    pub name: String,
    /// Surface at rest, aircraft frame (m).
    pub mesh: TriMesh,
    /// Index into [`Model::materials`].
    pub material: usize,
    /// Displacement from rest at each of [`Model::times_s`] (aircraft frame); `None`: the
    /// body does not move.
    pub displacements: Option<Vec<Isometry3<f64>>>,
}

impl Body {
    /// Where the body's node sits at rest: the centre of its mesh's box (aircraft frame).
    /// Rounded to 32-bit floats, so that the node's stored translation is the anchor.
    pub fn anchor(&self) -> Point3<f64> {
        self.mesh
            .compute_aabb()
            .map_or_else(Point3::origin, |b| nalgebra::center(&b.min, &b.max))
            .map(|c| f64::from(c as f32))
    }
}

/// Bodies, materials and the sample times of their motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// Sample times (s), strictly increasing, at least two.
    pub times_s: Vec<f64>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Bodies, in node order.
    pub bodies: Vec<Body>,
}

/// The displacement a viewer shows a fraction `s` in [0, 1] of the way from sample
/// displacement `a` to `b`, for a body whose node sits at `anchor` (aircraft frame): the
/// node's translation D(anchor) interpolated linearly, its rotation spherically (glTF's
/// `LINEAR` interpolation), so D_s(p) = t_s + R_s (p - anchor).
pub fn interpolated_displacement(
    a: &Isometry3<f64>,
    b: &Isometry3<f64>,
    anchor: &Point3<f64>,
    s: f64,
) -> Isometry3<f64> {
    let (ta, tb) = (a * anchor, b * anchor);
    let translation = ta.coords.lerp(&tb.coords, s);
    let rotation = a.rotation.slerp(&b.rotation, s);
    Isometry3::from_parts(Translation3::from(translation), rotation) * Translation3::from(-anchor.coords)
}

/// The `extras` of a part's node: `{"flapwright_part": name}`, the report's part name. three.js
/// strips `.`, `:`, `/`, `[` and `]` from node names (`PropertyBinding.sanitizeNodeName`:
/// `ib-inner.rail` becomes `ib-innerrail`) but keeps a node's extras as the object's
/// `userData`, where a viewer finds the part by its report name.
fn part_extras(name: &str) -> Result<json::Extras> {
    let extras = serde_json::json!({ PART_EXTRAS_KEY: name });
    serde_json::value::to_raw_value(&extras)
        .map(Some)
        .map_err(|e| Error::Write(e.to_string()))
}

/// The key of a part node's `extras` that holds the report's part name: `{"flapwright_part": "ib-inner.rail"}`.
pub const PART_EXTRAS_KEY: &str = "flapwright_part";

/// The name of the node that carries a moving part's coarse pose: the part's name and
/// `#pose`.
pub fn pose_node_name(part: &str) -> String {
    format!("{part}#pose")
}

/// A node pose as glTF stores it: translation and rotation quaternion (x, y, z, w).
type StoredPose = ([f32; 3], [f32; 4]);

/// Splits the pose (translation `t`, rotation `r`) into a coarse pose, `t` and `r` rounded
/// to 32-bit floats, and the fine pose that remains, T(t_c) R_c T(t_f) R_f = T(t) R:
/// R_f = R_c^-1 R and t_f = R_c^-1 (t - t_c), both tiny, so that their own rounding costs
/// about 1e-15 m and rad. R_c is the stored quaternion normalised, as a reader takes it.
fn split_pose(t: &Point3<f64>, r: &UnitQuaternion<f64>) -> (StoredPose, StoredPose) {
    let round = |v: f64| v as f32;
    let q = r.coords;
    let coarse_q = [round(q.x), round(q.y), round(q.z), round(q.w)];
    let coarse_t = [round(t.x), round(t.y), round(t.z)];
    let [x, y, z, w] = coarse_q.map(f64::from);
    let coarse_rotation = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z));
    let fine_rotation = coarse_rotation.inverse() * r;
    let fine_t = coarse_rotation.inverse() * (t.coords - Vector3::from(coarse_t.map(f64::from)));
    let f = fine_rotation.coords;
    (
        (coarse_t, coarse_q),
        (
            [round(fine_t.x), round(fine_t.y), round(fine_t.z)],
            [round(f.x), round(f.y), round(f.z), round(f.w)],
        ),
    )
}

/// Bytes of the binary buffer, each view 4-byte aligned.
#[derive(Default)]
struct Buffer {
    bytes: Vec<u8>,
}

impl Buffer {
    /// Appends `values` as little-endian 32-bit words; returns (offset, length).
    fn push_words(&mut self, values: impl IntoIterator<Item = [u8; 4]>) -> (usize, usize) {
        let offset = self.bytes.len();
        for word in values {
            self.bytes.extend_from_slice(&word);
        }
        (offset, self.bytes.len() - offset)
    }
}

fn check(model: &Model) -> Result<()> {
    if model.bodies.is_empty() {
        return Err(Error::NoBodies);
    }
    let times = &model.times_s;
    if times.len() < 2 || times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Error::BadTimes { count: times.len() });
    }
    for body in &model.bodies {
        let bad = |reason: String| Error::BadMesh {
            body: body.name.clone(),
            reason,
        };
        if body.mesh.triangles.is_empty() {
            return Err(bad("no triangle".into()));
        }
        let count = body.mesh.vertices.len();
        if body.mesh.triangles.iter().flatten().any(|&i| i as usize >= count) {
            return Err(bad(format!("a triangle index beyond its {count} vertices")));
        }
        if body
            .mesh
            .vertices
            .iter()
            .any(|v| !v.coords.iter().all(|c| c.is_finite()))
        {
            return Err(bad("a non-finite vertex".into()));
        }
        if body.material >= model.materials.len() {
            return Err(Error::NoSuchMaterial {
                body: body.name.clone(),
                material: body.material,
                count: model.materials.len(),
            });
        }
        if let Some(displacements) = &body.displacements {
            if displacements.len() != times.len() {
                return Err(Error::SampleCount {
                    body: body.name.clone(),
                    given: displacements.len(),
                    times: times.len(),
                });
            }
            if let Some(sample) = displacements
                .iter()
                .position(|d| !d.to_homogeneous().iter().all(|c| c.is_finite()))
            {
                return Err(Error::NonFiniteDisplacement {
                    body: body.name.clone(),
                    sample,
                });
            }
        }
    }
    Ok(())
}

fn f32_words(values: &[f32]) -> impl Iterator<Item = [u8; 4]> + '_ {
    values.iter().map(|v| v.to_le_bytes())
}

/// Writes `model` as a binary glTF 2.0 file (see the [crate docs](crate)).
///
/// Errors: [`Error::NoBodies`], [`Error::BadTimes`], [`Error::SampleCount`],
/// [`Error::BadMesh`], [`Error::NonFiniteDisplacement`], [`Error::NoSuchMaterial`],
/// [`Error::Write`].
pub fn to_glb(model: &Model) -> Result<Vec<u8>> {
    check(model)?;
    let mut root = json::Root::default();
    let mut buffer = Buffer::default();
    // Views are recorded with their offsets into the one buffer, pushed once it is known.
    let mut views: Vec<(usize, usize, Option<json::buffer::Target>)> = Vec::new();
    let mut view = |(offset, length): (usize, usize), target: Option<json::buffer::Target>| {
        views.push((offset, length, target));
        json::Index::<json::buffer::View>::new((views.len() - 1) as u32)
    };
    let accessor = |view: json::Index<json::buffer::View>,
                    count: usize,
                    component: json::accessor::ComponentType,
                    type_: json::accessor::Type,
                    bounds: Option<(Vec<f32>, Vec<f32>)>| json::Accessor {
        buffer_view: Some(view),
        byte_offset: None,
        count: USize64::from(count),
        component_type: Valid(json::accessor::GenericComponentType(component)),
        extensions: Default::default(),
        extras: Default::default(),
        type_: Valid(type_),
        min: bounds.as_ref().map(|(min, _)| json::Value::from(min.clone())),
        max: bounds.map(|(_, max)| json::Value::from(max)),
        name: None,
        normalized: false,
        sparse: None,
    };
    let materials: Vec<json::Index<json::Material>> = model
        .materials
        .iter()
        .map(|m| {
            root.push(json::Material {
                name: Some(m.name.clone()),
                alpha_mode: Valid(if m.rgba[3] < 1.0 {
                    json::material::AlphaMode::Blend
                } else {
                    json::material::AlphaMode::Opaque
                }),
                double_sided: true,
                pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                    base_color_factor: json::material::PbrBaseColorFactor(m.rgba),
                    metallic_factor: json::material::StrengthFactor(0.1),
                    roughness_factor: json::material::StrengthFactor(0.6),
                    ..Default::default()
                },
                ..Default::default()
            })
        })
        .collect();
    let times: Vec<f32> = model.times_s.iter().map(|&t| t as f32).collect();
    let time_view = view(buffer.push_words(f32_words(&times)), None);
    let time_accessor = root.push(accessor(
        time_view,
        times.len(),
        json::accessor::ComponentType::F32,
        json::accessor::Type::Scalar,
        Some((vec![times[0]], vec![times[times.len() - 1]])),
    ));
    let mut nodes = Vec::new();
    let mut channels = Vec::new();
    let mut samplers = Vec::new();
    for body in &model.bodies {
        let anchor = body.anchor();
        let positions: Vec<f32> = body
            .mesh
            .vertices
            .iter()
            .flat_map(|v| (v - anchor).iter().map(|&c| c as f32).collect::<Vec<_>>())
            .collect();
        let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in positions.chunks_exact(3) {
            for k in 0..3 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let position_view = view(
            buffer.push_words(f32_words(&positions)),
            Some(json::buffer::Target::ArrayBuffer),
        );
        let position_accessor = root.push(accessor(
            position_view,
            body.mesh.vertices.len(),
            json::accessor::ComponentType::F32,
            json::accessor::Type::Vec3,
            Some((min.to_vec(), max.to_vec())),
        ));
        let index_view = view(
            buffer.push_words(body.mesh.triangles.iter().flatten().map(|i| i.to_le_bytes())),
            Some(json::buffer::Target::ElementArrayBuffer),
        );
        let index_accessor = root.push(accessor(
            index_view,
            body.mesh.triangles.len() * 3,
            json::accessor::ComponentType::U32,
            json::accessor::Type::Scalar,
            None,
        ));
        let mesh = root.push(json::Mesh {
            extensions: Default::default(),
            extras: Default::default(),
            name: Some(body.name.clone()),
            primitives: vec![json::mesh::Primitive {
                attributes: BTreeMap::from([(Valid(json::mesh::Semantic::Positions), position_accessor)]),
                extensions: Default::default(),
                extras: Default::default(),
                indices: Some(index_accessor),
                material: Some(materials[body.material]),
                mode: Valid(json::mesh::Mode::Triangles),
                targets: None,
            }],
            weights: None,
        });
        let Some(displacements) = &body.displacements else {
            nodes.push(root.push(json::Node {
                name: Some(body.name.clone()),
                extras: part_extras(&body.name)?,
                mesh: Some(mesh),
                translation: Some(anchor.coords.map(|c| c as f32).into()),
                ..Default::default()
            }));
            continue;
        };
        // The part's node (its mesh and the fine keyframes) under its pose node (the
        // coarse keyframes), so that the two 32-bit poses compose to the 64-bit one.
        let part = root.push(json::Node {
            name: Some(body.name.clone()),
            extras: part_extras(&body.name)?,
            mesh: Some(mesh),
            ..Default::default()
        });
        let pose = root.push(json::Node {
            name: Some(pose_node_name(&body.name)),
            children: Some(vec![part]),
            translation: Some(anchor.coords.map(|c| c as f32).into()),
            ..Default::default()
        });
        nodes.push(pose);
        let (coarse, fine): (Vec<_>, Vec<_>) = displacements
            .iter()
            .map(|d| split_pose(&(d * anchor), &d.rotation))
            .unzip();
        for (node, keys) in [(pose, coarse), (part, fine)] {
            let translations: Vec<f32> = keys.iter().flat_map(|(t, _)| *t).collect();
            let rotations: Vec<f32> = keys.iter().flat_map(|(_, q)| *q).collect();
            for (values, type_, property) in [
                (
                    &translations,
                    json::accessor::Type::Vec3,
                    json::animation::Property::Translation,
                ),
                (
                    &rotations,
                    json::accessor::Type::Vec4,
                    json::animation::Property::Rotation,
                ),
            ] {
                let output_view = view(buffer.push_words(f32_words(values)), None);
                let output = root.push(accessor(
                    output_view,
                    times.len(),
                    json::accessor::ComponentType::F32,
                    type_,
                    None,
                ));
                samplers.push(json::animation::Sampler {
                    extensions: Default::default(),
                    extras: Default::default(),
                    input: time_accessor,
                    interpolation: Valid(json::animation::Interpolation::Linear),
                    output,
                });
                channels.push(json::animation::Channel {
                    sampler: json::Index::new((samplers.len() - 1) as u32),
                    target: json::animation::Target {
                        extensions: Default::default(),
                        extras: Default::default(),
                        node,
                        path: Valid(property),
                    },
                    extensions: Default::default(),
                    extras: Default::default(),
                });
            }
        }
    }
    let turn = gltf_from_aircraft().coords;
    let root_node = root.push(json::Node {
        name: Some(ROOT_NODE.into()),
        children: Some(nodes),
        rotation: Some(json::scene::UnitQuaternion([
            turn.x as f32,
            turn.y as f32,
            turn.z as f32,
            turn.w as f32,
        ])),
        ..Default::default()
    });
    if !channels.is_empty() {
        root.push(json::Animation {
            extensions: Default::default(),
            extras: Default::default(),
            channels,
            name: Some(ANIMATION.into()),
            samplers,
        });
    }
    let scene = root.push(json::Scene {
        extensions: Default::default(),
        extras: Default::default(),
        name: Some("flapwright".into()),
        nodes: vec![root_node],
    });
    root.scene = Some(scene);
    let length = buffer.bytes.len();
    let gltf_buffer = root.push(json::Buffer {
        byte_length: USize64::from(length),
        extensions: Default::default(),
        extras: Default::default(),
        name: None,
        uri: None,
    });
    for (offset, length, target) in views {
        root.push(json::buffer::View {
            buffer: gltf_buffer,
            byte_length: USize64::from(length),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            extensions: Default::default(),
            extras: Default::default(),
            name: None,
            target: target.map(Valid),
        });
    }
    root.asset.generator = Some(format!("flapwright {}", env!("CARGO_PKG_VERSION")));
    let text = json::serialize::to_string(&root).map_err(|e| Error::Write(e.to_string()))?;
    let total = text.len().next_multiple_of(4) + length + 28;
    let glb = gltf::binary::Glb {
        header: gltf::binary::Header {
            magic: *b"glTF",
            version: 2,
            length: u32::try_from(total).map_err(|_| Error::Write(format!("{total} bytes exceed 4 GiB")))?,
        },
        json: Cow::Owned(text.into_bytes()),
        bin: Some(Cow::Owned(buffer.bytes)),
    };
    glb.to_vec().map_err(|e| Error::Write(e.to_string()))
}
