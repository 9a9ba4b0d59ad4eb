//! The four-bar's support laid out as a truss
//! ([`flapwright_mechanism::shared::support_truss`]): the fixed pivots O1 and O2 joined by
//! a tie (the loop's ground link, what a flap support beam's chord is), held to the wing by
//! a strut from each and a brace, every one pinned at both ends. Every load on the support
//! acts at O1 and O2 (the crank's and the rocker's pins; the screw's mount B0 stands on
//! the wing), so the tie too carries an axial force alone.
//!
//! Why: each strut clamped to the skin carried its pivot's 60-100 kN at the end of a
//! 0.6-1.0 m lever in bending, as a solid round bar; on `transport-flap` the two struts
//! were 76-195 kg of each station's four-bar (`ob-inner`: 195 of 319 kg, `003_...` Table
//! 1: 61 kg for the whole four-bar). As rods they carry the same loads by their tensions.
//!
//! The tops offered are the struts' own candidates on the lower skin
//! ([`flapwright_mechanism::shared::placement::strut_tops`], clear of the structure and of
//! the moving flap with the struts' radius and a link radius of margin) aft of the rear
//! spar's web, as the hooked-track's; where the tie does not clear, a pivot has no clear
//! top or no triple holds the support, the struts stay clamped cantilevers.
//!
//! Only the chosen mechanism's support is laid out ([`FourBar::with_support_truss`]): the
//! search's finalists and followers are ranked by their depth and clearance, which the
//! truss does not change (its rods run up from the pivots to the skin, its tie between
//! them), and laying one out for each of the 24-40 built per station made `design` of
//! `transport-flap` 30 % slower.

use nalgebra::{Isometry2, Vector3};

use super::bodies::bodies_and_joints;
use super::synthesis::sampled_flap_poses;
use super::FourBar;
use flapwright_mechanism::seam::FlapMechanism;
use flapwright_mechanism::shared::placement::{strut_tops, PLACEMENT_SAMPLES, STRUT_TOPS_AHEAD};
use flapwright_mechanism::shared::support_truss::{resultant, SupportTruss};
use flapwright_mechanism::Result;

impl FourBar {
    /// The mechanism with its support laid out as a truss where one clears, its solids and
    /// its depth redrawn; itself where none does or a strut was not placed clear.
    pub(super) fn with_support_truss(mut self) -> Result<Self> {
        if !self.synthesis.placement_clear {
            return Ok(self);
        }
        let flap_poses = sampled_flap_poses(&self.loop_, self.synthesis.crank_rotation_rad[1]);
        // The in-plane margin the struts' placement keeps (`synthesis`): a link radius.
        let margin = self.spec.hardware.link_radius_m;
        let Some(truss) = self.lay_out_truss(&flap_poses, margin) else {
            return Ok(self);
        };
        self.synthesis.strut_tops_m = [truss.rods[0].top_m, truss.rods[1].top_m];
        self.synthesis.truss = Some(truss);
        (self.bodies, self.joints) =
            bodies_and_joints(&self.spec, &self.synthesis, &self.loop_, &self.drive, self.link_rates);
        self.synthesis.depth_below_section_m = self.whole_depth()?;
        Ok(self)
    }

    /// The support's truss under the station's design loads over the deployment, clear of
    /// the flap at `flap_poses` by `margin` (m) beyond the struts' radius; `None` where none
    /// is (see the module doc) or the station has no load cases.
    pub(super) fn lay_out_truss(&self, flap_poses: &[Isometry2<f64>], margin: f64) -> Option<SupportTruss> {
        let spec = &self.spec;
        let outline = &spec.outline;
        let (o1, o2) = (self.loop_.o1, self.loop_.o2);
        let (_, _, flap_chord) = outline.flap_chord()?;
        let reach = spec.hardware.strut_radius_m + margin;
        let tie_clear = !outline.wing.segment_meets(o1, o2)
            && outline.structure.segment_clear_by(o1, o2, reach)
            && flap_poses.iter().all(|pose| {
                let back = pose.inverse();
                outline.flap.segment_clear_by(back * o2, back * o1, reach)
            });
        if spec.design_loads.is_empty() || !tie_clear {
            return None;
        }
        let web_face = outline.rear_web().map_or(f64::INFINITY, |(face, _, _)| face);
        let tops = |foot| -> Vec<_> {
            strut_tops(
                outline,
                foot,
                &STRUT_TOPS_AHEAD,
                spec.hardware.strut_radius_m,
                margin,
                flap_poses,
                None,
            )
            .filter(|top| top.x <= web_face)
            .collect()
        };
        let mut resultants: Vec<Vector3<f64>> = Vec::new();
        for input in self.input_range().samples(PLACEMENT_SAMPLES + 1) {
            for load in &spec.design_loads {
                let [at_o1, at_o2] = self.support_forces(input, load).ok()?;
                resultants.push(resultant(&[(o1, at_o1), (o2, at_o2)], o1));
            }
        }
        SupportTruss::lightest(o1, o2, &tops(o1), &tops(o2), &resultants, flap_chord)
    }
}
