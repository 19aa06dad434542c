//! SVG line plots of recorded signals over time (plotters, SVG backend).

use super::{write_whole, RecordError, Recorder};
use plotters::prelude::*;
use std::path::Path;

/// Line colours, cycled over the plotted signals.
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

impl Recorder {
    /// Plots columns `signals` (scalar names or `q[i]`) over time into an SVG file at `path`
    /// with `title`, x label `time [s]`, y label `y_label`, one line and legend entry each;
    /// NaN samples break the line.
    pub fn plot_svg(
        &self,
        path: &Path,
        title: &str,
        signals: &[&str],
        y_label: &str,
    ) -> Result<(), RecordError> {
        if self.is_empty() {
            return Err(RecordError::Empty);
        }
        if signals.is_empty() {
            return Err(RecordError::NoSignals);
        }
        let cols = signals
            .iter()
            .map(|s| self.column(s))
            .collect::<Result<Vec<_>, _>>()?;
        let drawn = write_whole(path, |tmp| {
            draw(self.time(), signals, &cols, tmp, title, y_label)
        });
        drawn.map_err(|e| RecordError::Plot {
            path: path.to_path_buf(),
            message: e.to_string(),
        })
    }
}

/// Padded finite range of `values`, `(-1, 1)` if there is none.
fn range<'a>(values: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (-1.0, 1.0);
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.5 * lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// Draws the chart.
fn draw(
    time: &[f64],
    names: &[&str],
    cols: &[Vec<f64>],
    path: &Path,
    title: &str,
    y_label: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    let (x0, x1) = range(time.iter());
    let (y0, y1) = range(cols.iter().flat_map(|c| c.iter()));
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let (plot_area, legend_area) = root.split_horizontally(900 - legend_width(names));
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc("time [s]")
        .y_desc(y_label)
        .draw()?;
    let mut entries = Vec::new();
    for (i, (name, col)) in names.iter().zip(cols).enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        for seg in segments(time, col) {
            chart.draw_series(LineSeries::new(seg, color.stroke_width(2)))?;
        }
        entries.push((*name, color));
    }
    draw_legend(&legend_area, &entries)?;
    root.present()?;
    Ok(())
}

/// Width in pixels of a legend panel for `names` ([`draw_legend`]).
pub fn legend_width(names: &[&str]) -> u32 {
    let longest = names.iter().map(|n| n.chars().count()).max().unwrap_or(0);
    (40 + 8 * longest as u32).clamp(80, 320)
}

/// Draws a legend (a line sample and the name per entry) into its own panel beside the chart,
/// so that it never covers the data.
pub fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    entries: &[(&str, RGBColor)],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    for (k, (name, color)) in entries.iter().enumerate() {
        let y = 60 + 22 * k as i32;
        let sample = PathElement::new(vec![(4, y), (26, y)], color.stroke_width(2));
        area.draw(&sample)?;
        area.draw(&Text::new(
            name.to_string(),
            (32, y - 7),
            ("sans-serif", 14),
        ))?;
    }
    Ok(())
}

/// Runs of finite `(t, y)` points, split at NaN samples.
fn segments(time: &[f64], col: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut out = vec![Vec::new()];
    for (&t, &y) in time.iter().zip(col) {
        match (y.is_finite(), out.last_mut()) {
            (true, Some(seg)) => seg.push((t, y)),
            (false, Some(seg)) if !seg.is_empty() => out.push(Vec::new()),
            _ => {}
        }
    }
    out.retain(|s| !s.is_empty());
    out
}
