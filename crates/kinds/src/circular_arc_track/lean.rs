//! The lean deployment sweep (issue 39): what a trade study plots of the track at many nut
//! positions (θ12, θ13, their rates and accelerations, points A and D with velocities and
//! accelerations, F_input and the screw torques T_R, T_L: 21 columns), in structure-of-arrays
//! form, without the diagnostics, slot reactions and virtual-work cross-check of the full
//! [`Sweep`](super::Sweep), which a report asks for and a sweep of thousands of samples does
//! not.
//!
//! Same equations as `pose` and `kinetostatics` (thesis 3.1-3.4, 3.6), with the trigonometry
//! the triangle A0 B0 A already answers replaced by algebra: cos θ12 and sin θ12 are the law
//! of cosines' numerator and Kahan's area over 2 a1 a2, so a sample costs one square root, two
//! divisions and the two `atan2` that give the angles themselves. Equal to the full sweep to
//! 1e-12 (test `the_lean_sweep_is_the_full_sweeps_columns`).
//!
//! Why it is shaped as it is (`cargo bench -p flapwright-kinds --bench pose`,
//! `lean_sweep_1000`; BENCHMARKS.md): the columns share one allocation (24 separate ones
//! made glibc return and refetch the heap's top on every call, a quarter of the time); the
//! angles are computed in a loop of their own, since the `atan2` calls clobber every vector
//! register the arithmetic would keep; `libm`'s `atan2` (musl's, in Rust, already among the
//! workspace's crates) is inlined where the C library's goes through a wrapper that sets
//! `errno`: 80 against 84 µs a 1000-sample sweep.

use super::sweep::SweepStop;
use super::synthesis::CircularArcTrack;
use super::CircularArcTrackSpec;
use flapwright_mechanism::shared::angle::four_times_triangle_area;
use flapwright_mechanism::shared::load_case::{ExternalMoment, LoadCase};
use flapwright_mechanism::{Error, Result};

/// Relative slack on the triangle inequality attributed to rounding (as the slider-crank's).
const TRIANGLE_ROUNDING_TOLERANCE: f64 = 1e-14;

/// Relative slack on the slot ends attributed to rounding (as the pose's red cell 1).
const SLOT_END_TOLERANCE: f64 = 1e-12;

/// A column of a [`LeanSweep`]: the nut position and the 21 figures computed from it.
/// Station frame (thesis: x towards the nose, y up, origin at the hinge A0); SI units.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LeanColumn {
    /// s34 (m).
    Input,
    /// θ12 (rad), thesis eq. 3.1.1.
    CrankAngle,
    /// θ13 (rad), thesis eq. 3.1.2.
    SliderAngle,
    /// ω12 (rad/s).
    CrankRate,
    /// ω13 (rad/s).
    SliderRate,
    /// α12 (rad/s²).
    CrankAccel,
    /// α13 (rad/s²).
    SliderAccel,
    /// A, the nut pivot on the flap: x (m).
    NutPivotX,
    /// A: y (m).
    NutPivotY,
    /// A: dx/dt (m/s).
    NutPivotVx,
    /// A: dy/dt (m/s).
    NutPivotVy,
    /// A: d²x/dt² (m/s²).
    NutPivotAx,
    /// A: d²y/dt² (m/s²).
    NutPivotAy,
    /// D, the flap's centre of mass: x (m).
    CentreOfMassX,
    /// D: y (m).
    CentreOfMassY,
    /// D: dx/dt (m/s).
    CentreOfMassVx,
    /// D: dy/dt (m/s).
    CentreOfMassVy,
    /// D: d²x/dt² (m/s²).
    CentreOfMassAx,
    /// D: d²y/dt² (m/s²).
    CentreOfMassAy,
    /// F_input (N), eq. 3.4.16.
    ActuatorForce,
    /// T_R (N m), eq. 3.6.9.
    RaiseTorque,
    /// T_L (N m), eq. 3.6.10.
    LowerTorque,
}

impl LeanColumn {
    /// Every column in storage order.
    pub const ALL: [Self; 22] = [
        Self::Input,
        Self::CrankAngle,
        Self::SliderAngle,
        Self::CrankRate,
        Self::SliderRate,
        Self::CrankAccel,
        Self::SliderAccel,
        Self::NutPivotX,
        Self::NutPivotY,
        Self::NutPivotVx,
        Self::NutPivotVy,
        Self::NutPivotAx,
        Self::NutPivotAy,
        Self::CentreOfMassX,
        Self::CentreOfMassY,
        Self::CentreOfMassVx,
        Self::CentreOfMassVy,
        Self::CentreOfMassAx,
        Self::CentreOfMassAy,
        Self::ActuatorForce,
        Self::RaiseTorque,
        Self::LowerTorque,
    ];

    /// The column's name with its unit, as a table's header gives it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Input => "input_m",
            Self::CrankAngle => "crank_angle_rad",
            Self::SliderAngle => "slider_angle_rad",
            Self::CrankRate => "crank_rate_radps",
            Self::SliderRate => "slider_rate_radps",
            Self::CrankAccel => "crank_accel_radps2",
            Self::SliderAccel => "slider_accel_radps2",
            Self::NutPivotX => "nut_pivot_a_x_m",
            Self::NutPivotY => "nut_pivot_a_y_m",
            Self::NutPivotVx => "nut_pivot_a_vx_mps",
            Self::NutPivotVy => "nut_pivot_a_vy_mps",
            Self::NutPivotAx => "nut_pivot_a_ax_mps2",
            Self::NutPivotAy => "nut_pivot_a_ay_mps2",
            Self::CentreOfMassX => "centre_of_mass_d_x_m",
            Self::CentreOfMassY => "centre_of_mass_d_y_m",
            Self::CentreOfMassVx => "centre_of_mass_d_vx_mps",
            Self::CentreOfMassVy => "centre_of_mass_d_vy_mps",
            Self::CentreOfMassAx => "centre_of_mass_d_ax_mps2",
            Self::CentreOfMassAy => "centre_of_mass_d_ay_mps2",
            Self::ActuatorForce => "actuator_force_n",
            Self::RaiseTorque => "raise_torque_nm",
            Self::LowerTorque => "lower_torque_nm",
        }
    }
}

/// A lean deployment sweep under one load case: one column per [`LeanColumn`], a row per
/// sample, every column in one buffer (column-major, as a 22 × samples array).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LeanSweep {
    samples: usize,
    values: Vec<f64>,
    /// Set when the sweep could not reach the end (the columns stop before it).
    pub stopped: Option<SweepStop>,
}

impl LeanSweep {
    /// Samples in each column.
    pub fn len(&self) -> usize {
        self.samples
    }

    /// True when no sample was computed.
    pub fn is_empty(&self) -> bool {
        self.samples == 0
    }

    /// One column, a value per sample.
    pub fn column(&self, column: LeanColumn) -> &[f64] {
        let start = column as usize * self.samples;
        &self.values[start..start + self.samples]
    }

    /// Every column one after another in [`LeanColumn::ALL`]'s order (column-major).
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Keeps the first `samples` of every column.
    fn truncate(&mut self, samples: usize) {
        if samples >= self.samples {
            return;
        }
        for column in 1..LeanColumn::ALL.len() {
            let from = column * self.samples;
            self.values.copy_within(from..from + samples, column * samples);
        }
        self.values.truncate(LeanColumn::ALL.len() * samples);
        self.samples = samples;
    }
}

impl CircularArcTrack {
    /// The lean sweep at the full sweep's inputs: `samples` evenly spaced nut positions from
    /// s34,i to s34,f at the spec's nominal speed and acceleration, under `load` (its
    /// inertia included when it asks, as [`CircularArcTrack::forces`]).
    ///
    /// Errors: [`Error::TooFewSamples`] for fewer than 2 samples. An input outside the
    /// slots, a toggle or a non-finite figure stops the sweep there, said in
    /// [`LeanSweep::stopped`] as the full sweep says it.
    pub fn lean_sweep(&self, samples: usize, load: &LoadCase) -> Result<LeanSweep> {
        let inputs = self.evenly_spaced_inputs(samples)?;
        Ok(self.lean_sweep_at(inputs, load))
    }

    /// The lean sweep at the given nut positions (m).
    pub fn lean_sweep_at(&self, inputs: impl IntoIterator<Item = f64>, load: &LoadCase) -> LeanSweep {
        let mut sweep = LeanSweep::default();
        self.lean_sweep_at_into(inputs, load, &mut sweep);
        sweep
    }

    /// [`CircularArcTrack::lean_sweep`] into `sweep`, whose buffer is reused: a trade study
    /// sweeping many mechanisms (or a caller from another language) allocates once, where a
    /// buffer above the C library's threshold for mapping fresh pages costs page faults on
    /// every call (a third of a 1000-sample sweep called from Python on this machine).
    pub fn lean_sweep_into(&self, samples: usize, load: &LoadCase, sweep: &mut LeanSweep) -> Result<()> {
        let inputs = self.evenly_spaced_inputs(samples)?;
        self.lean_sweep_at_into(inputs, load, sweep);
        Ok(())
    }

    /// [`CircularArcTrack::lean_sweep_at`] into `sweep`, whose buffer is reused.
    pub fn lean_sweep_at_into(&self, inputs: impl IntoIterator<Item = f64>, load: &LoadCase, sweep: &mut LeanSweep) {
        let values = &mut sweep.values;
        values.clear();
        values.extend(inputs);
        let samples = values.len();
        values.resize(LeanColumn::ALL.len() * samples, 0.0);
        sweep.samples = samples;
        sweep.stopped = None;
        if let Some(stop) = LeanConstants::of(self, load).fill_columns(self, sweep) {
            sweep.truncate(stop.sample_index);
            sweep.stopped = Some(stop);
        }
    }

    /// Red cell 1 (s34 within the slots) and the triangle A0 B0 A's 4 × area (m²), as
    /// [`CircularArcTrack::pose`] checks them.
    fn lean_triangle(&self, s: f64) -> Result<f64> {
        let synthesis = &self.synthesis;
        let slack = SLOT_END_TOLERANCE * synthesis.stroke_end_m;
        if !(s >= synthesis.stroke_start_m - slack && s <= synthesis.stroke_end_m + slack) {
            return Err(Error::OutOfSlot {
                input_m: s,
                min_input_m: synthesis.stroke_start_m,
                max_input_m: synthesis.stroke_end_m,
            });
        }
        let (a1, a2) = (self.spec.base_distance_m, self.spec.crank_length_m);
        four_times_triangle_area(a1, a2, s, TRIANGLE_ROUNDING_TOLERANCE).ok_or_else(|| {
            let (min_input_m, max_input_m) = self.linkage.assembly_range_m();
            Error::CannotAssemble {
                input_m: s,
                min_input_m,
                max_input_m,
            }
        })
    }
}

/// The published case's lean sweep (`000_...` Table 2, [`CircularArcTrackSpec::thesis_case_study`])
/// into `sweep`: the track synthesised once and shared, the buffer reused (a caller from
/// another language asks for the deployment, not for a mechanism of its own).
pub fn thesis_lean_sweep_into(samples: usize, load: &LoadCase, sweep: &mut LeanSweep) -> Result<()> {
    static TRACK: std::sync::OnceLock<Result<CircularArcTrack>> = std::sync::OnceLock::new();
    let track = TRACK.get_or_init(|| CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()));
    track
        .as_ref()
        .map_err(Clone::clone)?
        .lean_sweep_into(samples, load, sweep)
}

/// A point's six columns (x, y, vx, vy, ax, ay) cut to one length.
struct PointSlices<'a>([&'a mut [f64]; 6]);

impl PointSlices<'_> {
    /// Sample `i` of a point at `(x, y)` from the hinge A0 on the flap turning at `rate`
    /// (rad/s) with `accel` (rad/s²): v = ω k×r, a = α k×r - ω² r.
    #[inline(always)]
    fn set(&mut self, i: usize, (x, y): (f64, f64), rate: f64, accel: f64) {
        let [px, py, vx, vy, ax, ay] = &mut self.0;
        px[i] = x;
        py[i] = y;
        vx[i] = -y * rate;
        vy[i] = x * rate;
        ax[i] = -y * accel - x * rate * rate;
        ay[i] = x * accel - y * rate * rate;
    }
}

/// What every sample shares: lengths, the base direction, the stowed directions, the load.
struct LeanConstants {
    base_m: f64,
    crank_m: f64,
    /// cos α0, sin α0: A0 B0's direction.
    base_direction: (f64, f64),
    /// A_i / a2: the crank's stowed direction, which the flap's rotation takes to A0A.
    stowed_crank_direction: (f64, f64),
    centre_of_mass_stowed: (f64, f64),
    speed: f64,
    accel: f64,
    /// n m g (N).
    weight_n: f64,
    /// T_R and T_L per newton of screw load (m).
    raise_per_newton_m: f64,
    lower_per_newton_m: f64,
    moment: ExternalMoment,
    include_inertia: bool,
    stroke_start_m: f64,
    stroke_m: f64,
}

impl LeanConstants {
    fn of(track: &CircularArcTrack, load: &LoadCase) -> Self {
        let (spec, synthesis) = (&track.spec, &track.synthesis);
        let base = synthesis.screw_mount_m.coords / spec.base_distance_m;
        let stowed = synthesis.nut_pivot_stowed_m.coords / spec.crank_length_m;
        let per_newton = spec.screw.torques(1.0);
        Self {
            base_m: spec.base_distance_m,
            crank_m: spec.crank_length_m,
            base_direction: (base.x, base.y),
            stowed_crank_direction: (stowed.x, stowed.y),
            centre_of_mass_stowed: (spec.centre_of_mass_stowed_m.x, spec.centre_of_mass_stowed_m.y),
            speed: spec.nominal_input_speed_mps,
            accel: spec.nominal_input_accel_mps2,
            weight_n: load.load_factor * spec.flap_mass_kg * spec.gravity_mps2,
            raise_per_newton_m: per_newton.raise_torque_nm,
            lower_per_newton_m: per_newton.lower_torque_nm,
            moment: load.external_moment,
            include_inertia: load.include_inertia,
            stroke_start_m: synthesis.stroke_start_m,
            stroke_m: synthesis.stroke_m,
        }
    }

    /// Every column but the inputs: the slider-crank's state
    /// (`InvertedSliderCrank::state`), the flap's rotation taking A_i to A, and eq. 3.4.16
    /// with the screw torques; stops at the first sample that cannot be posed (red cell 1,
    /// assembly, toggle) or gives a non-finite figure and says which.
    ///
    /// Two divisions a sample, 1/s and 1/4A (4A = 4 × the triangle's area): sin δ and
    /// cos δ (δ = θ13 - θ12) enter only as 1/(a2 sin δ) = 2s/4A, cot δ = (a2² + s² - a1²)/4A,
    /// a2 cos δ = (a2² + s² - a1²)/2s and a2 sin δ = 4A/2s.
    fn fill_columns(&self, track: &CircularArcTrack, out: &mut LeanSweep) -> Option<SweepStop> {
        let samples = out.samples;
        let (a1, a2) = (self.base_m, self.crank_m);
        let (a1_squared, a2_squared) = (a1 * a1, a2 * a2);
        let tolerance = track.linkage.toggle_tolerance_rad;
        let mut chunks = out.values.chunks_exact_mut(samples.max(1));
        let mut next = || chunks.next().map_or(&mut [][..], |chunk| &mut chunk[..samples]);
        let input_m: &[f64] = next();
        let [crank_angle, slider_angle, crank_rate_out, slider_rate_out, crank_accel_out, slider_accel_out] =
            std::array::from_fn(|_| next());
        let mut point_a = PointSlices(std::array::from_fn(|_| next()));
        let mut point_d = PointSlices(std::array::from_fn(|_| next()));
        let [force_out, raise_out, lower_out] = std::array::from_fn(|_| next());

        // The triangle and the angles first, in a loop of their own (the `atan2` calls
        // clobber every vector register, which would spill the arithmetic's); the triangle's
        // area goes to the force column, which the second loop overwrites.
        let mut stop = None;
        for i in 0..samples {
            let s = input_m[i];
            let four_area = match track.lean_triangle(s) {
                Ok(four_area) => four_area,
                Err(reason) => {
                    stop = Some(stop_at(i, s, reason));
                    break;
                }
            };
            let crank = libm::atan2(four_area, a1_squared + a2_squared - s * s);
            let slider = std::f64::consts::PI - libm::atan2(four_area, a1_squared + s * s - a2_squared);
            let delta = slider - crank;
            let transmission = delta.min(std::f64::consts::PI - delta);
            if transmission < tolerance {
                let reason = Error::Toggle {
                    input_m: s,
                    transmission_angle_rad: transmission,
                    tolerance_rad: tolerance,
                };
                stop = Some(stop_at(i, s, reason));
                break;
            }
            force_out[i] = four_area;
            crank_angle[i] = crank;
            slider_angle[i] = slider;
        }

        let posed = stop.as_ref().map_or(samples, |stop| stop.sample_index);
        let (v, dv) = (self.speed, self.accel);
        let (bx, by) = self.base_direction;
        let (sx, sy) = self.stowed_crank_direction;
        let (dx0, dy0) = self.centre_of_mass_stowed;
        let half_over_a1a2 = 0.5 / (a1 * a2);
        let (mass, inertia) = (track.spec.flap_mass_kg, track.spec.flap_moment_of_inertia_kgm2);
        let inertia_on = if self.include_inertia { 1.0 } else { 0.0 };
        // The moment's law read once, so the loop has no branch on it.
        let (moment_stowed, moment_per_fraction) = match self.moment {
            ExternalMoment::Constant(moment) => (moment, 0.0),
            ExternalMoment::Linear { stowed_nm, deployed_nm } => (stowed_nm, deployed_nm - stowed_nm),
        };
        let over_stroke = 1.0 / self.stroke_m;
        for i in 0..posed {
            let (s, four_area) = (input_m[i], force_out[i]);
            let cos_d_numerator = a2_squared + s * s - a1_squared;
            let (over_s, over_area) = (1.0 / s, 1.0 / four_area);
            let rate_per_input = 2.0 * s * over_area;
            let cot_d = cos_d_numerator * over_area;
            let crank_rate = v * rate_per_input;
            let slider_rate = v * cot_d * over_s;
            // α12 = (s̈ - s ω13² + a2 ω12² cos δ) / (a2 sin δ).
            let crank_accel = (dv - s * slider_rate * slider_rate) * rate_per_input + crank_rate * crank_rate * cot_d;
            // α13 = (a2 α12 cos δ + a2 ω12² sin δ - 2 ṡ ω13) / s.
            let sum = crank_accel * cos_d_numerator + crank_rate * crank_rate * four_area;
            let slider_accel = (0.5 * sum * over_s - 2.0 * v * slider_rate) * over_s;

            // A0A's direction: the base direction turned by θ12, whose cosine and sine the
            // triangle gives (law of cosines, Kahan's area); A = a2 times it.
            let (cos12, sin12) = (
                (a1_squared + a2_squared - s * s) * half_over_a1a2,
                four_area * half_over_a1a2,
            );
            let crank_dir = (cos12 * bx - sin12 * by, sin12 * bx + cos12 * by);
            // D: the flap's stowed D turned as A_i's direction turns onto A0A's.
            let (cos_defl, sin_defl) = (sx * crank_dir.0 + sy * crank_dir.1, sx * crank_dir.1 - sy * crank_dir.0);
            let d = (cos_defl * dx0 - sin_defl * dy0, sin_defl * dx0 + cos_defl * dy0);
            let accel_d = (
                -d.1 * crank_accel - d.0 * crank_rate * crank_rate,
                d.0 * crank_accel - d.1 * crank_rate * crank_rate,
            );

            // Eq. 3.4.16: F = (M12 + x_D n m g [+ I α12 + D × m a_D]) / (a2 sin δ), the
            // d'Alembert terms multiplied by 0 or 1 rather than branched on, and M12 linear
            // in the stroke fraction clamped to [0, 1] (`ExternalMoment::at`).
            let fraction = ((s - self.stroke_start_m) * over_stroke).clamp(0.0, 1.0);
            let moment = moment_stowed + moment_per_fraction * fraction;
            let inertia_moment = inertia * crank_accel + mass * (d.0 * accel_d.1 - d.1 * accel_d.0);
            let force = (moment + self.weight_n * d.0 + inertia_on * inertia_moment) * rate_per_input;

            crank_rate_out[i] = crank_rate;
            slider_rate_out[i] = slider_rate;
            crank_accel_out[i] = crank_accel;
            slider_accel_out[i] = slider_accel;
            point_a.set(i, (a2 * crank_dir.0, a2 * crank_dir.1), crank_rate, crank_accel);
            point_d.set(i, d, crank_rate, crank_accel);
            force_out[i] = force;
            raise_out[i] = self.raise_per_newton_m * force;
            lower_out[i] = self.lower_per_newton_m * force;
        }
        // The first sample with a figure that is not finite, named as the full sweep names
        // it (the slider-crank's state before the forces).
        let first_not_finite = (0..posed).find_map(|i| {
            [
                ("crank_rate_radps", crank_rate_out[i]),
                ("slider_rate_radps", slider_rate_out[i]),
                ("crank_accel_radps2", crank_accel_out[i]),
                ("slider_accel_radps2", slider_accel_out[i]),
                ("actuator_force_n", force_out[i]),
            ]
            .into_iter()
            .find(|(_, value)| !value.is_finite())
            .map(|(quantity, _)| (i, quantity))
        });
        match first_not_finite {
            Some((i, quantity)) => {
                let reason = Error::NonFinite {
                    quantity,
                    input_m: input_m[i],
                };
                Some(stop_at(i, input_m[i], reason))
            }
            None => stop,
        }
    }
}

fn stop_at(sample_index: usize, input_m: f64, reason: Error) -> SweepStop {
    SweepStop {
        sample_index,
        input_m,
        reason,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::circular_arc_track::CircularArcTrackSpec;
    use LeanColumn::*;

    fn thesis_track() -> CircularArcTrack {
        CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).expect("the thesis case synthesises")
    }

    #[test]
    fn the_lean_sweep_is_the_full_sweeps_columns() {
        let track = thesis_track();
        let mut with_inertia = LoadCase::thesis_landing();
        with_inertia.include_inertia = true;
        for load in [LoadCase::thesis_cruise(), LoadCase::thesis_landing(), with_inertia] {
            let lean = track.lean_sweep(101, &load).expect("sweeps");
            assert_eq!(lean.len(), 101);
            assert_eq!(lean.values().len(), 22 * 101);
            assert!(lean.stopped.is_none());
            let spec = &track.spec;
            for (i, &input) in lean.column(Input).iter().enumerate() {
                let pose = track
                    .pose(input, spec.nominal_input_speed_mps, spec.nominal_input_accel_mps2)
                    .expect("poses");
                let forces = track.forces(&pose, &load).expect("forces");
                let (a, d, l) = (&pose.nut_pivot_a, &pose.centre_of_mass_d, &pose.linkage);
                let force_scale = forces.actuator_force_n.abs();
                for (column, full, scale) in [
                    (CrankAngle, l.crank_angle_rad, 1.0),
                    (SliderAngle, l.slider_angle_rad, 1.0),
                    (CrankRate, l.crank_rate_radps, 1.0),
                    (SliderRate, l.slider_rate_radps, 1.0),
                    (CrankAccel, l.crank_accel_radps2, 1.0),
                    (SliderAccel, l.slider_accel_radps2, 1.0),
                    (NutPivotX, a.position_m.x, 1.0),
                    (NutPivotY, a.position_m.y, 1.0),
                    (NutPivotVx, a.velocity_mps.x, 1.0),
                    (NutPivotVy, a.velocity_mps.y, 1.0),
                    (NutPivotAx, a.acceleration_mps2.x, 1.0),
                    (NutPivotAy, a.acceleration_mps2.y, 1.0),
                    (CentreOfMassX, d.position_m.x, 1.0),
                    (CentreOfMassY, d.position_m.y, 1.0),
                    (CentreOfMassVx, d.velocity_mps.x, 1.0),
                    (CentreOfMassVy, d.velocity_mps.y, 1.0),
                    (CentreOfMassAx, d.acceleration_mps2.x, 1.0),
                    (CentreOfMassAy, d.acceleration_mps2.y, 1.0),
                    (ActuatorForce, forces.actuator_force_n, force_scale),
                    (RaiseTorque, forces.screw.raise_torque_nm, force_scale),
                    (LowerTorque, forces.screw.lower_torque_nm, force_scale),
                ] {
                    let lean = lean.column(column)[i];
                    assert!(
                        (lean - full).abs() <= 1e-12 * scale.max(1.0),
                        "{} {} sample {i}: lean {lean} full {full}",
                        load.name,
                        column.name()
                    );
                }
            }
        }
    }

    #[test]
    fn the_lean_sweep_stops_where_the_full_sweep_stops() {
        let track = thesis_track();
        let landing = LoadCase::thesis_landing();
        let (start, end) = (track.synthesis.stroke_start_m, track.synthesis.stroke_end_m);
        let inputs = [start, 0.5 * (start + end), end * 1.01, end];
        let lean = track.lean_sweep_at(inputs, &landing);
        let full = track.sweep_at(inputs, &landing);
        assert_eq!(lean.len(), 2);
        assert_eq!(lean.stopped, full.stopped);
        assert!(matches!(
            lean.stopped.as_ref().map(|stop| &stop.reason),
            Some(Error::OutOfSlot { .. })
        ));
        // Truncation keeps each column's own first samples.
        let whole = track.lean_sweep_at(inputs[..2].iter().copied(), &landing);
        for column in LeanColumn::ALL {
            assert_eq!(lean.column(column), whole.column(column), "{}", column.name());
        }
        assert!(matches!(
            track.lean_sweep(1, &landing),
            Err(Error::TooFewSamples { samples: 1 })
        ));
        // A reused buffer gives what a fresh one does, a stop and its truncation included.
        let mut reused = track.lean_sweep(101, &landing).expect("sweeps");
        track.lean_sweep_at_into(inputs, &landing, &mut reused);
        assert_eq!(reused, lean);
        track.lean_sweep_into(11, &landing, &mut reused).expect("sweeps");
        assert_eq!(reused, track.lean_sweep(11, &landing).expect("sweeps"));
    }

    #[test]
    fn the_lean_sweep_stops_at_a_toggle() {
        let mut track = thesis_track();
        // A toggle tolerance above the whole stroke's transmission angle: the first sample.
        track.linkage.toggle_tolerance_rad = std::f64::consts::FRAC_PI_2;
        let lean = track.lean_sweep(11, &LoadCase::thesis_landing()).expect("sweeps");
        let full = track.sweep(11, &LoadCase::thesis_landing()).expect("sweeps");
        assert!(lean.is_empty());
        assert_eq!(lean.stopped, full.stopped);
        assert!(matches!(
            lean.stopped.map(|stop| stop.reason),
            Some(Error::Toggle { .. })
        ));
    }
}
