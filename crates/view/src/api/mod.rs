//! The JSON API of the page (documented in the crate root) over the loaded state.

mod recording_page;

pub use recording_page::MAX_PAGE;

use crate::collision::CollisionFile;
use crate::recording::{self, Recording};
use crate::robot::{PoseJson, Robot, RobotSource};
use crate::{files, ViewError};
use axum::body::Bytes;
use axum::extract::{Path as UrlPath, Query, State};
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Json, Router};
use nalgebra::Isometry3;
use recording_page::recording_page;
use serde::Deserialize;
use serde_json::{json, Value};
use std::path::PathBuf;
use std::sync::{Arc, Mutex, PoisonError};

/// What `biped view` shows.
#[derive(Debug, Clone)]
pub struct ViewConfig {
    /// The robot.
    pub robot: RobotSource,
    /// The collision-model file to show and edit.
    pub ssv: Option<PathBuf>,
    /// A recording folder or table.
    pub recording: Option<PathBuf>,
    /// The built page (`web/dist`).
    pub web_dir: PathBuf,
}

/// The loaded robot, model file and recordings the API serves.
#[derive(Debug)]
pub struct AppState {
    /// The robot.
    pub robot: Robot,
    /// The collision-model file (locked while read or replaced).
    pub ssv: Mutex<Option<CollisionFile>>,
    /// The recordings.
    pub recordings: Vec<Recording>,
    /// Body poses at the neutral configuration.
    pub neutral: Vec<Isometry3<f64>>,
    /// Folder of the page's files.
    pub web_dir: PathBuf,
}

impl AppState {
    /// Loads everything `config` names; errors name the option or file at fault.
    pub fn load(config: &ViewConfig) -> Result<Self, ViewError> {
        let (robot, described) = match &config.robot {
            RobotSource::Description { file, package_path } => {
                let (robot, model) = crate::description::load(file, package_path)?;
                (robot, model.map(|m| (m, file)))
            }
            other => (Robot::load(other)?, None),
        };
        let ssv = match (&config.ssv, described) {
            (Some(path), _) => Some(CollisionFile::open(path, &robot)?),
            (None, Some((model, file))) => {
                let mut shown = CollisionFile::open(&model, &robot)?;
                shown.read_only = Some(crate::description::read_only_reason(&model, file));
                Some(shown)
            }
            (None, None) => None,
        };
        let recordings = match &config.recording {
            Some(path) => recording::open(path, &robot)?,
            None => Vec::new(),
        };
        Ok(Self {
            neutral: recording::neutral_poses(&robot)?,
            robot,
            ssv: Mutex::new(ssv),
            recordings,
            web_dir: config.web_dir.clone(),
        })
    }

    pub(super) fn recording(&self, name: Option<&str>) -> Result<Option<&Recording>, ApiError> {
        match name {
            None => Ok(self.recordings.first()),
            Some(n) => self
                .recordings
                .iter()
                .find(|r| r.name == n)
                .map(Some)
                .ok_or_else(|| ApiError::not_found(format!("recording: no recording named `{n}`"))),
        }
    }

    /// Body poses of `frame` of a recording, or the neutral poses without a frame.
    fn poses(
        &self,
        name: Option<&str>,
        frame: Option<usize>,
    ) -> Result<&[Isometry3<f64>], ApiError> {
        let Some(k) = frame else {
            return Ok(&self.neutral);
        };
        let rec = self.recording(name)?.ok_or_else(no_recording)?;
        rec.poses.get(k).map(Vec::as_slice).ok_or_else(|| {
            let n = rec.poses.len();
            ApiError::bad(format!(
                "frame: {k} is out of range (the recording has {n} frames)"
            ))
        })
    }
}

/// An error answer: a status and `{"error": message}`.
pub struct ApiError(StatusCode, String);

impl ApiError {
    pub(super) fn bad(msg: String) -> Self {
        Self(StatusCode::BAD_REQUEST, msg)
    }
    pub(super) fn not_found(msg: String) -> Self {
        Self(StatusCode::NOT_FOUND, msg)
    }
    fn invalid(e: ViewError) -> Self {
        Self(StatusCode::UNPROCESSABLE_ENTITY, e.to_string())
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.0, Json(json!({ "error": self.1 }))).into_response()
    }
}

pub(super) type Shared = Arc<AppState>;

/// The routes of the API and the page.
pub fn router(state: Shared) -> Router {
    Router::new()
        .route("/api/scene", get(scene))
        .route("/api/ssv", get(get_ssv).put(put_ssv))
        .route("/api/ssv/check", axum::routing::post(check_ssv))
        .route("/api/distances", get(distances))
        .route("/api/recording", get(recording_page))
        .route("/api/mesh/{k}", get(mesh))
        .fallback(files::serve_file)
        .with_state(state)
}

async fn scene(State(s): State<Shared>) -> Json<Value> {
    let ssv = s
        .ssv
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .as_ref()
        .map(CollisionFile::to_json);
    let neutral: Vec<PoseJson> = s.neutral.iter().map(PoseJson::from).collect();
    let names: Vec<&str> = s.recordings.iter().map(|r| r.name.as_str()).collect();
    Json(json!({
        "robot": s.robot.label,
        "bodies": s.robot.bodies,
        "world": s.robot.world,
        "neutral": neutral,
        "ssv": ssv,
        "recordings": names,
        "warnings": s.robot.warnings,
    }))
}

pub(super) fn no_recording() -> ApiError {
    ApiError::not_found("no recording: start biped view with --recording DIR".into())
}

fn no_ssv() -> ApiError {
    ApiError::not_found("no collision model: start biped view with --ssv FILE.toml".into())
}

async fn get_ssv(State(s): State<Shared>) -> Result<Response, ApiError> {
    let guard = s.ssv.lock().unwrap_or_else(PoisonError::into_inner);
    let file = guard.as_ref().ok_or_else(no_ssv)?;
    let text = file.text.clone();
    Ok(([(header::CONTENT_TYPE, "text/plain; charset=utf-8")], text).into_response())
}

fn utf8(body: &Bytes) -> Result<String, ApiError> {
    String::from_utf8(body.to_vec()).map_err(|_| {
        ApiError(
            StatusCode::UNPROCESSABLE_ENTITY,
            "the new text is not UTF-8".into(),
        )
    })
}

async fn put_ssv(State(s): State<Shared>, body: Bytes) -> Result<Json<Value>, ApiError> {
    let text = utf8(&body)?;
    let mut guard = s.ssv.lock().unwrap_or_else(PoisonError::into_inner);
    let file = guard.as_mut().ok_or_else(no_ssv)?;
    match file.replace(text, &s.robot) {
        Ok(()) => Ok(Json(json!({ "ssv": file.to_json() }))),
        Err(e @ ViewError::Io(_)) => {
            Err(ApiError(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))
        }
        Err(e @ ViewError::ReadOnly(_)) => Err(ApiError(StatusCode::FORBIDDEN, e.to_string())),
        Err(e) => Err(ApiError::invalid(e)),
    }
}

/// `frame` and `recording` of the distance queries.
#[derive(Deserialize)]
struct FrameQuery {
    frame: Option<usize>,
    recording: Option<String>,
}

async fn check_ssv(
    State(s): State<Shared>,
    Query(q): Query<FrameQuery>,
    body: Bytes,
) -> Result<Json<Value>, ApiError> {
    let text = utf8(&body)?;
    let (path, read_only) = {
        let guard = s.ssv.lock().unwrap_or_else(PoisonError::into_inner);
        let file = guard.as_ref().ok_or_else(no_ssv)?;
        (file.path.clone(), file.read_only.clone())
    };
    let mut candidate =
        CollisionFile::from_text(&path, text, &s.robot).map_err(ApiError::invalid)?;
    candidate.read_only = read_only;
    let poses = s.poses(q.recording.as_deref(), q.frame)?;
    let pairs = candidate.distances(poses).map_err(ApiError::invalid)?;
    Ok(Json(json!({ "ssv": candidate.to_json(), "pairs": pairs })))
}

async fn distances(
    State(s): State<Shared>,
    Query(q): Query<FrameQuery>,
) -> Result<Json<Value>, ApiError> {
    let poses = s.poses(q.recording.as_deref(), q.frame)?;
    let mut guard = s.ssv.lock().unwrap_or_else(PoisonError::into_inner);
    let file = guard.as_mut().ok_or_else(no_ssv)?;
    let pairs = file.distances(poses).map_err(ApiError::invalid)?;
    let d_a = file.loaded.model.activation_distance();
    Ok(Json(json!({ "activation_distance": d_a, "pairs": pairs })))
}

async fn mesh(State(s): State<Shared>, UrlPath(k): UrlPath<usize>) -> Result<Response, ApiError> {
    let path = s
        .robot
        .meshes
        .get(k)
        .ok_or_else(|| ApiError::not_found(format!("no mesh {k}")))?;
    let bytes = std::fs::read(path).map_err(|e| {
        ApiError(
            StatusCode::INTERNAL_SERVER_ERROR,
            format!("{}: {e}", path.display()),
        )
    })?;
    Ok(([(header::CONTENT_TYPE, "application/octet-stream")], bytes).into_response())
}
