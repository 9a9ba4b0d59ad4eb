//! Scratch: render SVG (arg 1) cropped to viewBox "x y w h" (arg 3) at scale 2 into PNG (arg 2).
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let svg = std::fs::read_to_string(&args[1]).unwrap();
    let v: Vec<f64> = args[3]
        .split_whitespace()
        .map(|s| s.parse().unwrap())
        .collect();
    let start = svg.find("<svg").unwrap();
    let end = start + svg[start..].find('>').unwrap();
    let head = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="{} {} {} {}" font-family="DejaVu Sans, Arial, Helvetica, sans-serif""#,
        v[2] * 2.0,
        v[3] * 2.0,
        v[0],
        v[1],
        v[2],
        v[3]
    );
    let svg = format!("{}{}{}", &svg[..start], head, &svg[end..]);
    let mut options = resvg::usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let tree = resvg::usvg::Tree::from_str(&svg, &options).unwrap();
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    pixmap.save_png(&args[2]).unwrap();
}
