//! Renders SVG files to PNG beside them, to look at what Flapwright drew:
//! `cargo run -p flapwright-drawing --example render_png -- flapwright-out/*.svg`.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut options = resvg::usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let paths: Vec<String> = std::env::args().skip(1).collect();
    assert!(!paths.is_empty(), "give one or more SVG files");
    for path in paths {
        let svg = std::fs::read_to_string(&path)?;
        let tree = resvg::usvg::Tree::from_str(&svg, &options)?;
        let size = tree.size().to_int_size();
        let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("empty SVG")?;
        pixmap.fill(resvg::tiny_skia::Color::WHITE);
        resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
        let png = std::path::Path::new(&path).with_extension("png");
        pixmap.save_png(&png)?;
        println!("{}", png.display());
    }
    Ok(())
}
