//! The per-station report record serialises with the documented keys.

use flapwright_planes::{compute_station, cut_mesh, FlapDeployment, FlapSetting, HingeAxis, StationReport};
use nalgebra::{Point3, Vector3};

use crate::meshes::{circle, prism};

#[test]
fn station_report_has_frame_skew_residual_and_sections() {
    let hinge = HingeAxis::try_new(Point3::new(3.0, 1.0, 0.2), Vector3::new(0.3, 1.0, 0.05)).unwrap();
    let deployment = FlapDeployment {
        hinge,
        base_point_ac: hinge.point_ac,
        overlap_axis_ac: Vector3::z_axis(),
        gap_axis_ac: Vector3::x_axis(),
        settings: vec![
            FlapSetting::stowed(),
            FlapSetting {
                deflection_rad: 0.6,
                ..FlapSetting::stowed()
            },
        ],
    };
    let station = compute_station(
        "outer",
        &deployment,
        hinge.point_at(1.0),
        &[hinge.point_at(1.0) + Vector3::new(0.3, 0.0, 0.0)],
        None,
        0.0,
        11,
    )
    .unwrap();
    let tube = prism(
        &circle(0.02, 32),
        Point3::new(2.8, 0.0, 0.25),
        Vector3::z(),
        Vector3::x(),
        Vector3::y(),
        &[0.0, 5.0],
    );
    let section = cut_mesh(&tube, &station.frame, "torque-tube").unwrap();
    let json = serde_json::to_value(StationReport::new(&station, &[section])).unwrap();
    for key in ["origin_m", "x_axis", "y_axis", "z_axis"] {
        assert_eq!(json["frame"][key].as_array().unwrap().len(), 3, "{key}");
    }
    assert!(json["skew_angle_deg"].as_f64().unwrap() > 0.0);
    assert!(json["out_of_plane_residual_m"].as_f64().unwrap() < 1e-12);
    assert_eq!(json["construction"], "perpendicular-to-axis");
    assert_eq!(json["sections"][0]["part_name"], "torque-tube");
    assert_eq!(json["sections"][0]["polygons"][0][0].as_array().unwrap().len(), 2);
}
