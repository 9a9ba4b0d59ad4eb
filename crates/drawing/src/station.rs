//! `render_station_svg`: lays out one station drawing (header, drawing area, legend and
//! note block) and assembles the layers.

use crate::annotate::{block_slots, dimensions_layer, joints_layer, slot_labels};
use crate::error::{Error, Result};
use crate::labels::{LabelPlacer, PageBox};
use crate::layers::{
    breaks_layer, clashes_layer, envelope_layer, fairing_layer, fairing_parts_layer, sections_layer, setting_layer,
    slots_layer,
};
use crate::legend::{legend, legend_rows, note_block, NOTE_HEIGHT_PX, NOTE_WIDTH_PX, ROW_PX};
use crate::model::StationDrawing;
use crate::style::{num, text, Anchor, FONT_FAMILY, INK};
use crate::validate::validate_station;
use crate::view::{Bounds, ScreenMap};
use nalgebra::Point2;
use svg::node::element::Rectangle;
use svg::Document;

/// Page width of a station drawing, px.
pub const STATION_PAGE_WIDTH_PX: f64 = 1600.0;
/// Page margin, px.
const MARGIN_PX: f64 = 30.0;
/// Height of the header (title and subtitle), px.
const HEADER_PX: f64 = 76.0;
/// Room kept around the geometry for labels and dimension lines, px.
const LABEL_ROOM_PX: f64 = 70.0;
/// Tallest drawing area, px.
const MAX_DRAWING_HEIGHT_PX: f64 = 1000.0;

/// Every station-frame point the drawing shows, for its bounding box.
fn all_points(drawing: &StationDrawing) -> Vec<Point2<f64>> {
    let mut points: Vec<Point2<f64>> = Vec::new();
    for section in &drawing.sections {
        points.extend(section.polygons.iter().flatten());
    }
    for setting in &drawing.settings {
        points.extend(setting.flap_outline.iter().flatten());
        points.extend(setting.links.iter().flat_map(|l| l.points.iter()));
        points.extend(setting.joints.iter().map(|j| j.at));
    }
    for slot in &drawing.slots {
        points.extend(slot.sample(32));
    }
    points.extend(drawing.envelope.iter().flatten());
    points.extend(drawing.fairing_line.iter().flatten());
    points.extend(drawing.fairing_parts.iter().flat_map(|l| l.points.iter()));
    points.extend(drawing.clashes.iter().map(|c| c.at));
    for dimension in &drawing.dimensions {
        points.push(dimension.from);
        points.push(dimension.to);
    }
    points
}

/// Marks every drawn line (section outlines, flap outlines, links, fairing line) as a
/// light obstacle for labels.
fn block_lines(drawing: &StationDrawing, map: &ScreenMap, placer: &mut LabelPlacer) {
    for polygon in drawing.sections.iter().flat_map(|s| s.polygons.iter()) {
        placer.block_line(&map.page_points(polygon), true);
    }
    for setting in &drawing.settings {
        for outline in &setting.flap_outline {
            placer.block_line(&map.page_points(outline), true);
        }
        for link in &setting.links {
            placer.block_line(&map.page_points(&link.points), false);
        }
    }
    if let Some(line) = &drawing.fairing_line {
        placer.block_line(&map.page_points(line), false);
    }
}

/// Renders one station as a standalone SVG document (UTF-8 text).
///
/// Station frame in, metres (see [`StationDrawing`]); the page shows the nose (+x) to
/// the RIGHT and y up, as the thesis figures do (`000_...`, Figs. 24-30), i.e. the
/// section seen from outboard. Equal scale on both axes; a scale bar in mm; settings
/// in order solid / dashed / dotted with a legend; joints labelled with primes per
/// setting (A, A', A''); dimensions in mm.
///
/// # Errors
/// [`Error::EmptyDrawing`] when there is nothing to draw, [`Error::NonFinitePoint`] for
/// a NaN or infinite coordinate, [`Error::TooFewPoints`], [`Error::NonPositiveRadius`],
/// [`Error::ZeroLengthDimension`], and [`Error::DegenerateExtent`] when all the geometry
/// lies on one point.
///
/// # Example
/// ```
/// use flapwright_drawing::{render_station_svg, Dimension, Joint, Link, MechanismSnapshot, StationDrawing};
/// use nalgebra::Point2;
///
/// let crank = |deg: f64| {
///     let (s, c) = deg.to_radians().sin_cos();
///     Point2::new(0.24 * c, 0.24 * s)
/// };
/// let snapshot = |label: &str, deg: f64| MechanismSnapshot {
///     label: label.into(),
///     deflection_deg: deg,
///     flap_outline: vec![],
///     links: vec![Link { name: "crank".into(), points: vec![Point2::origin(), crank(80.0 + deg)] }],
///     joints: vec![
///         Joint { name: "A0".into(), at: Point2::origin(), fixed: true },
///         Joint { name: "A".into(), at: crank(80.0 + deg), fixed: false },
///     ],
/// };
/// let drawing = StationDrawing {
///     title: "Crank".into(),
///     settings: vec![snapshot("stowed", 0.0), snapshot("takeoff", 15.0), snapshot("landing", 35.0)],
///     dimensions: vec![Dimension::new("a2", Point2::origin(), crank(80.0))],
///     ..Default::default()
/// };
/// let svg = render_station_svg(&drawing)?;
/// assert!(svg.contains("a2 = 240.0 mm") && svg.contains("setting-2-landing"));
/// # Ok::<(), flapwright_drawing::Error>(())
/// ```
pub fn render_station_svg(drawing: &StationDrawing) -> Result<String> {
    validate_station(drawing)?;
    let points = all_points(drawing);
    let bounds = Bounds::around(&points).ok_or(Error::EmptyDrawing)?;
    let extent = bounds.width().max(bounds.height());
    if extent <= 0.0 {
        return Err(Error::DegenerateExtent {
            width_m: bounds.width(),
            height_m: bounds.height(),
        });
    }
    // A thin drawing (a single line) still gets some height.
    let bounds = bounds.grown(0.02 * extent);
    let area_left = MARGIN_PX + LABEL_ROOM_PX;
    let area_top = HEADER_PX + LABEL_ROOM_PX;
    let area_width = STATION_PAGE_WIDTH_PX - 2.0 * area_left;
    let map = ScreenMap::fit(bounds, area_left, area_top, area_width, MAX_DRAWING_HEIGHT_PX);
    let drawing_bottom = area_top + map.height_px() + LABEL_ROOM_PX;

    let rows = legend_rows(drawing) as f64;
    let footer_px = (ROW_PX * rows + 10.0).max(NOTE_HEIGHT_PX) + MARGIN_PX;
    let page_height = (drawing_bottom + 16.0 + footer_px).ceil();

    let frame = PageBox {
        left: MARGIN_PX,
        top: HEADER_PX,
        right: STATION_PAGE_WIDTH_PX - MARGIN_PX,
        bottom: drawing_bottom,
    };
    let mut placer = LabelPlacer::new(frame);
    block_slots(&drawing.slots, &map, &mut placer);
    block_lines(drawing, &map, &mut placer);

    let mut document = Document::new()
        .set("xmlns", "http://www.w3.org/2000/svg")
        .set("width", num(STATION_PAGE_WIDTH_PX))
        .set("height", num(page_height))
        .set(
            "viewBox",
            format!("0 0 {} {}", num(STATION_PAGE_WIDTH_PX), num(page_height)),
        )
        .set("font-family", FONT_FAMILY)
        .add(
            Rectangle::new()
                .set("width", "100%")
                .set("height", "100%")
                .set("fill", "white"),
        )
        .add(
            text(&drawing.title, MARGIN_PX, 36.0, 22.0, Anchor::Start, INK)
                .set("font-weight", "bold")
                .set("id", "title"),
        )
        .add(text(&drawing.subtitle, MARGIN_PX, 60.0, 14.0, Anchor::Start, "#444444").set("id", "subtitle"))
        .add(
            Rectangle::new()
                .set("x", num(MARGIN_PX))
                .set("y", num(HEADER_PX))
                .set("width", num(STATION_PAGE_WIDTH_PX - 2.0 * MARGIN_PX))
                .set("height", num(drawing_bottom - HEADER_PX))
                .set("fill", "none")
                .set("stroke", "#bbbbbb")
                .set("stroke-width", "1"),
        );

    if !drawing.envelope.is_empty() {
        document = document.add(envelope_layer(&drawing.envelope, &map));
    }
    document = document.add(sections_layer(&drawing.sections, &map));
    if !drawing.breaks.is_empty() {
        document = document.add(breaks_layer(&drawing.breaks, &map));
    }
    if !drawing.slots.is_empty() {
        document = document.add(slots_layer(&drawing.slots, &map));
    }
    if let Some(line) = &drawing.fairing_line {
        document = document.add(fairing_layer(line, &map));
    }
    // Last setting first, so the stowed (solid) one is on top.
    for (index, setting) in drawing.settings.iter().enumerate().rev() {
        document = document.add(setting_layer(index, setting, &map));
    }
    // Over the settings: the part is often the stowed one's.
    if !drawing.fairing_parts.is_empty() {
        document = document.add(fairing_parts_layer(&drawing.fairing_parts, &map));
    }
    let (markers, joint_labels) = joints_layer(&drawing.settings, &map, &mut placer);
    let dimensions = dimensions_layer(&drawing.dimensions, &map, &mut placer);
    let slot_names = slot_labels(&drawing.slots, &map, &mut placer);
    document = document.add(dimensions).add(markers).add(joint_labels).add(slot_names);
    if !drawing.clashes.is_empty() {
        document = document.add(clashes_layer(&drawing.clashes, &map, &mut placer));
    }

    let footer_top = drawing_bottom + 30.0;
    let legend_width = STATION_PAGE_WIDTH_PX - 2.0 * MARGIN_PX - NOTE_WIDTH_PX - 20.0;
    document = document
        .add(legend(drawing, MARGIN_PX, footer_top, 0.62 * legend_width))
        .add(note_block(
            STATION_PAGE_WIDTH_PX - MARGIN_PX - NOTE_WIDTH_PX,
            footer_top - 14.0,
            map.px_per_m,
        ));
    Ok(document.to_string())
}
