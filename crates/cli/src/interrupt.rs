//! SIGINT and SIGTERM: remove the temporary files of writes in progress,
//! then exit with the shell's status for the signal (130 or 143).
//!
//! Every output goes through `lowdisc-files`, whose registry knows the
//! live temporaries; a watcher thread waits for the signals and cleans up.
//! Destinations keep their old contents, since the rename never happens.

use std::io;

use signal_hook::consts::{SIGINT, SIGTERM};
use signal_hook::iterator::Signals;

/// Starts the watcher thread. Fails only if the handlers cannot be
/// registered (the signals then keep their default action).
pub fn install() -> io::Result<()> {
    let mut signals = Signals::new([SIGINT, SIGTERM])?;
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                lowdisc_files::remove_live_temporaries();
                std::process::exit(128 + signal);
            }
        })?;
    Ok(())
}
