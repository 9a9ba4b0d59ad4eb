//! Sizing: flap loads, rods, screw jacks, torque tubes, drive power and weights.
//!
//! # Overview
//!
//! Data flows in the order of `003_...` (Zaccai, Bertels, Vos 2016) section 4:
//! 1. [`loads`]: flap normal load by spanwise elements, N = C_N c b q (eq 1), with C_N
//!    from a [`NormalForceTable`] and a [`LoadCase`] (load factor, CS-25 safety factor 1.5).
//! 2. [`distribution`]: element loads to the support stations and, per station, to the
//!    forward and aft attachment points, by statics (the printed eqs 2-3 are corrected).
//! 3. The mechanism crate turns attachment loads into link forces and screw torques over
//!    the deployment (not here).
//! 4. [`rod`]: each link sized for tension, compression and Euler buckling; [`actuator`]:
//!    motor torque and self-locking (thesis `000` sections 3.6, 5.2); [`torque_tube`]:
//!    cumulative drive torque and tube radii (eqs 4, 6, 7); [`drive`]: power (eq 5) and
//!    work per deployment; [`weights`]: masses per station and in total.
//! 5. [`report`]: [`SizingReport`], the `sizing` section of `report.json`.
//!
//! # Units and frames
//!
//! SI throughout: m, N, N m, Pa, kg, kg/m^3, rad, rad/s, W, J. Flap loads are along the
//! flap normal (upper side positive), moments about the spanwise axis nose-up positive,
//! chordwise positions measured aft of the forward-attachment (hinge) line, spanwise
//! positions along the hinge line from any origin shared by elements and stations.
//!
//! # Design notes
//!
//! - Inputs are plain typed values, so this crate depends on no other flapwright crate;
//!   the CLI maps mechanism results (link force histories, screw torques) onto them.
//! - Each sizing result keeps the radius of every requirement, not just the governing
//!   one, so a report can show the margin.
//! - Suspicious but computable results (a rod fatter than its station, a non-slender
//!   rod, an intermediate column, a back-drivable screw) are returned with a
//!   [`SizingWarning`] carrying the numbers, never silently.
//!
//! # Limitations
//!
//! - Rods carry axial load; members that bend are sized for the peak combined stress of
//!   round sections (axial plus amplified bending, [`bending_radius_m`]); no shear, no
//!   stress concentration, no fatigue spectrum (use a fatigue allowable in the
//!   [`Material`] as `003_...` 5.1 does).
//! - Spanwise distribution for more than two stations treats the flap as pinned
//!   segments between stations (as the `003_...` multi-body model does), not as a
//!   continuous beam.
//! - Torque tubes sum the peak station torques (conservative when the peaks occur at
//!   different deployment angles); screw jack, gearbox and motor masses are not modelled.
//!
//! # Pitfalls
//!
//! - Rod and tube loads are design loads: multiply by [`LoadCase::design_factor`] once,
//!   upstream, not again here.
//! - `003_...` eqs 2-3 as printed divide a moment by 2; the correct divisor is the
//!   attachment spacing l ([`distribution`] docs).
//! - Screw jack torques: if they come from loads already factored by the [`LoadCase`],
//!   size the jack with safety factor 1.0; the thesis (section 5.2) applies 1.5 to
//!   torques from unfactored loads.
//! - An element's load acts at its midpoint: split elements at the stations, or an
//!   element straddling a station sends its whole load to one segment.
//! - Lowering torque sign follows thesis eq 3.6.10: positive means self-locking.
//! - Torque tubes are listed from the far (outboard) end towards the motor.

pub mod actuator;
pub mod distribution;
pub mod drive;
mod error;
pub mod loads;
pub mod material;
pub mod report;
pub mod rod;
pub mod section;
pub mod torque_tube;
pub mod warning;
pub mod weights;

mod check;

pub use actuator::{motor_torque_nm, size_actuator, ActuatorInput, ActuatorSizing};
pub use distribution::{
    attachment_loads, distribute_to_stations, station_attachment_loads, AttachmentLoads, StationLoad,
};
pub use drive::{deployment_work_j, drive_demand, drive_power_w, DeploymentWork, DriveDemand};
pub use error::{Error, Result};
pub use loads::{
    element_loads, element_normal_force_n, ElementLoad, FlapElement, LoadCase, NormalForceTable, CS25_SAFETY_FACTOR,
};
pub use material::Material;
pub use report::{SizingReport, SizingTotals};
pub use rod::{
    axial_envelope_n, bending_radius_m, buckling_radius_m, euler_critical_load_n, size_rod, strength_radius_m,
    BendingLoad, GoverningCase, RodInput, RodSizing,
};
pub use section::SectionShape;
pub use torque_tube::{
    cumulative_torques_nm, ideal_motor_torque_nm, size_torque_tubes, torsion_radius_m, TorqueTubeInput,
    TorqueTubeSizing,
};
pub use warning::SizingWarning;
pub use weights::{mass_kg, prism_volume_m3, MassBreakdown, MassItem, StationMass};

/// The screw thread (thesis eqs 3.6.9, 3.6.10) is the mechanism crate's.
pub use flapwright_mechanism::ScrewJack;
