//! The pictures read at a glance (issue 40): every SVG that `export --svg` writes for
//! every shipped scene, and the study charts of two of them, renders (resvg), no legend box
//! of a chart holds a point of that chart or has one of its curves through it, and no two
//! labels of a drawing overlap (each label's text carries the box the drawing placed it
//! in, `data-box`). `FLAPWRIGHT_PICTURES=DIR` keeps every page there as PNG to look at.

use std::path::{Path, PathBuf};

use crate::{repo_root, run_flapwright};

/// Every SVG below `dir`.
fn svgs_below(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(folder) = pending.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else if path.extension().is_some_and(|e| e == "svg") {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// A box (left, top, right, bottom), px.
type PageBox = (f64, f64, f64, f64);

fn number(node: &roxmltree::Node, name: &str) -> f64 {
    node.attribute(name)
        .unwrap_or_else(|| panic!("<{}> without {name}", node.tag_name().name()))
        .parse()
        .unwrap()
}

fn has_class(node: &roxmltree::Node, class: &str) -> bool {
    node.attribute("class")
        .is_some_and(|c| c.split_whitespace().any(|c| c == class))
}

/// The curves and points of one chart, page px: each polyline's vertices, each marker's centre.
fn chart_curves(chart: &roxmltree::Node) -> Vec<Vec<(f64, f64)>> {
    chart
        .descendants()
        .filter(|n| has_class(n, "series"))
        .flat_map(|series| series.descendants().filter(|n| n.is_element()))
        .filter_map(|shape| match shape.tag_name().name() {
            "polyline" => Some(
                shape
                    .attribute("points")
                    .unwrap()
                    .split_whitespace()
                    .map(|pair| {
                        let (x, y) = pair.split_once(',').unwrap();
                        (x.parse().unwrap(), y.parse().unwrap())
                    })
                    .collect(),
            ),
            "circle" => Some(vec![(number(&shape, "cx"), number(&shape, "cy"))]),
            _ => None,
        })
        .collect()
}

fn within((x, y): (f64, f64), (left, top, right, bottom): PageBox) -> bool {
    x > left && x < right && y > top && y < bottom
}

/// What a page breaks of the rules: legends over their chart's data, labels over labels.
fn problems_of(svg: &str, name: &str) -> Vec<String> {
    let document = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut problems = Vec::new();
    for chart in document.descendants().filter(|n| has_class(n, "plot")) {
        let Some(legend) = chart.descendants().find(|n| has_class(n, "legend")) else {
            continue;
        };
        let frame = legend
            .children()
            .find(|n| n.has_tag_name("rect"))
            .expect("the legend's box");
        let (x, y) = (number(&frame, "x"), number(&frame, "y"));
        let legend_box = (x, y, x + number(&frame, "width"), y + number(&frame, "height"));
        for curve in chart_curves(&chart) {
            // Every vertex, and each segment walked in steps of half a pixel.
            let mut samples = curve.clone();
            for pair in curve.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                let steps = ((b.0 - a.0).hypot(b.1 - a.1) * 2.0).ceil() as usize;
                samples.extend((1..steps).map(|k| {
                    let t = k as f64 / steps as f64;
                    (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
                }));
            }
            if let Some(p) = samples.iter().find(|p| within(**p, legend_box)) {
                problems.push(format!(
                    "{name}: chart {:?}: the legend {legend_box:?} covers data at {p:?}",
                    chart.attribute("id").unwrap_or("?")
                ));
            }
        }
    }
    let labels: Vec<(String, PageBox)> = document
        .descendants()
        .filter_map(|n| {
            let boxed: Vec<f64> = n
                .attribute("data-box")?
                .split(' ')
                .map(|v| v.parse().unwrap())
                .collect();
            let text: String = n
                .descendants()
                .filter(|t| t.is_text())
                .filter_map(|t| t.text())
                .collect();
            Some((text.trim().to_string(), (boxed[0], boxed[1], boxed[2], boxed[3])))
        })
        .collect();
    for (i, (a, box_a)) in labels.iter().enumerate() {
        for (b, box_b) in &labels[i + 1..] {
            let width = box_a.2.min(box_b.2) - box_a.0.max(box_b.0);
            let height = box_a.3.min(box_b.3) - box_a.1.max(box_b.1);
            if width > 0.0 && height > 0.0 {
                problems.push(format!(
                    "{name}: labels `{a}` and `{b}` overlap by {width:.1} x {height:.1} px"
                ));
            }
        }
    }
    problems
}

/// Renders `svg` with resvg (system fonts), as a reader would see it.
fn render(svg: &str, name: &str) -> resvg::tiny_skia::Pixmap {
    let mut options = resvg::usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let tree = resvg::usvg::Tree::from_str(svg, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).expect("a page");
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    pixmap
}

#[test]
fn no_legend_covers_its_data_and_no_label_covers_another_on_any_shipped_scene() {
    let dir = tempfile::tempdir().unwrap();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(repo_root().join("data/scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    scenes.sort();
    for scene in &scenes {
        let stem = scene.file_stem().unwrap().to_str().unwrap();
        let out = format!("export-{stem}");
        let run = run_flapwright(dir.path(), &["export", scene.to_str().unwrap(), "--svg", "--out", &out]);
        assert!(run.status.success(), "{stem}: {}", String::from_utf8_lossy(&run.stderr));
    }
    for stem in ["transport-flap", "light-aircraft"] {
        let scene = repo_root().join(format!("data/scenes/{stem}.toml"));
        let out = format!("study-{stem}");
        let run = run_flapwright(dir.path(), &["study", scene.to_str().unwrap(), "--out", &out]);
        assert!(
            run.status.success(),
            "study {stem}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
    let keep = std::env::var_os("FLAPWRIGHT_PICTURES").map(PathBuf::from);
    let pages = svgs_below(dir.path());
    assert!(pages.len() >= 2 * scenes.len(), "{} pages", pages.len());
    let mut problems = Vec::new();
    for page in &pages {
        let name = page.strip_prefix(dir.path()).unwrap().display().to_string();
        let svg = std::fs::read_to_string(page).unwrap();
        problems.extend(problems_of(&svg, &name));
        let pixmap = render(&svg, &name);
        if let Some(keep) = &keep {
            let png = keep.join(name.replace('/', "--")).with_extension("png");
            std::fs::create_dir_all(keep).unwrap();
            pixmap.save_png(&png).unwrap();
        }
    }
    assert!(
        problems.is_empty(),
        "{} problem(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The audit finds what it looks for: a legend drawn over a curve and two labels on one
/// spot are both reported.
#[test]
fn the_audit_sees_a_covered_curve_and_overlapping_labels() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg">
        <g class="plot" id="p"><g class="series series-0"><polyline points="0,0 100,100"/></g>
        <g class="legend"><rect x="40" y="40" width="20" height="20"/></g></g>
        <text data-box="0 0 10 10">A</text><text data-box="5 5 15 15">B</text>
        <text data-box="20 0 30 10">C</text></svg>"#;
    let problems = problems_of(svg, "made");
    assert_eq!(problems.len(), 2, "{problems:#?}");
    assert!(problems[0].contains("covers data"));
    assert!(problems[1].contains("`A` and `B` overlap"));
}
