//! JUnit XML for CI: one test case per station and part pair of the interference check.

use flapwright_interference::{ContactResult, InterferenceReport, PairClearance};
use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};

/// One line on a failing pair: the parts, the clearance or how deep they overlap, the
/// place in the deployment (% of the actuator travel) and where (aircraft frame).
pub fn describe_failure(c: &PairClearance, required_clearance_m: f64) -> String {
    let [ax, ay, az] = c.point_a_ac;
    let [bx, by, bz] = c.point_b_ac;
    let at = 100.0 * c.at_parameter;
    if c.min_clearance_m <= 0.0 {
        format!(
            "{} and {} overlap (clearance 0, required {:.2} mm): deepest {:.1} mm (surface sampled every {:.1} mm) at {at:.1} % of the deployment, from ({ax:.4}, {ay:.4}, {az:.4}) on {} to ({bx:.4}, {by:.4}, {bz:.4}) on {} (aircraft frame, m)",
            c.part_a,
            c.part_b,
            required_clearance_m * 1e3,
            c.penetration_m * 1e3,
            c.penetration_resolution_m * 1e3,
            c.part_a,
            c.part_b,
        )
    } else if c.min_clearance_m < required_clearance_m {
        format!(
            "{} and {}: clearance {:.2} mm (certified >= {:.2} mm) is below the required {:.2} mm at {at:.1} % of the deployment; closest points (aircraft frame, m) ({ax:.4}, {ay:.4}, {az:.4}) and ({bx:.4}, {by:.4}, {bz:.4})",
            c.part_a,
            c.part_b,
            c.min_clearance_m * 1e3,
            (c.min_clearance_m - c.residual_bound_m) * 1e3,
            required_clearance_m * 1e3,
        )
    } else {
        // The samples clear the requirement but the bound between them does not.
        format!(
            "{} and {}: smallest sampled clearance {:.2} mm (at {at:.1} % of the deployment) is not certified: between samples it may be as low as {:.2} mm, below the required {:.2} mm, after {} evaluations; lower interference.tolerance_m or raise interference.max_evaluations",
            c.part_a,
            c.part_b,
            c.min_clearance_m * 1e3,
            (c.min_clearance_m - c.residual_bound_m) * 1e3,
            required_clearance_m * 1e3,
            c.evaluations,
        )
    }
}

/// One line on a joint that comes apart.
pub fn describe_joint_failure(c: &ContactResult, joint_play_m: f64) -> String {
    let (d, s) = (&c.declared, &c.separation);
    format!(
        "{} and {} (joint {}) come {:.2} mm apart (certified <= {:.2} mm), more than the joint's play {:.2} mm, at {:.1} % of the deployment",
        d.part_a,
        d.part_b,
        d.joint,
        s.max_separation_m * 1e3,
        s.upper_bound_m * 1e3,
        joint_play_m * 1e3,
        100.0 * s.at_parameter,
    )
}

/// What became of one JUnit test case.
enum Outcome {
    Passed,
    /// Failed: the kind of failure and its text.
    Failed(&'static str, String),
    /// Not checked, and why.
    Skipped(String),
}

/// One JUnit test case, with the time its check took (s; None: nothing was swept).
fn test_case(name: String, class: String, outcome: Outcome, time_s: Option<f64>) -> TestCase {
    let status = match outcome {
        Outcome::Passed => TestCaseStatus::success(),
        Outcome::Failed(kind, message) => {
            let mut status = TestCaseStatus::non_success(NonSuccessKind::Failure);
            status.set_message(message);
            status.set_type(kind);
            status
        }
        Outcome::Skipped(reason) => {
            let mut status = TestCaseStatus::skipped();
            status.set_message(reason);
            status
        }
    };
    let mut case = TestCase::new(name, status);
    case.set_classname(class);
    if let Some(seconds) = time_s.filter(|s| s.is_finite() && *s >= 0.0) {
        case.set_time(std::time::Duration::from_secs_f64(seconds));
    }
    case
}

/// The JUnit document of an interference report.
pub fn interference_junit(scene_name: &str, report: &InterferenceReport) -> crate::Result<String> {
    let mut suite = TestSuite::new(format!("flapwright interference: {scene_name}"));
    for pair in &report.pairs {
        let c = &pair.clearance;
        let outcome = match pair.passes {
            true => Outcome::Passed,
            false => Outcome::Failed("interference", describe_failure(c, pair.required_clearance_m)),
        };
        suite.add_test_case(test_case(
            format!("{} vs {}", c.part_a, c.part_b),
            pair.station.clone().unwrap_or_else(|| "flap".into()),
            outcome,
            Some(pair.sweep_time_s),
        ));
    }
    // Pairs certified by their swept boxes alone pass, like swept pairs that clear.
    for apart in &report.certified_apart {
        suite.add_test_case(test_case(
            format!("{} vs {}", apart.part_a, apart.part_b),
            apart.station.clone().unwrap_or_else(|| "flap".into()),
            Outcome::Passed,
            None,
        ));
    }
    for contact in &report.declared_contacts {
        let d = &contact.declared;
        let outcome = match contact.passes {
            true => Outcome::Passed,
            false => Outcome::Failed("joint", describe_joint_failure(contact, report.joint_play_m)),
        };
        suite.add_test_case(test_case(
            format!("{} joined to {}", d.part_a, d.part_b),
            d.station.clone(),
            outcome,
            Some(contact.sweep_time_s),
        ));
    }
    // Pairs the check leaves out are skipped cases, so CI counts them (`check --strict`
    // fails on them).
    for skipped in &report.unchecked_pairs {
        suite.add_test_case(test_case(
            format!("{} vs {}", skipped.part_a, skipped.part_b),
            skipped.station.clone(),
            Outcome::Skipped(skipped.reason.clone()),
            None,
        ));
    }
    let mut junit = Report::new("flapwright check");
    junit.add_test_suite(suite);
    Ok(junit.to_string()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(min_clearance_m: f64, residual_bound_m: f64, penetration_m: f64) -> PairClearance {
        PairClearance {
            part_a: "inner.screw".into(),
            part_b: "torque-tube".into(),
            min_clearance_m,
            at_parameter: 0.1,
            point_a_ac: [0.0; 3],
            point_b_ac: [0.0; 3],
            penetration_m,
            penetration_resolution_m: 0.001,
            residual_bound_m,
            evaluations: 9,
            trace: Vec::new(),
        }
    }

    #[test]
    fn each_way_of_failing_says_what_failed() {
        let overlap = describe_failure(&pair(0.0, 0.0, 0.0194), 0.003);
        assert!(
            overlap.contains("overlap") && overlap.contains("deepest 19.4 mm"),
            "{overlap}"
        );
        let close = describe_failure(&pair(0.002, 0.0005, 0.0), 0.003);
        assert!(
            close.contains("clearance 2.00 mm") && close.contains("below the required 3.00 mm"),
            "{close}"
        );
        // Sampled clearance above the requirement, certified bound below it.
        let uncertain = describe_failure(&pair(0.015, 0.018, 0.0), 0.003);
        assert!(
            uncertain.contains("not certified") && uncertain.contains("-3.00 mm"),
            "{uncertain}"
        );
        assert!(
            uncertain.contains("interference.tolerance_m"),
            "says what to change: {uncertain}"
        );
        assert!(!uncertain.contains("15.00 mm (certified"), "{uncertain}");
    }
}
