//! Plain geometry of one station, as handed to [`crate::render_station_svg`].
//!
//! Every coordinate is in the station frame (DESIGN.md "Frames and units"): metres,
//! origin at the hinge point A0, x in the plane towards the nose, y up, z outboard
//! (towards the viewer of the drawing). Angles in radians unless the name says `_deg`.

use nalgebra::Point2;

/// How a section part is painted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PartStyle {
    /// Wing skin (fixed structure): light grey fill, dark outline.
    WingSkin,
    /// Flap section (as cut, usually stowed): pale fill, dark outline.
    Flap,
    /// Spar web: dark grey fill.
    Spar,
    /// Torque tube: black fill (the "big black dot" of the thesis, Fig. 24).
    TorqueTube,
    /// Anything else: grey outline, no fill.
    Other,
}

/// One part of the section cut: one or more closed polygons (station frame, m).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionOutline {
    /// Part name, shown in the SVG `<title>` and used in error messages.
    pub part: String,
    /// How to paint it.
    pub kind: PartStyle,
    /// Closed polygons (the last point joins the first), each with at least 3 points.
    pub polygons: Vec<Vec<Point2<f64>>>,
}

/// A rigid link drawn as a polyline (station frame, m), at least 2 points.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Link name (e.g. "screw jack", "flap bracket").
    pub name: String,
    /// Polyline through the link's joints/corners.
    pub points: Vec<Point2<f64>>,
}

/// A joint: a small circle with a label (station frame, m).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Label drawn beside the joint (e.g. "A0", "B0", "A", "F", "G").
    pub name: String,
    /// Position of the joint centre.
    pub at: Point2<f64>,
    /// Fixed to the wing (drawn with a ground symbol, labelled once for all settings).
    pub fixed: bool,
}

/// The mechanism at one flap setting.
#[derive(Debug, Clone, PartialEq)]
pub struct MechanismSnapshot {
    /// Setting name ("stowed", "takeoff", "landing"); also the SVG class of its group.
    pub label: String,
    /// Flap deflection at this setting, degrees (trailing edge down positive).
    pub deflection_deg: f64,
    /// Flap outline at this setting: closed polygons.
    pub flap_outline: Vec<Vec<Point2<f64>>>,
    /// Links at this setting.
    pub links: Vec<Link>,
    /// Joints at this setting.
    pub joints: Vec<Joint>,
}

/// A circular slot (track) in the fixed structure, drawn as a thick arc.
#[derive(Debug, Clone, PartialEq)]
pub struct SlotArc {
    /// Slot name (e.g. "slot b1").
    pub name: String,
    /// Centre of the arc (station frame, m).
    pub centre: Point2<f64>,
    /// Radius of the slot centre line, metres.
    pub radius_m: f64,
    /// Start angle, radians, counter-clockwise from +x (towards the nose).
    pub start_rad: f64,
    /// End angle, radians, counter-clockwise from +x; may be less than `start_rad`.
    pub end_rad: f64,
}

/// A linear dimension between two points, drawn offset with extension lines, arrowheads
/// and the value in millimetres.
#[derive(Debug, Clone, PartialEq)]
pub struct Dimension {
    /// Label drawn before the value (e.g. "a2"); the text reads "a2 = 240.0 mm".
    pub label: String,
    /// First end (station frame, m).
    pub from: Point2<f64>,
    /// Second end (station frame, m).
    pub to: Point2<f64>,
}

/// Everything drawn for one station.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StationDrawing {
    /// Title (e.g. "Station 2 - outer flap, y = 3.20 m").
    pub title: String,
    /// Subtitle (mechanism kind, scene name...).
    pub subtitle: String,
    /// Section cut of the fixed and moving parts.
    pub sections: Vec<SectionOutline>,
    /// The mechanism at each setting; styles go by position: first solid, second
    /// dashed, third dotted.
    pub settings: Vec<MechanismSnapshot>,
    /// Slots in the fixed structure.
    pub slots: Vec<SlotArc>,
    /// Closed outlines of what the moving parts sweep during deployment.
    pub envelope: Vec<Vec<Point2<f64>>>,
    /// The fairing line (open polyline), if any.
    pub fairing_line: Option<Vec<Point2<f64>>>,
    /// Dimensions of the synthesised links.
    pub dimensions: Vec<Dimension>,
    /// The parts that set the fairing line, where they reach deepest (skeletons, like
    /// [`MechanismSnapshot::links`]): drawn in the fairing line's colour.
    pub fairing_parts: Vec<Link>,
    /// Pairs that fail the clearance check, marked where they come closest.
    pub clashes: Vec<Clash>,
    /// Where a section was cut short to keep the mechanism legible: a segment across each
    /// cut (station frame, m), drawn as a break mark so that the cut does not read as
    /// the part's edge.
    pub breaks: Vec<[Point2<f64>; 2]>,
}

/// A pair that fails the clearance check, as the drawing marks it.
#[derive(Debug, Clone, PartialEq)]
pub struct Clash {
    /// What to write beside the mark ("inner.screw / wing: -2.1 mm at 40 %").
    pub label: String,
    /// The closest (or deepest) point of the pair, station frame (m).
    pub at: Point2<f64>,
}

impl Dimension {
    /// A dimension from `from` to `to` labelled `label` (station frame, m).
    pub fn new(label: impl Into<String>, from: Point2<f64>, to: Point2<f64>) -> Self {
        Self {
            label: label.into(),
            from,
            to,
        }
    }

    /// Length of the dimension, metres.
    pub fn length_m(&self) -> f64 {
        nalgebra::distance(&self.from, &self.to)
    }
}

impl SlotArc {
    /// Points along the slot centre line (station frame, m), `count` >= 2 samples.
    pub fn sample(&self, count: usize) -> Vec<Point2<f64>> {
        let count = count.max(2);
        (0..count)
            .map(|i| {
                let t = i as f64 / (count - 1) as f64;
                let angle = self.start_rad + t * (self.end_rad - self.start_rad);
                Point2::new(
                    self.centre.x + self.radius_m * angle.cos(),
                    self.centre.y + self.radius_m * angle.sin(),
                )
            })
            .collect()
    }
}
