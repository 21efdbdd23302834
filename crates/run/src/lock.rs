//! One writer per run folder: every run holds an exclusive OS lock on its folder's lock file
//! for as long as it writes, and a second writer is refused at once, whatever its flags.
//!
//! The lock file sits beside the folder, `<folder>.lock` (`runs/M-JJ/coarse.lock` for
//! `runs/M-JJ/coarse/` and for the store's `runs/M-JJ/coarse.partial/`): a file inside the
//! folder would move with the store's final rename, and a run continued with `--restart`
//! from a `.partial` folder must meet the sweep that writes it. The file is never removed
//! (a process that opened it just before the removal would lock a file no one else sees);
//! it holds the holder's pid, host and start time, for the refusal message.
//!
//! The lock is `flock(2)` (`std::fs::File::try_lock`): the kernel releases it when the
//! holder ends in any way, SIGKILL included, so the lock of a dead run is taken over at
//! once on the same host. On NFS v4 the Linux client maps it to a byte-range lock held by
//! the server with a lease: a holder on another host that dies without unlocking keeps it
//! until the lease expires (90 s by default). On NFS v3 mounted with `nolock`, or a
//! filesystem without locks, it only excludes writers on the same host: run the runs of
//! one folder from one host there (docs/history/status-log.md, "Issue 44").

use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use crate::runs_folder;
use crate::RunError;

/// The exclusive hold of a run folder; released when dropped (or when the process ends).
#[derive(Debug)]
pub struct RunLock {
    /// the open, locked lock file
    _file: File,
    /// its path
    path: PathBuf,
}

impl RunLock {
    /// Takes the lock of run folder `dir` (a `.partial` folder shares its finished folder's
    /// lock), after checking that no folder of it below `runs/` links outside
    /// ([`runs_folder::check_links`]). Refused with [`RunError::Running`] when another
    /// process (or another writer of this one) holds it.
    pub fn acquire(dir: &Path) -> Result<RunLock, RunError> {
        runs_folder::check_links(dir)?;
        let path = lock_path(dir)?;
        let failed = |what: &str, e: std::io::Error| RunError::OutDir {
            dir: dir.to_path_buf(),
            reason: format!("{what} lock file {}: {e}", path.display()),
        };
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).map_err(|e| failed("creating the folder of", e))?;
        }
        // not truncated before it is held: the holder's line is read by the refused
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(|e| failed("opening", e))?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                return Err(RunError::Running {
                    dir: dir.to_path_buf(),
                    holder: holder(&path),
                })
            }
            Err(TryLockError::Error(e)) => return Err(failed("locking", e)),
        }
        file.set_len(0)
            .and_then(|()| file.write_all(holder_line().as_bytes()))
            .map_err(|e| failed("writing", e))?;
        Ok(RunLock { _file: file, path })
    }

    /// The lock file.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

/// The lock file of run folder `dir`: `<dir>.lock` beside it, the `.partial` suffix left
/// off, the folder's parent resolved (so `--out .` and `--out ./x/` find it too).
pub fn lock_path(dir: &Path) -> Result<PathBuf, RunError> {
    let absolute = std::path::absolute(dir).map_err(|e| RunError::OutDir {
        dir: dir.to_path_buf(),
        reason: format!("cannot resolve the folder: {e}"),
    })?;
    // `..` and `.` resolved without following links (std::path::absolute keeps them)
    let mut plain = PathBuf::new();
    for c in absolute.components() {
        match c {
            std::path::Component::ParentDir => {
                plain.pop();
            }
            std::path::Component::CurDir => {}
            other => plain.push(other),
        }
    }
    let Some(name) = plain.file_name().map(|n| n.to_string_lossy().into_owned()) else {
        return Err(RunError::OutDir {
            dir: dir.to_path_buf(),
            reason: "a run folder needs a parent folder for its lock file; choose a folder \
                     below /"
                .into(),
        });
    };
    let stem = name.strip_suffix(".partial").unwrap_or(&name);
    Ok(plain.with_file_name(format!("{stem}.lock")))
}

/// What the lock file says of its holder ("pid 4242 on host hpc1 since 2026-12-05 20:31:07
/// UTC"), or that it says nothing yet.
fn holder(path: &Path) -> String {
    match std::fs::read_to_string(path) {
        Ok(text) if !text.trim().is_empty() => text.trim().to_string(),
        _ => format!(
            "holder not yet written in {}; it has just started",
            path.display()
        ),
    }
}

/// This process's line for the lock file.
fn holder_line() -> String {
    format!(
        "pid {} on host {} since {}\n",
        std::process::id(),
        host_name(),
        utc_now()
    )
}

/// The host's name (Linux: /proc/sys/kernel/hostname; else $HOSTNAME; else "unknown").
fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .map(|h| h.trim().to_string())
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "unknown".into())
}

/// The time now, "YYYY-MM-DD HH:MM:SS UTC".
fn utc_now() -> String {
    let secs = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // H. Hinnant's civil_from_days
    let z = days + 719_468;
    let (era, doe) = (z.div_euclid(146_097), z.rem_euclid(146_097));
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC",
        rest / 3600,
        rest / 60 % 60,
        rest % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_partial_folder_shares_the_lock_of_its_finished_folder() {
        let a = lock_path(Path::new("runs/M-JJ/coarse")).unwrap();
        let b = lock_path(Path::new("runs/M-JJ/coarse.partial/")).unwrap();
        let c = lock_path(Path::new("runs/M-JJ/x/../coarse")).unwrap();
        assert_eq!(a, b);
        assert_eq!(a, c);
        assert!(a.ends_with("runs/M-JJ/coarse.lock"), "{}", a.display());
    }

    #[test]
    fn a_second_writer_is_refused_with_the_holder_and_the_lock_is_free_after() {
        let dir = std::env::temp_dir().join(format!("runout-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let run = dir.join("case").join("smoke");
        let first = RunLock::acquire(&run).unwrap();
        let second = RunLock::acquire(&crate::store::partial_dir(&run)).unwrap_err();
        let text = second.to_string();
        assert!(matches!(second, RunError::Running { .. }), "{text}");
        let pid = format!("pid {} on host ", std::process::id());
        assert!(text.contains("is running") && text.contains(&pid), "{text}");
        drop(first);
        let again = RunLock::acquire(&run).unwrap();
        assert!(again.path().exists());
        drop(again);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_time_reads_as_a_utc_date() {
        let t = utc_now();
        assert_eq!(t.len(), "2026-12-05 20:31:07 UTC".len(), "{t}");
        assert!(t.starts_with("20"), "{t}");
    }
}
