//! How a scene names an airfoil: a NACA designation or a coordinate file.

use std::path::Path;

use super::files::FileSource;
use crate::error::{Error, Result};

use flapwright_geom::airfoil::{Airfoil, TrailingEdge};

/// Airfoil files shipped with Flapwright (`data/airfoils/`, UIUC database; see its README),
/// found by file name when the scene's folder has no file of that name.
pub const BUNDLED_AIRFOILS: &[(&str, &str)] = &[
    ("n63210.dat", include_str!("../../../../data/airfoils/n63210.dat")),
    ("n63212.dat", include_str!("../../../../data/airfoils/n63212.dat")),
    ("n63215.dat", include_str!("../../../../data/airfoils/n63215.dat")),
    ("n64212.dat", include_str!("../../../../data/airfoils/n64212.dat")),
    (
        "naca651212.dat",
        include_str!("../../../../data/airfoils/naca651212.dat"),
    ),
    (
        "naca64a010.dat",
        include_str!("../../../../data/airfoils/naca64a010.dat"),
    ),
];

/// A parsed airfoil reference.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AirfoilRef {
    /// `NACA 2412`: 4 or 5 digits.
    Naca(String),
    /// A `.dat` file name or path.
    File(String),
}

/// Where a file airfoil's text comes from.
#[derive(Debug)]
pub enum AirfoilSource {
    /// A file the scene's [`FileSource`] gave (its bytes, or why they could not be read).
    Given(std::io::Result<Vec<u8>>),
    /// A file bundled in the binary.
    Bundled(&'static str),
}

impl AirfoilRef {
    /// Parses `"NACA 2412"`, `"naca23012"` or `"something.dat"`; the message says what is
    /// accepted.
    pub fn parse(text: &str) -> Result<Self, String> {
        let trimmed = text.trim();
        let lower = trimmed.to_ascii_lowercase();
        if let Some(rest) = lower.strip_prefix("naca") {
            let digits = rest.trim_start_matches([' ', '-', '_']);
            let is_digits = !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit());
            if is_digits && (digits.len() == 4 || digits.len() == 5) {
                return Ok(Self::Naca(digits.to_string()));
            }
            return Err(format!(
                "`{trimmed}` is not a NACA 4- or 5-digit designation (e.g. \"NACA 2412\", \"NACA 23012\")"
            ));
        }
        if lower.ends_with(".dat") {
            return Ok(Self::File(trimmed.to_string()));
        }
        Err(format!(
            "`{trimmed}` is neither a NACA designation (\"NACA 2412\") nor a .dat file name"
        ))
    }

    /// Finds a file airfoil: among the scene's `files` first (next to the scene), then among
    /// the bundled files.
    pub fn locate(name: &str, files: &dyn FileSource) -> Option<AirfoilSource> {
        if let Some(bytes) = files.read(name) {
            return Some(AirfoilSource::Given(bytes));
        }
        let file_name = Path::new(name).file_name()?.to_str()?;
        BUNDLED_AIRFOILS
            .iter()
            .find(|(bundled, _)| *bundled == file_name)
            .map(|(_, text)| AirfoilSource::Bundled(text))
    }
}

/// Margin of an airfoil file's x about the unit chord (0 to 1); its y stays within half a
/// chord of the chord line. A coordinate beyond (`1e308`) is a typo, which reached the
/// mesher as a polygon it could not triangulate.
pub const AIRFOIL_COORDINATE_MARGIN: f64 = 0.1;

/// Reads an airfoil the scene names and resamples it to the scene's resolution; a file's
/// coordinates must be of a unit-chord section: x within `AIRFOIL_COORDINATE_MARGIN` (0.1) of [0, 1], y in
/// [-0.5, 0.5].
pub fn load_airfoil(text: &str, files: &dyn FileSource, points_per_side: usize) -> Result<Airfoil> {
    let airfoil = match AirfoilRef::parse(text).map_err(|message| Error::AirfoilReference { message })? {
        AirfoilRef::Naca(digits) => Airfoil::naca(&digits, points_per_side, TrailingEdge::Closed)
            .map_err(|source| Error::NacaAirfoil { digits, source })?,
        AirfoilRef::File(name) => {
            let source =
                AirfoilRef::locate(&name, files).ok_or_else(|| Error::AirfoilFileNotFound { file: name.clone() })?;
            let parsed = match source {
                AirfoilSource::Given(bytes) => {
                    let bytes = bytes.map_err(|source| Error::OpeningAirfoil {
                        file: name.clone(),
                        source,
                    })?;
                    Airfoil::from_dat(bytes.as_slice())
                }
                AirfoilSource::Bundled(text) => Airfoil::from_dat(text.as_bytes()),
            };
            let parsed = parsed.map_err(|source| Error::ReadingAirfoil {
                file: name.clone(),
                source,
            })?;
            let (lo, hi) = (-AIRFOIL_COORDINATE_MARGIN, 1.0 + AIRFOIL_COORDINATE_MARGIN);
            if let Some(p) = parsed
                .points
                .iter()
                .find(|p| !(lo..=hi).contains(&p.x) || !(-0.5..=0.5).contains(&p.y))
            {
                return Err(Error::AirfoilOffUnitChord {
                    file: name,
                    x: p.x,
                    y: p.y,
                });
            }
            parsed
                .resampled(points_per_side)
                .map_err(|source| Error::ResamplingAirfoil { file: name, source })?
        }
    };
    Ok(airfoil)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_naca_and_files() {
        assert_eq!(AirfoilRef::parse("NACA 2412"), Ok(AirfoilRef::Naca("2412".into())));
        assert_eq!(AirfoilRef::parse("naca23012"), Ok(AirfoilRef::Naca("23012".into())));
        assert_eq!(
            AirfoilRef::parse("n63212.dat"),
            Ok(AirfoilRef::File("n63212.dat".into()))
        );
        assert!(AirfoilRef::parse("NACA 241").is_err());
        assert!(AirfoilRef::parse("clark-y").is_err());
    }

    #[test]
    fn bundled_files_are_found() {
        assert!(matches!(
            AirfoilRef::locate("n63212.dat", &super::super::files::NoFiles),
            Some(AirfoilSource::Bundled(_))
        ));
        assert!(AirfoilRef::locate("missing.dat", &super::super::files::NoFiles).is_none());
        // A file the scene gives comes before a bundled one of that name.
        let given = super::super::files::MemoryFiles::new().with("n63212.dat", "x");
        assert!(matches!(
            AirfoilRef::locate("n63212.dat", &given),
            Some(AirfoilSource::Given(Ok(bytes))) if bytes == b"x"
        ));
    }
}
