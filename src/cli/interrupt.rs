//! SIGINT / SIGTERM during a run that writes an output directory: the first signal asks the
//! run to stop at its next check (it then writes an `"interrupted"` result), a second one ends
//! the process at once (exit status 130, the previous result left as it was).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

/// Set by the first signal.
static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Installs the handler (once per process; later calls do nothing).
pub fn install() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let handler = || {
            if REQUESTED.swap(true, Ordering::SeqCst) {
                std::process::exit(130);
            }
        };
        // Without a handler (another one installed) a signal ends the process as before.
        let _ = ctrlc::set_handler(handler);
    });
}

/// Whether a signal asked the run to stop.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}
