//! The strict URDF rule check on good and broken robots.

use super::*;

#[test]
fn built_and_read_back_robots_pass_the_rule_check() {
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let model = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer)).unwrap();
    assert_eq!(check_rules(&model.robot), Vec::<String>::new());
    assert_eq!(check_rules(&read_back(&model)), Vec::<String>::new());
}

#[test]
fn rule_check_catches_broken_robots() {
    /// The inner station's screw pivot, a revolute joint.
    fn revolute(r: &mut Robot) -> &mut urdf_rs::Joint {
        r.joints.iter_mut().find(|j| j.name == "inner_B0").expect("inner_B0")
    }
    let (inner, outer) = (thesis_track(), scaled_track(0.8));
    let good = build_robot("right_wing", &base_link(), &two_stations(&inner, &outer))
        .unwrap()
        .robot;
    type Breaker = fn(&mut Robot);
    let cases: [(&str, Breaker); 9] = [
        ("link name `inner_screw` is not unique", |r| {
            r.links[2].name = "inner_screw".to_owned()
        }),
        ("joint name `inner_B0` is not unique", |r| {
            r.joints[2].name = "inner_B0".to_owned()
        }),
        ("parent link `nowhere` does not exist", |r| {
            r.joints[1].parent.link = "nowhere".to_owned()
        }),
        ("expected exactly one root link, found 2", |r| {
            r.links.push(r.links[0].clone());
            r.links.last_mut().unwrap().name = "loose".to_owned();
        }),
        ("is the child of two joints", |r| {
            let mut extra = r.joints[1].clone();
            extra.name = "extra".to_owned();
            extra.parent.link = "outer_station".to_owned();
            r.joints.push(extra);
        }),
        ("has length", |r| revolute(r).axis.xyz.0 = [0.0, 0.0, 1.1]),
        ("lower limit", |r| {
            let limit = &mut revolute(r).limit;
            std::mem::swap(&mut limit.lower, &mut limit.upper);
        }),
        ("not reachable from root", |r| {
            // inner_station's mount now hangs off its own screw: a cycle.
            r.joints[0].parent.link = "inner_screw".to_owned();
            r.links.push(r.links[0].clone());
            r.links.last_mut().unwrap().name = "spare".to_owned();
            let mut spare = r.joints[0].clone();
            spare.name = "spare_mount".to_owned();
            spare.parent.link = "wing".to_owned();
            spare.child.link = "spare".to_owned();
            r.joints.push(spare);
        }),
        ("is not relative to the URDF", |r| {
            if let urdf_rs::Geometry::Mesh { filename, .. } = &mut r.links[0].visual[0].geometry {
                *filename = "/abs/skin.stl".to_owned();
            }
        }),
    ];
    for (expected, breaker) in cases {
        let mut broken = good.clone();
        breaker(&mut broken);
        let violations = check_rules(&broken);
        assert!(
            violations.iter().any(|v| v.contains(expected)),
            "expected a violation containing `{expected}`, got {violations:?}"
        );
    }
}
