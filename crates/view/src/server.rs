//! Serving the API and the page on a current-thread tokio runtime until told to stop.

use crate::api::{router, AppState};
use std::net::{SocketAddr, TcpListener};
use std::sync::mpsc::Receiver;
use std::sync::Arc;

/// A bound listener with the state it serves.
pub struct Server {
    listener: TcpListener,
    state: Arc<AppState>,
}

impl Server {
    /// Binds `addr` (port 0 picks a free port).
    pub fn bind(addr: SocketAddr, state: AppState) -> std::io::Result<Self> {
        let listener = TcpListener::bind(addr)?;
        Ok(Self {
            listener,
            state: Arc::new(state),
        })
    }

    /// The address it listens on.
    pub fn local_addr(&self) -> std::io::Result<SocketAddr> {
        self.listener.local_addr()
    }
}

/// Serves until a message arrives on `stop` (or its sender is dropped); requests under way
/// are finished first.
pub fn serve(server: Server, stop: Receiver<()>) -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_io()
        .build()?;
    server.listener.set_nonblocking(true)?;
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    std::thread::spawn(move || {
        let _ = stop.recv();
        let _ = tx.send(());
    });
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::from_std(server.listener)?;
        axum::serve(listener, router(server.state))
            .with_graceful_shutdown(async move {
                let _ = rx.await;
            })
            .await
    })
}
