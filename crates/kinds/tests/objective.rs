//! The synthesis objective (`flapwright_mechanism::shared::objective`): its load by virtual
//! work against every kind's statics, and the link-track's search weighed by it.

use flapwright_kinds::link_track::{LinkTrack, LinkTrackSpec};
use flapwright_mechanism::seam::FlapMechanism;
use flapwright_mechanism::shared::objective::{LoadWeighing, DEFAULT_LOAD_WEIGHT};
use flapwright_mechanism::{FlapNormalForce, LoadCase};
use nalgebra::{Point2, Vector2};

use crate::synthesised::model_section::link_track_spec;
use crate::synthesised::{flight_load, landing_load, synthesised_mechanisms};

/// The search objective's load (`shared::objective`: minus the flap wrench's power per unit
/// input, from central differences of the flap's poses alone) equals each kind's own
/// statics at every sampled input: the searches weigh the load the report then prints.
#[test]
fn the_objectives_load_by_virtual_work_equals_each_kinds_statics() {
    let kinds = synthesised_mechanisms();
    let flight = flight_load();
    for mechanism in &kinds {
        let range = mechanism.input_range();
        let weighing = LoadWeighing {
            loads: vec![flight.clone()],
            flap_mass: mechanism.flap_mass().unwrap(),
            weight: DEFAULT_LOAD_WEIGHT,
            load_cap: None,
            mass: None,
        };
        // Inputs measured from stowed, as the objective's body rotations are.
        let travel = range.travel();
        let steps: Vec<f64> = (1..20).map(|k| travel * k as f64 / 20.0).collect();
        let flap_at = |step: f64| {
            mechanism
                .pose(range.at_fraction(step / travel))
                .ok()
                .map(|pose| pose.flap)
        };
        let torques = weighing.body_torques(&steps, travel, &flap_at);
        // The hooked-track's flap starts turning where its roller leaves the straight
        // lead-in for the hook (`hooked_track/rail.rs`, `lead_m` of stroke from stowed): the
        // flap's rate jumps there, and a central difference straddling the join measures
        // neither side's load (3.5e-4 off when a sample sat on it), so samples within ten
        // difference steps of it are left out; the others agree as every kind's do.
        let join = mechanism.details()["synthesis"]["lead_m"].as_f64();
        for (step, torque) in steps.iter().zip(torques) {
            if join.is_some_and(|lead| (step - lead).abs() < 10.0 * 1e-4 * travel.abs()) {
                continue;
            }
            let statics = mechanism
                .kinetostatics(range.at_fraction(step / travel), &flight)
                .unwrap();
            let torque = torque.unwrap();
            let relative = (torque - statics.actuator_load.abs()).abs() / statics.actuator_load.abs();
            let tolerance = 1e-6;
            assert!(
                relative < tolerance,
                "{}: {torque} against {}",
                mechanism.kind(),
                statics.actuator_load
            );
        }
    }
}

/// Weighed by the load, the link-track's search may give up a little depth for a link that
/// turns further, so its actuator carries less (the transport's `ob-inner` went from
/// 212 kN m to 58 kN m this way).
#[test]
fn a_link_track_weighed_by_its_load_carries_less_than_the_shallowest() {
    let flight = LoadCase {
        flap_normal_force: Some(FlapNormalForce {
            coefficients: vec![(0.0, 0.3), (35f64.to_radians(), 1.3)],
            newtons_per_coefficient: 8000.0,
            at_stowed_m: Point2::new(-0.12, 0.1),
            normal_stowed: Vector2::new(0.0, 1.0),
        }),
        load_factor: 2.0,
        ..landing_load()
    };
    let peak = |mechanism: &LinkTrack| peak_load(mechanism, &flight);
    let shallowest = LinkTrack::synthesise(link_track_spec()).unwrap();
    let weighed = LinkTrack::synthesise(LinkTrackSpec {
        design_loads: vec![flight.clone()],
        ..link_track_spec()
    })
    .unwrap();
    let (depth, weighed_depth) = (
        shallowest.synthesis().depth_below_section_m,
        weighed.synthesis().depth_below_section_m,
    );
    // Both searches refine locally, so the weighed one may even come out shallower; it may
    // not be deeper by more than the load it saves is worth at the default weight (half the
    // reference load off the actuator is worth a tenth of the flap chord).
    let flap_chord = link_track_spec().outline.flap_chord().unwrap().2;
    assert!(
        weighed_depth <= depth + 0.1 * flap_chord,
        "{weighed_depth} against {depth}"
    );
    // The trade it chose from: non-dominated (deeper only where lighter-loaded), shallowest
    // first, the chosen one of least cost among them; none without load cases.
    let trade = &weighed.synthesis().trade;
    assert!(!trade.is_empty() && trade.len() <= 8, "{}", trade.len());
    for pair in trade.windows(2) {
        assert!(pair[0].depth_below_section_m <= pair[1].depth_below_section_m);
        assert!(pair[0].peak_torque_nm > pair[1].peak_torque_nm, "{pair:?}");
    }
    let chosen: Vec<_> = trade.iter().filter(|c| c.chosen).collect();
    assert_eq!(chosen.len(), 1);
    assert!(trade.iter().all(|c| c.cost >= chosen[0].cost));
    assert!((chosen[0].depth_below_section_m - weighed_depth).abs() < 1e-12);
    assert!(shallowest.synthesis().trade.is_empty());
    assert!(
        peak(&weighed) <= peak(&shallowest),
        "{} against {}",
        peak(&weighed),
        peak(&shallowest)
    );
}

/// The flap poses of `mechanism` at `samples` + 1 evenly spaced drive fractions.
fn flap_poses(mechanism: &LinkTrack, samples: usize) -> Vec<nalgebra::Isometry2<f64>> {
    let range = mechanism.input_range();
    (0..=samples)
        .map(|k| {
            mechanism
                .pose(range.at_fraction(k as f64 / samples as f64))
                .unwrap()
                .flap
        })
        .collect()
}

/// A link-track told to follow a motion (`shared::follow`, the flap's first station's as
/// this plane sees it) picks the mechanism nearest it: given its own unconstrained choice's
/// motion, it finds that mechanism again (within the search's resolution); given the motion
/// of another link-track through the same settings (its pivot fixed elsewhere), it ends
/// nearer that motion than its own choice is.
#[test]
fn a_link_track_follows_the_motion_it_is_given() {
    use flapwright_mechanism::shared::follow::{FollowedMotion, MISS_CHORD_FRACTIONS};
    use flapwright_mechanism::shared::outline::FlapPoint;
    let own = LinkTrack::synthesise(link_track_spec()).unwrap();
    let outline = &link_track_spec().outline;
    let points: Vec<Point2<f64>> = MISS_CHORD_FRACTIONS
        .iter()
        .map(|&chord_fraction| {
            outline
                .flap_point(FlapPoint {
                    chord_fraction,
                    depth_fraction: 0.0,
                })
                .unwrap()
        })
        .collect();
    let miss_of = |follower: &LinkTrack, motion: &FollowedMotion| {
        let range = follower.input_range();
        motion.miss(&points, &|s| follower.pose(range.at_fraction(s)).ok().map(|p| p.flap))
    };
    let motion_of = |lead: &LinkTrack| FollowedMotion {
        station: "lead".into(),
        flap_poses: flap_poses(lead, 24),
        attachments: lead.flap_attachments().iter().map(|a| a.position).collect(),
    };
    // Its own motion: found again.
    let motion = motion_of(&own);
    assert_eq!(miss_of(&own, &motion), 0.0);
    let again = LinkTrack::synthesise(LinkTrackSpec {
        follow: Some(motion.clone()),
        ..link_track_spec()
    })
    .unwrap();
    let followed = again.synthesis().followed.clone().unwrap();
    assert_eq!(followed.station, "lead");
    assert!((followed.miss_m - miss_of(&again, &motion)).abs() < 1e-12);
    assert!(followed.miss_m < 1e-3, "{}", followed.miss_m);
    // Another link-track's motion through the same settings: its pivot a fifth of the flap
    // chord from the unconstrained choice's.
    let chord = outline.flap_chord().unwrap().2;
    let pivot = own.synthesis().link_pivot_m;
    let other = [Vector2::new(0.2, 0.0), Vector2::new(-0.2, 0.0), Vector2::new(0.0, -0.2)]
        .iter()
        .find_map(|offset| {
            LinkTrack::synthesise(LinkTrackSpec {
                link_pivot: Some(pivot + offset * chord),
                ..link_track_spec()
            })
            .ok()
        })
        .expect("a link-track with its pivot moved");
    let motion = motion_of(&other);
    let unconstrained = miss_of(&own, &motion);
    let follower = LinkTrack::synthesise(LinkTrackSpec {
        follow: Some(motion.clone()),
        ..link_track_spec()
    })
    .unwrap();
    let miss = miss_of(&follower, &motion);
    assert!(unconstrained > 1e-3, "the two motions differ: {unconstrained}");
    assert!(miss < 0.5 * unconstrained, "{miss} against {unconstrained}");
}

/// The dropped hinge's screw jack placed weighing its force under the load cases
/// (`shared::placement::screw_jack_placement` with the spec's weighing) carries no more
/// than the shallowest clear placement, for a fairing at most as much deeper as the load
/// it saves is worth; and whichever jack it picks, the spanwise layout keeps the truss in
/// the station plane, where its members' tops were placed on the lower skin.
#[test]
fn a_dropped_hinge_jack_weighed_by_its_load_carries_no_more_than_the_shallowest() {
    use crate::synthesised::model_section::dropped_hinge_spec;
    use flapwright_kinds::dropped_hinge::{DroppedHinge, DroppedHingeSpec};
    let flight = flight_load();
    let peak = |mechanism: &DroppedHinge| peak_load(mechanism, &flight);
    let shallowest = DroppedHinge::synthesise(dropped_hinge_spec()).unwrap();
    let weighed = DroppedHinge::synthesise(DroppedHingeSpec {
        design_loads: vec![flight.clone()],
        ..dropped_hinge_spec()
    })
    .unwrap();
    assert!(
        peak(&weighed) <= peak(&shallowest),
        "{} against {}",
        peak(&weighed),
        peak(&shallowest)
    );
    for mechanism in [&shallowest, &weighed] {
        let layout = flapwright_mechanism::spanwise::spanwise_layout(mechanism).unwrap();
        for (body, offsets) in mechanism.bodies().iter().zip(&layout) {
            for (solid, offset) in body.solids.iter().zip(offsets) {
                if solid.name.starts_with("truss-") {
                    assert_eq!(*offset, 0.0, "{} stands aside", solid.name);
                }
            }
        }
    }
}

/// The largest actuator load of `mechanism` under `case` at 33 inputs over its deployment.
fn peak_load(mechanism: &dyn FlapMechanism, case: &LoadCase) -> f64 {
    mechanism
        .input_range()
        .samples(33)
        .into_iter()
        .map(|q| mechanism.kinetostatics(q, case).unwrap().actuator_load.abs())
        .fold(0.0, f64::max)
}

/// `trade_index` takes another candidate of the weighed search's trade: the mechanism
/// synthesised is that candidate (its pivot, depth and peak torque as the trade lists
/// them), marked chosen in the trade it is listed in; an index the trade does not have is
/// refused, naming the count.
#[test]
fn a_link_track_takes_the_trade_candidate_it_is_given_by_index() {
    let spec = LinkTrackSpec {
        design_loads: vec![flight_load()],
        ..link_track_spec()
    };
    let weighed = LinkTrack::synthesise(spec.clone()).unwrap();
    let trade = weighed.synthesis().trade.clone();
    assert!(trade.len() >= 2, "a trade to pick from: {trade:?}");
    assert_eq!(trade.iter().filter(|c| c.chosen).count(), 1);
    for (index, candidate) in trade.iter().enumerate() {
        let picked = LinkTrack::synthesise(LinkTrackSpec {
            trade_index: Some(index),
            ..spec.clone()
        })
        .unwrap();
        let s = picked.synthesis();
        assert_eq!(s.link_pivot_m, candidate.link_pivot_m, "candidate {index}");
        assert_eq!(s.depth_below_section_m, candidate.depth_below_section_m);
        let chosen: Vec<usize> = (0..s.trade.len()).filter(|&k| s.trade[k].chosen).collect();
        assert_eq!(chosen, vec![index]);
        let torque = peak_load(&picked, &flight_load());
        assert!(
            (torque - candidate.peak_torque_nm).abs() <= 1e-3 * candidate.peak_torque_nm,
            "candidate {index}: {torque} against {}",
            candidate.peak_torque_nm
        );
    }
    match LinkTrack::synthesise(LinkTrackSpec {
        trade_index: Some(trade.len()),
        ..spec
    }) {
        Err(flapwright_mechanism::Error::NoSuchTradeCandidate { index, count, .. }) => {
            assert_eq!((index, count), (trade.len(), trade.len()));
        }
        other => panic!("{other:?}"),
    }
}

/// The dropped hinge's weighed jack placement lists its trade between the jack's depth and
/// its load (no candidate beats another on both, the chosen one the least costly), and
/// `trade_index` takes another candidate: the jack synthesised is that candidate (its
/// attachment and mount as listed, its peak load as listed to 2 %: the list samples 17
/// poses, `peak_load` 33), marked chosen; an index the trade does not have is refused,
/// naming the count.
#[test]
fn a_dropped_hinge_takes_the_jack_trade_candidate_it_is_given_by_index() {
    use crate::synthesised::model_section::dropped_hinge_spec;
    use flapwright_kinds::dropped_hinge::{DroppedHinge, DroppedHingeActuator, DroppedHingeSpec};
    let flight = flight_load();
    let spec = DroppedHingeSpec {
        design_loads: vec![flight.clone()],
        ..dropped_hinge_spec()
    };
    let with_index = |index: usize| {
        let mut spec = spec.clone();
        if let DroppedHingeActuator::ScrewJack { trade_index, .. } = &mut spec.actuator {
            *trade_index = Some(index);
        }
        spec
    };
    let weighed = DroppedHinge::synthesise(spec.clone()).unwrap();
    let trade = weighed
        .synthesis()
        .screw_jack
        .as_ref()
        .expect("a screw jack")
        .trade
        .clone();
    assert!(trade.len() >= 2, "a trade to pick from: {trade:?}");
    let chosen: Vec<_> = trade.iter().filter(|c| c.chosen).collect();
    assert_eq!(chosen.len(), 1);
    assert!(trade.iter().all(|c| c.cost >= chosen[0].cost));
    for a in &trade {
        for b in &trade {
            let beats = a.depth_below_pivot_m < b.depth_below_pivot_m && a.peak_load_n < b.peak_load_n;
            assert!(!beats || b.chosen, "{a:?} beats {b:?}");
        }
    }
    assert!(trade
        .windows(2)
        .all(|w| w[0].depth_below_pivot_m <= w[1].depth_below_pivot_m));
    for (index, candidate) in trade.iter().enumerate() {
        let picked = DroppedHinge::synthesise(with_index(index)).unwrap();
        let jack = picked.synthesis().screw_jack.clone().expect("a screw jack");
        assert_eq!(jack.actuator_attachment_m, candidate.attachment_m, "candidate {index}");
        assert_eq!(jack.actuator_mount_m, candidate.mount_m, "candidate {index}");
        let marked: Vec<usize> = (0..jack.trade.len()).filter(|&k| jack.trade[k].chosen).collect();
        assert_eq!(marked, vec![index]);
        let load = peak_load(&picked, &flight);
        assert!(
            (load - candidate.peak_load_n).abs() <= 0.02 * candidate.peak_load_n,
            "candidate {index}: {load} against {}",
            candidate.peak_load_n
        );
    }
    match DroppedHinge::synthesise(with_index(trade.len())) {
        Err(flapwright_mechanism::Error::NoSuchTradeCandidate { index, count, .. }) => {
            assert_eq!((index, count), (trade.len(), trade.len()));
        }
        other => panic!("{:?}", other.map(|_| "a mechanism")),
    }
}

/// The four-bar's `trade_index` takes that candidate of its jack placement's trade: the
/// synthesised screw takes hold and is mounted where its own trade lists that candidate,
/// marked chosen there; an index no linkage's trade has is refused, naming the count.
#[test]
fn a_four_bar_takes_the_jack_trade_candidate_it_is_given_by_index() {
    use crate::synthesised::model_section::four_bar_spec;
    use flapwright_kinds::four_bar::{FourBar, FourBarSpec};
    let spec = FourBarSpec {
        design_loads: vec![flight_load()],
        ..four_bar_spec()
    };
    let weighed = FourBar::synthesise(spec.clone()).unwrap();
    let trade = weighed.synthesis().jack_trade.clone();
    assert!(trade.len() >= 2, "a trade to pick from: {trade:?}");
    assert_eq!(trade.iter().filter(|c| c.chosen).count(), 1);
    for index in 0..trade.len() {
        let picked = FourBar::synthesise(FourBarSpec {
            trade_index: Some(index),
            ..spec.clone()
        })
        .unwrap();
        let s = picked.synthesis();
        let listed = s.jack_trade.get(index).expect("the index in its own trade");
        assert!(listed.chosen, "candidate {index}");
        assert_eq!(s.jack_trade.iter().filter(|c| c.chosen).count(), 1);
        assert_eq!(
            (s.actuator_attachment_m, s.actuator_mount_m),
            (listed.attachment_m, listed.mount_m)
        );
    }
    match FourBar::synthesise(FourBarSpec {
        trade_index: Some(flapwright_mechanism::shared::placement::JACK_TRADE_CANDIDATES),
        ..spec
    }) {
        Err(flapwright_mechanism::Error::NoSuchTradeCandidate { index, .. }) => {
            assert_eq!(index, flapwright_mechanism::shared::placement::JACK_TRADE_CANDIDATES);
        }
        other => panic!("{:?}", other.map(|_| "a mechanism")),
    }
}

/// The searches' mass estimate (`shared::objective::MassWeighing`) is the sizing stage's:
/// a screw sized for strength and Euler buckling and an arm sized for its bending moment by
/// `flapwright_sizing::size_rod` weigh what the estimate says, to rounding, over loads and
/// lengths where strength and where buckling governs the screw.
#[test]
fn the_searches_mass_estimate_is_the_sizing_stages() {
    use flapwright_mechanism::shared::objective::{MassWeighing, MemberMaterial};
    use flapwright_sizing::{size_rod, BendingLoad, Material, RodInput};
    let member = |m: &Material| MemberMaterial {
        density_kg_m3: m.density_kg_m3,
        allowable_pa: m.allowable_tensile_pa,
        youngs_modulus_pa: m.youngs_modulus_pa,
    };
    let (steel, aluminium) = (Material::steel_4340(), Material::aluminium_7075_t6());
    let weighing = MassWeighing {
        weight: 1.0,
        link: member(&aluminium),
        screw: member(&steel),
        safety_factor: 1.5,
        screw_end_fixity_factor: 0.7,
    };
    let mut governing = std::collections::BTreeSet::new();
    for (length, force) in [(0.05, 400e3), (0.4, 60e3), (0.9, 20e3), (1.5, 150e3)] {
        let mut screw = RodInput::new("s", "screw", length, 0.0, force * 1.5);
        screw.end_fixity_factor = 0.7;
        let sized = size_rod(&screw, &steel).unwrap();
        governing.insert(format!("{:?}", sized.governing));
        let estimate = weighing.screw_mass_kg(length, force);
        assert!(
            (estimate - sized.mass_kg).abs() <= 1e-9 * sized.mass_kg,
            "screw {length} m, {force} N: {estimate} kg against {} kg",
            sized.mass_kg
        );
    }
    assert_eq!(governing.len(), 2, "strength and buckling both tried: {governing:?}");
    for (length, moment) in [(0.2, 5e3), (0.6, 30e3)] {
        let mut arm = RodInput::new("s", "horn", length, 0.0, 0.0);
        arm.bending = vec![BendingLoad {
            axial_n: 0.0,
            bending_moment_nm: moment * 1.5,
        }];
        let sized = size_rod(&arm, &aluminium).unwrap();
        let estimate = weighing.arm_mass_kg(length, moment);
        assert!(
            (estimate - sized.mass_kg).abs() <= 1e-9 * sized.mass_kg,
            "arm {length} m, {moment} N m: {estimate} kg against {} kg",
            sized.mass_kg
        );
    }
}
