//! Stopping runs on SIGINT and SIGTERM (issue 21), for the programs that drive runs
//! (`runout run`, `cargo xtask sweep`): the first signal sets the flag that
//! [`super::RunOptions::stop`] watches, so every run stops after its current step with a
//! checkpoint and status `Interrupted`; a second signal exits at once (the last
//! checkpoints stay). The library installs nothing by itself.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// The exit status of a program stopped by a signal (128 + SIGINT, as shells report it).
pub const EXIT_INTERRUPTED: i32 = 130;

/// Installs the handler and returns its flag; `program` names the messages' sender and
/// `what` says what stops (e.g. "the run stops after this step").
pub fn stop_on_signals(program: &'static str, what: &'static str) -> Arc<AtomicBool> {
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    let installed = ctrlc::set_handler(move || {
        if flag.swap(true, Ordering::SeqCst) {
            eprintln!("{program}: second signal: stopping now; the last checkpoint stays");
            std::process::exit(EXIT_INTERRUPTED);
        }
        eprintln!("{program}: signal received: {what} (a second signal stops at once)");
    });
    if let Err(e) = installed {
        eprintln!("{program}: warning: signals will stop without a checkpoint: {e}");
    }
    stop
}
