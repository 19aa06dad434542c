//! SVG plot of forward-dynamics run time over the Dill level, like thesis Fig. 2.19 (log scales).

use super::bench::Timings;
use biped_sim::record::plot::{draw_legend, legend_width};
use biped_sim::record::write_whole;
use plotters::prelude::*;
use std::path::Path;

/// One plotted algorithm: legend, colour, and which timing it shows.
type Series = (&'static str, RGBColor, fn(&Timings) -> f64);

/// Writes run time (us, log) over DoFs (log) per algorithm to `path` (parent folders created;
/// the file appears whole or not at all).
pub fn runtime_svg(path: &Path, rows: &[Timings]) -> Result<(), Box<dyn std::error::Error>> {
    write_whole(path, |tmp| draw(tmp, rows)).map_err(|e| format!("{}: {e}", path.display()).into())
}

/// Draws the plot of [`runtime_svg`] into `path`.
fn draw(path: &Path, rows: &[Timings]) -> Result<(), Box<dyn std::error::Error>> {
    let series: [Series; 3] = [
        ("O(n)", RED, |t| t.on),
        ("CRBA + Cholesky", BLUE, |t| t.crba),
        ("CRBA + sparse LTL", GREEN, |t| t.sparse),
    ];
    let us = |ns: f64| ns / 1e3;
    let all = rows
        .iter()
        .flat_map(|t| series.iter().map(move |s| us((s.2)(t))));
    let (lo, hi) = all.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    let dofs = |t: &Timings| t.nv as f64;
    let x_hi = rows.iter().map(dofs).fold(2.0, f64::max);
    let root = SVGBackend::new(path, (800, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let names: Vec<&str> = series.iter().map(|s| s.0).collect();
    let (plot_area, legend_area) = root.split_horizontally(800 - legend_width(&names));
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(
            "Forward dynamics of Dill(n): run time per call",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(
            (1.0f64..x_hi * 1.5).log_scale(),
            (lo.max(1e-3) / 1.5..hi * 1.5).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("degrees of freedom 2^n")
        .y_desc("run time [µs]")
        .draw()?;
    for (_, color, f) in series {
        let pts: Vec<(f64, f64)> = rows.iter().map(|t| (dofs(t), us(f(t)))).collect();
        chart.draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))?;
        chart.draw_series(pts.into_iter().map(|p| Circle::new(p, 3, color.filled())))?;
    }
    let entries: Vec<(&str, RGBColor)> = series.iter().map(|s| (s.0, s.1)).collect();
    draw_legend(&legend_area, &entries)?;
    root.present()?;
    Ok(())
}
