//! Forward kinematics of the written URDF, walked in the test, against the trajectory.

use super::*;

/// Forward kinematics written in the test: walks the tree from the root, composing each
/// joint's origin and motion (revolute: turn about the axis; prismatic: slide along it).
fn forward_kinematics(robot: &Robot, values: &HashMap<&str, f64>) -> HashMap<String, Isometry3<f64>> {
    let children: Vec<&str> = robot.joints.iter().map(|j| j.child.link.as_str()).collect();
    let root = robot
        .links
        .iter()
        .find(|l| !children.contains(&l.name.as_str()))
        .expect("a root link");
    let mut poses = HashMap::from([(root.name.clone(), Isometry3::identity())]);
    let mut changed = true;
    while changed {
        changed = false;
        for joint in &robot.joints {
            let Some(parent) = poses.get(&joint.parent.link).copied() else {
                continue;
            };
            if poses.contains_key(&joint.child.link) {
                continue;
            }
            let axis = Vector3::from(joint.axis.xyz.0);
            let q = values.get(joint.name.as_str()).copied().unwrap_or(0.0);
            let motion = match joint.joint_type {
                JointType::Revolute | JointType::Continuous => Isometry3::rotation(axis * q),
                JointType::Prismatic => Isometry3::translation(axis.x * q, axis.y * q, axis.z * q),
                JointType::Fixed => Isometry3::identity(),
                ref other => panic!("unexpected joint type {other:?}"),
            };
            poses.insert(joint.child.link.clone(), parent * pose_isometry(&joint.origin) * motion);
            changed = true;
        }
    }
    assert_eq!(poses.len(), robot.links.len(), "every link reached");
    poses
}

/// Largest key-point error (m) of the URDF read back from XML, over all samples.
fn key_point_error(robot: &Robot, trajectory: &Trajectory) -> f64 {
    let mut worst = 0.0_f64;
    for sample in &trajectory.samples {
        let values: HashMap<&str, f64> = trajectory
            .joint_names
            .iter()
            .map(String::as_str)
            .zip(sample.joint_values.iter().copied())
            .collect();
        let poses = forward_kinematics(robot, &values);
        for key in &trajectory.key_points {
            let computed = poses[&key.link] * Point3::from(key.position_link_m);
            let expected = Point3::from(sample.key_points_ac_m[&key.name]);
            worst = worst.max((computed - expected).norm());
        }
    }
    worst
}

#[test]
fn forward_kinematics_of_the_file_reproduces_every_key_point() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let model = build_robot("right_wing", &base_link(), &stations).unwrap();
    let trajectory = trajectory(&stations, SAMPLES).unwrap();
    assert_eq!(trajectory.samples.len(), SAMPLES);
    // Every named point on every link that carries it: A0 and B0 on the station, A0 also on
    // the flap (it turns about it), B0 and B on the screw, A on the nut and the flap, D F G
    // on the flap, and A D F G on the owning station's flap link.
    let names: Vec<&str> = trajectory.key_points.iter().map(|k| k.name.as_str()).collect();
    let inner: Vec<&str> = names.iter().copied().filter(|n| n.starts_with("inner.")).collect();
    assert_eq!(
        inner,
        [
            "inner.A0",
            "inner.flap.A0",
            "inner.B0",
            "inner.screw.B0",
            "inner.nut.A",
            "inner.flap.A",
            "inner.screw.B",
            "inner.flap.D",
            "inner.flap.F",
            "inner.flap.G"
        ]
    );
    let on_flap_link: Vec<&str> = names.iter().copied().filter(|n| n.starts_with("flap.")).collect();
    assert_eq!(on_flap_link, ["flap.A", "flap.D", "flap.F", "flap.G"]);
    assert_eq!(names.len(), 2 * inner.len() + on_flap_link.len());
    let robot = read_back(&model);
    let error = key_point_error(&robot, &trajectory);
    assert!(error <= KEY_POINT_TOLERANCE_M, "key point error {error} m");
    // The check is sharp: a hinge value 1e-4 rad off moves the flap points by ~3e-5 m.
    let mut wrong = trajectory.clone();
    for sample in &mut wrong.samples {
        sample.joint_values[0] += 1e-4;
    }
    assert!(key_point_error(&robot, &wrong) > 10.0 * KEY_POINT_TOLERANCE_M);
    // In fact it is rounding: 1e-12 m holds with a wide margin.
    assert!(error <= 1e-12, "key point error {error} m");
}

#[test]
fn placements_at_gimbal_lock_survive_the_file() {
    let track = thesis_track();
    for pitch in [FRAC_PI_2, -FRAC_PI_2, FRAC_PI_2 - 1e-7] {
        let rotation = UnitQuaternion::from_euler_angles(0.4, pitch, -2.1);
        let station = StationMechanism3d {
            name: "only".to_owned(),
            aircraft_from_station: Isometry3::from_parts(Translation3::new(1.0, -2.0, 0.5), rotation),
            mechanism: &track,
            flap_name: "flap".to_owned(),
            owns_flap: true,
            flap_mesh: None,
            aft_element: None,
            flap_inertia: None,
            bodies: Vec::new(),
            actuator_peak_load: None,
        };
        let stations = [station];
        let model = build_robot("gimbal", &base_link(), &stations).unwrap();
        let error = key_point_error(&read_back(&model), &trajectory(&stations, 9).unwrap());
        assert!(error <= 1e-12, "pitch {pitch}: key point error {error} m");
    }
}

#[test]
fn meshes_appear_where_they_are_given_at_stowed() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let robot = read_back(&build_robot("right_wing", &base_link(), &stations).unwrap());
    let trajectory = trajectory(&stations, 3).unwrap();
    let stowed = &trajectory.samples[0];
    let values = trajectory
        .joint_names
        .iter()
        .map(String::as_str)
        .zip(stowed.joint_values.iter().copied())
        .collect();
    let poses = forward_kinematics(&robot, &values);
    let vertex_ac = Point3::new(3.05, 1.62, 0.37);
    for link in &robot.links {
        for visual in &link.visual {
            let shown = poses[&link.name] * pose_isometry(&visual.origin) * vertex_ac;
            assert_relative_eq!(shown, vertex_ac, epsilon = 1e-12);
        }
    }
    assert_eq!(robot.links.iter().map(|l| l.visual.len()).sum::<usize>(), 3);
}

#[test]
fn joint_values_start_stowed_and_stay_within_limits() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let stations = two_stations(&inner, &outer);
    let robot = build_robot("right_wing", &base_link(), &stations).unwrap().robot;
    let trajectory = trajectory(&stations, SAMPLES).unwrap();
    let synthesis = inner.synthesis();
    // Inner station: screw about B0 (rad), nut along the screw (m), flap about A (rad).
    let first = &trajectory.samples[0].joint_values;
    assert!(first[..3].iter().all(|v| v.abs() <= 1e-15), "stowed: {first:?}");
    let last = &trajectory.samples[SAMPLES - 1].joint_values;
    assert_relative_eq!(last[1], synthesis.stroke_m, max_relative = 1e-12);
    // The flap turns by the screw's turn plus its own about A: 35 deg in all.
    assert_relative_eq!(last[0] + last[2], 35f64.to_radians(), max_relative = 1e-12);
    // Collinearity (thesis step 8): the screw points the same way at both stroke ends.
    assert!(last[0].abs() < 1e-12, "{}", last[0]);
    let limit = |name: &str| {
        let joint = robot.joints.iter().find(|j| j.name == name).unwrap();
        (joint.limit.lower, joint.limit.upper)
    };
    let mut screw_range = (0.0_f64, 0.0_f64);
    for sample in &trajectory.samples {
        for (name, value) in trajectory.joint_names.iter().zip(&sample.joint_values) {
            let (lower, upper) = limit(name);
            assert!(
                *value >= lower - 1e-12 && *value <= upper + 1e-12,
                "{name} = {value} outside [{lower}, {upper}]"
            );
        }
        screw_range.0 = screw_range.0.min(sample.joint_values[0]);
        screw_range.1 = screw_range.1.max(sample.joint_values[0]);
    }
    // The screw's extreme is where B0A is tangent to A's circle about A0, s34 =
    // sqrt(a1^2 - a2^2): its angle there bounds the sampled range, and the limit (129
    // samples widened by half a step) holds it within 1 %.
    let (a1, a2) = (inner.spec().base_distance_m, inner.spec().crank_length_m);
    let tangent = ((a1 - a2) * (a1 + a2)).sqrt();
    let (_, slider_tangent) = inner.linkage().angles(tangent).unwrap();
    let analytic = slider_tangent - synthesis.end_slider_angle_rad;
    let (lower, upper) = limit("inner_B0");
    let limit_extreme = if analytic > 0.0 { upper } else { lower };
    let sampled = if analytic > 0.0 { screw_range.1 } else { screw_range.0 };
    assert!(sampled.abs() <= analytic.abs() + 1e-12, "{sampled} vs {analytic}");
    // The limit holds the true extreme, widened by at most one sample step of the screw
    // (about 1.1 mm of stroke: 3 % of this extreme).
    assert!(limit_extreme.abs() >= analytic.abs(), "{limit_extreme} vs {analytic}");
    assert_relative_eq!(limit_extreme, analytic, max_relative = 5e-2);
}

#[test]
fn body_inertia_lands_on_its_link_at_stowed_whatever_the_link_frame() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let mut stations = two_stations(&inner, &outer);
    // A made-up, anisotropic inertia for every body of the inner station, given in the
    // aircraft frame: the file must carry it to each body's link frame.
    let tensor = Matrix3::new(3.0, 0.4, -0.2, 0.4, 2.0, 0.1, -0.2, 0.1, 1.5) * 1e-3;
    let centre = Point3::new(3.1, 1.55, 0.35);
    let inertia = RigidInertia {
        mass_kg: 1.25,
        centre_of_mass_ac_m: centre,
        inertia_ac_kg_m2: tensor,
    };
    stations[0].bodies = (0..flapwright_mechanism::FlapMechanism::bodies(&inner).len())
        .map(|body| BodyGeometry {
            body,
            meshes: vec![MeshRef {
                name: format!("solid{body}"),
                filename: format!("inner.solid{body}.stl"),
            }],
            inertia: Some(inertia),
        })
        .collect();
    stations[0].flap_inertia = Some(inertia);
    let robot = read_back(&build_robot("right_wing", &base_link(), &stations).unwrap());
    let poses = forward_kinematics(&robot, &HashMap::new());
    let dressed: Vec<_> = robot.links.iter().filter(|l| l.inertial.mass.value > 0.0).collect();
    assert_eq!(
        dressed.len(),
        flapwright_mechanism::FlapMechanism::bodies(&inner).len() + 1
    );
    for link in dressed {
        assert_eq!(link.inertial.mass.value, 1.25);
        let frame = poses[&link.name] * pose_isometry(&link.inertial.origin);
        assert_relative_eq!(frame.translation.vector, centre.coords, epsilon = 1e-12);
        let i = &link.inertial.inertia;
        let in_link = Matrix3::new(i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz);
        let turn = frame.rotation.to_rotation_matrix();
        let back = turn.matrix() * in_link * turn.matrix().transpose();
        assert_relative_eq!(back, tensor, epsilon = 1e-15);
        assert_eq!(link.collision.len(), link.visual.len());
    }
}

#[test]
fn combined_inertia_is_the_parallel_axis_sum() {
    // Two 1 kg points 2 m apart on x: 2 kg at the middle, I_yy = I_zz = 2 kg m^2.
    let point = |x: f64| RigidInertia {
        mass_kg: 1.0,
        centre_of_mass_ac_m: Point3::new(x, 0.0, 0.0),
        inertia_ac_kg_m2: Matrix3::zeros(),
    };
    let both = RigidInertia::combined(&[point(1.0), point(3.0)]).unwrap();
    assert_eq!(both.mass_kg, 2.0);
    assert_relative_eq!(both.centre_of_mass_ac_m, Point3::new(2.0, 0.0, 0.0));
    assert_relative_eq!(
        both.inertia_ac_kg_m2,
        Matrix3::from_diagonal(&Vector3::new(0.0, 2.0, 2.0)),
        epsilon = 1e-15
    );
    assert!(RigidInertia::combined(&[]).is_none());
}
