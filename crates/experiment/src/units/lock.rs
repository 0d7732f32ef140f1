//! The lock file of a unit in progress, `DIR/units/I.lock`: created
//! exclusively (so two processes never run the same unit), holding
//! `{ pid, host, start_unix_s }` so that `status` can tell a running unit
//! from one whose process died (a *stale* lock: same host, no such
//! process), and removed when the attempt ends, on success or failure.
//!
//! A stale lock is taken over by the next attempt. A lock of another host
//! cannot be checked from here: it counts as running, and an attempt on
//! this host refuses it with an error naming the file to remove.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::{Context, Result, bail};
use serde::{Deserialize, Serialize};

/// What a lock file holds.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Holder {
    /// The process id.
    pub pid: u32,
    /// Its host name.
    pub host: String,
    /// When it took the lock, seconds since 1970.
    pub start_unix_s: u64,
}

/// Whether the holder of a lock still runs, as seen from this host.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Liveness {
    /// Its process runs here.
    Alive,
    /// It was taken on this host by a process that no longer exists.
    Stale,
    /// It was taken on another host (assumed to run).
    Elsewhere,
}

impl Holder {
    /// This process, now.
    pub fn this_process() -> Holder {
        Holder {
            pid: std::process::id(),
            host: host_name(),
            start_unix_s: unix_now(),
        }
    }

    /// Whether it still runs.
    pub fn liveness(&self) -> Liveness {
        if self.host != host_name() {
            Liveness::Elsewhere
        } else if Path::new("/proc").join(self.pid.to_string()).exists() {
            Liveness::Alive
        } else {
            Liveness::Stale
        }
    }
}

/// The name of this machine (`/proc/sys/kernel/hostname`, then `$HOSTNAME`).
pub fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .or_else(|| std::env::var("HOSTNAME").ok())
        .unwrap_or_else(|| "unknown".into())
}

/// Seconds since 1970.
pub fn unix_now() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

/// Reads the holder of lock file `path`, if there is one (an unreadable
/// lock counts as held by an unknown process of another host).
pub fn holder(path: &Path) -> Option<Holder> {
    let text = std::fs::read_to_string(path).ok()?;
    Some(serde_json::from_str(&text).unwrap_or(Holder {
        pid: 0,
        host: "unknown (unreadable lock)".into(),
        start_unix_s: 0,
    }))
}

/// A held lock; [`Lock::release`] removes its file.
#[derive(Debug)]
pub struct Lock {
    path: PathBuf,
}

impl Lock {
    /// Takes the lock at `path` for this process, taking over a stale one.
    pub fn take(path: &Path) -> Result<Lock> {
        for _ in 0..2 {
            match std::fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(path)
            {
                Ok(mut file) => {
                    let text = serde_json::to_string(&Holder::this_process())? + "\n";
                    file.write_all(text.as_bytes())
                        .and_then(|()| file.sync_all())
                        .with_context(|| format!("cannot write `{}`", path.display()))?;
                    return Ok(Lock {
                        path: path.to_path_buf(),
                    });
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => match holder(path) {
                    Some(h) if h.liveness() != Liveness::Stale => bail!(
                        "the unit is being run by pid {} on {} (lock `{}`; remove it if that process is gone)",
                        h.pid,
                        h.host,
                        path.display()
                    ),
                    _ => {
                        let _ = std::fs::remove_file(path);
                    }
                },
                Err(e) => {
                    return Err(e).with_context(|| format!("cannot create `{}`", path.display()));
                }
            }
        }
        bail!("cannot take the lock `{}`", path.display())
    }

    /// Removes the lock file.
    pub fn release(self) -> Result<()> {
        std::fs::remove_file(&self.path)
            .with_context(|| format!("cannot remove `{}`", self.path.display()))
    }
}
