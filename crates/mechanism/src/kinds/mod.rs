//! The mechanism kinds, one folder each: every kind implements
//! [`FlapMechanism`](crate::seam::FlapMechanism) and names no other kind.
//!
//! | kind (scene name) | module | source | actuator |
//! |---|---|---|---|
//! | `circular-arc-track` | [`circular_arc_track`] | thesis `000_...` (Arslan 2022) | screw jack |
//! | `dropped-hinge` | [`dropped_hinge`] | `003_...` Figs. 6-7 | screw jack or rotary |
//! | `four-bar` | [`four_bar`] | `003_...` Figs. 6, 8 | screw jack |
//! | `link-track` | [`link_track`] | `003_...` Figs. 6, 9 | rotary |
//! | `hooked-track` | [`hooked_track`] | `003_...` Figs. 6, 10 | screw jack |
//! | `five-bar-double-flap` | [`five_bar`] | `001_...` section 2 | rotary (motor crank) |
//!
//! A kind's folder holds what only that kind uses (its spec, synthesis, loop, bodies,
//! members, search); what two or more kinds use lives in [`crate::shared`], and what the
//! other stages see of a kind in [`crate::seam`]. Adding a kind: a folder here, a line
//! below, its re-exports at the crate root, and its row in the scene's kind table.

pub mod circular_arc_track;
pub mod dropped_hinge;
pub mod five_bar;
pub mod four_bar;
pub mod hooked_track;
pub mod link_track;
