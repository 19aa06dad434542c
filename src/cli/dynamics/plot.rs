//! SVG plot of forward-dynamics run time over the Dill level, like thesis Fig. 2.19 (log scales).

use super::bench::Timings;
use crate::cli::files::{self, WithPath};
use plotters::prelude::*;
use std::path::Path;

/// One plotted algorithm: legend, colour, and which timing it shows.
type Series = (&'static str, RGBColor, fn(&Timings) -> f64);

/// Writes run time (us, log) over DoFs (log) per algorithm to `path` (parent folders created).
pub fn runtime_svg(path: &Path, rows: &[Timings]) -> Result<(), Box<dyn std::error::Error>> {
    if let Some(dir) = path.parent() {
        files::create_dir_all(dir)?;
    }
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
    let mut chart = ChartBuilder::on(&root)
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
        .y_desc("run time [us]")
        .draw()?;
    for (name, color, f) in series {
        let pts: Vec<(f64, f64)> = rows.iter().map(|t| (dofs(t), us(f(t)))).collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], color));
        chart.draw_series(pts.into_iter().map(|p| Circle::new(p, 3, color.filled())))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present().with_path(path)?;
    Ok(())
}
