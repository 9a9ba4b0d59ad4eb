//! The crate's one error type: every way a design, an export or a study fails, each
//! variant named for the condition or for what the library was doing, with what it concerns
//! (the stage, the station, the flap, the part, the file) as fields and the lower crate's
//! error as its [`source`](std::error::Error::source).
//!
//! A variant's message is the context of its source, not a sentence that repeats it: the
//! command line prints the whole chain joined by `: ` (``stage `planes`: placing station
//! inner: <the planes crate's message>``), and [`Error::chain_message`] gives the same line.
//! Which failures are the input's fault is the caller's decision; [`Error::scene_error`]
//! finds the scene's problems wherever a stage met them.

use std::fmt;
use std::io;

use crate::scene::SceneError;

/// Result with the crate's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong while designing, exporting or studying a scene.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    // The scene.
    /// The scene has problems, by key path (found by a stage after validation) or located
    /// in its file: bad input.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A stage of the pipeline failed.
    #[error("stage `{stage}`")]
    Stage {
        /// The stage's name, as the report's `stages` lists it (`planes`, `synthesis`, ...).
        stage: String,
        /// Why it failed.
        #[source]
        source: Box<Error>,
    },

    // Airfoils.
    /// The scene's airfoil is neither a NACA designation nor a `.dat` file name.
    #[error("{message}")]
    AirfoilReference {
        /// What was written and what is accepted.
        message: String,
    },
    /// A NACA section could not be built.
    #[error("building NACA {digits}")]
    NacaAirfoil {
        /// The designation's digits (`2412`).
        digits: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// An airfoil file is neither beside the scene nor bundled.
    #[error("airfoil file {file} not found")]
    AirfoilFileNotFound {
        /// The file as the scene names it.
        file: String,
    },
    /// An airfoil file beside the scene could not be read.
    #[error("opening {file}")]
    OpeningAirfoil {
        /// The file as the scene names it.
        file: String,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// An airfoil file's text is not a coordinate file.
    #[error("reading airfoil file {file}")]
    ReadingAirfoil {
        /// The file as the scene names it.
        file: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// An airfoil file holds a point outside the unit-chord box (x within
    /// [`AIRFOIL_COORDINATE_MARGIN`](crate::scene::AIRFOIL_COORDINATE_MARGIN) of [0, 1],
    /// y in [-0.5, 0.5]).
    #[error(
        "{file} has the point ({}, {}): an airfoil file holds a unit-chord section, x in [{}, {}] and y in [-0.5, 0.5]",
        crate::scene::number(*.x),
        crate::scene::number(*.y),
        -crate::scene::AIRFOIL_COORDINATE_MARGIN,
        1.0 + crate::scene::AIRFOIL_COORDINATE_MARGIN
    )]
    AirfoilOffUnitChord {
        /// The file as the scene names it.
        file: String,
        /// The point's x (chords).
        x: f64,
        /// The point's y (chords).
        y: f64,
    },
    /// An airfoil could not be resampled to the scene's resolution.
    #[error("resampling airfoil {file}")]
    ResamplingAirfoil {
        /// The file as the scene names it.
        file: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// The airfoil a scene key names could not be loaded.
    #[error("{key}")]
    SceneAirfoil {
        /// The key's path (`wing.sections[1].airfoil`, `flap[0].aft_element.airfoil`).
        key: String,
        /// Why.
        #[source]
        source: Box<Error>,
    },

    // The wing's geometry.
    /// A scene value validation guarantees is missing: a broken invariant, not bad input.
    #[error("{key}: {problem} (validation should have caught this)")]
    Unvalidated {
        /// The key's path (`flap[0].hinge`).
        key: String,
        /// What is wrong with it.
        problem: &'static str,
    },
    /// The scene names a material that is neither a preset nor one of its `[[materials]]`
    /// (validation should have caught it).
    #[error("material {material} (validation should have caught this)")]
    UnknownMaterial {
        /// The material's name.
        material: String,
    },
    /// The wing, its flaps, spars and torque tube do not make a wing model.
    #[error("building the wing model")]
    BuildingWingModel(#[source] flapwright_geom::Error),
    /// The wing alone could not be built (to place the torque tube on it).
    #[error("building the wing")]
    BuildingWing(#[source] flapwright_geom::Error),
    /// The torque tube's axis could not be placed on the wing's sections.
    #[error("structure.torque_tube: placing the axis on the wing")]
    PlacingTorqueTube(#[source] flapwright_geom::Error),
    /// The parts could not be meshed.
    #[error("meshing the parts")]
    MeshingParts(#[source] flapwright_geom::Error),
    /// A part's mesh gives no collision shape.
    #[error("collision shape of {part}")]
    CollisionShape {
        /// The part's name.
        part: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// A flap element's mesh gives no mass properties (for the URDF's inertia).
    #[error("the mesh of {part}")]
    FlapMesh {
        /// The part's name.
        part: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },

    // Stations and their planes.
    /// A station on a wing carries no flap.
    #[error("station has no flap")]
    StationWithoutFlap {
        /// The station's name.
        station: String,
    },
    /// A station names a flap the scene does not have.
    #[error("station names an unknown flap")]
    UnknownFlap {
        /// The station's name.
        station: String,
        /// The flap it names.
        flap: String,
    },
    /// A stage that needs the station's plane met a station without one.
    #[error("station {station} is not placed")]
    StationNotPlaced {
        /// The station's name.
        station: String,
    },
    /// The station plane's construction on the hinge axis failed.
    #[error("placing station {station}")]
    PlacingStation {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// The station's frame and residuals could not be computed.
    #[error("station {station}")]
    ComputingStation {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// The parts could not be cut by a station's plane.
    #[error("cutting the parts at station {station}")]
    CuttingParts {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// A skew-corrected plane needs its flap's poses at the settings, which need the
    /// settings' gap and overlap.
    #[error("station {station}: a skew-corrected plane needs its flap's take-off and landing gap and overlap")]
    SkewWithoutSettings {
        /// The station's name.
        station: String,
    },
    /// The skew direction of a station's landing motion is undefined.
    #[error("station {station}: the skew direction of its landing motion")]
    SkewDirection {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// The skew-corrected plane's normal is undefined.
    #[error("station {station}: the skew-corrected plane")]
    SkewCorrectedPlane {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// The plane of a station misses the flap its loads act on.
    #[error("the station plane misses its flap")]
    PlaneMissesFlap {
        /// The station's name.
        station: String,
        /// The flap's name.
        flap: String,
    },

    // The flap's motion and positions.
    /// The rigid motion of a flap carried by several stations could not be fitted.
    #[error("the fitted motion of flap {flap}")]
    FittedFlapMotion {
        /// The flap's name.
        flap: String,
        /// Why.
        #[source]
        source: Box<Error>,
    },
    /// A rigid flap's pose at a setting gives no planar displacement in a station's plane.
    #[error("flap {flap}: its {setting} pose in station {station}")]
    RigidFlapSetting {
        /// The flap's name.
        flap: String,
        /// `takeoff` or `landing`.
        setting: &'static str,
        /// The station's name.
        station: String,
    },
    /// No rigid pose of a flap fits its stations' displacements at a setting.
    #[error("flap {flap}: the rigid flap's {setting} pose")]
    RigidFlapPose {
        /// The flap's name.
        flap: String,
        /// `takeoff` or `landing`.
        setting: &'static str,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// The gap and overlap of a station's flap cannot be measured.
    #[error("gap and overlap at station {station}")]
    GapAndOverlap {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// A flap's position at a setting could not be found in a station's plane.
    #[error("flap {flap} {setting} setting at station {station}")]
    SettingPosition {
        /// The flap's name.
        flap: String,
        /// `takeoff` or `landing`.
        setting: &'static str,
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// A two-element flap's second slot (the aft element behind the main one) cannot be
    /// measured.
    #[error("second slot of flap {flap} at station {station}")]
    SecondSlot {
        /// The flap's name.
        flap: String,
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_planes::Error,
    },
    /// A flap's load could not be shared among its stations.
    #[error("sharing flap {flap}'s load among its stations")]
    SharingLoad {
        /// The flap's name.
        flap: String,
        /// Why.
        #[source]
        source: flapwright_sizing::Error,
    },

    // Mechanism parts, the interference check and the fairings.
    /// A station's mechanism has no input for a flap setting.
    #[error("station {station} at {deflection_deg} deg")]
    SettingInput {
        /// The station's name.
        station: String,
        /// The setting's flap deflection (deg).
        deflection_deg: f64,
        /// Why.
        #[source]
        source: flapwright_mechanism::Error,
    },
    /// A mechanism solid encloses no volume, so it has no mass properties.
    #[error("{part} holds no volume")]
    NoVolume {
        /// The solid's name (`<station>.<solid>`).
        part: String,
    },
    /// A moving body could not be posed over the deployment (the glTF's keys).
    #[error("posing {part}")]
    Posing {
        /// The body's name.
        part: String,
        /// Why.
        #[source]
        source: flapwright_mechanism::Error,
    },
    /// A flap is carried by no station, so it has no motion.
    #[error("flap {flap} has no station")]
    FlapWithoutStation {
        /// The flap's name.
        flap: String,
    },
    /// A part taken for a flap element is not one.
    #[error("part {part} is not a flap element")]
    NotAFlapElement {
        /// The part's name.
        part: String,
    },
    /// A station's fairing depth could not be measured.
    #[error("fairing depth at station {station}")]
    FairingDepth {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_mechanism::Error,
    },

    // Drive dynamics.
    /// A station's deployment under its motor could not be integrated.
    #[error("station {station}: deploying under the motor")]
    Deploying {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_dynamics::Error,
    },
    /// `[dynamics]` needs what a station's kind does not give.
    #[error("station {station} ({kind}): [dynamics] needs {needs}")]
    DynamicsNeeds {
        /// The station's name.
        station: String,
        /// The station's mechanism kind.
        kind: &'static str,
        /// What is missing.
        needs: &'static str,
    },
    /// The rigid flap's equation of motion could not be written for a station.
    #[error("station {station}: the rigid flap's equation of motion")]
    RigidFlapDynamics {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_mechanism::Error,
    },

    // Drawings.
    /// A station's deployment plots under its motor could not be drawn.
    #[error("drawing the dynamics plots of {station}")]
    DynamicsPlots {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_drawing::Error,
    },
    /// A station's drawing could not be rendered.
    #[error("drawing station {station}")]
    DrawingStation {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_drawing::Error,
    },
    /// A station's plots could not be rendered.
    #[error("plotting station {station}")]
    PlottingStation {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_drawing::Error,
    },

    // Output.
    /// The [`Sink`](crate::Sink) refused a file.
    #[error("writing {file}")]
    Write {
        /// The file's name in the output folder.
        file: String,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// A mesh could not be encoded as STL.
    #[error("writing {file}")]
    EncodingStl {
        /// The STL file's name.
        file: String,
        /// Why.
        #[source]
        source: flapwright_geom::Error,
    },
    /// The report could not be serialised.
    #[error("serialising the report")]
    SerialisingReport(#[source] serde_json::Error),

    // The study.
    /// The scene's text, parsed again for the study's kind tables, is not TOML.
    #[error("parsing the scene as TOML")]
    StudySceneToml(#[source] toml::de::Error),
    /// The scene has no station whose mechanism the kinds could replace.
    #[error("the scene has no [[station]] to study")]
    NoStationToStudy,
    /// None of the stations asked for is in the scene.
    #[error("no station named {}", .names.join(", "))]
    NoSuchStation {
        /// The names asked for.
        names: Vec<String>,
    },
    /// The scene's text and the scene parsed from it disagree on the stations.
    #[error("the scene's [[station]] tables are not the scene it was parsed into")]
    StudyStationsMismatch,
    /// The study's gap and overlap charts of a station could not be drawn.
    #[error("drawing the study charts of {station}")]
    StudyCharts {
        /// The station's name.
        station: String,
        /// Why.
        #[source]
        source: flapwright_drawing::Error,
    },
    /// The [`Sink`](crate::Sink) refused a chart of the study.
    #[error("writing the study charts")]
    WritingStudyCharts {
        /// The chart's file name.
        file: String,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// The study could not be serialised.
    #[error("serialising the study")]
    SerialisingStudy(#[source] serde_json::Error),
    /// The [`Sink`](crate::Sink) refused a kind's folder.
    #[error("writing the {kind} folder")]
    WritingKindFolder {
        /// The kind (the folder's name).
        kind: String,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// No kind of the study could be designed.
    #[error(transparent)]
    NoKindDesigned(#[from] NoKindDesigned),
    /// A kind's report lacks a section the study's figures are read from.
    #[error(transparent)]
    MissingSection(#[from] MissingSection),

    // The lower crates, where the step that met their error says nothing more.
    /// From `flapwright-geom`.
    #[error(transparent)]
    Geom(#[from] flapwright_geom::Error),
    /// From `flapwright-planes`.
    #[error(transparent)]
    Planes(#[from] flapwright_planes::Error),
    /// From `flapwright-mechanism`.
    #[error(transparent)]
    Mechanism(#[from] flapwright_mechanism::Error),
    /// From `flapwright-interference`.
    #[error(transparent)]
    Interference(#[from] flapwright_interference::Error),
    /// From `flapwright-sizing`.
    #[error(transparent)]
    Sizing(#[from] flapwright_sizing::Error),
    /// From `flapwright-dynamics`.
    #[error(transparent)]
    Dynamics(#[from] flapwright_dynamics::Error),
    /// From `flapwright-gltf`.
    #[error(transparent)]
    Gltf(#[from] flapwright_gltf::Error),
    /// From `flapwright-urdf`.
    #[error(transparent)]
    Urdf(#[from] flapwright_urdf::Error),
    /// A JSON file (the URDF's trajectory) could not be serialised.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// The JUnit document could not be serialised.
    #[error(transparent)]
    Junit(#[from] quick_junit::SerializeError),
}

impl Error {
    /// The scene's problems behind this error, found through the steps that wrapped them
    /// ([`Error::Stage`] and the others whose source is an [`Error`]): `Some` when the scene
    /// is at fault. Errors of the lower crates are not looked into.
    pub fn scene_error(&self) -> Option<&SceneError> {
        match self {
            Self::Scene(scene_error) => Some(scene_error),
            other => other.wrapped()?.scene_error(),
        }
    }

    /// As [`Error::scene_error`], by value: the scene's problems without the steps that
    /// wrapped them (the problems name their keys), or this error unchanged when the scene
    /// is not at fault.
    pub fn into_scene_error(self) -> Result<SceneError, Self> {
        if self.scene_error().is_none() {
            return Err(self);
        }
        let mut error = self;
        loop {
            error = match error {
                Self::Scene(scene_error) => return Ok(scene_error),
                Self::Stage { source, .. }
                | Self::SceneAirfoil { source, .. }
                | Self::FittedFlapMotion { source, .. } => *source,
                other => return Err(other),
            };
        }
    }

    /// The message and each source's, joined by `: ` on one line (as `anyhow` prints an
    /// error with `{:#}`): ``stage `planes`: placing station inner: <why>``.
    pub fn chain_message(&self) -> String {
        ChainMessage(self).to_string()
    }

    /// The [`Error`] this one wraps, for the variants whose source is one.
    fn wrapped(&self) -> Option<&Error> {
        match self {
            Self::Stage { source, .. } | Self::SceneAirfoil { source, .. } | Self::FittedFlapMotion { source, .. } => {
                Some(source)
            }
            _ => None,
        }
    }
}

/// An error and its sources, joined by `: `.
struct ChainMessage<'a>(&'a dyn std::error::Error);

impl fmt::Display for ChainMessage<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)?;
        let mut source = self.0.source();
        while let Some(cause) = source {
            write!(f, ": {cause}")?;
            source = cause.source();
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Problem;

    fn invalid() -> SceneError {
        SceneError::Invalid(vec![Problem::new("station[0].mechanism", "cannot be synthesised")])
    }

    #[test]
    fn the_chain_reads_as_each_step_wrapped_the_next() {
        let error = Error::Stage {
            stage: "planes".into(),
            source: Box::new(Error::PlacingStation {
                station: "inner".into(),
                source: flapwright_planes::Error::FlapNotBehindWing { chord_m: -1.0 },
            }),
        };
        assert_eq!(error.to_string(), "stage `planes`");
        assert_eq!(
            error.chain_message(),
            "stage `planes`: placing station inner: local chord = -1 m (wing nose to stowed flap trailing edge): the flap is not behind the wing"
        );
    }

    #[test]
    fn the_scene_error_is_found_through_the_stages_only() {
        let staged = Error::Stage {
            stage: "synthesis".into(),
            source: Box::new(Error::Scene(invalid())),
        };
        assert!(staged.scene_error().is_some());
        assert_eq!(
            staged.chain_message(),
            "stage `synthesis`: 1 problem(s) in the scene:\n  - station[0].mechanism: cannot be synthesised"
        );
        assert!(matches!(staged.into_scene_error(), Ok(SceneError::Invalid(p)) if p.len() == 1));
        let other = Error::NoStationToStudy;
        assert!(other.scene_error().is_none());
        assert!(matches!(other.into_scene_error(), Err(Error::NoStationToStudy)));
    }
}

/// No kind could be designed: each kind's reason, on one line.
#[derive(Debug)]
pub struct NoKindDesigned {
    /// The scene's name.
    pub scene: String,
    /// Each kind and its reason, as one line.
    pub reasons: Vec<(String, String)>,
    /// Every reason is a problem of the input (the scene), not of Flapwright.
    pub input_problem: bool,
}

impl std::fmt::Display for NoKindDesigned {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let reasons: Vec<String> = self
            .reasons
            .iter()
            .map(|(kind, why)| format!("{kind}: {why}"))
            .collect();
        write!(
            f,
            "study of \"{}\": no kind could be designed; {}",
            self.scene,
            reasons.join("; ")
        )
    }
}

impl std::error::Error for NoKindDesigned {}

/// A section of a kind's report that a station's figures are read from is absent. Every
/// variant is designed with a wing, kinematics, sizing and the interference check, so each
/// section is there for every station a kind designs; one missing means a stage broke
/// that promise, and the study says so rather than report a figure it never read (a
/// station without sweeps would otherwise show no load, and one without pairs "clears").
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MissingSection {
    /// The station whose figures were being read.
    pub station: String,
    /// The report's key that is absent (`mechanism`, `interference`, ...).
    pub section: &'static str,
}

impl std::fmt::Display for MissingSection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "station {}: the kind's report has no `{}`, which the study's figures are read from",
            self.station, self.section
        )
    }
}

impl std::error::Error for MissingSection {}
