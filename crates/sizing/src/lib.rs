//! Sizing: flap loads, rods, screw jacks, torque tubes, drive power and weights. (Being filled: issue 6.)
