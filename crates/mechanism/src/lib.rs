//! Planar flap mechanisms: synthesis, kinematics, kinetostatics. (Being filled: issue 4.)
