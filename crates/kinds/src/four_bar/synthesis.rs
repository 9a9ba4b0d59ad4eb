//! The four-bar's synthesis: the search's feasible loops, the shallowest whole mechanism
//! among the finalists once the screw and the struts are placed, and its record.

use nalgebra::{Isometry2, Point2};

use super::bodies::{bodies_and_joints, crank_start};
use super::linkage::{Loop, LoopPose};
use super::search::{candidate, candidates, check_pair, search_failure, Candidate};
use super::{
    failure, mm, FollowStation, FourBar, FourBarSearch, FourBarSpec, FourBarSynthesis, FourBarTopology,
    CLEAR_FINALISTS, FINALISTS, LOOP_SAMPLES, RATE_INTERVALS,
};
use flapwright_mechanism::seam::FlapMechanism;
use flapwright_mechanism::shared::geometry::{turn_about, turn_angle};
use flapwright_mechanism::shared::placement::{
    place_screw_jack, strut_top, JackSize, ScrewJackChoice, PLACEMENT_SAMPLES, STRUT_TOPS_AHEAD,
};
use flapwright_mechanism::shared::rocker_drive::RockerDrive;
use flapwright_mechanism::{Error, Result, SynthesisDefect};

/// Points per side of the grid about each followed pivot (odd: the pivot is one).
const FOLLOW_STEPS: usize = 9;
/// Half the side of that grid, fraction of the flap chord.
const FOLLOW_REACH: f64 = 0.1;
/// Whole mechanisms built clear before the one nearest the followed schedule is kept.
const FOLLOW_BUILDS: usize = 40;
/// How much further from the followed motion than the nearest build a follower may move
/// its flap for a less costly mechanism (m; rad where it follows a deflection schedule).
const FOLLOW_MISS_TOLERANCE_M: f64 = 0.002;

impl FourBar {
    /// Synthesises the four-bar (searching the moving pivots the spec leaves free), its
    /// drive and solids. Errors: [`Error::Synthesis`] with the defect.
    pub fn synthesise(spec: FourBarSpec) -> Result<Self> {
        for position in [spec.takeoff, spec.landing] {
            let t = position.flap.translation.vector;
            if !(t.x.is_finite() && t.y.is_finite() && position.deflection_rad.is_finite()) {
                return Err(failure(
                    SynthesisDefect::MissingPositions,
                    "a precision position is not finite".into(),
                ));
            }
        }
        let Some((_, _, flap_chord)) = spec.outline.flap_chord() else {
            return Err(failure(
                SynthesisDefect::MissingPositions,
                "the station has no flap section".into(),
            ));
        };
        let chord = spec.outline.chord_m().unwrap_or(flap_chord);
        let mut search = FourBarSearch::default();
        let given = |p: Point2<f64>, which: &str| {
            candidate(&spec, p, chord)
                .map_err(|(defect, why)| failure(defect, format!("{which} pivot {}: {why}", mm(p))))
        };
        let free = spec.forward_pivot.is_none() && spec.aft_pivot.is_none();
        if let (true, Some(follow)) = (free, spec.follow.as_ref()) {
            if let Some(found) = Self::following(&spec, follow, chord, flap_chord) {
                return found.with_support_truss();
            }
        }
        let grid = if spec.forward_pivot.is_none() || spec.aft_pivot.is_none() {
            candidates(&spec, &mut search, chord)
        } else {
            Vec::new()
        };
        let forward = match spec.forward_pivot {
            Some(p) => vec![given(p, "forward")?],
            None => grid.clone(),
        };
        let aft = match spec.aft_pivot {
            Some(p) => vec![given(p, "aft")?],
            None => grid,
        };
        let fixed_pair = spec.forward_pivot.is_some() && spec.aft_pivot.is_some();
        let section_bottom = spec.outline.section_bottom();
        let mut feasible: Vec<(f64, f64, Loop)> = Vec::new();
        let mut last_defect = None;
        for first in &forward {
            for second in &aft {
                // Each unordered pair once.
                if spec.forward_pivot.is_none() && spec.aft_pivot.is_none() && first.moving.x <= second.moving.x {
                    continue;
                }
                if links_coincide(first, second, flap_chord) {
                    if fixed_pair {
                        last_defect = Some((SynthesisDefect::NoRealSolution, "the two links coincide".to_string()));
                    }
                    continue;
                }
                search.pairs += 1;
                // The screw drives the link that turns less (a square mount keeps it above
                // the minimum transmission angle over up to pi - 2 mu_min of rotation).
                let (crank, rocker) = crank_and_rocker(first, second);
                match check_pair(&spec, crank, rocker) {
                    Ok((loop_, transmission)) => {
                        search.feasible += 1;
                        let lowest = [loop_.o1, loop_.o2, loop_.a1, loop_.a2]
                            .iter()
                            .map(|p| p.y)
                            .fold(f64::INFINITY, f64::min);
                        let depth = (section_bottom - lowest).max(0.0);
                        feasible.push((depth, transmission, loop_));
                    }
                    Err((defect, why)) => {
                        match defect {
                            SynthesisDefect::BranchOrOrder => search.branch_change += 1,
                            SynthesisDefect::Toggle => search.toggle += 1,
                            _ => search.link_in_wing += 1,
                        }
                        last_defect = Some((defect, why));
                    }
                }
            }
        }
        if feasible.is_empty() {
            if fixed_pair {
                let (defect, why) = last_defect.unwrap_or((SynthesisDefect::NoRealSolution, "no pair".into()));
                return Err(failure(defect, why));
            }
            return Err(search_failure(&search));
        }
        // The shallowest loops by their pivots, then the shallowest whole mechanism once the
        // screw and the struts are placed (they set the fairing as often as the pivots do).
        feasible.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
        // A mechanism whose screw and struts are placed clear ranks before one that is not.
        let mut best: Option<((bool, f64), Self)> = None;
        let mut first_error = None;
        for (examined, &(_, _, loop_)) in feasible.iter().take(FINALISTS).enumerate() {
            // Enough once a clear mechanism is in hand and the shallowest few were seen.
            if examined >= CLEAR_FINALISTS && best.as_ref().is_some_and(|((blocked, _), _)| !blocked) {
                break;
            }
            // A loop whose links come near the flap cannot be placed clear: not built once
            // another mechanism is in hand (building it costs a jack placement).
            if best.is_some() && !links_may_clear_flap(&spec, &loop_) {
                continue;
            }
            match Self::build(spec.clone(), loop_, search) {
                Ok(four_bar) => {
                    let s = &four_bar.synthesis;
                    let rank = (!(s.actuator_clear && s.placement_clear), s.depth_below_section_m);
                    let better = best
                        .as_ref()
                        .is_none_or(|((blocked, d), _)| (rank.0, rank.1 + 1e-9) < (*blocked, *d));
                    if better {
                        best = Some((rank, four_bar));
                    }
                }
                Err(error) => {
                    first_error.get_or_insert(error);
                }
            }
        }
        match (best, first_error) {
            (Some((_, four_bar)), _) => four_bar.with_support_truss(),
            (None, Some(error)) => Err(error),
            (None, None) => Err(search_failure(&search)),
        }
    }

    /// Depth of every solid of the mechanism over the deployment below the stowed section's
    /// lowest point (m).
    pub(super) fn whole_depth(&self) -> Result<f64> {
        let section_bottom = self.spec.outline.section_bottom();
        let mut lowest = f64::INFINITY;
        for input in self.input_range().samples(PLACEMENT_SAMPLES + 1) {
            let pose = FlapMechanism::pose(self, input)?;
            for (body, placement) in self.bodies.iter().zip(&pose.bodies) {
                for solid in &body.solids {
                    let posed = flapwright_mechanism::seam::posed_shape(&solid.shape, placement);
                    let low = posed.skeleton().iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
                    lowest = lowest.min(low - posed.radius_m());
                }
            }
        }
        Ok((section_bottom - lowest).max(0.0))
    }

    pub(super) fn build(spec: FourBarSpec, loop_: Loop, search: FourBarSearch) -> Result<Self> {
        let turns = [
            turn_angle(loop_.o1, loop_.a1, spec.takeoff.flap * loop_.a1),
            turn_angle(loop_.o1, loop_.a1, spec.landing.flap * loop_.a1),
        ];
        let travel = turns[1];
        let mut min_transmission = f64::INFINITY;
        let mut max_crank_ratio = 0.0_f64;
        for k in 0..=LOOP_SAMPLES {
            let phi = travel * k as f64 / LOOP_SAMPLES as f64;
            let pose = loop_.at(phi).ok_or_else(|| {
                failure(
                    SynthesisDefect::NoRealSolution,
                    "the loop breaks inside the deployment".into(),
                )
            })?;
            min_transmission = min_transmission.min(pose.transmission);
            let (rocker, flap) = loop_.rates(&pose);
            max_crank_ratio = max_crank_ratio.max(rocker.abs()).max(flap.abs());
        }
        // Between samples the transmission angle changes at most as fast as the coupler and
        // rocker turn: |dμ/dφ| <= |ω_r| + |ω_f| per unit crank rate, bounded by the rates at
        // half the sampled minimum (they grow as 1/sin μ).
        let step = travel.abs() / LOOP_SAMPLES as f64;
        let crank_arm = (loop_.a1 - loop_.o1).norm();
        let rate_bound = |mu: f64| crank_arm / (loop_.rocker * mu.sin()) + crank_arm / (loop_.coupler * mu.sin());
        let certified = (min_transmission - 0.5 * step * rate_bound(0.5 * min_transmission)).max(0.0);
        // The rocker's and the flap's rates per unit crank rate: certified on
        // RATE_INTERVALS pieces of the deployment, or from the transmission angle alone.
        let link_rates = loop_.rate_bounds(travel, certified, RATE_INTERVALS).unwrap_or_else(|| {
            let sine = certified.sin().max(1e-9);
            (crank_arm / (loop_.rocker * sine), crank_arm / (loop_.coupler * sine))
        });
        let hw = spec.hardware;
        // In-plane margin for the 3D check's clearance and the flap's taper across a part's width.
        let margin = hw.link_radius_m;
        let choice = ScrewJackChoice {
            arm: (loop_.o1, loop_.a1),
            attachment_fraction: spec.actuator_attachment_fraction,
            // On the crank, then on a horn beyond its fixed pivot.
            other_fractions: &[0.35, 0.7, 0.9, -0.4, -0.7],
            mount: spec.actuator_mount,
            standoff_m: spec.actuator_standoff_m,
            min_transmission_rad: spec.min_transmission_angle_rad,
        };
        let size = JackSize::new(&hw, spec.screw_drive.mean_radius_m);
        let flap_at = |phi: f64| loop_.at(phi).map(|p| p.flap);
        let placed = place_screw_jack(
            loop_.o1,
            travel,
            &choice,
            &size,
            margin,
            &spec.outline,
            &flap_at,
            spec.weighing().as_ref(),
        );
        let trade_index = spec.trade_index;
        let placed = placed.picked(super::KIND, trade_index)?;
        let (attachment, mount, actuator_clear) = (placed.attachment, placed.mount, placed.clear);
        let mut placement_clear = links_clear_of_flap(&spec, &loop_, attachment, travel, margin);
        let flap_poses = sampled_flap_poses(&loop_, travel);
        let strut = |from: Point2<f64>| {
            strut_top(
                &spec.outline,
                from,
                &STRUT_TOPS_AHEAD,
                hw.strut_radius_m,
                margin,
                &flap_poses,
                None,
            )
        };
        // A pivot whose strut to the skin would cross the flap's path is held by a beam to
        // the other pivot instead (one support beam carrying both), if that beam is clear.
        let beam_clear = |from: Point2<f64>, to: Point2<f64>| {
            flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                spec.outline
                    .flap
                    .segment_clear_by(back * from, back * to, hw.strut_radius_m + margin)
            }) && !spec.outline.wing.segment_meets(from, to)
        };
        let (first, second) = (strut(loop_.o1), strut(loop_.o2));
        let (first, second) = match (first, second) {
            (Some(a), None) if beam_clear(loop_.o2, loop_.o1) => (Some(a), Some(loop_.o1)),
            (None, Some(b)) if beam_clear(loop_.o1, loop_.o2) => (Some(loop_.o2), Some(b)),
            other => other,
        };
        let strut_tops = match (first, second) {
            (Some(a), Some(b)) => [a, b],
            (a, b) => {
                placement_clear = false;
                let straight_up = |o: Point2<f64>| {
                    spec.outline
                        .wing_lower_point(o.x)
                        .unwrap_or(Point2::new(o.x, o.y + hw.strut_radius_m))
                };
                [
                    a.unwrap_or_else(|| straight_up(loop_.o1)),
                    b.unwrap_or_else(|| straight_up(loop_.o2)),
                ]
            }
        };
        let drive = RockerDrive::try_new(loop_.o1, mount, attachment).map_err(|_| {
            failure(
                SynthesisDefect::Toggle,
                format!(
                    "the screw mount {}, O1 and the crank attachment lie on one line",
                    mm(mount)
                ),
            )
        })?;
        let drive_min = drive.min_transmission_rad(travel, LOOP_SAMPLES);
        if let Some(problem) =
            drive.transmission_problem(travel, spec.min_transmission_angle_rad, LOOP_SAMPLES, "crank")
        {
            return Err(failure(SynthesisDefect::Toggle, problem));
        }
        let stroke_m = [drive.stroke_at(0.0), drive.stroke_at(travel)];
        let (screw, nominal_speed_mps) = spec.screw_drive.screw_for(stroke_m[1] - stroke_m[0]);
        let miss = [(turns[0], spec.takeoff), (turns[1], spec.landing)]
            .iter()
            .filter_map(|(phi, position)| {
                let pose = loop_.at(*phi)?;
                Some(
                    (pose.a1 - position.flap * loop_.a1)
                        .norm()
                        .max((pose.a2 - position.flap * loop_.a2).norm()),
                )
            })
            .fold(0.0, f64::max);
        let synthesis = FourBarSynthesis {
            crank_pivot_m: loop_.o1,
            rocker_pivot_m: loop_.o2,
            moving_pivots_m: [loop_.a1, loop_.a2],
            crank_rotation_rad: turns,
            min_transmission_angle_rad: min_transmission,
            drive_min_transmission_angle_rad: drive_min,
            jack_installation: flapwright_mechanism::shared::rocker_drive::JackInstallation::of(&drive, travel),
            jack_trade: placed.trade,
            certified_min_transmission_angle_rad: certified,
            depth_below_section_m: 0.0,
            precision_miss_m: miss,
            actuator_mount_m: mount,
            actuator_attachment_m: attachment,
            stroke_m,
            screw,
            // Long enough to carry the nut at the longest stroke: a free end would sweep.
            screw_length_m: stroke_m[0].max(stroke_m[1]) + hw.nut_radius_m,
            strut_tops_m: strut_tops,
            truss: None,
            actuator_clear,
            placement_clear,
            nominal_speed_mps,
            search,
            topology: FourBarTopology::of(loop_.o1, loop_.a1, loop_.a2, attachment, mount),
            followed: None,
        };
        let (bodies, joints) = bodies_and_joints(&spec, &synthesis, &loop_, &drive, link_rates);
        let mut four_bar = Self {
            spec,
            synthesis,
            loop_,
            drive,
            link_rates,
            bodies,
            joints,
        };
        four_bar.synthesis.depth_below_section_m = four_bar.whole_depth()?;
        Ok(four_bar)
    }

    /// The four-bar that moves the flap most like `follow`'s station: pairs from a grid of
    /// [`FOLLOW_STEPS`]² points within [`FOLLOW_REACH`] of the flap chord about each of its
    /// pivots, nearest first; of the first [`FOLLOW_BUILDS`] whose whole mechanism builds
    /// clear, the least costly ([`Self::weighed_cost`]) of those whose flap stays within
    /// [`FOLLOW_MISS_TOLERANCE_M`] of the nearest to `follow`'s motion (the largest miss at
    /// the flap's 5 % and 95 % chord points over the deployment) where the caller gives it,
    /// else to the nearest deflection schedule (rad, the same number); `None` when none
    /// builds clear. Nearest alone, the follower at `transport-flap`'s `ib-outer` took a loop
    /// whose screw carried 1.58 times its neighbour's between landing gaps of 2.05 and
    /// 2.10 %c, for a fairing 4 mm deeper (1.38 now).
    fn following(spec: &FourBarSpec, follow: &FollowStation, chord: f64, flap_chord: f64) -> Option<Self> {
        let around = |centre: Point2<f64>| -> Vec<Point2<f64>> {
            let step = 2.0 * FOLLOW_REACH * flap_chord / (FOLLOW_STEPS - 1) as f64;
            let half = (FOLLOW_STEPS / 2) as f64;
            (0..FOLLOW_STEPS * FOLLOW_STEPS)
                .map(|k| {
                    let (i, j) = ((k / FOLLOW_STEPS) as f64 - half, (k % FOLLOW_STEPS) as f64 - half);
                    centre + nalgebra::Vector2::new(i * step, j * step)
                })
                .collect()
        };
        let usable = |points: Vec<Point2<f64>>| -> Vec<_> {
            points
                .into_iter()
                .filter_map(|p| candidate(spec, p, chord).ok())
                .collect()
        };
        let [forward_pivot, aft_pivot] = follow.pivots;
        let (forward, aft) = (usable(around(forward_pivot)), usable(around(aft_pivot)));
        let mut pairs: Vec<(f64, _, _)> = Vec::new();
        for f in &forward {
            for a in &aft {
                if links_coincide(f, a, flap_chord) {
                    continue;
                }
                let miss = (f.moving - forward_pivot).norm() + (a.moving - aft_pivot).norm();
                pairs.push((miss, f, a));
            }
        }
        pairs.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mismatch_of = |four_bar: &Self| -> f64 {
            let range = four_bar.input_range();
            match &follow.motion {
                Some(motion) => {
                    let points = flapwright_mechanism::shared::follow::miss_points(&spec.outline);
                    motion.miss(&points, &|fraction| {
                        four_bar
                            .loop_pose(range.at_fraction(fraction))
                            .ok()
                            .map(|(_, pose)| pose.flap)
                    })
                }
                None => {
                    let samples = follow.deflections_rad.len().max(2) - 1;
                    follow
                        .deflections_rad
                        .iter()
                        .enumerate()
                        .map(|(k, target)| {
                            four_bar
                                .deflection_at_input(range.at_fraction(k as f64 / samples as f64))
                                .map_or(f64::INFINITY, |d| (d - target).abs())
                        })
                        .fold(0.0, f64::max)
                }
            }
        };
        let mut search = FourBarSearch::default();
        let mut built: Vec<(f64, Self)> = Vec::new();
        for (_, f, a) in pairs {
            if built.len() >= FOLLOW_BUILDS {
                break;
            }
            search.pairs += 1;
            let (crank, rocker) = crank_and_rocker(f, a);
            let Ok((loop_, _)) = check_pair(spec, crank, rocker) else {
                continue;
            };
            search.feasible += 1;
            if !links_may_clear_flap(spec, &loop_) {
                continue;
            }
            let Ok(four_bar) = Self::build(spec.clone(), loop_, search) else {
                continue;
            };
            if !(four_bar.synthesis.actuator_clear && four_bar.synthesis.placement_clear) {
                continue;
            }
            built.push((mismatch_of(&four_bar), four_bar));
        }
        // Of the builds within FOLLOW_MISS_TOLERANCE_M of the nearest motion, the least
        // costly (depth and the screw's load), the nearest first among equals.
        let nearest = built.iter().map(|(m, _)| *m).fold(f64::INFINITY, f64::min);
        let best = built
            .into_iter()
            .filter(|(m, _)| *m <= nearest + FOLLOW_MISS_TOLERANCE_M)
            .map(|(m, four_bar)| (four_bar.weighed_cost(flap_chord), m, four_bar))
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        best.map(|(_, miss, mut four_bar)| {
            four_bar.synthesis.followed = follow.motion.as_ref().map(|motion| motion.followed(miss));
            four_bar
        })
    }

    /// What a mechanism costs: its whole depth in flap chords plus, under load cases, the
    /// weight times its screw's peak load in reference loads (each reference load above the
    /// cap costing more: [`flapwright_mechanism::shared::objective::LoadWeighing::cost`]),
    /// the load the jack's placement found; the depth alone without load cases.
    fn weighed_cost(&self, flap_chord: f64) -> f64 {
        let s = &self.synthesis;
        let chosen = s.jack_trade.iter().find(|c| c.chosen);
        match (self.spec.weighing(), chosen) {
            (Some(weighing), Some(chosen)) => {
                let poses = sampled_flap_poses(&self.loop_, s.crank_rotation_rad[1]);
                let reference = weighing.reference_force_n(&poses);
                weighing.cost(s.depth_below_section_m, flap_chord, chosen.peak_load_n, reference)
            }
            _ => s.depth_below_section_m / flap_chord,
        }
    }

    /// The designer's choices.
    pub fn spec(&self) -> &FourBarSpec {
        &self.spec
    }

    /// What synthesis computed.
    pub fn synthesis(&self) -> &FourBarSynthesis {
        &self.synthesis
    }

    /// The flap's displacement and the loop's transmission angle at crank angle `phi`: the
    /// closed-form pose (benchmarked).
    pub fn flap_at_crank_angle(&self, phi: f64) -> Option<(Isometry2<f64>, f64)> {
        self.loop_.at(phi).map(|p| (p.flap, p.transmission))
    }

    pub(super) fn loop_pose(
        &self,
        input: f64,
    ) -> Result<(flapwright_mechanism::shared::rocker_drive::RockerState, LoopPose)> {
        let state = self.drive.state(input)?;
        let pose = self.loop_.at(state.rotation_rad).ok_or(Error::CannotAssemble {
            input_m: input,
            min_input_m: self.synthesis.stroke_m[0].min(self.synthesis.stroke_m[1]),
            max_input_m: self.synthesis.stroke_m[0].max(self.synthesis.stroke_m[1]),
        })?;
        Ok((state, pose))
    }
}

/// The flap's displacements at [`PLACEMENT_SAMPLES`] + 1 crank angles from 0 to `travel`
/// (where the loop closes).
pub(super) fn sampled_flap_poses(loop_: &Loop, travel: f64) -> Vec<Isometry2<f64>> {
    (0..=PLACEMENT_SAMPLES)
        .filter_map(|k| loop_.at(travel * k as f64 / PLACEMENT_SAMPLES as f64).map(|p| p.flap))
        .collect()
}

/// Part of its radius a link keeps from the flap beyond its radius, in the station plane.
const LINK_FLAP_MARGIN: f64 = 0.25;

/// True when the crank (from its horn where the screw sits there) and the rocker keep their
/// radius and [`LINK_FLAP_MARGIN`] of it from the flap section at [`PLACEMENT_SAMPLES`]
/// poses, short of their eyes at A1 and A2 (within `eye` of the pin, the flap's fitting
/// surrounds them). The loop's search keeps the links out of the wing, not off the flap
/// they hang from: on `transport-flap` at a landing gap of 1.60 %c the inboard rocker passed
/// 5 mm from the flap at landing, which the 3D check could not certify.
fn links_clear_of_flap(spec: &FourBarSpec, loop_: &Loop, attachment: Point2<f64>, travel: f64, eye: f64) -> bool {
    let radius = spec.hardware.link_radius_m;
    let reach = radius * (1.0 + LINK_FLAP_MARGIN);
    let start = crank_start(loop_.o1, loop_.a1, attachment);
    let short_of = |from: Point2<f64>, pin: Point2<f64>| {
        let length = (pin - from).norm();
        if length <= eye {
            from
        } else {
            pin + (from - pin) * (eye / length)
        }
    };
    (0..=PLACEMENT_SAMPLES).all(|k| {
        let phi = travel * k as f64 / PLACEMENT_SAMPLES as f64;
        let Some(pose) = loop_.at(phi) else {
            return false;
        };
        let back = pose.flap.inverse();
        let crank = turn_about(loop_.o1, phi);
        [(crank * start, pose.a1), (loop_.o2, pose.a2)]
            .iter()
            .all(|&(from, pin)| {
                spec.outline
                    .flap
                    .segment_clear_by(back * from, back * short_of(from, pin), reach)
            })
    })
}

/// [`links_clear_of_flap`] for the loop's crank from O1 to A1 and its rocker, before the
/// jack is placed: false only where the whole mechanism's links cannot clear the flap (a
/// horn beyond O1 adds to the crank), so a search skips the loop's build (the finalists'
/// and the followers' builds were 30 % of `design` of `transport-flap` once the check
/// rejected more of them).
fn links_may_clear_flap(spec: &FourBarSpec, loop_: &Loop) -> bool {
    let travel = turn_angle(loop_.o1, loop_.a1, spec.landing.flap * loop_.a1);
    links_clear_of_flap(spec, loop_, loop_.o1, travel, spec.hardware.link_radius_m)
}

/// True when two links would (nearly) coincide: moving pivots closer than a tenth of the
/// flap chord, or fixed pivots closer than 2 % of it.
fn links_coincide(a: &Candidate, b: &Candidate, flap_chord: f64) -> bool {
    (a.moving - b.moving).norm() < 0.1 * flap_chord || (a.fixed - b.fixed).norm() < 0.02 * flap_chord
}

/// The screw drives the link that turns less (a square mount keeps it above the minimum
/// transmission angle over up to pi - 2 mu_min of rotation): (crank, rocker).
fn crank_and_rocker<'a>(a: &'a Candidate, b: &'a Candidate) -> (&'a Candidate, &'a Candidate) {
    if a.turns[1].abs() <= b.turns[1].abs() {
        (a, b)
    } else {
        (b, a)
    }
}
