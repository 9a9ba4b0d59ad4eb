//! Masses: volume x density, per station and for the whole wing.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::check::non_negative;
use crate::material::Material;
use crate::section::SectionShape;
use crate::Result;

/// Volume of a prismatic circular member V = A L, m^3 (outer radius and length in m).
pub fn prism_volume_m3(shape: SectionShape, outer_radius_m: f64, length_m: f64) -> f64 {
    shape.area_m2(outer_radius_m) * length_m
}

/// Mass m = V rho, kg (`003_...` section 4.1, "total volume of the rods by the material
/// density").
///
/// # Errors
/// [`crate::Error::InvalidMaterial`], [`crate::Error::OutOfRange`] for a negative or
/// non-finite volume.
pub fn mass_kg(volume_m3: f64, material: &Material) -> Result<f64> {
    material.validate()?;
    Ok(non_negative("volume_m3", volume_m3)? * material.density_kg_m3)
}

/// One sized part's mass.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MassItem {
    /// Station the part belongs to.
    pub station: String,
    /// Part name.
    pub part: String,
    /// Mass, kg.
    pub mass_kg: f64,
}

/// Mass of one station.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StationMass {
    /// Station name.
    pub station: String,
    /// Sum of its parts, kg.
    pub mass_kg: f64,
    /// Number of parts summed.
    pub parts: usize,
}

/// Per-station and whole-wing mass totals.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct MassBreakdown {
    /// Stations sorted by name (deterministic report order).
    pub per_station: Vec<StationMass>,
    /// Whole-wing total, kg.
    pub total_kg: f64,
}

impl MassBreakdown {
    /// Groups the items by station and sums them.
    pub fn from_items(items: &[MassItem]) -> Self {
        let mut by_station: BTreeMap<&str, (f64, usize)> = BTreeMap::new();
        for item in items {
            let entry = by_station.entry(item.station.as_str()).or_default();
            entry.0 += item.mass_kg;
            entry.1 += 1;
        }
        let per_station: Vec<StationMass> = by_station
            .into_iter()
            .map(|(station, (mass_kg, parts))| StationMass {
                station: station.to_owned(),
                mass_kg,
                parts,
            })
            .collect();
        let total_kg = per_station.iter().map(|s| s.mass_kg).sum();
        Self { per_station, total_kg }
    }

    /// The mass of `station`'s sized parts (kg); 0 for a station with none listed.
    pub fn station_kg(&self, station: &str) -> f64 {
        self.per_station
            .iter()
            .find(|m| m.station == station)
            .map_or(0.0, |m| m.mass_kg)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn breakdown_groups_and_sums() {
        let item = |station: &str, mass_kg| MassItem {
            station: station.into(),
            part: "p".into(),
            mass_kg,
        };
        let b = MassBreakdown::from_items(&[item("b", 1.0), item("a", 2.0), item("b", 0.5)]);
        assert_eq!(
            b.per_station[0],
            StationMass {
                station: "a".into(),
                mass_kg: 2.0,
                parts: 1
            }
        );
        assert_eq!(
            b.per_station[1],
            StationMass {
                station: "b".into(),
                mass_kg: 1.5,
                parts: 2
            }
        );
        assert_eq!(b.total_kg, 3.5);
        assert_eq!((b.station_kg("b"), b.station_kg("none")), (1.5, 0.0));
        let steel = Material::steel_4340();
        // 1 m of solid r = 10 mm steel: pi x 1e-4 x 7850 = 2.466 kg.
        let m = mass_kg(prism_volume_m3(SectionShape::Solid, 0.01, 1.0), &steel).unwrap();
        assert!((m - std::f64::consts::PI * 1e-4 * 7850.0).abs() < 1e-12);
        assert!(mass_kg(-1.0, &steel).is_err());
    }
}
