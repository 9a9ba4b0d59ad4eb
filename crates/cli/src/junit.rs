//! JUnit XML for CI: one test case per station and part pair of the interference check.

use flapwright_interference::{ContactResult, InterferenceReport, PairClearance};
use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};

/// One line on a failing pair: the parts, the clearance or how deep they overlap, the
/// flap rotation and where (aircraft frame).
pub fn describe_failure(c: &PairClearance, required_clearance_m: f64) -> String {
    let [ax, ay, az] = c.point_a_ac;
    let [bx, by, bz] = c.point_b_ac;
    let at = c.at_parameter.to_degrees();
    if c.min_clearance_m <= 0.0 {
        format!(
            "{} and {} overlap (clearance 0, required {:.2} mm): deepest {:.1} mm (surface sampled every {:.1} mm) at flap rotation {at:.2} deg, from ({ax:.4}, {ay:.4}, {az:.4}) on {} to ({bx:.4}, {by:.4}, {bz:.4}) on {} (aircraft frame, m)",
            c.part_a,
            c.part_b,
            required_clearance_m * 1e3,
            c.penetration_m * 1e3,
            c.penetration_resolution_m * 1e3,
            c.part_a,
            c.part_b,
        )
    } else {
        format!(
            "{} and {}: clearance {:.2} mm (certified >= {:.2} mm) is below the required {:.2} mm at flap rotation {at:.2} deg; closest points (aircraft frame, m) ({ax:.4}, {ay:.4}, {az:.4}) and ({bx:.4}, {by:.4}, {bz:.4})",
            c.part_a,
            c.part_b,
            c.min_clearance_m * 1e3,
            (c.min_clearance_m - c.residual_bound_m) * 1e3,
            required_clearance_m * 1e3,
        )
    }
}

/// One line on a joint that comes apart.
pub fn describe_joint_failure(c: &ContactResult, joint_play_m: f64) -> String {
    let (d, s) = (&c.declared, &c.separation);
    format!(
        "{} and {} (joint {}) come {:.2} mm apart (certified <= {:.2} mm), more than the joint's play {:.2} mm, at flap rotation {:.2} deg",
        d.part_a,
        d.part_b,
        d.joint,
        s.max_separation_m * 1e3,
        s.upper_bound_m * 1e3,
        joint_play_m * 1e3,
        s.at_parameter.to_degrees(),
    )
}

/// The JUnit document of an interference report.
pub fn interference_junit(scene_name: &str, report: &InterferenceReport) -> anyhow::Result<String> {
    let mut suite = TestSuite::new(format!("flapwright interference: {scene_name}"));
    for pair in &report.pairs {
        let c = &pair.clearance;
        let name = format!("{} vs {}", c.part_a, c.part_b);
        let status = if pair.passes {
            TestCaseStatus::success()
        } else {
            let mut status = TestCaseStatus::non_success(NonSuccessKind::Failure);
            status.set_message(describe_failure(c, report.required_clearance_m));
            status.set_type("interference");
            status
        };
        let mut case = TestCase::new(name, status);
        case.set_classname(pair.station.clone().unwrap_or_else(|| "flap".into()));
        suite.add_test_case(case);
    }
    for contact in &report.declared_contacts {
        let status = if contact.passes {
            TestCaseStatus::success()
        } else {
            let mut status = TestCaseStatus::non_success(NonSuccessKind::Failure);
            status.set_message(describe_joint_failure(contact, report.joint_play_m));
            status.set_type("joint");
            status
        };
        let d = &contact.declared;
        let mut case = TestCase::new(format!("{} joined to {}", d.part_a, d.part_b), status);
        case.set_classname(d.station.clone());
        suite.add_test_case(case);
    }
    let mut junit = Report::new("flapwright check");
    junit.add_test_suite(suite);
    Ok(junit.to_string()?)
}
