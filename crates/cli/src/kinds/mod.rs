//! Mechanism kinds as the scene file gives them: `[station.mechanism]` picks a kind by its
//! `kind` key, and each kind's module holds its table, the checks of its keys and its
//! synthesis into a [`FlapMechanism`] (the seam every other stage uses). Adding a kind adds
//! a module here, a variant and two match arms in this file, and its mechanism module in
//! `flapwright-mechanism`: nothing that names another kind.

mod circular_arc_track;

use std::sync::Arc;

use flapwright_mechanism::FlapMechanism;
use serde::Deserialize;

pub use circular_arc_track::CircularArcTrackScene;

use crate::scene::KeyChecker;

/// What the rest of Flapwright asks of a kind's scene table.
pub trait KindScene {
    /// Checks every key of the table (ranges, cross-key rules), reporting under `path`
    /// (`station[i].mechanism`).
    fn check(&self, checker: &mut dyn KeyChecker, path: &str);

    /// The flap deflection range the table asks for (deg) and the key that sets it: every
    /// station of one rigid flap must agree.
    fn deflection_range(&self) -> (f64, &'static str);

    /// Moving solids the interference check builds (an upper bound, for the pre-flight
    /// work estimate).
    fn moving_parts(&self) -> usize;

    /// The synthesised mechanism; on failure, the message and the keys to change.
    fn synthesise(&self) -> Result<Arc<dyn FlapMechanism>, String>;

    /// The keys that decide the kind's geometry, for messages about degenerate layouts.
    fn geometry_keys(&self) -> &'static str;
}

/// `[station.mechanism]`: `kind` picks the variant, the other keys are its dimensions.
#[derive(Debug, Clone)]
pub enum MechanismScene {
    /// Circular-arc track with screw jack (thesis `000_...`, Chapters 3-5).
    CircularArcTrack(CircularArcTrackScene),
}

impl MechanismScene {
    /// The `kind` values, as written in the scene.
    pub const KINDS: &'static [&'static str] = &["circular-arc-track"];

    /// The kind behind the variant: everything else reaches the kind through it.
    pub fn kind(&self) -> &dyn KindScene {
        match self {
            Self::CircularArcTrack(m) => m,
        }
    }
}

// By hand rather than `#[serde(tag = "kind")]`: serde buffers an internally tagged enum,
// and an error inside it then names the table, never the key (`[station.mechanism]`
// instead of `station[0].mechanism.flap_mass_kg`). Here the variant is deserialised from
// the table with its own key path, passed up in the message (see `parse::nested_error`).
impl<'de> Deserialize<'de> for MechanismScene {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let mut table = toml::Table::deserialize(deserializer)?;
        let kind = match table.remove("kind") {
            Some(toml::Value::String(kind)) => kind,
            Some(other) => {
                return Err(D::Error::custom(crate::scene::parse::nested_error_at(
                    "kind",
                    &format!("= {other}: must be a string, one of {}", Self::KINDS.join(", ")),
                )))
            }
            None => return Err(D::Error::missing_field("kind")),
        };
        let variant = |table: toml::Table| {
            serde_path_to_error::deserialize(toml::Value::Table(table))
                .map_err(|e| D::Error::custom(crate::scene::parse::nested_error(e.path(), e.inner().message())))
        };
        match kind.as_str() {
            "circular-arc-track" => variant(table).map(Self::CircularArcTrack),
            other => Err(D::Error::custom(crate::scene::parse::nested_error_at(
                "kind",
                &format!(
                    "= \"{other}\": unknown mechanism kind; one of {}",
                    Self::KINDS.join(", ")
                ),
            ))),
        }
    }
}
