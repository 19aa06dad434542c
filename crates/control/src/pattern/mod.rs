//! Walking pattern generation: footsteps, CoM (LIPM, ZMP preview), feet and upper body.
