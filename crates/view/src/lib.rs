//! `biped view`: a local web app that shows the robot, its SSV collision model and recorded
//! motions, and edits the collision model (thesis 6.6.2). This crate is the server: the JSON
//! API below and the static files of the page (built from `web/` by `npm run build`).
//!
//! # API
//!
//! * `GET /api/scene` — `{"robot", "bodies": [{"name", "geometry": [{"pose", "shape"}]}],
//!   "world": [..], "neutral": [pose per body], "ssv": model | null, "recordings": [names],
//!   "warnings": [..]}`. Poses are `{"position": [x,y,z], "quaternion": [x,y,z,w]}`; shapes
//!   `{"type": "box"|"cylinder"|"sphere"|"capsule"|"mesh", ...}` with a mesh's `url`
//!   (`/api/mesh/K`). The model: `{"file", "activation_distance", "bodies": [{"name",
//!   "body", "offset"}], "segments": [{"name", "body", "ssvs": [{"kind", "points",
//!   "radius"}], "source"}], "pairs"}`; `source` is `{"kind": "ssvs", "entries", "span",
//!   "tables"}` (the `ssvs` array's place in the file text, UTF-16 indices, or with `tables`
//!   that of its `[[segment.ssvs]]` tables), `{"kind": "mirror_of", "of", "lines"}` (the
//!   spans of its `mirror_of` and `plane` lines, or `null`) or `{"kind": "version_of", "of",
//!   "keep", "span"}` (the `keep` array's place); `pair_list` is the
//!   `pairs = [...]` array with its `span` (or `null`), `pair_tables` the `[[pair]]` tables
//!   `[{"a", "b", "span"}]` (`null` if a pair is written as neither), `read_only` why a save
//!   is refused (`--robot` without `--ssv`) or `null`.
//! * `GET /api/ssv` — the model file's text. `PUT /api/ssv` — new text: loaded with the same
//!   loader as `biped ssv model` and bound to the robot; on success written as a whole and
//!   answered 200 with `{"ssv": model}`; otherwise 422 `{"error": "FILE:LINE: ..."}` and the
//!   file left as it was (403 for a read-only model).
//! * `POST /api/ssv/check?frame=K[&recording=NAME]` — text as for `PUT`, nothing written: `{"ssv", "pairs"}` or
//!   422 `{"error"}` (what the page uses while editing).
//! * `GET /api/distances?frame=K[&recording=NAME]` — `{"activation_distance", "pairs": [{"a",
//!   "b", "distance", "point_a", "point_b"}]}` at frame `K` (the neutral pose without one);
//!   `distance` is `null` for a pair whose bounding boxes, enlarged by `d_a / 2`, are apart.
//! * `GET /api/recording?name=NAME&from=I&count=N&signals=A,B` — `{"names", "name", "frames",
//!   "time", "columns", "from", "count", "next", "poses": [[[x,y,z,qx,qy,qz,qw] per body] per
//!   frame], "com", "zmp", "forces", "signals": {A: [..]}}` for frames `I..I+N` (at most
//!   [`api::MAX_PAGE`]); `time` and `columns` (without the `body[...]` poses) are always
//!   complete. Frames are those of a recording for replay (docs/recording.md), or a table's
//!   rows thinned to about [`recording::FRAME_RATE`] per second, where the columns of a walk's
//!   `METHOD.csv` (`L_z`, `tau_z`, `min_distance`, ...) join those of `METHOD_trajectory.csv`.
//! * `GET /api/mesh/K` — a mesh file of the scene.

pub mod api;
pub mod collision;
pub mod csv;
mod description;
mod files;
mod ground;
pub mod markers;
pub mod recording;
pub mod robot;
mod server;
pub mod source;
mod urdf;

pub use api::{AppState, ViewConfig};
pub use robot::{Robot, RobotSource};
pub use server::{serve, Server};

/// What can go wrong in the viewer; every message names the option or file at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ViewError {
    /// The robot could not be loaded.
    #[error("{0}")]
    Robot(String),
    /// The SSV model file does not load or does not fit the robot (located message).
    #[error("{0}")]
    Ssv(String),
    /// A recording could not be read.
    #[error("{0}")]
    Recording(String),
    /// A file could not be written.
    #[error("{0}")]
    Io(String),
    /// The file may not be written (the collision model of a `--robot` description).
    #[error("{0}")]
    ReadOnly(String),
}
