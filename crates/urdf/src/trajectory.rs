//! The trajectory file beside the URDF: joint values per deployment sample and key points.

use std::collections::BTreeMap;

use nalgebra::Point3;
use serde::Serialize;

use super::layout::{key_points, validate_stations, StationTree};
use super::StationMechanism3d;
use crate::error::{Error, Result};

/// A named point fixed on one URDF link, for checking forward kinematics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KeyPoint {
    /// `<station>.<point>` for a point fixed on the station (A0, B0),
    /// `<station>.<body>.<point>` for one a body carries, `<flap>.<point>` on the flap link.
    pub name: String,
    /// The URDF link that carries the point.
    pub link: String,
    /// Its position in that link's frame (m).
    pub position_link_m: [f64; 3],
}

/// One deployment sample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrajectorySample {
    /// Actuator input of every station (m or rad), in [`Trajectory::stations`] order.
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
    /// Movable joint names `<station>_<seam joint>` in each station's tree order: the
    /// relative rotation (rad, revolute) or slide (m, prismatic) since stowed.
    pub joint_names: Vec<String>,
    /// Key points and the links that carry them.
    pub key_points: Vec<KeyPoint>,
    /// Deployment samples, stowed first.
    pub samples: Vec<TrajectorySample>,
}

/// `samples` deployment samples: each station at the same drive fraction, from stowed to
/// deployed (both included), posed through the mechanism seam, with key points mapped to
/// the aircraft frame by `aircraft_from_station`.
///
/// Errors: [`Error::TooFewSamples`] below 2, the station checks of
/// [`super::build_robot`], and pose errors.
pub fn trajectory(stations: &[StationMechanism3d], samples: usize) -> Result<Trajectory> {
    if samples < 2 {
        return Err(Error::TooFewSamples { samples });
    }
    validate_stations(stations)?;
    let trees = stations.iter().map(StationTree::new).collect::<Result<Vec<_>>>()?;
    let layouts = stations
        .iter()
        .zip(&trees)
        .map(|(s, t)| key_points(s, t))
        .collect::<Result<Vec<_>>>()?;
    let inputs: Vec<Vec<f64>> = stations
        .iter()
        .map(|s| s.mechanism.input_range().samples(samples))
        .collect();
    let mut trajectory = Trajectory {
        stations: stations.iter().map(|s| s.name.clone()).collect(),
        joint_names: trees
            .iter()
            .flat_map(|t| t.movable().map(|l| l.joint_name.clone()))
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
            joint_values: Vec::with_capacity(trajectory.joint_names.len()),
            key_points_ac_m: BTreeMap::new(),
        };
        for (((station, tree), layout), station_inputs) in stations.iter().zip(&trees).zip(&layouts).zip(&inputs) {
            let input = station_inputs[index];
            let pose = station.mechanism.pose(input)?;
            sample.input_m.push(input);
            let values = tree.joint_values(&pose);
            if values.iter().any(|v| !v.is_finite()) {
                return Err(Error::NonFinite {
                    quantity: "URDF joint value",
                    input_m: input,
                });
            }
            sample.joint_values.extend(values);
            for point in layout {
                let p = pose.point(&point.follows).ok_or(Error::NonFinite {
                    quantity: "key point",
                    input_m: input,
                })?;
                let p_ac = station.aircraft_from_station * Point3::new(p.x, p.y, 0.0);
                sample.key_points_ac_m.insert(point.name.clone(), to_array(p_ac));
            }
        }
        trajectory.samples.push(sample);
    }
    Ok(trajectory)
}

fn to_array(p: Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}
