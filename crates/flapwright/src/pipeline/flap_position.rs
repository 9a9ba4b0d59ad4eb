//! Gap and overlap of each station's flap behind the main wing (Zaccai et al. `003`
//! definitions, measured in the station plane by `flapwright_planes::FlapBehindWing`) at the
//! scene's flap settings.

use flapwright_mechanism::{PrecisionPosition, StationOutline};
use flapwright_planes::FlapBehindWing;
use nalgebra::{Isometry2, Isometry3, Point2, Point3};

use crate::error::{Error, Result};
use crate::kinds::SynthesisContext;
use crate::pipeline::record::{
    structural_gap_m, AftSlotReport, AftSlotSetting, FlapPositionReport, PlacedStation, RigidFlapSetting,
    SettingPosition, StationRecord,
};
use crate::scene::{FlapScene, Problem, SceneError};

/// The flap is one rigid body. Where several stations carry it, or a station's plane is
/// skew-corrected, its take-off and landing poses in 3D are the rigid motions of
/// [`setting_poses`] (on each placed station), and each station's precision positions
/// become those poses as its plane sees them: the section points moved by the pose,
/// projected on the plane and fitted by a planar displacement. On a tapered flap the
/// poses are conical (`003_...` section 2, Fig. 2b); taken one station at a time the
/// settings would move a rigid flap apart. Returns per station what this changed, in the
/// order of `stations`; stations without settings or poses are left alone.
pub fn rigid_flap_settings(
    flap: &str,
    stations: &mut [(&PlacedStation, &mut SynthesisContext)],
) -> Result<Vec<Vec<RigidFlapSetting>>> {
    let lift = |p: &Point2<f64>| Point3::new(p.x, p.y, 0.0);
    let mut changes = vec![Vec::new(); stations.len()];
    for ((placed, context), change) in stations.iter_mut().zip(&mut changes) {
        let (Some(poses), Some(settings)) = (placed.setting_poses_ac, context.settings.as_mut()) else {
            continue;
        };
        let points = section_fit_points(placed, flap);
        let frame = placed.station.frame.aircraft_from_station();
        for (pose, position) in poses.iter().zip([&mut settings.0, &mut settings.1]) {
            let setting = position.name;
            let seen = frame.inverse() * pose * frame;
            let moved: Vec<Point3<f64>> = points.iter().map(|p| seen * lift(p)).collect();
            let in_plane: Vec<Point2<f64>> = moved.iter().map(|q| Point2::new(q.x, q.y)).collect();
            let displacement = flapwright_mechanism::shared::precision::fit_displacement(&points, &in_plane)
                .ok_or_else(|| Error::RigidFlapSetting {
                    flap: flap.to_string(),
                    setting,
                    station: placed.station.name.clone(),
                })?;
            let own = position.flap;
            change.push(RigidFlapSetting {
                setting,
                // Over the whole section, not the fitted points only: the extreme points
                // set the gap and the overlap.
                shift_from_station_target_m: placed
                    .polygons_of(|name| name == flap)
                    .iter()
                    .flatten()
                    .map(|p| (displacement * p - own * p).norm())
                    .fold(0.0, f64::max),
                out_of_plane_m: moved.iter().map(|q| q.z.abs()).fold(0.0, f64::max),
                deflection_in_plane_deg: displacement.rotation.angle().to_degrees(),
            });
            position.flap = displacement;
            position.deflection_rad = displacement.rotation.angle();
        }
    }
    Ok(changes)
}

/// Per station of `placed` (scene order), the take-off and landing 3D poses (aircraft
/// frame, mapping the stowed flap to the setting) its flap's settings ask for, where
/// several stations carry the flap or one of them asks for a skew-corrected plane: the
/// rigid motions fitted (`flapwright_geom::fit_rigid_motion`) to every station's flap
/// section points each moved by its own station's displacement for the setting's gap and
/// overlap; one station's displacement lifted into 3D when it is alone. `None` elsewhere,
/// and where the flap gives no take-off and landing gap and overlap.
pub fn setting_poses(
    scene: &crate::scene::Scene,
    placed: &[PlacedStation],
) -> Result<Vec<Option<[Isometry3<f64>; 2]>>> {
    let mut poses = vec![None; placed.len()];
    for flap in &scene.flap {
        let carriers: Vec<usize> = (0..placed.len().min(scene.station.len()))
            .filter(|&i| scene.station[i].flap.as_deref() == Some(flap.name.as_str()))
            .collect();
        let skewed = carriers
            .iter()
            .any(|&i| scene.station[i].plane == Some(flapwright_planes::PlaneConstruction::SkewCorrected));
        if carriers.len() < 2 && !skewed {
            continue;
        }
        let mut asked = Vec::new();
        for &i in &carriers {
            let (context, _) =
                synthesis_context(flap, &scene.flap, &placed[i], scene.interference.required_clearance_m)?;
            if let Some((takeoff, landing)) = context.settings {
                asked.push((i, [takeoff.flap, landing.flap]));
            }
        }
        if asked.is_empty() {
            continue;
        }
        let points: Vec<Vec<Point2<f64>>> = placed.iter().map(|p| section_fit_points(p, &flap.name)).collect();
        let frames: Vec<Isometry3<f64>> = placed
            .iter()
            .map(|p| *p.station.frame.aircraft_from_station())
            .collect();
        let mut both = [Isometry3::identity(); 2];
        for (which, setting) in ["takeoff", "landing"].into_iter().enumerate() {
            let setting_asks: Vec<(usize, Isometry2<f64>)> = asked.iter().map(|&(i, d)| (i, d[which])).collect();
            both[which] = fitted_pose(&points, &frames, &setting_asks).map_err(|source| Error::RigidFlapPose {
                flap: flap.name.clone(),
                setting,
                source,
            })?;
        }
        for &(i, _) in &asked {
            poses[i] = Some(both);
        }
    }
    Ok(poses)
}

/// The points of `flap`'s stowed section at `placed` that a rigid fit weighs (station
/// frame, m).
fn section_fit_points(placed: &PlacedStation, flap: &str) -> Vec<Point2<f64>> {
    flapwright_interference::fit_points(&placed.polygons_of(|name| name == flap))
}

/// The rigid 3D motion (aircraft frame) that best moves each station's section `points[i]`
/// (station frame `frames[i]`) as that station's planar displacement asks, over the
/// stations listed in `asked`; one station's displacement lifted into 3D when it is alone.
fn fitted_pose(
    points: &[Vec<Point2<f64>>],
    frames: &[Isometry3<f64>],
    asked: &[(usize, Isometry2<f64>)],
) -> flapwright_geom::Result<Isometry3<f64>> {
    let lift = |p: &Point2<f64>| Point3::new(p.x, p.y, 0.0);
    if let [(i, d)] = asked {
        let planar = Isometry3::from_parts(
            nalgebra::Translation3::new(d.translation.x, d.translation.y, 0.0),
            nalgebra::UnitQuaternion::from_axis_angle(&nalgebra::Vector3::z_axis(), d.rotation.angle()),
        );
        return Ok(frames[*i] * planar * frames[*i].inverse());
    }
    let (mut from, mut to) = (Vec::new(), Vec::new());
    for &(i, d) in asked {
        from.extend(points[i].iter().map(|p| frames[i] * lift(p)));
        to.extend(points[i].iter().map(|p| frames[i] * lift(&(d * p))));
    }
    Ok(flapwright_geom::fit_rigid_motion(&from, &to)?.motion)
}

/// The wing and stowed flap sections of `placed`, ready to measure; `None` when the plane
/// misses the wing or the flap.
pub fn flap_behind_wing(placed: &PlacedStation, flap_name: &str) -> Result<Option<FlapBehindWing>> {
    let (wing, flap) = (
        placed.polygons_of(|name| name == "wing"),
        placed.polygons_of(|name| name == flap_name),
    );
    if wing.is_empty() || flap.is_empty() {
        return Ok(None);
    }
    // The gap and overlap are the (main) flap element's; the chord they are a share of
    // runs to the whole flap's trailing edge (a two-element flap's aft element's).
    Ok(Some(
        FlapBehindWing::new(&wing, &flap)
            .and_then(|measure| measure.with_chord_to(&placed.flap_polygons(flap_name)))
            .map_err(|source| Error::GapAndOverlap {
                station: placed.station.name.clone(),
                source,
            })?,
    ))
}

/// What a kind synthesised from the flap settings needs at one placed station: the wing
/// and stowed flap sections, and take-off and landing as flap displacements in the plane
/// (where `flap`'s settings give gap and overlap), with the flap behind the wing they were
/// measured by (kept on the record for the gap-overlap stage).
/// A target gap below the flap's sealed gap (for `required_clearance_m`) is synthesised
/// at the sealed gap ([`structural_gap_m`]).
pub fn synthesis_context(
    flap: &FlapScene,
    flaps: &[FlapScene],
    placed: &PlacedStation,
    required_clearance_m: f64,
) -> Result<(SynthesisContext, Option<FlapBehindWing>)> {
    let outline = StationOutline {
        wing: placed.polygons_of(|name| name == "wing").into(),
        // The whole flap: a rail or a link must keep out of either element.
        flap: placed.flap_polygons(&flap.name).into(),
        // Spars and the torque tube; other flaps' sections are not structure.
        structure: placed
            .polygons_of(|name| name != "wing" && !flaps.iter().any(|f| f.owns_part(name)))
            .into(),
        lip: Vec::new(),
        lip_clearance_m: 0.0,
    };
    let Some(measure) = flap_behind_wing(placed, &flap.name)? else {
        return Ok((SynthesisContext::default(), None));
    };
    let outline = StationOutline {
        lip: measure.lip().to_vec(),
        lip_clearance_m: flap.settings.sealed_gap_m(required_clearance_m) - required_clearance_m,
        ..outline
    };
    let chord = measure.chord_m();
    let position = |name: &'static str, deflection_deg: f64| -> Result<Option<PrecisionPosition>> {
        let (Some(gap), Some(overlap)) = flap.settings.targets(name) else {
            return Ok(None);
        };
        let deflection_rad = deflection_deg.to_radians();
        let (gap_m, _) = structural_gap_m(gap, chord, flap.settings.sealed_gap_m(required_clearance_m));
        let displacement = match measure.displacement_for_setting(deflection_rad, gap_m, overlap * chord / 100.0) {
            // The settings ask for what the sections cannot give: an input problem, which no
            // rule before the station planes are cut can foresee (it depends on the sections'
            // shapes), named by the keys to change.
            Err(flapwright_planes::Error::GapUnreachable { smallest_gap_m, .. }) => {
                let index = flaps.iter().position(|f| f.name == flap.name).unwrap_or(0);
                return Err(SceneError::Invalid(vec![Problem::new(
                    format!("flap[{index}].settings.{name}_overlap_percent"),
                    format!(
                        "= {}: at station {} no flap position behind the wing at {name}_deg = {} gives this overlap with a gap of {:.1} mm ({name}_gap_percent = {}, or the sealed gap); the smallest gap it reaches is {:.1} mm: give a larger overlap or a larger {name}_gap_percent",
                        crate::scene::number(overlap),
                        placed.station.name,
                        crate::scene::number(deflection_deg),
                        gap_m * 1e3,
                        crate::scene::number(gap),
                        smallest_gap_m * 1e3,
                    ),
                )])
                .into());
            }
            other => other.map_err(|source| Error::SettingPosition {
                flap: flap.name.clone(),
                setting: name,
                station: placed.station.name.clone(),
                source,
            })?,
        };
        Ok(Some(PrecisionPosition {
            name,
            deflection_rad,
            flap: displacement,
        }))
    };
    let settings = match (
        position("takeoff", flap.settings.takeoff_deg)?,
        position("landing", flap.settings.landing_deg)?,
    ) {
        (Some(takeoff), Some(landing)) => Some((takeoff, landing)),
        _ => None,
    };
    Ok((
        SynthesisContext {
            outline: Some(outline),
            settings,
            down_st: Some({
                // The aircraft's down (-z) on the plane's in-plane axes.
                let frame = &placed.station.frame;
                nalgebra::Vector2::new(-frame.x_axis_ac().z, -frame.y_axis_ac().z)
            }),
            companion: None,
            followed: None,
            design_loads: Vec::new(),
            actuator_load_weight: flapwright_mechanism::shared::objective::DEFAULT_LOAD_WEIGHT,
            rotary_actuator_load_weight: flapwright_mechanism::shared::objective::DEFAULT_ROTARY_LOAD_WEIGHT,
            four_bar_actuator_load_cap: flapwright_kinds::four_bar::DEFAULT_JACK_LOAD_CAP,
            mass_weighing: None,
            sized: Default::default(),
        },
        Some(measure),
    ))
}

/// The gap and overlap at each station's flap settings (`flap_position`), measured by the
/// record's `flap_behind_wing` (set at synthesis); None where the station has no flap
/// section to measure.
pub fn flap_positions(flaps: &[FlapScene], records: &mut [StationRecord], required_clearance_m: f64) -> Result<()> {
    for record in records.iter_mut() {
        record.flap_position = flap_position(flaps, record, required_clearance_m)?;
    }
    Ok(())
}

fn flap_position(
    flaps: &[FlapScene],
    record: &StationRecord,
    required_clearance_m: f64,
) -> Result<Option<FlapPositionReport>> {
    let Some(flap) = record
        .flap
        .as_ref()
        .and_then(|name| flaps.iter().find(|f| &f.name == name))
    else {
        return Ok(None);
    };
    let Some(measure) = &record.flap_behind_wing else {
        return Ok(None);
    };
    let seam = record.mechanism.as_ref();
    let named = [
        ("stowed", 0.0),
        ("takeoff", flap.settings.takeoff_deg),
        ("landing", flap.settings.landing_deg),
    ];
    let mut aft_settings = Vec::new();
    let aft_measure = second_slot(flap, record)?;
    let aft_body = flapwright_mechanism::seam::aft_flap_body(seam.bodies());
    let settings = named
        .into_iter()
        .map(|(setting, deflection_deg)| {
            // A rigid flap's setting is at its rotation as this plane sees it.
            let deflection_deg = record
                .rigid_flap
                .iter()
                .find(|r| r.setting == setting)
                .map_or(deflection_deg, |r| r.deflection_in_plane_deg);
            // Where the mechanism puts the flap at this deflection: any planar motion.
            let pose = seam.pose(seam.input_at_deflection(deflection_deg.to_radians())?)?;
            if let Some(aft_measure) = &aft_measure {
                let relative = pose.flap.inverse() * pose.aft_flap(aft_body);
                aft_settings.push(AftSlotSetting {
                    setting: setting.into(),
                    relative_deflection_deg: relative.rotation.angle().to_degrees(),
                    position: aft_measure.at_displacement(&relative),
                });
            }
            let (target_gap_percent_chord, target_overlap_percent_chord) = flap.settings.targets(setting);
            let sealed_gap_m = target_gap_percent_chord.and_then(|gap| {
                let (gap_m, sealed) =
                    structural_gap_m(gap, measure.chord_m(), flap.settings.sealed_gap_m(required_clearance_m));
                sealed.then_some(gap_m)
            });
            Ok(SettingPosition::new(
                setting,
                deflection_deg,
                measure.at_displacement(&pose.flap),
                (target_gap_percent_chord, target_overlap_percent_chord),
                sealed_gap_m,
                measure.chord_m(),
            ))
        })
        .collect::<Result<Vec<_>>>()?;
    let te = measure.trailing_edge();
    Ok(Some(FlapPositionReport {
        trailing_edge_st_m: [te.x, te.y],
        local_chord_m: measure.chord_m(),
        settings,
        rigid_flap: record.rigid_flap.clone(),
        aft_slot: aft_measure.map(|measure| {
            let te = measure.trailing_edge();
            AftSlotReport {
                trailing_edge_st_m: [te.x, te.y],
                flap_chord_m: measure.chord_m(),
                settings: aft_settings,
            }
        }),
    }))
}

/// A two-element flap's second slot at `record`'s station: the aft element behind the
/// main element (None for a one-element flap or an unplaced station).
fn second_slot(flap: &FlapScene, record: &StationRecord) -> Result<Option<FlapBehindWing>> {
    Ok(match &record.placed {
        Some(placed) if flap.aft_element.is_some() => {
            let aft_name = flapwright_geom::parts::aft_element_name(&flap.name);
            let (main, aft) = (
                placed.polygons_of(|name| name == flap.name),
                placed.polygons_of(|name| name == aft_name),
            );
            if main.is_empty() || aft.is_empty() {
                None
            } else {
                Some(FlapBehindWing::new(&main, &aft).map_err(|source| Error::SecondSlot {
                    flap: flap.name.clone(),
                    station: record.station.clone(),
                    source,
                })?)
            }
        }
        _ => None,
    })
}

/// Fills each deployment sample's gap and overlap, where the mechanism puts the flap at
/// that sample's input, and the second slot's where the kind moves an aft element.
pub fn annotate_samples(
    mechanism: &StationRecord,
    measure: &FlapBehindWing,
    report: &mut crate::pipeline::record::MechanismReport,
    flaps: &[FlapScene],
) -> Result<()> {
    let flap = mechanism
        .flap
        .as_ref()
        .and_then(|name| flaps.iter().find(|f| &f.name == name));
    let second = match flap {
        Some(flap) => second_slot(flap, mechanism)?,
        None => None,
    };
    let aft_body = flapwright_mechanism::seam::aft_flap_body(mechanism.mechanism.bodies());
    let gap_overlap = |at: &flapwright_planes::GapOverlap| flapwright_mechanism::FlapGapOverlap {
        gap_m: at.gap_m,
        gap_percent_chord: at.gap_percent_chord,
        overlap_m: at.overlap_m,
        overlap_percent_chord: at.overlap_percent_chord,
    };
    for case in &mut report.load_cases {
        for sample in &mut case.samples {
            let pose = mechanism.mechanism.pose(sample.input)?;
            let at = measure.at_displacement(&pose.flap);
            sample.flap_position = Some(gap_overlap(&at));
            if let (Some(aft), Some(slot), Some(k)) = (&mut sample.aft_element, &second, aft_body) {
                aft.slot = Some(gap_overlap(
                    &slot.at_displacement(&(pose.flap.inverse() * pose.bodies[k])),
                ));
            }
        }
    }
    Ok(())
}
