//! Reading and writing airfoil coordinate files (`.dat`): Selig and Lednicer formats.
//!
//! Selig: a title line, then x y pairs from the upper trailing edge round the leading edge
//! to the lower trailing edge. Lednicer: a title line, a line with the upper and lower
//! point counts (e.g. `17. 17.`), then the upper side leading edge -> trailing edge, a
//! blank line, and the lower side leading edge -> trailing edge. Both are detected
//! automatically: a first number pair that are both integers >= 2 is a Lednicer header
//! (no unit-chord coordinate can be).

use std::io::{BufRead, BufReader, Read, Write};

use nalgebra::Point2;

use super::{Airfoil, Surface};
use crate::error::{Error, Result};

fn parse_pair(text: &str) -> Option<(f64, f64)> {
    let mut it = text
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|s| !s.is_empty());
    let x = it.next()?.parse().ok()?;
    let y = it.next()?.parse().ok()?;
    it.next().is_none().then_some((x, y))
}

impl Airfoil {
    /// Reads a Selig or Lednicer `.dat` file (format detected). The title line is optional
    /// in Selig files (name "unnamed" then). Coordinates are taken as they are (not
    /// re-normalised).
    pub fn from_dat(reader: impl Read) -> Result<Airfoil> {
        let mut name = None;
        let mut pairs = Vec::new();
        for (index, line) in BufReader::new(reader).lines().enumerate() {
            let line = line?;
            let text = line.trim();
            if text.is_empty() {
                continue;
            }
            match parse_pair(text) {
                Some((x, y)) => pairs.push((x, y)),
                None if name.is_none() && pairs.is_empty() => name = Some(text.to_owned()),
                None => {
                    return Err(Error::DatSyntax {
                        line: index + 1,
                        text: text.to_owned(),
                    })
                }
            }
        }
        let name = name.unwrap_or_else(|| "unnamed".to_owned());
        let is_count = |v: f64| v >= 2.0 && v.fract() == 0.0;
        let points = match pairs.first() {
            Some(&(a, b)) if is_count(a) && is_count(b) => {
                let (upper, lower) = (a as usize, b as usize);
                let data = &pairs[1..];
                if data.len() != upper + lower {
                    return Err(Error::LednicerCount {
                        upper,
                        lower,
                        found: data.len(),
                    });
                }
                let to_point = |&(x, y): &(f64, f64)| Point2::new(x, y);
                let mut points: Vec<Point2<f64>> = data[..upper].iter().rev().map(to_point).collect();
                let lower_points: Vec<Point2<f64>> = data[upper..].iter().map(to_point).collect();
                let skip = usize::from(lower_points.first() == points.last());
                points.extend(lower_points.into_iter().skip(skip));
                points
            }
            _ => pairs.iter().map(|&(x, y)| Point2::new(x, y)).collect(),
        };
        Airfoil::try_new(name, points)
    }

    /// Writes the airfoil as a Selig `.dat` file: title line, then one `x y` pair per line
    /// in Selig order, each number in Rust's shortest round-trip form (exact re-read).
    pub fn write_dat(&self, mut writer: impl Write) -> Result<()> {
        writeln!(writer, "{}", self.name)?;
        for p in &self.points {
            writeln!(writer, "{} {}", p.x, p.y)?;
        }
        Ok(())
    }

    /// Writes the airfoil as a Lednicer `.dat` file (title, counts, upper side LE -> TE,
    /// blank line, lower side LE -> TE; the leading edge appears on both sides).
    pub fn write_dat_lednicer(&self, mut writer: impl Write) -> Result<()> {
        let (upper, lower) = (self.side(Surface::Upper), self.side(Surface::Lower));
        writeln!(writer, "{}", self.name)?;
        writeln!(writer, "{}. {}.", upper.len(), lower.len())?;
        writeln!(writer)?;
        for p in &upper {
            writeln!(writer, "{} {}", p.x, p.y)?;
        }
        writeln!(writer)?;
        for p in &lower {
            writeln!(writer, "{} {}", p.x, p.y)?;
        }
        Ok(())
    }
}
