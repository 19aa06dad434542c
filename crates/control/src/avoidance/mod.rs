//! Self-collision avoidance from SSV segment distances (thesis ch. 5).
