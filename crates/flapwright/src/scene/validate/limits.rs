//! Magnitude limits of scene values: every length, count and resolution has a finite
//! range, so that a valid scene has bounded run time and memory (`docs/scene.md`'s scene
//! reference quotes these numbers).
//!
//! The ranges are wide enough for every real wing from a 1/17 wind-tunnel model to the
//! largest transport (semi-span 40 m, root chord 15 m), and narrow enough that a typo
//! (`1e308`, `1e-300`) is caught before it reaches a mesher or a sampler.

/// Largest distance of any scene point from the origin, per coordinate, m.
pub const MAX_ABS_COORDINATE_M: f64 = 1_000.0;
/// Largest spanwise position and root-to-tip span, m (A380 semi-span: 40 m).
pub const MAX_SPAN_M: f64 = 100.0;
/// Smallest section chord, m (a 1/17 model of a 0.1 m chord is 6 mm).
pub const MIN_CHORD_M: f64 = 0.005;
/// Largest section chord, m.
pub const MAX_CHORD_M: f64 = 50.0;
/// Shortest length anywhere (spar thickness, tube radius, axis and segment lengths), m.
pub const MIN_LENGTH_M: f64 = 1e-4;
/// Most wing sections.
pub const MAX_SECTIONS: usize = 64;
/// Most flaps.
pub const MAX_FLAPS: usize = 16;
/// Most support stations (the work budget may allow fewer, see `budget`).
pub const MAX_STATIONS: usize = 64;
/// Most spars.
pub const MAX_SPARS: usize = 8;
/// Most points on the torque-tube polyline.
pub const MAX_TORQUE_TUBE_POINTS: usize = 256;
/// Most custom materials.
pub const MAX_MATERIALS: usize = 64;
/// Custom material density, kg/m^3 (balsa 100 to tungsten 19 300, with margin).
pub const DENSITY_KG_M3: (f64, f64) = (10.0, 25_000.0);
/// Allowable stresses, Pa (1 MPa foams to 10 GPa, above any metal or composite).
pub const ALLOWABLE_PA: (f64, f64) = (1e6, 1e10);
/// Young's modulus, Pa (1 GPa plastics to 1.2 TPa diamond).
pub const YOUNGS_MODULUS_PA: (f64, f64) = (1e8, 1.2e12);
/// Gearbox efficiency: below 5 % no drive is designed on purpose.
pub const GEARBOX_EFFICIENCY: (f64, f64) = (0.05, 1.0);
/// Airfoil points per side (resampling).
pub const AIRFOIL_POINTS_PER_SIDE: (usize, usize) = (8, 2000);
/// Deployment samples per load case.
pub const DEPLOYMENT_SAMPLES: (usize, usize) = (2, 100_000);
/// Fairing samples over the deployment.
pub const FAIRING_SAMPLES: (usize, usize) = (2, 10_001);
/// Fairing points per capsule outline.
pub const FAIRING_POINTS_PER_CAPSULE: (usize, usize) = (2, 1_000);
/// Initial samples of each clearance sweep.
pub const INITIAL_SAMPLES: (usize, usize) = (2, 10_000);
/// Largest evaluation cap of one clearance sweep.
pub const MAX_EVALUATIONS: usize = 100_000;

/// Mechanism link lengths, slot radii and the screw length, m: 1 mm (a 1/17 model's
/// links are a few mm) to 20 m (above any transport flap's track).
pub const MECHANISM_LENGTH_M: (f64, f64) = (1e-3, 20.0);
/// Flap mass carried by one station, kg (0: a massless flap, the hinge moment alone; up to a
/// transport flap's tonnes).
pub const FLAP_MASS_KG: (f64, f64) = (0.0, 1e5);
/// Screw lead, m (0.1 mm fine threads to 100 mm multi-start ball screws).
pub const SCREW_LEAD_M: (f64, f64) = (1e-4, 0.1);
/// Screw mean thread radius, m.
pub const SCREW_MEAN_RADIUS_M: (f64, f64) = (1e-4, 1.0);
/// Screw friction coefficient (0: frictionless ideal; 1: dry steel on steel at worst).
pub const SCREW_FRICTION: (f64, f64) = (0.0, 1.0);
/// Nut speed, m/s (0.1 mm/s to 10 m/s).
pub const NUT_SPEED_MPS: (f64, f64) = (1e-4, 10.0);
/// Smallest angle between the two slot pins seen from the hinge, deg: at 0 or 180 deg the
/// pins lie on one line through A0 and their radial reactions cannot hold a tangential load
/// (thesis eqs 3.5.x, Cramer determinant sin(theta_F - theta_G) = 0).
pub const MIN_SLOT_OFFSET_ANGLE_DEG: f64 = 1.0;
