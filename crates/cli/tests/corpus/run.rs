//! Running one corpus case against the real binary: a fresh working folder,
//! the fault it asks for, an address-space cap and a timeout, and what came
//! out (exit code or signal, stderr, files left).

use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Longest run of one case before it counts as a hang.
pub const TIMEOUT: Duration = Duration::from_secs(60);

/// Address-space cap of every case (`prlimit --as`): 8 GiB, as the issue's
/// survey used; a runaway allocation aborts instead of swapping.
pub const ADDRESS_SPACE: &str = "8589934592";

/// What one run produced.
#[derive(Debug)]
pub struct Outcome {
    /// Exit code (`None` when killed by a signal or timed out).
    pub code: Option<i32>,
    /// The signal that killed it.
    pub signal: Option<i32>,
    /// Whether it ran past [`TIMEOUT`].
    pub hung: bool,
    /// Standard error (empty when it went to a fault device).
    pub stderr: String,
    /// Files in the working folder afterwards, sorted, relative.
    pub files: Vec<String>,
}

/// How the standard streams and the process are disturbed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fault {
    /// Plain pipes.
    None,
    /// stdout is `/dev/full`.
    FullStdout,
    /// stderr is `/dev/full`.
    FullStderr,
    /// stdout is a pipe whose reader is closed.
    ClosedStdout,
    /// stderr is a pipe whose reader is closed.
    ClosedStderr,
    /// SIGINT (2) or SIGTERM (15) after the given delay.
    Signal(&'static str, u64),
    /// Outputs go to a tiny tmpfs (the runner substitutes its folder).
    TmpfsFull,
}

impl Fault {
    /// Parses the manifest's `fault` field.
    pub fn parse(text: &str) -> Fault {
        match text.split_once(':') {
            Some(("sigint", ms)) => Fault::Signal("-INT", ms.parse().expect("delay")),
            Some(("sigterm", ms)) => Fault::Signal("-TERM", ms.parse().expect("delay")),
            _ => match text {
                "none" => Fault::None,
                "full-stdout" => Fault::FullStdout,
                "full-stderr" => Fault::FullStderr,
                "closed-stdout" => Fault::ClosedStdout,
                "closed-stderr" => Fault::ClosedStderr,
                "tmpfs-full" => Fault::TmpfsFull,
                other => panic!("unknown fault {other}"),
            },
        }
    }
}

/// Whether `prlimit` (util-linux) can cap the address space here.
pub fn have_prlimit() -> bool {
    Command::new("prlimit")
        .args(["--as=1073741824", "true"])
        .status()
        .is_ok_and(|s| s.success())
}

fn list(dir: &Path, prefix: &str, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = format!("{prefix}{}", e.file_name().to_string_lossy());
        if e.path().is_dir() {
            list(&e.path(), &format!("{name}/"), out);
        }
        out.push(name);
    }
}

/// Files under `dir`, sorted, relative to it.
pub fn files_in(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    list(dir, "", &mut out);
    out.sort();
    out
}

/// Runs `lowdisc args` in `cwd` under `fault`.
pub fn run(args: &[String], cwd: &Path, fault: Fault, prlimit: bool) -> Outcome {
    let bin = env!("CARGO_BIN_EXE_lowdisc");
    let mut cmd = if prlimit {
        let mut c = Command::new("prlimit");
        c.arg(format!("--as={ADDRESS_SPACE}")).arg("--").arg(bin);
        c
    } else {
        Command::new(bin)
    };
    cmd.args(args).current_dir(cwd).stdin(Stdio::null());
    let full = || {
        File::options()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full")
    };
    match fault {
        Fault::FullStdout => cmd.stdout(full()).stderr(Stdio::piped()),
        Fault::FullStderr => cmd.stdout(Stdio::null()).stderr(full()),
        Fault::ClosedStderr => cmd.stdout(Stdio::null()).stderr(Stdio::piped()),
        _ => cmd.stdout(Stdio::piped()).stderr(Stdio::piped()),
    };
    let mut child = cmd.spawn().expect("the binary starts");
    match fault {
        Fault::ClosedStdout => drop(child.stdout.take()),
        Fault::ClosedStderr => drop(child.stderr.take()),
        _ => {}
    }
    // Drain the pipes on threads so a chatty case never blocks on a full pipe.
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let out = drain(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let err = drain(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let start = Instant::now();
    let mut signalled = false;
    let (status, hung) = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break (Some(status), false);
        }
        if let Fault::Signal(sig, ms) = fault {
            if !signalled && start.elapsed() >= Duration::from_millis(ms) {
                signalled = true;
                let _ = Command::new("kill")
                    .args([sig, &child.id().to_string()])
                    .status();
            }
        }
        if start.elapsed() > TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            break (None, true);
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let _ = out.join();
    let stderr = err.join().unwrap_or_default();
    use std::os::unix::process::ExitStatusExt;
    Outcome {
        code: status.and_then(|s| s.code()),
        signal: status.and_then(|s| s.signal()),
        hung,
        stderr,
        files: files_in(cwd),
    }
}

/// The message class of an outcome: what kind of answer the user got.
pub fn classify(o: &Outcome) -> String {
    // The error line, not a warning printed before it.
    let first = o
        .stderr
        .lines()
        .find(|l| l.starts_with("error"))
        .or_else(|| o.stderr.lines().next())
        .unwrap_or("");
    let has = |s: &str| o.stderr.contains(s);
    match o.code {
        Some(0) if has("warning") => "ok-warning".into(),
        Some(0) => "ok".into(),
        Some(2) => "usage".into(),
        Some(130) => "sigint".into(),
        Some(143) => "sigterm".into(),
        Some(1) if first.is_empty() => "error-silent".into(),
        Some(1) if has("--max-") || has(" limit") || has("must be") || has("at most") => {
            "error-limit".into()
        }
        Some(1) if has("is a directory") || has("not a regular file") => "error-not-a-file".into(),
        Some(1) if has("No such file") || has("does not exist") => "error-missing".into(),
        Some(1) if has("cannot write") || has("No space") || has("denied") => "error-write".into(),
        Some(1) if is_located(first) => "error-located".into(),
        Some(1) => "error".into(),
        Some(c) => format!("exit-{c}"),
        None => "killed".into(),
    }
}

/// Whether a message names a file and line (`name:LINE:` or `name:LINE:COL:`).
fn is_located(line: &str) -> bool {
    line.split(':').collect::<Vec<_>>().windows(2).any(|w| {
        !w[1].is_empty() && w[1].trim().chars().all(|c| c.is_ascii_digit()) && w[0].len() > 1
    })
}

/// A fresh empty folder for a case.
pub fn case_dir(root: &Path, id: &str) -> PathBuf {
    let dir = root.join(id.replace('/', "_"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("case folder");
    dir
}
