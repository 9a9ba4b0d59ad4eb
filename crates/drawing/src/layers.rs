//! The geometric layers of a station drawing: section parts, slots, swept envelope,
//! fairing line, the mechanism at each setting (flap outline and links) and the break
//! marks where a section is cut for the view.
//!
//! Each function maps station-frame geometry through a [`ScreenMap`] and returns an
//! SVG group; labels are placed separately (`annotate`).

use crate::model::{MechanismSnapshot, PartStyle, SectionOutline, SlotArc};
use crate::style::{css_name, num, points_attribute, setting_style, title, INK};
use crate::view::ScreenMap;
use nalgebra::Point2;
use svg::node::element::{Group, Polygon, Polyline};

/// Samples per slot arc polyline (arcs span well under 180 degrees in practice).
const ARC_SAMPLES: usize = 64;

/// Fill and stroke of a section part.
fn part_paint(kind: PartStyle) -> (&'static str, &'static str, f64) {
    match kind {
        PartStyle::WingSkin => ("#d4d4d4", INK, 1.4),
        PartStyle::Flap => ("#e9eef7", INK, 1.2),
        PartStyle::Spar => ("#7a7a7a", INK, 1.0),
        PartStyle::TorqueTube => ("#111111", "#111111", 1.0),
        PartStyle::Other => ("none", "#777777", 1.0),
    }
}

/// Short name of a part style for SVG classes and the legend.
pub(crate) fn part_class(kind: PartStyle) -> &'static str {
    match kind {
        PartStyle::WingSkin => "wing-skin",
        PartStyle::Flap => "flap-section",
        PartStyle::Spar => "spar",
        PartStyle::TorqueTube => "torque-tube",
        PartStyle::Other => "other-part",
    }
}

/// Section parts, drawn as filled polygons, torque tubes last so they stay visible.
pub(crate) fn sections_layer(sections: &[SectionOutline], map: &ScreenMap) -> Group {
    let mut ordered: Vec<&SectionOutline> = sections.iter().collect();
    ordered.sort_by_key(|s| matches!(s.kind, PartStyle::TorqueTube));
    let mut group = Group::new().set("id", "sections").set("class", "sections");
    for section in ordered {
        let (fill, stroke, width) = part_paint(section.kind);
        let mut part = Group::new()
            .set("class", format!("part {}", part_class(section.kind)))
            .add(title(&section.part));
        for polygon in &section.polygons {
            part = part.add(
                Polygon::new()
                    .set("points", points_attribute(&map.page_points(polygon)))
                    .set("fill", fill)
                    .set("stroke", stroke)
                    .set("stroke-width", num(width))
                    .set("stroke-linejoin", "round"),
            );
        }
        group = group.add(part);
    }
    group
}

/// Slots: a channel (dark edges, pale inside) with a dash-dot centre line.
pub(crate) fn slots_layer(slots: &[SlotArc], map: &ScreenMap) -> Group {
    let mut group = Group::new().set("id", "slots").set("class", "slots");
    for slot in slots {
        let points = points_attribute(&map.page_points(&slot.sample(ARC_SAMPLES)));
        let channel = |colour: &str, width: f64| {
            Polyline::new()
                .set("points", points.clone())
                .set("fill", "none")
                .set("stroke", colour.to_owned())
                .set("stroke-width", num(width))
                .set("stroke-linecap", "round")
                .set("stroke-linejoin", "round")
        };
        group = group.add(
            Group::new()
                .set("class", "slot")
                .add(title(&slot.name))
                .add(channel("#4d4d4d", 12.0))
                .add(channel("#f7f7f7", 9.0))
                .add(
                    channel("#8a8a8a", 0.8)
                        .set("stroke-dasharray", "10 3 2 3")
                        .set("stroke-linecap", "butt"),
                ),
        );
    }
    group
}

/// Swept envelope: translucent yellow fill (kept apart from the blue stowed flap) with a thin dashed outline.
pub(crate) fn envelope_layer(envelope: &[Vec<Point2<f64>>], map: &ScreenMap) -> Group {
    let mut group = Group::new()
        .set("id", "envelope")
        .set("class", "envelope")
        .add(title("swept envelope"));
    for outline in envelope {
        group = group.add(
            Polygon::new()
                .set("points", points_attribute(&map.page_points(outline)))
                .set("fill", ENVELOPE_FILL)
                .set("fill-opacity", "0.3")
                .set("stroke", ENVELOPE_STROKE)
                .set("stroke-width", "1")
                .set("stroke-dasharray", "4 3"),
        );
    }
    group
}

/// Fill colour of the swept envelope.
pub(crate) const ENVELOPE_FILL: &str = "#f0e442";
/// Outline colour of the swept envelope.
pub(crate) const ENVELOPE_STROKE: &str = "#9a8c00";
/// Colour of the fairing line.
pub(crate) const FAIRING_COLOUR: &str = "#0f7b5f";
/// Dash pattern of the fairing line (long dash, dot).
pub(crate) const FAIRING_DASH: &str = "18 4 3 4";

/// The fairing line: a green long-dash-dot polyline.
pub(crate) fn fairing_layer(line: &[Point2<f64>], map: &ScreenMap) -> Group {
    Group::new()
        .set("id", "fairing-line")
        .set("class", "fairing-line")
        .add(title("fairing line"))
        .add(
            Polyline::new()
                .set("points", points_attribute(&map.page_points(line)))
                .set("fill", "none")
                .set("stroke", FAIRING_COLOUR)
                .set("stroke-width", "2.2")
                .set("stroke-dasharray", FAIRING_DASH)
                .set("stroke-linejoin", "round"),
        )
}

/// SVG id of setting `index` ("setting-2-landing").
pub(crate) fn setting_id(index: usize, setting: &MechanismSnapshot) -> String {
    format!("setting-{index}-{}", css_name(&setting.label))
}

/// One setting: flap outline (lightly tinted) and links, in the setting's colour and
/// dash pattern. Joints are drawn by `annotate` so they sit above every setting.
pub(crate) fn setting_layer(index: usize, setting: &MechanismSnapshot, map: &ScreenMap) -> Group {
    let style = setting_style(index);
    let mut group = Group::new()
        .set("id", setting_id(index, setting))
        .set("class", format!("setting setting-{}", css_name(&setting.label)))
        .add(title(&format!("{} ({:.1} deg)", setting.label, setting.deflection_deg)));
    let dashed = |element: Polyline| match style.dash {
        Some(dash) => element.set("stroke-dasharray", dash),
        None => element,
    };
    for outline in &setting.flap_outline {
        let mut polygon = Polygon::new()
            .set("class", "flap-outline")
            .set("points", points_attribute(&map.page_points(outline)))
            .set("fill", style.colour)
            .set("fill-opacity", "0.07")
            .set("stroke", style.colour)
            .set("stroke-width", "1.8")
            .set("stroke-linejoin", "round")
            .set("stroke-linecap", "round");
        if let Some(dash) = style.dash {
            polygon = polygon.set("stroke-dasharray", dash);
        }
        group = group.add(polygon);
    }
    for link in &setting.links {
        group = group.add(
            dashed(
                Polyline::new()
                    .set("class", "link")
                    .set("points", points_attribute(&map.page_points(&link.points)))
                    .set("fill", "none")
                    .set("stroke", style.colour)
                    .set("stroke-width", "3.2")
                    .set("stroke-linejoin", "round")
                    .set("stroke-linecap", "round"),
            )
            .add(title(&link.name)),
        );
    }
    group
}

/// Colour of a failing pair's mark.
pub(crate) const CLASH_COLOUR: &str = "#d7191c";

/// The parts that set the fairing line, where they reach deepest: their skeletons, thick,
/// in the fairing line's colour.
pub(crate) fn fairing_parts_layer(parts: &[crate::model::Link], map: &ScreenMap) -> Group {
    let mut group = Group::new().set("id", "fairing-parts").set("class", "fairing-parts");
    for part in parts {
        group = group.add(
            Polyline::new()
                .set("points", points_attribute(&map.page_points(&part.points)))
                .set("fill", "none")
                .set("stroke", FAIRING_COLOUR)
                .set("stroke-width", "4")
                .set("stroke-opacity", "0.75")
                .set("stroke-linecap", "round")
                .set("stroke-linejoin", "round")
                .add(title(&format!("{}: sets the fairing line", part.name))),
        );
    }
    group
}

/// Failing pairs: a cross where the pair comes closest, with its label placed clear of
/// the other labels and lines.
pub(crate) fn clashes_layer(
    clashes: &[crate::model::Clash],
    map: &ScreenMap,
    placer: &mut crate::labels::LabelPlacer,
) -> Group {
    const SIZE: f64 = 12.0;
    const ARM_PX: f64 = 7.0;
    let mut group = Group::new().set("id", "clashes").set("class", "clashes");
    for clash in clashes {
        let (x, y) = map.page_point(&clash.at);
        let (half_width, half_height) = (0.5 * crate::style::text_width(&clash.label, SIZE), 0.5 * SIZE);
        let (cx, cy) = placer.place_near(x, y, half_width, half_height, 10.0);
        group = group.add(
            Group::new()
                .set("class", "clash")
                .add(title(&clash.label))
                .add(crate::style::line(
                    x - ARM_PX,
                    y - ARM_PX,
                    x + ARM_PX,
                    y + ARM_PX,
                    CLASH_COLOUR,
                    2.5,
                ))
                .add(crate::style::line(
                    x - ARM_PX,
                    y + ARM_PX,
                    x + ARM_PX,
                    y - ARM_PX,
                    CLASH_COLOUR,
                    2.5,
                ))
                .add(crate::style::line(x, y, cx, cy, CLASH_COLOUR, 0.7))
                .add(
                    crate::style::text(
                        &clash.label,
                        cx,
                        cy + 0.36 * SIZE,
                        SIZE,
                        crate::style::Anchor::Middle,
                        CLASH_COLOUR,
                    )
                    .set("font-weight", "bold")
                    .set(
                        "data-box",
                        crate::labels::PageBox::centred(cx, cy, half_width, half_height).attribute(),
                    ),
                ),
        );
    }
    group
}

/// How far a break mark reaches past the cut outline at each end, px.
const BREAK_OVERHANG_PX: f64 = 8.0;
/// Half the height of a break mark's zigzag, px.
const BREAK_ZIG_PX: f64 = 6.0;

/// The zigzag line of a break mark from `a` to `b` (page px): straight past both ends,
/// with a "Z" in its middle.
pub(crate) fn break_mark_points(a: (f64, f64), b: (f64, f64)) -> Option<Vec<(f64, f64)>> {
    let length = (b.0 - a.0).hypot(b.1 - a.1);
    if length < 1e-9 {
        return None;
    }
    let (ux, uy) = ((b.0 - a.0) / length, (b.1 - a.1) / length);
    let (nx, ny) = (-uy, ux);
    let at = |along: f64, side: f64| (a.0 + ux * along + nx * side, a.1 + uy * along + ny * side);
    let (middle, zig) = (0.5 * length, BREAK_ZIG_PX);
    Some(vec![
        at(-BREAK_OVERHANG_PX, 0.0),
        at(middle - zig, 0.0),
        at(middle - 0.5 * zig, zig),
        at(middle + 0.5 * zig, -zig),
        at(middle + zig, 0.0),
        at(length + BREAK_OVERHANG_PX, 0.0),
    ])
}

/// Break marks across the cuts of sections shortened for the view: a white band hides
/// the straight cut, a thin zigzag line over it says the part goes on.
pub(crate) fn breaks_layer(breaks: &[[Point2<f64>; 2]], map: &ScreenMap) -> Group {
    let mut group = Group::new().set("id", "breaks").set("class", "breaks");
    for [from, to] in breaks {
        let Some(points) = break_mark_points(map.page_point(from), map.page_point(to)) else {
            continue;
        };
        group = group.add(
            Group::new()
                .set("class", "break")
                .add(title("section cut for the view"))
                .add(
                    Polyline::new()
                        .set("points", points_attribute(&points))
                        .set("fill", "none")
                        .set("stroke", "white")
                        .set("stroke-width", "4"),
                )
                .add(
                    Polyline::new()
                        .set("points", points_attribute(&points))
                        .set("fill", "none")
                        .set("stroke", INK)
                        .set("stroke-width", "1.2")
                        .set("stroke-linejoin", "round"),
                ),
        );
    }
    group
}
