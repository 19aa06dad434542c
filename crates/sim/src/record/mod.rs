//! Time-series recorder of named signals, written as CSV and SVG plots.
