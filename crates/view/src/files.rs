//! The page's static files from the built bundle folder (`web/dist`).

use crate::api::AppState;
use axum::extract::State;
use axum::http::{header, StatusCode, Uri};
use axum::response::{IntoResponse, Response};
use std::path::Component;
use std::sync::Arc;

/// Content type by file extension.
fn content_type(name: &str) -> &'static str {
    match name.rsplit('.').next().unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "map" | "json" => "application/json",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        _ => "application/octet-stream",
    }
}

/// A file of the page (`/` is `index.html`); paths leaving the folder are not served.
pub async fn serve_file(State(s): State<Arc<AppState>>, uri: Uri) -> Response {
    let rel = uri.path().trim_start_matches('/');
    let rel = if rel.is_empty() { "index.html" } else { rel };
    let path = std::path::Path::new(rel);
    if !path.components().all(|c| matches!(c, Component::Normal(_))) {
        return (StatusCode::NOT_FOUND, "not found").into_response();
    }
    let file = s.web_dir.join(path);
    match std::fs::read(&file) {
        Ok(bytes) => ([(header::CONTENT_TYPE, content_type(rel))], bytes).into_response(),
        Err(_) if rel == "index.html" => {
            let msg = format!(
                "<!doctype html><title>biped view</title><p>The page is not built ({} is \
                 missing): run <code>npm ci &amp;&amp; npm run build</code> in <code>web/</code>. \
                 The API under <code>/api/</code> works without it.</p>",
                file.display()
            );
            let html = [(header::CONTENT_TYPE, "text/html; charset=utf-8")];
            (StatusCode::SERVICE_UNAVAILABLE, html, msg).into_response()
        }
        Err(_) => (StatusCode::NOT_FOUND, format!("not found: {rel}")).into_response(),
    }
}
