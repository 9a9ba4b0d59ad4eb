//! Annotations of a station drawing: joint markers and labels, dimension lines with
//! arrowheads and values in mm, slot names. Labels avoid each other through one
//! [`LabelPlacer`] shared by the whole drawing.

use crate::labels::{LabelPlacer, PageBox};
use crate::model::{Dimension, MechanismSnapshot, SlotArc};
use crate::style::{css_name, line, num, points_attribute, setting_style, text, text_width, Anchor, INK};
use crate::view::ScreenMap;
use svg::node::element::{Circle, Group, Line, Polygon};

/// Radius of a joint marker, px.
const JOINT_RADIUS_PX: f64 = 4.5;
/// Joint label font size, px.
const JOINT_FONT_PX: f64 = 14.0;
/// Dimension text font size, px.
const DIMENSION_FONT_PX: f64 = 12.5;
/// Colour of dimension lines and text.
const DIMENSION_COLOUR: &str = "#333333";
/// Arrowhead length and half width, px.
const ARROW_LENGTH_PX: f64 = 9.0;
/// Arrowhead half width, px.
const ARROW_HALF_WIDTH_PX: f64 = 3.2;
/// Distance at which a label gets a leader line to its joint, px.
const LEADER_MIN_PX: f64 = 22.0;

/// One joint to mark: page position, label text, colour, fixed or not, setting class.
struct JointMark {
    x: f64,
    y: f64,
    label: String,
    colour: &'static str,
    fixed: bool,
    class: String,
}

/// Joint markers (circles; fixed joints with a ground symbol) and their labels.
///
/// Fixed joints are drawn once (first setting that has them, by name); moving joints
/// once per setting, labelled with the setting's prime (A, A', A'').
pub(crate) fn joints_layer(
    settings: &[MechanismSnapshot],
    map: &ScreenMap,
    placer: &mut LabelPlacer,
) -> (Group, Group) {
    let mut marks: Vec<JointMark> = Vec::new();
    let mut fixed_seen: Vec<&str> = Vec::new();
    for (index, setting) in settings.iter().enumerate() {
        let style = setting_style(index);
        for joint in &setting.joints {
            if joint.fixed {
                if fixed_seen.contains(&joint.name.as_str()) {
                    continue;
                }
                fixed_seen.push(&joint.name);
            }
            let (x, y) = map.page_point(&joint.at);
            let (label, colour, class) = if joint.fixed {
                (joint.name.clone(), INK, "fixed".to_owned())
            } else {
                (
                    format!("{}{}", joint.name, style.prime),
                    style.colour,
                    format!("setting-{}", css_name(&setting.label)),
                )
            };
            marks.push(JointMark {
                x,
                y,
                label,
                colour,
                fixed: joint.fixed,
                class,
            });
        }
    }
    // Markers first: labels must avoid every marker, not only earlier ones.
    for mark in &marks {
        let reach = JOINT_RADIUS_PX + 2.0;
        placer.block(PageBox::centred(mark.x, mark.y, reach, reach));
        if mark.fixed {
            placer.block(PageBox {
                left: mark.x - 9.0,
                top: mark.y,
                right: mark.x + 9.0,
                bottom: mark.y + 16.0,
            });
        }
    }
    let mut markers = Group::new().set("id", "joints").set("class", "joints");
    let mut labels = Group::new().set("id", "joint-labels").set("class", "labels");
    for mark in &marks {
        if mark.fixed {
            markers = markers.add(ground_symbol(mark.x, mark.y));
        }
        markers = markers.add(
            Circle::new()
                .set("class", format!("joint {}", mark.class))
                .set("cx", num(mark.x))
                .set("cy", num(mark.y))
                .set("r", num(JOINT_RADIUS_PX))
                .set("fill", "white")
                .set("stroke", mark.colour)
                .set("stroke-width", "2"),
        );
        let half_width = 0.5 * text_width(&mark.label, JOINT_FONT_PX);
        let half_height = 0.5 * JOINT_FONT_PX;
        let (cx, cy) = placer.place_near(mark.x, mark.y, half_width, half_height, 3.0);
        let distance = ((cx - mark.x).powi(2) + (cy - mark.y).powi(2)).sqrt() - half_width.max(half_height);
        let mut label = Group::new().set("class", format!("joint-label {}", mark.class));
        if distance > LEADER_MIN_PX {
            label = label.add(
                Line::new()
                    .set("x1", num(mark.x))
                    .set("y1", num(mark.y))
                    .set("x2", num(cx))
                    .set("y2", num(cy))
                    .set("stroke", mark.colour)
                    .set("stroke-width", "0.7"),
            );
        }
        let baseline = cy + 0.36 * JOINT_FONT_PX;
        label = label.add(
            text(&mark.label, cx, baseline, JOINT_FONT_PX, Anchor::Middle, mark.colour)
                .set("font-weight", "bold")
                .set(
                    "data-box",
                    PageBox::centred(cx, cy, half_width, half_height).attribute(),
                ),
        );
        labels = labels.add(label);
    }
    (markers, labels)
}

/// Ground symbol under a fixed pivot at (x, y): a triangle and four hatch strokes.
fn ground_symbol(x: f64, y: f64) -> Group {
    let base = y + 12.0;
    let mut group = Group::new().set("class", "ground").add(
        Polygon::new()
            .set("points", points_attribute(&[(x, y), (x - 7.0, base), (x + 7.0, base)]))
            .set("fill", "#f0f0f0")
            .set("stroke", INK)
            .set("stroke-width", "1.2"),
    );
    group = group.add(line(x - 9.0, base, x + 9.0, base, INK, 1.4));
    for i in 0..4 {
        let x0 = x - 7.5 + 5.0 * f64::from(i);
        group = group.add(line(x0, base, x0 - 4.0, base + 4.0, INK, 1.0));
    }
    group
}

/// Filled arrowhead with its tip at (x, y) pointing along unit vector (ux, uy).
fn arrowhead(x: f64, y: f64, ux: f64, uy: f64) -> Polygon {
    let (bx, by) = (x - ux * ARROW_LENGTH_PX, y - uy * ARROW_LENGTH_PX);
    let (nx, ny) = (-uy * ARROW_HALF_WIDTH_PX, ux * ARROW_HALF_WIDTH_PX);
    Polygon::new()
        .set(
            "points",
            points_attribute(&[(x, y), (bx + nx, by + ny), (bx - nx, by - ny)]),
        )
        .set("fill", DIMENSION_COLOUR)
}

/// Text of a dimension: "a2 = 240.0 mm" (or just "240.0 mm" without a label).
pub(crate) fn dimension_text(dimension: &Dimension) -> String {
    let value_mm = dimension.length_m() * 1000.0;
    if dimension.label.is_empty() {
        format!("{value_mm:.1} mm")
    } else {
        format!("{} = {value_mm:.1} mm", dimension.label)
    }
}

/// Dimension lines: offset to the side (and distance) where the text collides least,
/// with extension lines, arrowheads at both ends and the value in mm along the line.
pub(crate) fn dimensions_layer(dimensions: &[Dimension], map: &ScreenMap, placer: &mut LabelPlacer) -> Group {
    let mut group = Group::new().set("id", "dimensions").set("class", "dimensions");
    for dimension in dimensions {
        let (x1, y1) = map.page_point(&dimension.from);
        let (x2, y2) = map.page_point(&dimension.to);
        let length = ((x2 - x1).powi(2) + (y2 - y1).powi(2)).sqrt();
        if length < 1e-9 {
            continue; // validated as non-zero in metres; below a pixel there is no line to draw
        }
        let (ux, uy) = ((x2 - x1) / length, (y2 - y1) / length);
        let (nx, ny) = (-uy, ux);
        let content = dimension_text(dimension);
        // Text turned along the line, never upside down.
        let mut angle = uy.atan2(ux).to_degrees();
        if angle > 90.0 {
            angle -= 180.0;
        } else if angle <= -90.0 {
            angle += 180.0;
        }
        let (half_w, half_h) = (
            0.5 * text_width(&content, DIMENSION_FONT_PX),
            0.5 * DIMENSION_FONT_PX + 1.0,
        );
        let (sin, cos) = angle.to_radians().sin_cos();
        let box_hw = cos.abs() * half_w + sin.abs() * half_h;
        let box_hh = sin.abs() * half_w + cos.abs() * half_h;
        // Candidates: each offset (alternating sides, growing), then slid along the line.
        let mut candidates: Vec<(f64, f64)> = Vec::new();
        for offset in [24.0, -24.0, 42.0, -42.0, 62.0, -62.0] {
            for along in [0.5, 0.35, 0.65, 0.25, 0.75] {
                candidates.push((offset, along));
            }
        }
        let text_centre = |(offset, along): (f64, f64)| {
            let reach = offset + offset.signum() * (half_h + 2.0);
            (x1 + along * (x2 - x1) + nx * reach, y1 + along * (y2 - y1) + ny * reach)
        };
        let (chosen, (tx, ty)) = placer.place_best(candidates.iter().map(|c| text_centre(*c)), box_hw, box_hh);
        let (offset, _) = candidates[chosen];
        let side = offset.signum();
        let (ax, ay) = (x1 + nx * offset, y1 + ny * offset);
        let (bx, by) = (x2 + nx * offset, y2 + ny * offset);
        placer.block_line(&[(ax, ay), (bx, by)], false);
        let overshoot = side * 4.0;
        let gap = side * 3.0;
        let mut item = Group::new()
            .set("class", "dimension")
            .add(line(
                x1 + nx * gap,
                y1 + ny * gap,
                ax + nx * overshoot,
                ay + ny * overshoot,
                DIMENSION_COLOUR,
                0.7,
            ))
            .add(line(
                x2 + nx * gap,
                y2 + ny * gap,
                bx + nx * overshoot,
                by + ny * overshoot,
                DIMENSION_COLOUR,
                0.7,
            ))
            .add(line(ax, ay, bx, by, DIMENSION_COLOUR, 0.9))
            .add(arrowhead(ax, ay, -ux, -uy))
            .add(arrowhead(bx, by, ux, uy));
        let baseline_shift = 0.36 * DIMENSION_FONT_PX;
        item = item.add(
            text(
                &content,
                tx,
                ty + baseline_shift,
                DIMENSION_FONT_PX,
                Anchor::Middle,
                DIMENSION_COLOUR,
            )
            .set("transform", format!("rotate({} {} {})", num(angle), num(tx), num(ty)))
            .set("data-box", PageBox::centred(tx, ty, box_hw, box_hh).attribute()),
        );
        group = group.add(item);
    }
    group
}

/// Slot names, placed near the end of each slot.
pub(crate) fn slot_labels(slots: &[SlotArc], map: &ScreenMap, placer: &mut LabelPlacer) -> Group {
    let size = 12.0;
    let mut group = Group::new().set("id", "slot-labels").set("class", "labels");
    for slot in slots {
        let ends = slot.sample(2);
        let (x, y) = map.page_point(&ends[1]);
        let (half_width, half_height) = (0.5 * text_width(&slot.name, size), 0.5 * size);
        let (cx, cy) = placer.place_near(x, y, half_width, half_height, 8.0);
        let mut label = Group::new().set("class", "slot-label");
        let distance = ((cx - x).powi(2) + (cy - y).powi(2)).sqrt() - half_width.max(half_height);
        if distance > LEADER_MIN_PX {
            label = label.add(line(x, y, cx, cy, "#4d4d4d", 0.7));
        }
        label = label.add(
            text(&slot.name, cx, cy + 0.36 * size, size, Anchor::Middle, "#4d4d4d")
                .set("font-style", "italic")
                .set(
                    "data-box",
                    PageBox::centred(cx, cy, half_width, half_height).attribute(),
                ),
        );
        group = group.add(label);
    }
    group
}

/// Blocks the page boxes around every slot sample so labels keep off the channels.
pub(crate) fn block_slots(slots: &[SlotArc], map: &ScreenMap, placer: &mut LabelPlacer) {
    for slot in slots {
        for p in slot.sample(24) {
            let (x, y) = map.page_point(&p);
            placer.block(PageBox::centred(x, y, 6.0, 6.0));
        }
    }
}
