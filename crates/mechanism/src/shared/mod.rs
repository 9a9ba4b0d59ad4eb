//! The toolbox the kinds share: what two or more kinds (or a kind and the seam) use sits
//! here, so that no kind's folder holds what another kind needs. Each module says in its
//! own docs what it is for; why it is here and not in one kind:
//!
//! | module | what | used by |
//! |---|---|---|
//! | `load_case` | [`LoadCase`](crate::LoadCase), [`ExternalMoment`](crate::ExternalMoment), [`FlapNormalForce`](crate::FlapNormalForce) | every kind's kinetostatics, the seam, `deployment`, [`crate::rigid_flap`] |
//! | [`flap_load`] | the flap's weight and air load as a wrench; [`flap_load::LinkHardware`] | every kind but the thesis track, [`crate::rigid_flap`] |
//! | `geometry` | 2D cross product, turns about a point | every kind, [`crate::jet`] |
//! | `angle` | guarded `acos`, Kahan's triangle area, toggle tolerance | the track, the slider-crank, [`crate::landing_gear`] |
//! | `slider_crank` | the inverted slider-crank A0 B0 A | the track, the rocker drive, [`crate::landing_gear`] |
//! | [`rocker_drive`] | a screw jack turning a body about a pivot | dropped hinge, four-bar, placement |
//! | `screw_jack` | the thread's torques; [`ScrewDrive`](crate::ScrewDrive) | the seam's [`Actuator`](crate::seam::Actuator), the track, dropped hinge, four-bar, hooked-track |
//! | `rotary_actuator` | geared rotary actuators ([`RotaryDrive`](crate::RotaryDrive)) | dropped hinge, link-track |
//! | [`placement`] | jack mounts and struts clear of the outlines | the synthesised kinds |
//! | [`precision`] | precision positions, poles, circle centres | the synthesised kinds |
//! | `feasibility` | loop checks over a deployment | four-bar, link-track, hooked-track |
//! | [`outline`] | the station's section outlines and their distance queries | the synthesised kinds |
//! | `members` | members to size and their loads | the seam ([`Member`](crate::seam::Member)), the kinds |
//! | [`objective`] | what the searches weigh besides depth: the actuator's load under the load cases, by virtual work | the synthesised kinds, [`placement`] |
//! | [`support_truss`] | a fixed support held to the wing by three pinned rods and a tie | hooked-track, four-bar |
//! | [`follow`] | the motion a station follows where another station of its flap was synthesised first | link-track |
//!
//! Every module is public: the kinds live in their own crate (`flapwright-kinds`) and
//! reach the toolbox from there; the types the other stages name are also re-exported at
//! this crate's root.

pub mod angle;
pub mod feasibility;
pub mod flap_load;
pub mod follow;
pub mod geometry;
pub mod load_case;
pub mod members;
pub mod objective;
pub mod outline;
pub mod placement;
pub mod precision;
pub mod rocker_drive;
pub mod rotary_actuator;
pub mod screw_jack;
pub mod slider_crank;
pub mod support_truss;
