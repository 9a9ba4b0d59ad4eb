//! Integration tests of the kinds (and of the toolbox in flapwright-mechanism through them), one module per topic.

mod adding_a_kind;
mod common;
mod finite_differences;
mod five_bar;
mod four_bar_members;
mod hooked_track;
mod landing_gear;
mod objective;
mod planar;
mod properties;
mod rigid_flap;
mod seam;
mod spanwise;
mod synthesised;
mod thesis_appendix_c;
mod thesis_tables;
mod toggle;
mod track_members;
