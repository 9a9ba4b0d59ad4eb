//! The deployment under a DC motor, integrated by diffsol (the only module that names it).
//!
//! State y = [q, q̇, i, E_supplied, E_resistive, E_gearbox, W_loads] with
//!
//! - q̇' = (n η K i + Q(q) - ½ J'(q) q̇²) / (J(q) + n² J_r)   (work-energy, `generalised`)
//! - L i' = v(t) - R i - n K q̇                               (`001_...` section 3.2)
//! - E_supplied' = v i, E_resistive' = R i², E_gearbox' = (1 - η) n K i q̇, W_loads' = Q q̇,
//!
//! the last four being the energy balance's quadratures, integrated with the motion so that
//! the balance E_supplied = E_resistive + E_gearbox + ½ L i² + ½ J q̇² - W_loads is checked
//! at the integrator's own accuracy. The armature's time constant L/R (5e-8 s for
//! L = 1e-7 H, R = 2 Ω) against the deployment's second makes the system stiff: an explicit
//! method's step is bound by stability to about 3 L/R whatever the tolerance.
//!
//! The Jacobian is analytic (diffsol's implicit solvers take it as a Jacobian-vector
//! product): ∂q̈/∂q = (Q' - ½ J'' q̇²)/J_e - q̈ J'/J_e, ∂q̈/∂q̇ = -J' q̇/J_e, ∂q̈/∂i = n η K/J_e,
//! ∂i'/∂q̇ = -n K/L, ∂i'/∂i = -R/L, with J'' and Q' from the kinds' third-order jets.
//!
//! End stops are events: the flap rests on its stowed stop (q and q̇ held) until the drive
//! torque exceeds the loads holding it there, n η K i + Q(q₀) > 0 (breakaway); the run
//! ends when q reaches the deployed stop.

use std::cell::{Cell, RefCell};

use diffsol::{NalgebraLU, NalgebraMat, OdeBuilder, OdeEquations, OdeSolverMethod, OdeSolverStopReason, Op, Vector};
use flapwright_mechanism::{Generalised, OneInputDynamics};
use serde::Serialize;

use crate::drive::{positive, Drive, SupplyVoltage};
use crate::error::{Error, Result};

type Matrix = NalgebraMat<f64>;

const STATES: usize = 7;

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Variable-order BDF (diffsol), stiff, with the analytic Jacobian: the default.
    Bdf,
    /// ESDIRK34 (diffsol), stiff, L-stable, with the analytic Jacobian.
    Esdirk34,
    /// Tsitouras 5(4) explicit Runge-Kutta (diffsol): for comparison.
    Tsit45,
}

impl Method {
    /// The scene name.
    pub fn name(&self) -> &'static str {
        match self {
            Method::Bdf => "bdf",
            Method::Esdirk34 => "esdirk34",
            Method::Tsit45 => "tsit45",
        }
    }
}

/// The most samples a run's time history keeps: past it, the history is thinned to every
/// other step (and then every fourth, ...), so that `max_steps` = 1e7 on a stiff motor
/// gives a report of a few megabytes, not gigabytes (at about 300 bytes of JSON a sample,
/// 1.2 MB a run). Peaks, counts and the energy balance still take every step.
pub const MAX_TIME_HISTORY_SAMPLES: usize = 4_000;

/// Integration settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Integration {
    /// Method.
    pub method: Method,
    /// Relative tolerance of the local error.
    pub relative_tolerance: f64,
    /// Absolute tolerance of the local error (rad, rad/s, A, J).
    pub absolute_tolerance: f64,
    /// Give up after this many steps (the explicit method on a stiff motor needs millions).
    pub max_steps: usize,
    /// Give up at this time (s) if the flap has not deployed.
    pub max_time_s: f64,
}

impl Default for Integration {
    /// BDF at rtol 1e-6 (the knee of error against run time, see `docs/dynamics.md`), atol 1e-8.
    fn default() -> Self {
        Self {
            method: Method::Bdf,
            relative_tolerance: 1e-6,
            absolute_tolerance: 1e-8,
            max_steps: 200_000,
            max_time_s: 60.0,
        }
    }
}

/// One accepted step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DynamicsSample {
    /// Time (s).
    pub time_s: f64,
    /// Input q (rad).
    pub input: f64,
    /// Input rate q̇ (rad/s).
    pub rate: f64,
    /// Armature current (A).
    pub current_a: f64,
    /// Motor torque K i (N m).
    pub motor_torque_nm: f64,
    /// Supply voltage (V).
    pub voltage_v: f64,
}

/// What the integrator did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub struct SolverCounts {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps: local error test failures plus Newton failures.
    pub rejected_steps: usize,
    /// Jacobian evaluations with their LU factorisations (0 for the explicit method).
    pub jacobian_evaluations: usize,
    /// Right-hand-side evaluations.
    pub rhs_evaluations: usize,
}

impl SolverCounts {
    fn add(&mut self, other: SolverCounts) {
        self.steps += other.steps;
        self.rejected_steps += other.rejected_steps;
        self.jacobian_evaluations += other.jacobian_evaluations;
        self.rhs_evaluations += other.rhs_evaluations;
    }
}

/// Where the energy went (J), integrated with the motion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyBalance {
    /// ∫ v i dt.
    pub supplied_j: f64,
    /// ∫ R i² dt.
    pub resistive_j: f64,
    /// ∫ (1 - η) n K i q̇ dt.
    pub gearbox_j: f64,
    /// ½ L i² at the end.
    pub magnetic_j: f64,
    /// ½ (J + n² J_r) q̇² at the end.
    pub kinetic_j: f64,
    /// ∫ Q q̇ dt: the work of the loads and weights on the flaps (negative when they resist).
    pub load_work_j: f64,
    /// supplied - resistive - gearbox - magnetic - kinetic + load work: zero but for the
    /// integration error.
    pub residual_j: f64,
}

/// A deployment under the motor.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DynamicsRun {
    /// The method used.
    pub method: Method,
    /// Tolerances.
    pub relative_tolerance: f64,
    /// Accepted steps (and the two events): every one up to [`MAX_TIME_HISTORY_SAMPLES`],
    /// then evenly thinned (every 2nd, 4th, ... step) to at most that many.
    pub samples: Vec<DynamicsSample>,
    /// When the drive overcame the loads at the stowed stop (s).
    pub breakaway_time_s: f64,
    /// When the flap reached its deployed stop (s); None if it did not within the limits.
    pub deployment_time_s: Option<f64>,
    /// Largest |current| (A).
    pub peak_current_a: f64,
    /// Largest |motor torque| (N m).
    pub peak_motor_torque_nm: f64,
    /// The integrator's counts.
    pub counts: SolverCounts,
    /// True when the run stopped at `max_steps`.
    pub hit_step_limit: bool,
    /// The energy balance at the end.
    pub energy: EnergyBalance,
}

/// The first-order system and its Jacobian, shared by the solvers' closures.
struct Deployment<'a> {
    system: &'a dyn OneInputDynamics,
    drive: Drive,
    supply: SupplyVoltage,
    failure: RefCell<Option<Error>>,
    /// Every `stride`-th ordinary step is kept in the time history (doubled each time it
    /// fills up, see [`MAX_TIME_HISTORY_SAMPLES`]); `since_kept` steps since the last kept.
    stride: Cell<usize>,
    since_kept: Cell<usize>,
}

impl Deployment<'_> {
    fn generalised(&self, q: f64) -> Option<Generalised> {
        match self.system.generalised_at(q) {
            Ok(g) => Some(g),
            Err(source) => {
                self.failure
                    .borrow_mut()
                    .get_or_insert(Error::Mechanism { input: q, source });
                None
            }
        }
    }

    fn effective_inertia(&self, g: &Generalised) -> f64 {
        g.inertia + self.drive.reflected_rotor_inertia()
    }

    fn rhs(&self, x: &[f64], t: f64, y: &mut [f64], held: bool) {
        let (q, w, i) = (x[0], x[1], x[2]);
        let Some(g) = self.generalised(q) else {
            y.fill(f64::NAN);
            return;
        };
        let (r, l) = (self.drive.motor.resistance_ohm, self.drive.motor.inductance_h);
        let v = self.supply.at(t);
        let emf = self.drive.emf_per_input_rate();
        y[0] = if held { 0.0 } else { w };
        y[1] = if held {
            0.0
        } else {
            (self.drive.input_torque_per_amp() * i + g.force - 0.5 * g.inertia_slope * w * w)
                / self.effective_inertia(&g)
        };
        y[2] = (v - r * i - emf * w) / l;
        y[3] = v * i;
        y[4] = r * i * i;
        y[5] = (1.0 - self.drive.gearbox.efficiency) * emf * i * w;
        y[6] = g.force * w;
    }

    fn jacobian_times(&self, x: &[f64], t: f64, v: &[f64], y: &mut [f64], held: bool) {
        let (q, w, i) = (x[0], x[1], x[2]);
        let Some(g) = self.generalised(q) else {
            y.fill(f64::NAN);
            return;
        };
        let (r, l) = (self.drive.motor.resistance_ohm, self.drive.motor.inductance_h);
        let emf = self.drive.emf_per_input_rate();
        let per_amp = self.drive.input_torque_per_amp();
        let inertia = self.effective_inertia(&g);
        let accel = (per_amp * i + g.force - 0.5 * g.inertia_slope * w * w) / inertia;
        let (dq, dw, di) = (v[0], v[1], v[2]);
        y[0] = if held { 0.0 } else { dw };
        y[1] = if held {
            0.0
        } else {
            ((g.force_slope - 0.5 * g.inertia_curvature * w * w) / inertia - accel * g.inertia_slope / inertia) * dq
                - g.inertia_slope * w / inertia * dw
                + per_amp / inertia * di
        };
        y[2] = (-r * di - emf * dw) / l;
        y[3] = self.supply.at(t) * di;
        y[4] = 2.0 * r * i * di;
        y[5] = (1.0 - self.drive.gearbox.efficiency) * emf * (i * dw + w * di);
        y[6] = g.force_slope * w * dq + g.force * dw;
    }
}

/// Runs a deployment: the flap held at its stowed stop until breakaway, then driven to
/// its deployed stop, under `supply` through `drive`.
pub fn integrate(
    system: &dyn OneInputDynamics,
    drive: &Drive,
    supply: &SupplyVoltage,
    settings: &Integration,
) -> Result<DynamicsRun> {
    drive.validate()?;
    supply.validate()?;
    positive("integration.relative_tolerance", settings.relative_tolerance)?;
    positive("integration.absolute_tolerance", settings.absolute_tolerance)?;
    positive("integration.max_time_s", settings.max_time_s)?;
    let deployment = Deployment {
        system,
        drive: *drive,
        supply: *supply,
        failure: RefCell::new(None),
        stride: Cell::new(1),
        since_kept: Cell::new(0),
    };
    let (stowed, deployed) = system.input_travel();
    let at_stop = system
        .generalised_at(stowed)
        .map_err(|source| Error::Mechanism { input: stowed, source })?;
    let mut run = DynamicsRun {
        method: settings.method,
        relative_tolerance: settings.relative_tolerance,
        samples: Vec::new(),
        breakaway_time_s: 0.0,
        deployment_time_s: None,
        peak_current_a: 0.0,
        peak_motor_torque_nm: 0.0,
        counts: SolverCounts::default(),
        hit_step_limit: false,
        energy: EnergyBalance {
            supplied_j: 0.0,
            resistive_j: 0.0,
            gearbox_j: 0.0,
            magnetic_j: 0.0,
            kinetic_j: 0.0,
            load_work_j: 0.0,
            residual_j: 0.0,
        },
    };
    let mut state = [0.0; STATES];
    state[0] = stowed;
    let mut time = 0.0;
    let direction = (deployed - stowed).signum();
    // Held at the stowed stop while the loads push the flap onto it.
    if at_stop.force * direction < 0.0 {
        let per_amp = drive.input_torque_per_amp();
        let breakaway = move |x: &[f64], _p: &[f64], _t: f64, y: &mut [f64]| {
            y[0] = (per_amp * x[2] + at_stop.force) * direction;
        };
        let phase = run_phase(&deployment, true, state, time, settings, breakaway, &mut run)?;
        (state, time) = (phase.state, phase.time);
        run.breakaway_time_s = time;
        if !phase.event {
            return finish(&deployment, run, state);
        }
    }
    let end_stop = move |x: &[f64], _p: &[f64], _t: f64, y: &mut [f64]| y[0] = (x[0] - deployed) * direction;
    let phase = run_phase(&deployment, false, state, time, settings, end_stop, &mut run)?;
    if phase.event {
        run.deployment_time_s = Some(phase.time);
    }
    finish(&deployment, run, phase.state)
}

struct Phase {
    state: [f64; STATES],
    time: f64,
    event: bool,
}

fn run_phase<R>(
    deployment: &Deployment,
    held: bool,
    start: [f64; STATES],
    start_time: f64,
    settings: &Integration,
    root: R,
    run: &mut DynamicsRun,
) -> Result<Phase>
where
    R: Fn(&[f64], &[f64], f64, &mut [f64]),
{
    let problem = OdeBuilder::<Matrix>::new()
        .t0(start_time)
        .rtol(settings.relative_tolerance)
        .atol([settings.absolute_tolerance; STATES])
        .rhs_implicit(
            |x: &[f64], _p: &[f64], t: f64, y: &mut [f64]| deployment.rhs(x, t, y, held),
            |x: &[f64], _p: &[f64], t: f64, v: &[f64], y: &mut [f64]| deployment.jacobian_times(x, t, v, y, held),
        )
        .init(
            move |_p: &[f64], _t: f64, y: &mut [f64]| y.copy_from_slice(&start),
            STATES,
        )
        .root(root, 1)
        .build()
        .map_err(|e| solver_error(settings.method, start_time, e))?;
    let phase = match settings.method {
        Method::Bdf => {
            let solver = problem
                .bdf::<NalgebraLU<f64>>()
                .map_err(|e| solver_error(settings.method, start_time, e))?;
            step_until_event(solver, deployment, settings, run)?
        }
        Method::Esdirk34 => {
            let solver = problem
                .esdirk34::<NalgebraLU<f64>>()
                .map_err(|e| solver_error(settings.method, start_time, e))?;
            step_until_event(solver, deployment, settings, run)?
        }
        Method::Tsit45 => {
            let solver = problem
                .tsit45()
                .map_err(|e| solver_error(settings.method, start_time, e))?;
            step_until_event(solver, deployment, settings, run)?
        }
    };
    Ok(phase)
}

fn solver_error(method: Method, time_s: f64, error: impl std::fmt::Display) -> Error {
    Error::Solver {
        method: method.name(),
        time_s,
        message: error.to_string(),
    }
}

fn step_until_event<'a, Eqn, S>(
    mut solver: S,
    deployment: &Deployment,
    settings: &Integration,
    run: &mut DynamicsRun,
) -> Result<Phase>
where
    Eqn: OdeEquations<T = f64> + 'a,
    S: OdeSolverMethod<'a, Eqn>,
{
    let method = settings.method;
    let read = |y: &Eqn::V| -> [f64; STATES] { std::array::from_fn(|k| y.get_index(k)) };
    let start = solver.state().t;
    let stop = settings.max_time_s.max(start * (1.0 + 1e-12) + 1e-12);
    solver.set_stop_time(stop).map_err(|e| solver_error(method, start, e))?;
    record(deployment, run, start, &read(solver.state().y), true);
    let mut steps = 0;
    let outcome = loop {
        if steps >= settings.max_steps {
            run.hit_step_limit = true;
            let state = solver.state();
            break Phase {
                state: read(state.y),
                time: state.t,
                event: false,
            };
        }
        steps += 1;
        let reason = solver.step();
        if let Some(error) = deployment.failure.borrow_mut().take() {
            return Err(error);
        }
        match reason.map_err(|e| solver_error(method, solver.state().t, e))? {
            OdeSolverStopReason::InternalTimestep => {
                let state = solver.state();
                record(deployment, run, state.t, &read(state.y), false);
            }
            OdeSolverStopReason::RootFound(time, _) => {
                let y = solver.interpolate(time).map_err(|e| solver_error(method, time, e))?;
                let state = read(&y);
                record(deployment, run, time, &state, true);
                break Phase {
                    state,
                    time,
                    event: true,
                };
            }
            OdeSolverStopReason::TstopReached => {
                let state = solver.state();
                let phase = Phase {
                    state: read(state.y),
                    time: state.t,
                    event: false,
                };
                record(deployment, run, phase.time, &phase.state, true);
                break phase;
            }
        }
    };
    let statistics = solver.get_statistics();
    run.counts.add(SolverCounts {
        steps: statistics.number_of_steps,
        rejected_steps: statistics.number_of_error_test_failures + statistics.number_of_nonlinear_solver_fails,
        jacobian_evaluations: statistics.number_of_linear_solver_setups,
        rhs_evaluations: solver.problem().eqn.rhs().statistics().number_of_calls,
    });
    Ok(outcome)
}

/// Takes a step's state into the peaks, and into the time history when it is an event
/// (`always`: a phase's start, its event or its end) or the `stride`-th ordinary step. When
/// the history reaches [`MAX_TIME_HISTORY_SAMPLES`], every other ordinary sample is dropped
/// (the first and the last kept) and the stride doubles: the history stays evenly
/// decimated in steps and bounded whatever `max_steps` allows.
fn record(deployment: &Deployment, run: &mut DynamicsRun, time_s: f64, state: &[f64; STATES], always: bool) {
    let torque = deployment.drive.motor.torque_constant_nm_per_a * state[2];
    run.peak_current_a = run.peak_current_a.max(state[2].abs());
    run.peak_motor_torque_nm = run.peak_motor_torque_nm.max(torque.abs());
    if !always {
        let since = deployment.since_kept.get() + 1;
        if since < deployment.stride.get() {
            deployment.since_kept.set(since);
            return;
        }
    }
    deployment.since_kept.set(0);
    if run.samples.len() >= MAX_TIME_HISTORY_SAMPLES {
        let last = run.samples.len() - 1;
        let mut index = 0;
        run.samples.retain(|_| {
            let keep = index == 0 || index == last || index % 2 == 0;
            index += 1;
            keep
        });
        deployment.stride.set(deployment.stride.get().saturating_mul(2));
    }
    run.samples.push(DynamicsSample {
        time_s,
        input: state[0],
        rate: state[1],
        current_a: state[2],
        motor_torque_nm: torque,
        voltage_v: deployment.supply.at(time_s),
    });
}

fn finish(deployment: &Deployment, mut run: DynamicsRun, state: [f64; STATES]) -> Result<DynamicsRun> {
    let g = deployment
        .system
        .generalised_at(state[0])
        .map_err(|source| Error::Mechanism {
            input: state[0],
            source,
        })?;
    let energy = &mut run.energy;
    energy.supplied_j = state[3];
    energy.resistive_j = state[4];
    energy.gearbox_j = state[5];
    energy.load_work_j = state[6];
    energy.magnetic_j = 0.5 * deployment.drive.motor.inductance_h * state[2] * state[2];
    energy.kinetic_j = 0.5 * deployment.effective_inertia(&g) * state[1] * state[1];
    energy.residual_j =
        energy.supplied_j - energy.resistive_j - energy.gearbox_j - energy.magnetic_j - energy.kinetic_j
            + energy.load_work_j;
    Ok(run)
}
