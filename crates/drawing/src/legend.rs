//! Footer of a station drawing: legend (settings and parts), and a note block with the
//! view direction, units, an axis triad and a scale bar in millimetres.

use crate::layers::{
    break_mark_points, part_class, CLASH_COLOUR, ENVELOPE_FILL, ENVELOPE_STROKE, FAIRING_COLOUR, FAIRING_DASH,
};
use crate::model::{PartStyle, StationDrawing};
use crate::style::{line, num, setting_style, text, Anchor, INK};
use svg::node::element::{Group, Polygon, Rectangle};

/// Row height of the legend, px.
pub(crate) const ROW_PX: f64 = 22.0;
/// Legend font size, px.
const FONT_PX: f64 = 13.0;
/// Width of the note block, px.
pub(crate) const NOTE_WIDTH_PX: f64 = 400.0;
/// Height of the note block, px.
pub(crate) const NOTE_HEIGHT_PX: f64 = 150.0;

/// A filled swatch box 36 x 12 px with its left end at x, centred on row y.
fn swatch(x: f64, y: f64, fill: &str, outline: &str) -> Rectangle {
    Rectangle::new()
        .set("x", num(x))
        .set("y", num(y - 6.0))
        .set("width", "36")
        .set("height", "12")
        .set("fill", fill.to_owned())
        .set("stroke", outline.to_owned())
        .set("stroke-width", "1")
}

/// Number of legend rows (the taller of the two columns).
pub(crate) fn legend_rows(drawing: &StationDrawing) -> usize {
    let parts = part_entries(drawing).len();
    (drawing.settings.len() + 1).max(parts + 1)
}

/// Legend entries for the parts column: (label, kind of swatch).
fn part_entries(drawing: &StationDrawing) -> Vec<(&'static str, Swatch)> {
    let mut entries = Vec::new();
    let has = |kind: PartStyle| drawing.sections.iter().any(|s| s.kind == kind);
    if !drawing.envelope.is_empty() {
        entries.push(("swept envelope", Swatch::Envelope));
    }
    if drawing.fairing_line.is_some() {
        entries.push(("fairing line", Swatch::Fairing));
    }
    if !drawing.fairing_parts.is_empty() {
        entries.push(("sets the fairing line", Swatch::FairingPart));
    }
    if !drawing.clashes.is_empty() {
        entries.push(("fails the clearance check", Swatch::Clash));
    }
    if !drawing.slots.is_empty() {
        entries.push(("slot (track)", Swatch::Slot));
    }
    if !drawing.breaks.is_empty() {
        entries.push(("section cut for the view", Swatch::Break));
    }
    for (kind, name) in [
        (PartStyle::WingSkin, "wing skin"),
        (PartStyle::Flap, "flap section"),
        (PartStyle::Spar, "spar"),
        (PartStyle::TorqueTube, "torque tube"),
        (PartStyle::Other, "other part"),
    ] {
        if has(kind) {
            entries.push((name, Swatch::Part(kind)));
        }
    }
    let has_fixed = drawing.settings.iter().any(|s| s.joints.iter().any(|j| j.fixed));
    if has_fixed {
        entries.push(("fixed pivot", Swatch::Ground));
    }
    entries
}

/// What the swatch of a parts entry looks like.
#[derive(Debug, Clone, Copy)]
enum Swatch {
    Envelope,
    FairingPart,
    Clash,
    Fairing,
    Slot,
    Part(PartStyle),
    Ground,
    Break,
}

/// The legend: settings (line style, deflection, joint primes) and parts, in two
/// columns starting at (x, y), `column_px` apart.
pub(crate) fn legend(drawing: &StationDrawing, x: f64, y: f64, column_px: f64) -> Group {
    let mut group = Group::new().set("id", "legend").set("class", "legend");
    group = group.add(text("Flap settings", x, y, FONT_PX, Anchor::Start, INK).set("font-weight", "bold"));
    for (index, setting) in drawing.settings.iter().enumerate() {
        let style = setting_style(index);
        let row_y = y + ROW_PX * (index as f64 + 1.0);
        let mut sample = line(x, row_y - 4.0, x + 44.0, row_y - 4.0, style.colour, 3.2).set("stroke-linecap", "round");
        if let Some(dash) = style.dash {
            sample = sample.set("stroke-dasharray", dash);
        }
        let mut names: Vec<String> = Vec::new();
        for joint in setting.joints.iter().filter(|j| !j.fixed) {
            let name = format!("{}{}", joint.name, style.prime);
            if !names.contains(&name) {
                names.push(name);
            }
        }
        let joints = if names.is_empty() {
            String::new()
        } else {
            format!(", joints {}", names.join(" "))
        };
        let words = format!(
            "{}: \u{3b4} = {:.1}\u{b0} ({}{joints})",
            setting.label, setting.deflection_deg, style.pattern_name
        );
        group = group
            .add(sample.set("class", format!("legend-setting setting-{index}")))
            .add(text(&words, x + 54.0, row_y, FONT_PX, Anchor::Start, style.colour));
    }
    let px = x + column_px;
    group = group.add(text("Parts", px, y, FONT_PX, Anchor::Start, INK).set("font-weight", "bold"));
    for (row, (label, kind)) in part_entries(drawing).into_iter().enumerate() {
        let row_y = y + ROW_PX * (row as f64 + 1.0) - 4.0;
        let sample: Group = match kind {
            Swatch::Envelope => Group::new().add(
                swatch(px + 4.0, row_y, ENVELOPE_FILL, ENVELOPE_STROKE)
                    .set("fill-opacity", "0.3")
                    .set("stroke-dasharray", "4 3"),
            ),
            Swatch::Fairing => Group::new()
                .add(line(px, row_y, px + 44.0, row_y, FAIRING_COLOUR, 2.2).set("stroke-dasharray", FAIRING_DASH)),
            Swatch::FairingPart => Group::new().add(
                line(px + 4.0, row_y, px + 40.0, row_y, FAIRING_COLOUR, 4.0)
                    .set("stroke-opacity", "0.75")
                    .set("stroke-linecap", "round"),
            ),
            Swatch::Clash => Group::new()
                .add(line(px + 15.0, row_y - 7.0, px + 29.0, row_y + 7.0, CLASH_COLOUR, 2.5))
                .add(line(px + 15.0, row_y + 7.0, px + 29.0, row_y - 7.0, CLASH_COLOUR, 2.5)),
            Swatch::Slot => Group::new()
                .add(line(px + 6.0, row_y, px + 38.0, row_y, "#4d4d4d", 12.0).set("stroke-linecap", "round"))
                .add(line(px + 6.0, row_y, px + 38.0, row_y, "#f7f7f7", 9.0).set("stroke-linecap", "round")),
            Swatch::Part(kind) => {
                let (fill, outline) = match kind {
                    PartStyle::WingSkin => ("#d4d4d4", INK),
                    PartStyle::Flap => ("#e9eef7", INK),
                    PartStyle::Spar => ("#7a7a7a", INK),
                    PartStyle::TorqueTube => ("#111111", "#111111"),
                    PartStyle::Other => ("none", "#777777"),
                };
                Group::new()
                    .set("class", part_class(kind))
                    .add(swatch(px + 4.0, row_y, fill, outline))
            }
            Swatch::Break => {
                let points = break_mark_points((px + 22.0, row_y - 8.0), (px + 22.0, row_y + 8.0)).unwrap_or_default();
                Group::new().add(
                    svg::node::element::Polyline::new()
                        .set("points", crate::style::points_attribute(&points))
                        .set("fill", "none")
                        .set("stroke", INK)
                        .set("stroke-width", "1.2"),
                )
            }
            Swatch::Ground => Group::new()
                .add(
                    Polygon::new()
                        .set(
                            "points",
                            format!(
                                "{},{} {},{} {},{}",
                                num(px + 22.0),
                                num(row_y - 7.0),
                                num(px + 15.0),
                                num(row_y + 5.0),
                                num(px + 29.0),
                                num(row_y + 5.0)
                            ),
                        )
                        .set("fill", "#f0f0f0")
                        .set("stroke", INK)
                        .set("stroke-width", "1.2"),
                )
                .add(line(px + 12.0, row_y + 5.0, px + 32.0, row_y + 5.0, INK, 1.4)),
        };
        group = group
            .add(sample)
            .add(text(label, px + 54.0, row_y + 4.0, FONT_PX, Anchor::Start, INK));
    }
    group
}

/// Largest length of the form {1, 2, 5} x 10^k millimetres that is at most `max_mm`.
pub(crate) fn scale_bar_length_mm(max_mm: f64) -> f64 {
    let magnitude = 10f64.powf(max_mm.log10().floor());
    [5.0, 2.0, 1.0]
        .iter()
        .map(|f| f * magnitude)
        .find(|len| *len <= max_mm * (1.0 + 1e-9))
        .unwrap_or(magnitude)
}

/// Note block at (x, y): view direction, frame, units, axis triad and scale bar.
pub(crate) fn note_block(x: f64, y: f64, px_per_m: f64) -> Group {
    let mut group = Group::new().set("id", "title-block").set("class", "title-block").add(
        Rectangle::new()
            .set("x", num(x))
            .set("y", num(y))
            .set("width", num(NOTE_WIDTH_PX))
            .set("height", num(NOTE_HEIGHT_PX))
            .set("fill", "white")
            .set("stroke", INK)
            .set("stroke-width", "1.2"),
    );
    let lines = [
        "Station frame, seen from outboard (+z towards you):",
        "nose (+x) to the right, y up, origin A0 = hinge point.",
        "Lengths in mm. Scale equal on both axes.",
    ];
    for (i, line) in lines.iter().enumerate() {
        group = group.add(text(
            line,
            x + 12.0,
            y + 22.0 + 18.0 * i as f64,
            12.5,
            Anchor::Start,
            INK,
        ));
    }
    // Axis triad at the lower right.
    let (ox, oy) = (x + NOTE_WIDTH_PX - 70.0, y + NOTE_HEIGHT_PX - 22.0);
    group = group
        .add(line(ox, oy, ox + 40.0, oy, INK, 1.5))
        .add(
            Polygon::new()
                .set(
                    "points",
                    format!(
                        "{},{} {},{} {},{}",
                        num(ox + 46.0),
                        num(oy),
                        num(ox + 38.0),
                        num(oy - 3.5),
                        num(ox + 38.0),
                        num(oy + 3.5)
                    ),
                )
                .set("fill", INK),
        )
        .add(line(ox, oy, ox, oy - 40.0, INK, 1.5))
        .add(
            Polygon::new()
                .set(
                    "points",
                    format!(
                        "{},{} {},{} {},{}",
                        num(ox),
                        num(oy - 46.0),
                        num(ox - 3.5),
                        num(oy - 38.0),
                        num(ox + 3.5),
                        num(oy - 38.0)
                    ),
                )
                .set("fill", INK),
        )
        .add(text("x (nose)", ox + 12.0, oy + 15.0, 11.0, Anchor::Start, INK))
        .add(text("y", ox + 7.0, oy - 36.0, 11.0, Anchor::Start, INK));
    // Scale bar at the lower left: four alternating segments.
    let px_per_mm = px_per_m / 1000.0;
    let length_mm = scale_bar_length_mm(220.0 / px_per_mm);
    let length_px = length_mm * px_per_mm;
    let (sx, sy) = (x + 16.0, y + NOTE_HEIGHT_PX - 36.0);
    let segments = 4;
    for i in 0..segments {
        let fill = if i % 2 == 0 { INK } else { "white" };
        group = group.add(
            Rectangle::new()
                .set("x", num(sx + length_px * i as f64 / segments as f64))
                .set("y", num(sy))
                .set("width", num(length_px / segments as f64))
                .set("height", "7")
                .set("fill", fill)
                .set("stroke", INK)
                .set("stroke-width", "1"),
        );
    }
    let half = crate::ticks::format_tick(0.5 * length_mm, 0.5 * length_mm);
    let full = crate::ticks::format_tick(length_mm, 0.5 * length_mm);
    group
        .set("data-scale-bar-mm", num(length_mm))
        .add(text("0", sx, sy + 22.0, 11.0, Anchor::Middle, INK))
        .add(text(&half, sx + 0.5 * length_px, sy + 22.0, 11.0, Anchor::Middle, INK))
        .add(text(
            &format!("{full} mm"),
            sx + length_px,
            sy + 22.0,
            11.0,
            Anchor::Middle,
            INK,
        ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_bar_lengths_are_round() {
        assert_eq!(scale_bar_length_mm(220.0), 200.0);
        assert_eq!(scale_bar_length_mm(99.0), 50.0);
        assert_eq!(scale_bar_length_mm(100.0), 100.0);
        assert_eq!(scale_bar_length_mm(7.3), 5.0);
        assert_eq!(scale_bar_length_mm(1999.0), 1000.0);
    }
}
