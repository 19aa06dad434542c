//! Vertical angular momentum compensation, reference trajectory and minimisation (thesis ch. 7).
