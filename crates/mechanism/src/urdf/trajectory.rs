//! The trajectory file beside the URDF: joint values per deployment sample and key points.

use std::collections::BTreeMap;

use nalgebra::Point3;
use serde::Serialize;

use super::layout::{joint_values, key_points, stroke_inputs, validate_stations, StationNames};
use super::StationMechanism3d;
use crate::error::{Error, Result};

/// A named point fixed on one URDF link, for checking forward kinematics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KeyPoint {
    /// `<station>.<point>` (A0, B0, B, A_nut, A, D, F, G) or `<flap>.<point>` (D, F, G).
    pub name: String,
    /// The URDF link that carries the point.
    pub link: String,
    /// Its position in that link's frame (m).
    pub position_link_m: [f64; 3],
}

/// One deployment sample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrajectorySample {
    /// Nut position s34 (m) of every station, in [`Trajectory::stations`] order.
    pub input_m: Vec<f64>,
    /// URDF joint values in [`Trajectory::joint_names`] order (rad for revolute joints,
    /// m for prismatic ones).
    pub joint_values: Vec<f64>,
    /// Every key point by name, from the mechanism's own pose, aircraft frame (m).
    pub key_points_ac_m: BTreeMap<String, [f64; 3]>,
}

/// Joint values that reproduce the computed poses, with key points to check them.
///
/// Applying `joint_values` to the robot of [`super::build_robot`] (same stations) puts
/// every [`KeyPoint`] (link frame) at its `key_points_ac_m` entry (aircraft frame): the
/// integration test walks the URDF tree and checks this to 1e-6 m at every sample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trajectory {
    /// Station names, in input order.
    pub stations: Vec<String>,
    /// Movable joint names: per station `<s>_flap_hinge` (deflection θ12 - θ12,i, rad),
    /// `<s>_screw_pivot` (θ13 - θ13,i, rad), `<s>_nut_slide` (s34, m).
    pub joint_names: Vec<String>,
    /// Key points and the links that carry them.
    pub key_points: Vec<KeyPoint>,
    /// Deployment samples, stowed first.
    pub samples: Vec<TrajectorySample>,
}

/// `samples` deployment samples: each station's nut at evenly spaced s34 from s34,i to
/// s34,f (both included, the same fraction of each station's stroke), posed by
/// [`crate::CircularArcTrack::pose`], with key points mapped to the aircraft frame by
/// `aircraft_from_station`.
///
/// Errors: [`Error::TooFewSamples`] below 2, the station checks of
/// [`super::build_robot`], and pose errors.
pub fn trajectory(stations: &[StationMechanism3d], samples: usize) -> Result<Trajectory> {
    if samples < 2 {
        return Err(Error::TooFewSamples { samples });
    }
    validate_stations(stations)?;
    let layouts: Vec<_> = stations.iter().map(key_points).collect();
    let inputs: Vec<Vec<f64>> = stations.iter().map(|s| stroke_inputs(s.track, samples)).collect();
    let mut trajectory = Trajectory {
        stations: stations.iter().map(|s| s.name.clone()).collect(),
        joint_names: stations
            .iter()
            .flat_map(|s| StationNames::new(&s.name).movable_joints())
            .collect(),
        key_points: layouts
            .iter()
            .flatten()
            .map(|k| KeyPoint {
                name: k.name.clone(),
                link: k.link.clone(),
                position_link_m: to_array(k.position_link_m),
            })
            .collect(),
        samples: Vec::with_capacity(samples),
    };
    for index in 0..samples {
        let mut sample = TrajectorySample {
            input_m: Vec::with_capacity(stations.len()),
            joint_values: Vec::with_capacity(3 * stations.len()),
            key_points_ac_m: BTreeMap::new(),
        };
        for ((station, layout), station_inputs) in stations.iter().zip(&layouts).zip(&inputs) {
            let input_m = station_inputs[index];
            let pose = station.track.pose(input_m, 0.0, 0.0)?;
            sample.input_m.push(input_m);
            sample.joint_values.extend(joint_values(station.track, &pose));
            for point in layout {
                let p = point.follows.at(station.track, &pose);
                let p_ac = station.aircraft_from_station * Point3::new(p.x, p.y, 0.0);
                sample.key_points_ac_m.insert(point.name.clone(), to_array(p_ac));
            }
        }
        if let Some(bad) = sample.joint_values.iter().position(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                quantity: "URDF joint value",
                input_m: sample.input_m[bad / 3],
            });
        }
        trajectory.samples.push(sample);
    }
    Ok(trajectory)
}

fn to_array(p: Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}
