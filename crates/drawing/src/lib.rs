//! SVG drawings of flap mechanism stations and plots against the deployment input.
//!
//! # Overview
//! Two entry points, both pure functions from plain data to SVG text:
//! - [`render_station_svg`] draws one [`StationDrawing`]: the section cut
//!   ([`SectionOutline`]: wing skin, flap, spar, torque tube), the mechanism at each
//!   setting ([`MechanismSnapshot`]: flap outline, [`Link`]s, [`Joint`]s), slots
//!   ([`SlotArc`]), the swept envelope, the fairing line and [`Dimension`]s, with a
//!   legend, a scale bar in mm and a note on the view direction. It imitates the thesis
//!   figures (`000_...`, Chapter 5, Figs. 24-30).
//! - [`render_plots_svg`] draws a grid of small charts ([`Plot`] of [`Series`]) with
//!   "nice" ticks ([`nice_ticks`]), axis labels and legends.
//!
//! This crate knows no mechanism: the caller (the CLI) turns mechanism and plane
//! results into these plain types. It writes no files; the caller does.
//!
//! # Units and frames
//! Station drawings take the station frame (DESIGN.md): metres, origin at the hinge
//! point A0, x towards the nose, y up, z outboard. On the page the nose is to the
//! RIGHT and y up (the section seen from outboard, as in the thesis figures); the scale
//! is equal on both axes. Lengths shown on the page are in millimetres. Deflections
//! are in degrees, slot angles in radians counter-clockwise from +x. Plots take values
//! in whatever units the caller's axis labels state.
//!
//! # Design notes
//! - SVG is built with the `svg` crate; every number is written with two decimals
//!   (1/100 px), so files are small and diff-friendly.
//! - Settings are styled by position (solid, dashed, dotted) and moving joints get
//!   primes (A, A', A''), so the drawing reads in black and white too.
//! - Labels are placed greedily around their anchors avoiding every marker, label and
//!   slot already on the page; text carries a white halo so crossing lines do not hide
//!   it.
//! - Input is validated first: a NaN or infinite value is refused with an error naming
//!   the item and index; nothing non-finite reaches the SVG.
//!
//! # Limitations
//! - Text widths are estimated (0.62 em per character), not measured, so label
//!   avoidance is approximate for very wide glyphs.
//! - Label placement is greedy; in very dense regions a label may keep a small overlap
//!   (the least-overlap candidate is used) and gets a leader line.
//! - One page size (1200 px wide); very slender geometry leaves white space.
//!
//! # Pitfalls
//! - Coordinates are metres, not millimetres: a drawing in mm renders fine but every
//!   dimension reads 1000 times too long.
//! - The nose is to the right: a station frame with x pointing aft (aircraft x) would
//!   show the section mirrored.
//! - Slot angles are radians; degrees give a wildly wrong arc without any error.
//! - Text rasterises only where fonts are available (usvg needs a font database); the
//!   geometry renders without.

mod annotate;
mod chart;
mod error;
mod hull;
mod labels;
mod layers;
mod legend;
mod model;
mod plot;
mod station;
mod style;
mod ticks;
mod validate;
mod view;

pub use error::{Error, Result};
pub use hull::convex_hull;
pub use model::{Clash, Dimension, Joint, Link, MechanismSnapshot, PartStyle, SectionOutline, SlotArc, StationDrawing};
pub use plot::{plots_page_size_px, render_plots_svg, Plot, Series, PLOT_COLUMNS};
pub use station::{render_station_svg, STATION_PAGE_WIDTH_PX};
pub use ticks::{format_tick, nice_step, nice_ticks, padded_ticks, Ticks};
