//! Station drawings: parse, render, show every setting, refuse bad input, keep labels apart.

use crate::fixtures::{mm, station};
use crate::raster::{declared_size, inked, of_colour, render};
use flapwright_drawing::{render_station_svg, Error, STATION_PAGE_WIDTH_PX};

/// Colours of the first three settings (stowed, takeoff, landing), as in the legend.
const SETTING_COLOURS: [&str; 3] = ["#1f4e9c", "#d97706", "#b0226e"];

#[test]
fn renders_to_a_non_blank_page_of_the_declared_size() {
    let svg = render_station_svg(&station()).expect("renders");
    let (width, height) = declared_size(&svg);
    assert_eq!(width, STATION_PAGE_WIDTH_PX as u32);
    let pixmap = render(&svg, true);
    assert_eq!((pixmap.width(), pixmap.height()), (width, height));
    let inked = inked(&pixmap);
    let total = (width * height) as usize;
    assert!(inked > total / 50, "only {inked} of {total} pixels inked");
    assert!(inked < total / 2, "{inked} of {total} pixels inked: page looks flooded");
}

#[test]
fn renders_without_fonts_too() {
    // CI machines may lack fonts: text then does not rasterise, geometry still does.
    let svg = render_station_svg(&station()).expect("renders");
    let without = inked(&render(&svg, false));
    let with = inked(&render(&svg, true));
    assert!(without > 10_000, "geometry missing without fonts: {without} px");
    assert!(with >= without, "fonts should only add ink ({with} < {without})");
}

#[test]
fn every_setting_is_tagged_and_visible() {
    let svg = render_station_svg(&station()).expect("renders");
    for id in ["setting-0-stowed", "setting-1-takeoff", "setting-2-landing"] {
        assert!(svg.contains(&format!("id=\"{id}\"")), "{id} missing");
    }
    let pixmap = render(&svg, false);
    for colour in SETTING_COLOURS {
        let count = of_colour(&pixmap, colour, 12);
        assert!(count > 200, "setting colour {colour} covers only {count} px");
    }
}

#[test]
fn removing_a_setting_removes_it_from_the_rendering() {
    let mut drawing = station();
    drawing.settings.truncate(2);
    let svg = render_station_svg(&drawing).expect("renders");
    assert!(!svg.contains("setting-landing"));
    let pixmap = render(&svg, false);
    assert!(of_colour(&pixmap, SETTING_COLOURS[1], 12) > 200, "takeoff still drawn");
    assert_eq!(
        of_colour(&pixmap, SETTING_COLOURS[2], 12),
        0,
        "landing colour left on the page"
    );
}

#[test]
fn nan_coordinate_gives_the_typed_error() {
    let mut drawing = station();
    drawing.settings[1].flap_outline[0][3].y = f64::NAN;
    assert_eq!(
        render_station_svg(&drawing),
        Err(Error::NonFinitePoint {
            what: "flap outline 0 of setting `takeoff`".into(),
            index: 3
        })
    );
    let mut drawing = station();
    drawing.settings[2].deflection_deg = f64::INFINITY;
    assert!(matches!(
        render_station_svg(&drawing),
        Err(Error::NonFinitePoint { index: 2, .. })
    ));
}

#[test]
fn degenerate_inputs_are_refused() {
    let mut drawing = station();
    drawing
        .dimensions
        .push(flapwright_drawing::Dimension::new("zero", mm(1.0, 1.0), mm(1.0, 1.0)));
    assert_eq!(
        render_station_svg(&drawing),
        Err(Error::ZeroLengthDimension { label: "zero".into() })
    );
    let mut drawing = station();
    drawing.slots[0].radius_m = -0.1;
    assert!(matches!(
        render_station_svg(&drawing),
        Err(Error::NonPositiveRadius { .. })
    ));
    let mut drawing = station();
    drawing.settings[0].links[0].points.truncate(1);
    assert!(matches!(
        render_station_svg(&drawing),
        Err(Error::TooFewPoints {
            count: 1,
            minimum: 2,
            ..
        })
    ));
    assert_eq!(render_station_svg(&Default::default()), Err(Error::EmptyDrawing));
}

#[test]
fn dimensions_read_in_millimetres() {
    let svg = render_station_svg(&station()).expect("renders");
    // |A0 A| = hypot(37, 237) mm = 239.9 mm.
    assert!(svg.contains("a2 = 239.9 mm"), "dimension text missing");
    // |A0 G| = hypot(268, 225) mm = 349.93 mm.
    assert!(svg.contains("b1 = 349.9 mm"));
    assert!(svg.contains("data-scale-bar-mm"), "scale bar missing");
}

/// Centre (x, y) and text of every joint label in the SVG.
fn joint_labels(svg: &str) -> Vec<(f64, f64, String)> {
    let mut labels = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find("class=\"joint-label") {
        rest = &rest[start..];
        let text_start = rest.find("<text").expect("label text");
        let element = &rest[text_start..rest.find("</text>").expect("text end")];
        let attribute = |name: &str| -> f64 {
            let from = element.find(&format!(" {name}=\"")).expect("attribute") + name.len() + 3;
            element[from..from + element[from..].find('"').expect("quote")]
                .parse()
                .expect("number")
        };
        let content = element[element.find('>').expect("tag end") + 1..].trim().to_owned();
        labels.push((attribute("x"), attribute("y"), content));
        rest = &rest[text_start + 5..];
    }
    labels
}

#[test]
fn joint_labels_do_not_overlap() {
    let svg = render_station_svg(&station()).expect("renders");
    let labels = joint_labels(&svg);
    // A0, B0 once; A and G at three settings.
    assert_eq!(labels.len(), 8, "labels: {labels:?}");
    let size = 14.0;
    let boxes: Vec<(f64, f64, f64, f64)> = labels
        .iter()
        .map(|(x, y, text)| {
            let half = 0.5 * 0.6 * size * text.chars().count() as f64;
            (x - half, y - 0.8 * size, x + half, y + 0.2 * size)
        })
        .collect();
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            let (a, b) = (boxes[i], boxes[j]);
            let apart = a.2 <= b.0 || b.2 <= a.0 || a.3 <= b.1 || b.3 <= a.1;
            assert!(apart, "labels {:?} and {:?} overlap", labels[i], labels[j]);
        }
    }
}

#[test]
fn clashes_and_fairing_parts_are_drawn_and_checked() {
    let mut drawing = station();
    drawing.fairing_parts = vec![flapwright_drawing::Link {
        name: "screw".into(),
        points: vec![mm(100.0, 50.0), mm(300.0, 20.0)],
    }];
    drawing.clashes = vec![flapwright_drawing::Clash {
        label: "inner.nut / wing: overlap 2.0 mm at 40 %".into(),
        at: mm(200.0, 300.0),
    }];
    let svg = render_station_svg(&drawing).unwrap();
    assert!(svg.contains("screw: sets the fairing line"));
    assert_eq!(svg.matches("class=\"clash\"").count(), 1);
    assert!(svg.contains("inner.nut / wing: overlap 2.0 mm at 40 %"));
    assert!(svg.contains("fails the clearance check") && svg.contains("sets the fairing line"));
    drawing.clashes[0].at.x = f64::NAN;
    assert!(matches!(render_station_svg(&drawing), Err(Error::NonFinitePoint { what, .. }) if what.contains("clash")));
}
