//! Rasterising helpers: parse with usvg, render with resvg, count pixels.

use resvg::tiny_skia::Pixmap;

/// Parses `svg` (system fonts loaded when `fonts`) and renders it at scale 1.
pub fn render(svg: &str, fonts: bool) -> Pixmap {
    let mut options = resvg::usvg::Options::default();
    if fonts {
        options.fontdb_mut().load_system_fonts();
    }
    let tree = resvg::usvg::Tree::from_str(svg, &options).expect("the SVG parses with usvg");
    let size = tree.size().to_int_size();
    let mut pixmap = Pixmap::new(size.width(), size.height()).expect("non-empty page");
    resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    pixmap
}

/// Pixels that are not (near) white.
pub fn inked(pixmap: &Pixmap) -> usize {
    pixmap
        .pixels()
        .iter()
        .filter(|p| p.red() < 245 || p.green() < 245 || p.blue() < 245)
        .count()
}

/// Pixels within `tolerance` (per channel) of the colour "#rrggbb".
pub fn of_colour(pixmap: &Pixmap, hex: &str, tolerance: u8) -> usize {
    let channel = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).expect("hex colour");
    let (r, g, b) = (channel(1), channel(3), channel(5));
    pixmap
        .pixels()
        .iter()
        .filter(|p| {
            let c = p.demultiply();
            c.red().abs_diff(r) <= tolerance && c.green().abs_diff(g) <= tolerance && c.blue().abs_diff(b) <= tolerance
        })
        .count()
}

/// Width and height attributes of the root `<svg>` element, px.
pub fn declared_size(svg: &str) -> (u32, u32) {
    let root = &svg[svg.find("<svg").expect("root element")..];
    let root = &root[..root.find('>').expect("root element end")];
    let attribute = |name: &str| -> u32 {
        let start = root.find(&format!(" {name}=\"")).expect("attribute") + name.len() + 3;
        let value = &root[start..start + root[start..].find('"').expect("quote")];
        value.parse::<f64>().expect("number").ceil() as u32
    };
    (attribute("width"), attribute("height"))
}
