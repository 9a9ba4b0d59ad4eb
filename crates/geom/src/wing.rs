//! Wing planform and lofting rules: sections root to tip, panels with sweep and dihedral,
//! twist, airfoil blending.
//!
//! Conventions (aircraft frame: x aft, y starboard = outboard, z up; metres):
//! - Sections stay streamwise and vertical: every section lies in a plane y = const.
//! - The *planform leading edge* of section k, `L_k`, is the untwisted leading edge. Panel
//!   k joins sections k and k+1 with `dy = y_(k+1) - y_k`:
//!   leading-edge sweep `x(L_(k+1)) = x(L_k) + dy tan(sweep)`; quarter-chord sweep
//!   `x(L_(k+1)) + c_(k+1)/4 = x(L_k) + c_k/4 + dy tan(sweep)`; dihedral raises the leading
//!   edge `z(L_(k+1)) = z(L_k) + dy tan(dihedral)`.
//! - Twist theta (positive nose up) rotates the section about the spanwise line through
//!   the chord point at `twist_axis_chord_fraction` f: a section point (u, v) (unit chord,
//!   u aft, v up) lies at `L + c (f, 0, 0) + R_y(theta) c (u - f, 0, v)`; R_y is the
//!   right-handed rotation about +y, which lifts the nose for theta > 0.
//! - Between sections chord, twist and the planform leading edge vary linearly in y; the
//!   airfoils are resampled to a common point count and blended linearly.

use nalgebra::{Point2, Point3, Rotation3, Vector3};

use crate::airfoil::{Airfoil, Surface};
use crate::error::{require_finite, require_range, Error, Result};

/// Largest accepted |sweep| and |dihedral| (deg).
pub const MAX_PANEL_ANGLE_DEG: f64 = 75.0;
/// Largest accepted |twist| (deg).
pub const MAX_TWIST_DEG: f64 = 45.0;

/// One wing section (a streamwise cut at `y_m`).
#[derive(Debug, Clone, PartialEq)]
pub struct WingSectionSpec {
    /// Spanwise position y (m), aircraft frame.
    pub y_m: f64,
    /// Chord c (m), > 0.
    pub chord_m: f64,
    /// Twist theta (deg), positive nose up, about the twist axis.
    pub twist_deg: f64,
    /// Section shape, unit chord.
    pub airfoil: Airfoil,
}

/// The panel between two consecutive sections.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanelSpec {
    /// Sweep angle (deg) of the line named by [`WingSpec::sweep_reference`], positive aft.
    pub sweep_deg: f64,
    /// Dihedral (deg), positive tip up.
    pub dihedral_deg: f64,
}

/// Which line the panel sweep angles refer to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepReference {
    /// The leading edge.
    LeadingEdge,
    /// The quarter-chord line.
    QuarterChord,
}

/// Everything that defines the wing.
#[derive(Debug, Clone, PartialEq)]
pub struct WingSpec {
    /// Planform leading edge of the first (root) section, aircraft frame (m); its y must
    /// equal `sections[0].y_m`.
    pub root_leading_edge_ac: Point3<f64>,
    /// Sections in strictly increasing y.
    pub sections: Vec<WingSectionSpec>,
    /// One panel per gap between consecutive sections.
    pub panels: Vec<PanelSpec>,
    /// Line the sweep angles refer to.
    pub sweep_reference: SweepReference,
    /// Chord fraction f of the twist axis, in [0, 1].
    pub twist_axis_chord_fraction: f64,
}

/// A section of the wing at some spanwise position.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionAt {
    /// Planform (untwisted) leading edge, aircraft frame (m).
    pub leading_edge_ac: Point3<f64>,
    /// Chord (m).
    pub chord_m: f64,
    /// Twist (rad), positive nose up.
    pub twist_rad: f64,
    /// Section shape (blended between the neighbouring sections).
    pub airfoil: Airfoil,
}

/// A validated wing.
#[derive(Debug, Clone)]
pub struct Wing {
    spec: WingSpec,
    leading_edges_ac: Vec<Point3<f64>>,
}

impl Wing {
    /// Validates the spec (order, counts, finite values, ranges) and places the sections.
    pub fn try_new(spec: WingSpec) -> Result<Wing> {
        if spec.sections.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "wing sections",
                count: spec.sections.len(),
                minimum: 2,
            });
        }
        if spec.panels.len() + 1 != spec.sections.len() {
            return Err(Error::PanelCount {
                panels: spec.panels.len(),
                sections: spec.sections.len(),
            });
        }
        for (i, s) in spec.sections.iter().enumerate() {
            require_finite("wing section y_m", s.y_m)?;
            require_range("wing section chord_m", s.chord_m, f64::MIN_POSITIVE, f64::MAX)?;
            require_range("wing section twist_deg", s.twist_deg, -MAX_TWIST_DEG, MAX_TWIST_DEG)?;
            if i > 0 && s.y_m <= spec.sections[i - 1].y_m {
                return Err(Error::SectionsOutOfOrder {
                    index: i,
                    y_m: s.y_m,
                    previous_y_m: spec.sections[i - 1].y_m,
                });
            }
        }
        for p in &spec.panels {
            require_range(
                "wing panel sweep_deg",
                p.sweep_deg,
                -MAX_PANEL_ANGLE_DEG,
                MAX_PANEL_ANGLE_DEG,
            )?;
            require_range(
                "wing panel dihedral_deg",
                p.dihedral_deg,
                -MAX_PANEL_ANGLE_DEG,
                MAX_PANEL_ANGLE_DEG,
            )?;
        }
        require_range(
            "wing twist_axis_chord_fraction",
            spec.twist_axis_chord_fraction,
            0.0,
            1.0,
        )?;
        let root = spec.root_leading_edge_ac;
        for (what, v) in [
            ("root leading edge x_m", root.x),
            ("root leading edge y_m", root.y),
            ("root leading edge z_m", root.z),
        ] {
            require_finite(what, v)?;
        }
        let first_y = spec.sections[0].y_m;
        if (root.y - first_y).abs() > 1e-9 * (1.0 + first_y.abs()) {
            return Err(Error::RootLeadingEdgeMismatch {
                root_y_m: root.y,
                section_y_m: first_y,
            });
        }
        let mut leading_edges_ac = vec![Point3::new(root.x, first_y, root.z)];
        for (k, panel) in spec.panels.iter().enumerate() {
            let (a, b) = (&spec.sections[k], &spec.sections[k + 1]);
            let dy = b.y_m - a.y_m;
            let run = dy * panel.sweep_deg.to_radians().tan();
            let dx = match spec.sweep_reference {
                SweepReference::LeadingEdge => run,
                SweepReference::QuarterChord => run + 0.25 * (a.chord_m - b.chord_m),
            };
            let previous = leading_edges_ac[k];
            leading_edges_ac.push(Point3::new(
                previous.x + dx,
                b.y_m,
                previous.z + dy * panel.dihedral_deg.to_radians().tan(),
            ));
        }
        for s in &spec.sections {
            s.airfoil.validate()?;
        }
        Ok(Wing { spec, leading_edges_ac })
    }

    /// The validated spec.
    pub fn spec(&self) -> &WingSpec {
        &self.spec
    }

    /// Root and tip spanwise positions (m).
    pub fn span_range_m(&self) -> (f64, f64) {
        (
            self.spec.sections[0].y_m,
            self.spec.sections[self.spec.sections.len() - 1].y_m,
        )
    }

    /// Planform leading edges of the given sections, aircraft frame (m).
    pub fn section_leading_edges_ac(&self) -> &[Point3<f64>] {
        &self.leading_edges_ac
    }

    /// Panel index k and fraction t in [0, 1] for `y_m`, or an error outside the span.
    pub(crate) fn locate(&self, y_m: f64, what: &str) -> Result<(usize, f64)> {
        let (root, tip) = self.span_range_m();
        if !(y_m >= root - 1e-12 && y_m <= tip + 1e-12) {
            return Err(Error::OutsideSpan {
                what: what.to_owned(),
                y_m,
                root_y_m: root,
                tip_y_m: tip,
            });
        }
        let sections = &self.spec.sections;
        let k = sections.partition_point(|s| s.y_m <= y_m).clamp(1, sections.len() - 1) - 1;
        let t = ((y_m - sections[k].y_m) / (sections[k + 1].y_m - sections[k].y_m)).clamp(0.0, 1.0);
        Ok((k, t))
    }

    /// Planform leading edge, chord (m) and twist (rad) at `y_m`, without the airfoil.
    pub fn planform_at(&self, y_m: f64) -> Result<(Point3<f64>, f64, f64)> {
        let (k, t) = self.locate(y_m, "wing section")?;
        let (a, b) = (&self.spec.sections[k], &self.spec.sections[k + 1]);
        let le = self.leading_edges_ac[k] + (self.leading_edges_ac[k + 1] - self.leading_edges_ac[k]) * t;
        let le = Point3::new(le.x, y_m, le.z);
        let chord = a.chord_m + (b.chord_m - a.chord_m) * t;
        let twist = (a.twist_deg + (b.twist_deg - a.twist_deg) * t).to_radians();
        Ok((le, chord, twist))
    }

    /// Dihedral (rad, positive tip up) of the panel holding `y_m`: on a panel boundary,
    /// the outboard panel's; an error outside the span.
    pub fn dihedral_rad_at(&self, y_m: f64) -> Result<f64> {
        let (k, _) = self.locate(y_m, "wing dihedral")?;
        Ok(self.spec.panels[k].dihedral_deg.to_radians())
    }

    /// The section at `y_m` with its airfoil blended from the neighbouring sections (each
    /// resampled to `points_per_side` when given, else to the larger of their counts).
    pub fn section_at_with(&self, y_m: f64, points_per_side: Option<usize>) -> Result<SectionAt> {
        let (k, t) = self.locate(y_m, "wing section")?;
        let (leading_edge_ac, chord_m, twist_rad) = self.planform_at(y_m)?;
        let (a, b) = (&self.spec.sections[k].airfoil, &self.spec.sections[k + 1].airfoil);
        let airfoil = match points_per_side {
            Some(n) => Airfoil::blended(&a.resampled(n)?, &b.resampled(n)?, t)?,
            None if t == 0.0 => a.clone(),
            None if t == 1.0 => b.clone(),
            None => Airfoil::blended(a, b, t)?,
        };
        Ok(SectionAt {
            leading_edge_ac,
            chord_m,
            twist_rad,
            airfoil,
        })
    }

    /// The section at `y_m` (airfoil blended between neighbouring sections).
    pub fn section_at(&self, y_m: f64) -> Result<SectionAt> {
        self.section_at_with(y_m, None)
    }

    /// Point on a surface at chord fraction `x_over_c` of the section at `y_m`, aircraft
    /// frame (m).
    pub fn point_ac(&self, y_m: f64, x_over_c: f64, surface: Surface) -> Result<Point3<f64>> {
        let section = self.section_at(y_m)?;
        let v = section.airfoil.surface_y(x_over_c, surface)?;
        Ok(self.section_point_ac(&section, Point2::new(x_over_c, v)))
    }

    /// Point on the chord line (v = 0) at chord fraction `x_over_c`, aircraft frame (m).
    pub fn chord_point_ac(&self, y_m: f64, x_over_c: f64) -> Result<Point3<f64>> {
        require_finite("chord fraction x/c", x_over_c)?;
        let section = self.section_at(y_m)?;
        Ok(self.section_point_ac(&section, Point2::new(x_over_c, 0.0)))
    }

    /// Maps a section point (u = x/c aft, v = y/c up, unit chord) of `section` to the
    /// aircraft frame: `L + c (f, 0, 0) + R_y(theta) c (u - f, 0, v)`.
    pub fn section_point_ac(&self, section: &SectionAt, point: Point2<f64>) -> Point3<f64> {
        let f = self.spec.twist_axis_chord_fraction;
        let c = section.chord_m;
        let rotation = Rotation3::from_axis_angle(&Vector3::y_axis(), section.twist_rad);
        section.leading_edge_ac
            + Vector3::new(f * c, 0.0, 0.0)
            + rotation * Vector3::new((point.x - f) * c, 0.0, point.y * c)
    }
}
