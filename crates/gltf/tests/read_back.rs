//! The written file read back by the `gltf` crate's reader: nodes, the root turn, the
//! animation's keyframes against the displacements given, and the interpolation a viewer
//! does between them.

use approx::assert_relative_eq;
use flapwright_geom::TriMesh;
use flapwright_gltf::{gltf_from_aircraft, interpolated_displacement, to_glb, Body, Error, Material, Model, ROOT_NODE};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

fn tetrahedron(offset: Vector3<f64>) -> TriMesh {
    let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z) + offset;
    TriMesh {
        vertices: vec![p(0.0, 0.0, 0.0), p(0.3, 0.0, 0.0), p(0.0, 0.2, 0.0), p(0.0, 0.0, 0.1)],
        triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    }
}

/// A flap turning about a hinge line parallel to y through (4, 2.5, 0.3), 40 deg over 9 samples.
fn turning(samples: usize) -> Vec<Isometry3<f64>> {
    let hinge = Vector3::new(4.0, 2.5, 0.3);
    (0..samples)
        .map(|k| {
            let angle = 40f64.to_radians() * k as f64 / (samples - 1) as f64;
            Translation3::from(hinge)
                * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), angle)
                * Translation3::from(-hinge)
        })
        .collect()
}

fn model(samples: usize) -> Model {
    Model {
        times_s: (0..samples).map(|k| k as f64 * 0.5).collect(),
        materials: vec![
            Material {
                name: "skin".into(),
                rgba: [0.7, 0.7, 0.75, 0.4],
            },
            Material {
                name: "flap".into(),
                rgba: [0.9, 0.5, 0.1, 1.0],
            },
        ],
        bodies: vec![
            Body {
                name: "wing".into(),
                mesh: tetrahedron(Vector3::new(3.0, 2.0, 0.2)),
                material: 0,
                displacements: None,
            },
            Body {
                name: "inner.flap".into(),
                mesh: tetrahedron(Vector3::new(4.2, 2.4, 0.25)),
                material: 1,
                displacements: Some(turning(samples)),
            },
        ],
    }
}

#[test]
fn every_body_is_a_named_node_under_the_turned_root() {
    let glb = to_glb(&model(9)).unwrap();
    let document = gltf::Gltf::from_slice(&glb).unwrap();
    let names: Vec<&str> = document.nodes().filter_map(|n| n.name()).collect();
    assert_eq!(names, ["wing", "inner.flap", "inner.flap#pose", ROOT_NODE]);
    let root = document.nodes().find(|n| n.name() == Some(ROOT_NODE)).unwrap();
    let (_, rotation, _) = root.transform().decomposed();
    let [x, y, z, w] = rotation;
    let turn = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w as f64, x as f64, y as f64, z as f64));
    // Up (aircraft z) is glTF's +Y; starboard (aircraft y) is glTF's -Z.
    assert_relative_eq!(turn * Vector3::z(), Vector3::y(), epsilon = 1e-7);
    assert_relative_eq!(turn * Vector3::y(), -Vector3::z(), epsilon = 1e-7);
    assert_relative_eq!(turn.angle_to(&gltf_from_aircraft()), 0.0, epsilon = 1e-7);
    assert_eq!(root.children().count(), 2);
    let pose = root.children().find(|n| n.name() == Some("inner.flap#pose")).unwrap();
    assert_eq!(
        pose.children()
            .map(|n| n.name().unwrap().to_string())
            .collect::<Vec<_>>(),
        ["inner.flap"]
    );
    assert_eq!(document.scenes().count(), 1);
    // Each part's node carries its report name in its extras (three.js strips the `.`
    // from `inner.flap`'s node name and keeps the extras as `userData`); the pose and
    // root nodes carry none.
    for node in document.nodes() {
        let extras = node.extras().as_ref().map(|raw| raw.get().to_string());
        match node.name() {
            Some(name @ ("wing" | "inner.flap")) => {
                let value: serde_json::Value = serde_json::from_str(&extras.expect("extras")).unwrap();
                assert_eq!(value, serde_json::json!({ flapwright_gltf::PART_EXTRAS_KEY: name }));
            }
            _ => assert!(extras.is_none(), "{:?}: {extras:?}", node.name()),
        }
    }
}

/// A node's keyframes as stored: translations and rotations (x, y, z, w).
type Keyframes = (Vec<[f32; 3]>, Vec<[f32; 4]>);

/// Every channel's keyframes by node name.
fn keyframes(document: &gltf::Gltf) -> std::collections::BTreeMap<String, Keyframes> {
    let blob = document.blob.as_deref().unwrap();
    let mut keys: std::collections::BTreeMap<String, Keyframes> = Default::default();
    for channel in document.animations().flat_map(|a| a.channels()) {
        let entry = keys
            .entry(channel.target().node().name().unwrap().to_string())
            .or_default();
        match channel.reader(|_| Some(blob)).read_outputs().unwrap() {
            gltf::animation::util::ReadOutputs::Translations(values) => entry.0 = values.collect(),
            gltf::animation::util::ReadOutputs::Rotations(values) => entry.1 = values.into_f32().collect(),
            _ => panic!("only translation and rotation channels"),
        }
    }
    keys
}

fn stored(t: [f32; 3], q: [f32; 4]) -> Isometry3<f64> {
    let [x, y, z, w] = q.map(f64::from);
    Isometry3::from_parts(
        Translation3::from(Vector3::from(t.map(f64::from))),
        UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(w, x, y, z)),
    )
}

#[test]
fn pose_and_part_keyframes_compose_to_the_displacements_in_double_precision() {
    let model = model(9);
    let glb = to_glb(&model).unwrap();
    let document = gltf::Gltf::from_slice(&glb).unwrap();
    let animations: Vec<_> = document.animations().collect();
    assert_eq!(animations.len(), 1);
    assert_eq!(animations[0].name(), Some("deployment"));
    let times: Vec<f32> = animations[0]
        .channels()
        .next()
        .unwrap()
        .reader(|_| document.blob.as_deref())
        .read_inputs()
        .unwrap()
        .collect();
    assert_eq!(times.len(), 9);
    assert_eq!(times[8], 4.0);
    let keys = keyframes(&document);
    assert_eq!(keys.len(), 2, "the flap's pose node and part node");
    let flap = &model.bodies[1];
    let anchor = flap.anchor();
    let (coarse, fine) = (&keys["inner.flap#pose"], &keys["inner.flap"]);
    let mut worst = (0.0_f64, 0.0_f64);
    for (k, d) in flap.displacements.as_ref().unwrap().iter().enumerate() {
        // What a reader composes: parent's pose, then the child's.
        let read = stored(coarse.0[k], coarse.1[k]) * stored(fine.0[k], fine.1[k]);
        let exact = Translation3::from((d * anchor).coords) * d.rotation;
        worst.0 = worst.0.max((read.translation.vector - exact.translation.vector).norm());
        worst.1 = worst.1.max(read.rotation.angle_to(&exact.rotation));
        // The coarse pose alone is the pose rounded to 32 bits.
        assert!((stored(coarse.0[k], coarse.1[k]).translation.vector - exact.translation.vector).norm() < 1e-6);
    }
    assert!(worst.0 < 1e-12 && worst.1 < 1e-12, "{worst:?}");
}

#[test]
fn vertices_read_back_at_rest_where_they_were_given() {
    let model = model(3);
    let glb = to_glb(&model).unwrap();
    let document = gltf::Gltf::from_slice(&glb).unwrap();
    let blob = document.blob.as_deref().unwrap();
    for body in &model.bodies {
        let node = document.nodes().find(|n| n.name() == Some(body.name.as_str())).unwrap();
        // The rest translation is the node's own, or its pose node's for a moving part.
        let pose = document
            .nodes()
            .find(|n| n.name() == Some(format!("{}#pose", body.name).as_str()))
            .unwrap_or_else(|| node.clone());
        let [tx, ty, tz] = pose.transform().decomposed().0;
        let mesh = node.mesh().unwrap();
        let primitive = mesh.primitives().next().unwrap();
        let reader = primitive.reader(|_| Some(blob));
        let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
        for (read, given) in positions.iter().zip(&body.mesh.vertices) {
            let shown = Point3::new(
                read[0] as f64 + tx as f64,
                read[1] as f64 + ty as f64,
                read[2] as f64 + tz as f64,
            );
            assert_relative_eq!(shown, given, epsilon = 1e-6);
        }
        let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
        assert_eq!(indices.len(), body.mesh.triangles.len() * 3);
    }
}

#[test]
fn interpolation_between_samples_is_exact_for_a_turn_about_the_anchor_only() {
    let a = Isometry3::identity();
    let anchor = Point3::new(1.0, 2.0, 3.0);
    // A turn about the anchor: the viewer's slerp reproduces it exactly.
    let about_anchor = |angle: f64| {
        Translation3::from(anchor.coords)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), angle)
            * Translation3::from(-anchor.coords)
    };
    let mid = interpolated_displacement(&a, &about_anchor(0.4), &anchor, 0.5);
    assert_relative_eq!(
        mid.to_homogeneous(),
        about_anchor(0.2).to_homogeneous(),
        epsilon = 1e-14
    );
    // A turn about a hinge 1 m away: the anchor travels on an arc, the viewer on its chord;
    // the sagitta at mid-step is r (1 - cos(step / 2)).
    let hinge = Vector3::new(1.0, 2.0, 2.0);
    let about_hinge = |angle: f64| {
        Translation3::from(hinge)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), angle)
            * Translation3::from(-hinge)
    };
    let step = 0.1;
    let mid = interpolated_displacement(&a, &about_hinge(step), &anchor, 0.5);
    let error = (mid * anchor - about_hinge(step / 2.0) * anchor).norm();
    assert_relative_eq!(error, 1.0 - (step / 2.0).cos(), max_relative = 1e-9);
}

#[test]
fn bad_models_are_refused_with_the_body_named() {
    let mut wrong = model(4);
    wrong.bodies[1].displacements.as_mut().unwrap().pop();
    assert_eq!(
        to_glb(&wrong),
        Err(Error::SampleCount {
            body: "inner.flap".into(),
            given: 3,
            times: 4
        })
    );
    let mut wrong = model(4);
    wrong.times_s[2] = wrong.times_s[1];
    assert!(matches!(to_glb(&wrong), Err(Error::BadTimes { count: 4 })));
    let mut wrong = model(4);
    wrong.bodies[0].mesh.vertices[1].x = f64::NAN;
    assert!(matches!(to_glb(&wrong), Err(Error::BadMesh { body, .. }) if body == "wing"));
    let mut wrong = model(4);
    wrong.bodies[0].material = 7;
    assert!(matches!(to_glb(&wrong), Err(Error::NoSuchMaterial { .. })));
    assert_eq!(
        to_glb(&Model {
            bodies: vec![],
            ..model(2)
        }),
        Err(Error::NoBodies)
    );
}
