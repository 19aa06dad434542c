//! `GET /api/recording`: a page of frames of a recording.

use super::{ApiError, Shared};
use axum::extract::{Query, State};
use axum::Json;
use nalgebra::Isometry3;
use serde::Deserialize;
use serde_json::{json, Value};

/// Most frames one `GET /api/recording` answers.
pub const MAX_PAGE: usize = 2000;

/// The page of frames asked for.
#[derive(Deserialize)]
pub(super) struct PageQuery {
    name: Option<String>,
    from: Option<usize>,
    count: Option<usize>,
    signals: Option<String>,
}

pub(super) async fn recording_page(
    State(s): State<Shared>,
    Query(q): Query<PageQuery>,
) -> Result<Json<Value>, ApiError> {
    let rec = s
        .recording(q.name.as_deref())?
        .ok_or_else(super::no_recording)?;
    let n = rec.time.len();
    let from = q.from.unwrap_or(0);
    if from > n {
        return Err(ApiError::bad(format!(
            "from: {from} is past the last frame ({n} frames)"
        )));
    }
    let count = q.count.unwrap_or(MAX_PAGE).min(MAX_PAGE).min(n - from);
    let frames = from..from + count;
    let poses: Vec<Vec<[f32; 7]>> = rec.poses[frames.clone()]
        .iter()
        .map(|f| f.iter().map(pose7).collect())
        .collect();
    let mut signals = serde_json::Map::new();
    for name in q
        .signals
        .iter()
        .flat_map(|s| s.split(','))
        .filter(|s| !s.is_empty())
    {
        let series = rec.series(name).ok_or_else(|| {
            ApiError::bad(format!(
                "signals: no column `{name}` in {}",
                rec.file.display()
            ))
        })?;
        signals.insert(name.to_string(), json!(series[frames.clone()]));
    }
    let markers = crate::markers::markers(rec, frames.clone());
    Ok(Json(json!({
        "names": s.recordings.iter().map(|r| &r.name).collect::<Vec<_>>(),
        "name": rec.name,
        "frames": n,
        "time": rec.time,
        "columns": rec.columns,
        "from": from,
        "count": count,
        "next": (from + count < n).then_some(from + count),
        "poses": poses,
        "com": markers.com,
        "zmp": markers.zmp,
        "forces": markers.forces,
        "signals": signals,
    })))
}

/// `[x, y, z, qx, qy, qz, qw]` in single precision (what a screen needs, half the text).
fn pose7(p: &Isometry3<f64>) -> [f32; 7] {
    let t = p.translation.vector;
    let q = p.rotation.quaternion();
    [t.x, t.y, t.z, q.i, q.j, q.k, q.w].map(|v| v as f32)
}
