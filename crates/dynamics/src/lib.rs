//! Rigid multibody kinematics and dynamics (thesis ch. 2, 7.2).
