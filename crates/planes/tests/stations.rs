//! Station construction: thesis planes, pure-rotation residual, conical skew angles.

use approx::assert_relative_eq;
use flapwright_planes::{
    compute_station, dihedral_up_vector_ac, skew_angle_rad, thesis_stations, FlapDeployment, FlapSetting, HingeAxis,
    Plane, PlaneConstruction,
};
use nalgebra::{Point3, Unit, Vector3};

/// Hinge line of a swept, dihedralled wing: sweep 25 deg, dihedral 5 deg.
fn swept_hinge() -> HingeAxis {
    let (sweep, dihedral) = (25f64.to_radians(), 5f64.to_radians());
    let direction = Vector3::new(sweep.sin(), sweep.cos() * dihedral.cos(), sweep.cos() * dihedral.sin());
    HingeAxis::try_new(Point3::new(3.1, 1.2, 0.35), direction).unwrap()
}

fn deployment(settings: Vec<FlapSetting>) -> FlapDeployment {
    let hinge = swept_hinge();
    FlapDeployment {
        base_point_ac: hinge.point_at(0.4),
        hinge,
        overlap_axis_ac: dihedral_up_vector_ac(5f64.to_radians()),
        gap_axis_ac: Vector3::x_axis(),
        settings,
    }
}

/// Flap points off the hinge line (aft attachments, trailing edge), aircraft frame.
fn flap_points() -> Vec<Point3<f64>> {
    let hinge = swept_hinge();
    vec![
        hinge.point_at(0.0),
        hinge.point_at(0.5) + Vector3::new(0.35, 0.0, 0.04),
        hinge.point_at(1.5) + Vector3::new(0.55, -0.02, -0.08),
        hinge.point_at(2.5) + Vector3::new(0.25, 0.1, 0.3),
    ]
}

fn setting(deflection_deg: f64) -> FlapSetting {
    FlapSetting {
        deflection_rad: deflection_deg.to_radians(),
        ..FlapSetting::stowed()
    }
}

#[test]
fn pure_rotation_residual_is_below_1e_12_m() {
    let deployment = deployment(vec![FlapSetting::stowed(), setting(15.0), setting(40.0)]);
    let origin = deployment.hinge.point_at(1.0);
    let station = compute_station(
        "outer",
        &deployment,
        origin,
        &flap_points(),
        None,
        5f64.to_radians(),
        201,
    )
    .unwrap();
    assert_eq!(station.construction, PlaneConstruction::PerpendicularToAxis);
    for residual in &station.attachment_residuals_m {
        assert!(*residual < 1e-12, "residual {residual} m");
    }
    // The plane is perpendicular to the hinge: its skew is the hinge sweep seen in planform.
    let hinge = deployment.hinge.direction_ac;
    assert_relative_eq!(station.skew_angle_rad, hinge.x.atan2(hinge.y), epsilon = 1e-14);
}

/// Independent construction: Rodrigues rotation of points written out by hand.
fn rotate_about(point: Point3<f64>, centre: Point3<f64>, axis: Vector3<f64>, angle: f64) -> Point3<f64> {
    let k = axis / axis.norm();
    let v = point - centre;
    centre + v * angle.cos() + k.cross(&v) * angle.sin() + k * k.dot(&v) * (1.0 - angle.cos())
}

#[test]
fn conical_skew_angle_matches_independent_construction() {
    let landing = FlapSetting {
        deflection_rad: 35f64.to_radians(),
        overlap_rotation_rad: 1.5f64.to_radians(),
        gap_rotation_rad: -0.8f64.to_radians(),
        base_translation_ac: Vector3::new(0.12, 0.0, -0.03),
    };
    let take_off = FlapSetting {
        deflection_rad: 15f64.to_radians(),
        overlap_rotation_rad: 0.6f64.to_radians(),
        gap_rotation_rad: -0.3f64.to_radians(),
        base_translation_ac: Vector3::new(0.07, 0.0, -0.01),
    };
    let deployment = deployment(vec![FlapSetting::stowed(), take_off, landing]);
    assert_eq!(
        PlaneConstruction::default_for(&deployment),
        PlaneConstruction::SkewCorrected
    );
    let dihedral = 5f64.to_radians();
    for distance_m in [0.0, 1.0, 2.5] {
        let forward_attachment = deployment.hinge.point_at(distance_m);
        let station =
            compute_station("s", &deployment, forward_attachment, &flap_points(), None, dihedral, 51).unwrap();

        // Rotate the hinge line (two points on it) by δ, θ_o, θ_g about the base point, translate.
        let base = deployment.base_point_ac;
        let move_point = |p: Point3<f64>| {
            let p = rotate_about(
                p,
                base,
                deployment.hinge.direction_ac.into_inner(),
                landing.deflection_rad,
            );
            let p = rotate_about(
                p,
                base,
                Vector3::new(0.0, -dihedral.sin(), dihedral.cos()),
                landing.overlap_rotation_rad,
            );
            let p = rotate_about(p, base, Vector3::x(), landing.gap_rotation_rad);
            p + landing.base_translation_ac
        };
        let hinge_start = move_point(deployment.hinge.point_at(0.0));
        let hinge_end = move_point(deployment.hinge.point_at(3.0));
        // The deployed attachment is where the deployed hinge line is at the same arc length.
        let deployed = hinge_start + (hinge_end - hinge_start) * (distance_m / 3.0);
        let skew = deployed - forward_attachment;
        // Measure the plane spanned by the skew direction and the wing-up vector.
        let wing_up = Vector3::new(0.0, -dihedral.sin(), dihedral.cos());
        let normal = skew.cross(&wing_up);
        let normal = if normal.y < 0.0 { -normal } else { normal };
        let expected = (normal.x / normal.y).atan();
        assert_relative_eq!(station.skew_angle_rad, expected, epsilon = 1e-9);
        // The plane contains the skew direction and the wing-up vector.
        let z = station.frame.z_axis_ac();
        assert!(z.dot(&skew.normalize()).abs() < 1e-12);
        assert!(z.dot(&wing_up).abs() < 1e-12);
        // Conical motion: points away from the base leave the plane.
        assert!(station.max_out_of_plane_residual_m() > 1e-4);
    }
}

#[test]
fn skew_angle_of_a_streamwise_plane_is_zero() {
    assert_eq!(skew_angle_rad(&Vector3::y_axis()), 0.0);
    assert_relative_eq!(
        skew_angle_rad(&Unit::new_normalize(Vector3::new(1.0, 1.0, 0.3))),
        std::f64::consts::FRAC_PI_4,
        epsilon = 1e-15
    );
}

#[test]
fn thesis_planes_follow_steps_1_to_3() {
    let axis = swept_hinge();
    // Inner flap side plane: streamwise-ish, not perpendicular to the axis (step 1).
    let inner_side = Plane::try_new(Point3::new(3.0, 1.5, 0.0), Vector3::new(0.05, 1.0, 0.1)).unwrap();
    let (d1, d2) = (0.25, 1.6);
    let stations = thesis_stations(&axis, &inner_side, d1, &[0.0, -d2]).unwrap();
    // P is on the plane and on the axis.
    assert!(inner_side.signed_distance_m(&stations.p_ac).abs() < 1e-14);
    let from_axis = stations.p_ac - axis.point_ac;
    assert!(from_axis.cross(&axis.direction_ac).norm() < 1e-14);
    // A0 = P + d1 along the axis (outboard).
    assert_relative_eq!((stations.a0_ac - stations.p_ac).norm(), d1, epsilon = 1e-14);
    assert!((stations.a0_ac - stations.p_ac).dot(&axis.direction_ac) > 0.0);
    // Outer plane through A0, perpendicular to the axis; inner plane d2 inboard.
    let (outer, inner) = (&stations.frames[0], &stations.frames[1]);
    assert_relative_eq!(outer.origin_ac(), stations.a0_ac, epsilon = 1e-14);
    assert_relative_eq!(
        outer.z_axis_ac().into_inner(),
        axis.direction_ac.into_inner(),
        epsilon = 1e-15
    );
    assert_relative_eq!(outer.signed_distance_m(&inner.origin_ac()), -d2, epsilon = 1e-14);
}

#[test]
fn axis_parallel_to_the_side_plane_is_an_error() {
    let axis = HingeAxis::try_new(Point3::origin(), Vector3::y()).unwrap();
    let plane = Plane::try_new(Point3::new(1.0, 0.0, 0.0), Vector3::x()).unwrap();
    assert!(thesis_stations(&axis, &plane, 0.1, &[0.0]).is_err());
}

#[test]
fn non_moving_attachment_has_no_skew_direction() {
    let deployment = deployment(vec![FlapSetting::stowed(), setting(30.0)]);
    let err = compute_station(
        "s",
        &deployment,
        deployment.hinge.point_at(1.0),
        &[],
        Some(PlaneConstruction::SkewCorrected),
        0.0,
        5,
    );
    assert!(err.is_err());
}

#[test]
fn conical_setting_puts_the_hinge_line_through_the_shifted_points() {
    let deployment = deployment(vec![FlapSetting::stowed()]);
    let (q_in, q_out) = (deployment.hinge.point_at(0.0), deployment.hinge.point_at(3.0));
    let inboard = flapwright_planes::SectionShift {
        hinge_point_ac: q_in,
        aft_m: 0.20,
        down_m: 0.03,
    };
    let outboard = flapwright_planes::SectionShift {
        hinge_point_ac: q_out,
        aft_m: 0.12,
        down_m: 0.05,
    };
    let setting =
        flapwright_planes::setting_from_section_shifts(&deployment, 30f64.to_radians(), &inboard, &outboard).unwrap();
    assert!(setting.overlap_rotation_rad.abs() > 1e-3 && setting.gap_rotation_rad.abs() > 1e-3);
    let pose = deployment.pose_ac(&setting);
    let up = deployment.overlap_axis_ac.into_inner();
    let target_in = q_in + Vector3::x() * 0.20 - up * 0.03;
    let target_out = q_out + Vector3::x() * 0.12 - up * 0.05;
    // The deployed hinge line (image of the stowed one) runs through both targets.
    let (p0, p1) = (pose.transform_point(&q_in), pose.transform_point(&q_out));
    let direction = (p1 - p0).normalize();
    for target in [target_in, target_out] {
        assert!((target - p0).cross(&direction).norm() < 1e-12);
    }
    // Equal shifts: no conical rotation.
    let outboard_equal = flapwright_planes::SectionShift {
        aft_m: 0.20,
        down_m: 0.03,
        ..outboard
    };
    let plain = flapwright_planes::setting_from_section_shifts(&deployment, 0.5, &inboard, &outboard_equal).unwrap();
    assert!(plain.overlap_rotation_rad.abs() < 1e-14 && plain.gap_rotation_rad.abs() < 1e-14);
}
