//! Colours, line styles, fonts and small SVG element helpers shared by all drawings.

use svg::node::element::{Line, Text, Title};

/// Font stack: DejaVu Sans first (installed on the build machines), then generic.
pub(crate) const FONT_FAMILY: &str = "DejaVu Sans, Arial, Helvetica, sans-serif";

/// Ink colour for text and outlines.
pub(crate) const INK: &str = "#1a1a1a";

/// Line style of one flap setting.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SettingStyle {
    /// Stroke colour.
    pub colour: &'static str,
    /// SVG `stroke-dasharray`, `None` for solid.
    pub dash: Option<&'static str>,
    /// Suffix added to moving joint labels (A, A', A'').
    pub prime: &'static str,
    /// Words for the legend ("solid", "dashed", ...).
    pub pattern_name: &'static str,
}

/// Styles by setting position: stowed solid blue, takeoff dashed amber, landing dotted
/// magenta; further settings dash-dot in other colours. Colour-blind safe pairs and
/// the line pattern and label primes carry the same information without colour.
const SETTING_STYLES: [SettingStyle; 5] = [
    SettingStyle {
        colour: "#1f4e9c",
        dash: None,
        prime: "",
        pattern_name: "solid",
    },
    SettingStyle {
        colour: "#d97706",
        dash: Some("12 6"),
        prime: "\u{2032}",
        pattern_name: "dashed",
    },
    SettingStyle {
        colour: "#b0226e",
        dash: Some("2 5"),
        prime: "\u{2033}",
        pattern_name: "dotted",
    },
    SettingStyle {
        colour: "#0f7b5f",
        dash: Some("14 4 2 4"),
        prime: "\u{2034}",
        pattern_name: "dash-dot",
    },
    SettingStyle {
        colour: "#6b4c9a",
        dash: Some("6 3"),
        prime: "\u{2057}",
        pattern_name: "short dash",
    },
];

/// Style of the setting at `index` (wraps around after five).
pub(crate) fn setting_style(index: usize) -> SettingStyle {
    SETTING_STYLES[index % SETTING_STYLES.len()]
}

/// Colours of plot series, in order (Okabe-Ito, colour-blind safe).
const SERIES_COLOURS: [&str; 6] = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9"];
/// Dash patterns of plot series, in order, so series differ without colour too.
const SERIES_DASHES: [Option<&str>; 4] = [None, Some("8 4"), Some("2 3"), Some("10 3 2 3")];

/// Colour and dash pattern of plot series `index`.
pub(crate) fn series_style(index: usize) -> (&'static str, Option<&'static str>) {
    (
        SERIES_COLOURS[index % SERIES_COLOURS.len()],
        SERIES_DASHES[index % SERIES_DASHES.len()],
    )
}

/// A screen number with at most two decimals and no trailing zeros.
pub(crate) fn num(value: f64) -> String {
    let text = format!("{value:.2}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// "x1,y1 x2,y2 ..." for `points` / `polyline` / `polygon` elements.
pub(crate) fn points_attribute(points: &[(f64, f64)]) -> String {
    points
        .iter()
        .map(|(x, y)| format!("{},{}", num(*x), num(*y)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Horizontal alignment of a text element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Anchor {
    /// Left end at x.
    Start,
    /// Centred on x.
    Middle,
    /// Right end at x.
    End,
}

/// A text element at (x, baseline y) with size, anchor and colour, and a white halo so
/// it stays readable where it crosses lines.
pub(crate) fn text(content: &str, x: f64, y: f64, size: f64, anchor: Anchor, colour: &str) -> Text {
    let anchor = match anchor {
        Anchor::Start => "start",
        Anchor::Middle => "middle",
        Anchor::End => "end",
    };
    Text::new(content)
        .set("x", num(x))
        .set("y", num(y))
        .set("font-size", num(size))
        .set("font-family", FONT_FAMILY)
        .set("text-anchor", anchor)
        .set("fill", colour)
        .set("stroke", "white")
        .set("stroke-width", num(size * 0.22))
        .set("stroke-linejoin", "round")
        .set("paint-order", "stroke")
}

/// Rough width of `content` in DejaVu Sans at `size` px (0.62 em per character; wide
/// enough for digits and capitals so that boxes built on it do not under-estimate).
pub(crate) fn text_width(content: &str, size: f64) -> f64 {
    content.chars().count() as f64 * size * 0.62
}

/// A `<title>` child element (shown as a tooltip by browsers).
pub(crate) fn title(content: &str) -> Title {
    Title::new(content)
}

/// Makes `label` usable inside an SVG id or class: ASCII letters, digits and '-'.
pub(crate) fn css_name(label: &str) -> String {
    let name: String = label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect();
    if name.is_empty() {
        "unnamed".to_owned()
    } else {
        name
    }
}

/// A plain stroked line from (x1, y1) to (x2, y2), px.
pub(crate) fn line(x1: f64, y1: f64, x2: f64, y2: f64, colour: &str, width: f64) -> Line {
    Line::new()
        .set("x1", num(x1))
        .set("y1", num(y1))
        .set("x2", num(x2))
        .set("y2", num(y2))
        .set("stroke", colour.to_owned())
        .set("stroke-width", num(width))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.256), "1.26");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(120.5), "120.5");
    }

    #[test]
    fn css_names_are_safe() {
        assert_eq!(css_name("Take-off 15°"), "take-off-15-");
        assert_eq!(css_name(""), "unnamed");
    }
}
