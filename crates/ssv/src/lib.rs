//! Swept-sphere-volume distance library (thesis ch. 6).
