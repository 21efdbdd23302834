//! `results/summary.csv`: one row per (case, fidelity), kept across sweeps (issue 21).
//!
//! A sweep (the whole matrix, `--only P` or one `--shard i/n`) produces rows for its own
//! cases only. It never rewrites the file with those alone: it **merges** them into the rows
//! already there. The key of a row is (case name, fidelity); a new row replaces the old row
//! of its key, and the rows of every other case and fidelity are kept. Rows are ordered by
//! fidelity (smoke, coarse, paper, then any other), then by the case matrix's order, then
//! (cases no longer in the matrix) by their place in the old file, so the order does not
//! depend on which shard wrote last.
//!
//! **Header.** A file whose header is not this version's [`crate::sweep`] header (written
//! by an older or newer xtask with other columns) is **refused**, with a message that says
//! to move it away: its rows cannot be merged column by column, and replacing it would
//! drop the rows of the other cases. The sweep checks this before it runs anything, so the
//! refusal costs no computing.
//!
//! **Concurrency.** Shards of one sweep may finish at the same time on a shared file
//! system. An atomic rename alone makes each write whole, but two read–merge–write cycles
//! that overlap still lose the rows of the one that renames first. So the cycle runs under
//! a lock: the file `summary.csv.lock` beside it, created with `create_new` (`O_CREAT |
//! O_EXCL`, atomic on local file systems, on NFS v3 and later, Lustre and GPFS; not on
//! NFS v2), removed when the cycle ends (also on an error or a panic). A writer that finds
//! the lock waits and retries (10 ms doubling to 0.5 s) for up to [`LOCK_TIMEOUT`]; the
//! cycle takes milliseconds, so a lock older than that was left by a process killed while
//! writing, and the sweep stops with a message naming the lock's holder and saying to delete
//! the lock and rerun (the finished runs are skipped, so the rows come back at once). A
//! stale lock is never broken automatically: two waiters breaking the same stale lock could
//! each remove the other's fresh one.
//!
//! The alternative, one file per shard under `results/shards/` gathered later, was not
//! chosen: it needs an extra `--gather` step (or a merge on every write, which is the same
//! read–merge–write race again), and a rerun with `--only` would have to decide between the
//! rows of two shard files by their age.

use std::fs::OpenOptions;
use std::io::{ErrorKind, Write as _};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use anyhow::{bail, Context, Result};

use crate::sweep::csv_field;

/// How long a writer waits for the lock of results/summary.csv before it gives up.
pub const LOCK_TIMEOUT: Duration = Duration::from_secs(120);
/// First and longest pause between two attempts to take the lock.
const RETRY: (Duration, Duration) = (Duration::from_millis(10), Duration::from_millis(500));
/// Fidelity order of the rows; any other name comes after these.
const FIDELITY_ORDER: [&str; 3] = ["smoke", "coarse", "paper"];

/// The records of a CSV text (no header handling; quoted fields may hold newlines).
fn records(text: &str) -> Result<Vec<Vec<String>>> {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes())
        .records()
        .map(|r| Ok(r?.iter().map(str::to_string).collect()))
        .collect()
}

/// One record as a CSV line (the quoting of [`csv_field`]), without the newline.
fn line(fields: &[String]) -> String {
    fields
        .iter()
        .map(|f| csv_field(f))
        .collect::<Vec<_>>()
        .join(",")
}

/// Why the existing rows cannot be merged, if they cannot: `None` for no file, an empty
/// file or one with `header`.
fn header_mismatch(existing: &str, header: &str) -> Result<Option<String>> {
    let found = records(existing)?.into_iter().next();
    Ok(found
        .map(|h| line(&h))
        .filter(|h| h != header)
        .map(|h| format!("its header is\n  {h}\nand this xtask writes\n  {header}")))
}

/// `existing` (the file's text, `None` without a file) with `new_rows` merged in: see the
/// module doc for the key, the order and the header rule. `order` is the case matrix's
/// order of case names. Every row of `new_rows` must have the header's width.
pub fn merge(
    header: &str,
    existing: Option<&str>,
    new_rows: &[String],
    order: &[&str],
) -> Result<String> {
    let width = records(header)?.first().map_or(0, Vec::len);
    let mut rows: Vec<Vec<String>> = Vec::new();
    if let Some(text) = existing {
        if let Some(why) = header_mismatch(text, header)? {
            bail!("{why}");
        }
        rows = records(text)?.into_iter().skip(1).collect();
    }
    for (k, row) in rows.iter().enumerate() {
        if row.len() < 2 {
            bail!(
                "data row {} has {} field(s), not a case and a fidelity",
                k + 1,
                row.len()
            );
        }
    }
    let key = |r: &[String]| (r[0].clone(), r[1].clone());
    for new in new_rows {
        for fields in records(new)? {
            if fields.len() != width {
                bail!(
                    "a new row has {} fields for {width} columns: {new}",
                    fields.len()
                );
            }
            match rows.iter().position(|r| key(r) == key(&fields)) {
                Some(k) => rows[k] = fields,
                None => rows.push(fields),
            }
        }
    }
    // (fidelity rank, matrix index, place in the file) with rows out of the matrix after
    // the matrix's rows of their fidelity
    let rank = |r: &[String]| {
        let fidelity = FIDELITY_ORDER
            .iter()
            .position(|f| *f == r[1])
            .unwrap_or(FIDELITY_ORDER.len());
        let case = order.iter().position(|c| *c == r[0]).unwrap_or(order.len());
        (fidelity, case)
    };
    let mut ranked: Vec<(usize, Vec<String>)> = rows.into_iter().enumerate().collect();
    ranked.sort_by_key(|(place, r)| (rank(r), *place));
    let mut out = String::from(header);
    out.push('\n');
    for (_, r) in ranked {
        out.push_str(&line(&r));
        out.push('\n');
    }
    Ok(out)
}

/// The lock file of `path`: `<path>.lock`.
fn lock_path(path: &Path) -> PathBuf {
    let mut p = path.as_os_str().to_owned();
    p.push(".lock");
    PathBuf::from(p)
}

/// This machine's host name (empty if unknown).
fn host_name() -> String {
    let mut buf = [0u8; 256];
    // SAFETY: the buffer is valid for its length; gethostname writes at most that many bytes.
    let rc = unsafe { libc::gethostname(buf.as_mut_ptr().cast(), buf.len()) };
    if rc != 0 {
        return String::new();
    }
    let end = buf.iter().position(|&b| b == 0).unwrap_or(buf.len());
    String::from_utf8_lossy(&buf[..end]).into_owned()
}

/// A held lock file; removed on drop.
pub struct FileLock {
    path: PathBuf,
}

impl FileLock {
    /// Takes the lock of `path` (`<path>.lock`, created with `create_new`), waiting for up to
    /// `timeout` while another writer holds it.
    pub fn acquire(path: &Path, timeout: Duration) -> Result<FileLock> {
        let lock = lock_path(path);
        if let Some(dir) = lock.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        let started = Instant::now();
        let mut pause = RETRY.0;
        loop {
            match OpenOptions::new().write(true).create_new(true).open(&lock) {
                Ok(mut f) => {
                    let since = SystemTime::now()
                        .duration_since(UNIX_EPOCH)
                        .map_or(0, |d| d.as_secs());
                    // who holds it, for the message of a writer that times out
                    let _ = writeln!(
                        f,
                        "pid {} on host {} since unix time {since}",
                        std::process::id(),
                        host_name()
                    );
                    return Ok(FileLock { path: lock });
                }
                Err(e) if e.kind() == ErrorKind::AlreadyExists => {
                    if started.elapsed() >= timeout {
                        let holder = std::fs::read_to_string(&lock)
                            .map(|h| h.trim().to_string())
                            .unwrap_or_default();
                        bail!(
                            "{} has been held for more than {:.0} s (by {}): another sweep is \
                             writing its rows, or one was killed while writing. If no sweep is \
                             running, delete the lock file and rerun the same command; its \
                             finished runs are skipped, so the rows come back without running \
                             them again",
                            lock.display(),
                            timeout.as_secs_f64(),
                            if holder.is_empty() {
                                "an unknown writer".to_string()
                            } else {
                                holder
                            }
                        );
                    }
                    std::thread::sleep(pause);
                    pause = (pause * 2).min(RETRY.1);
                }
                Err(e) => {
                    return Err(e).with_context(|| format!("creating {}", lock.display()));
                }
            }
        }
    }
}

impl Drop for FileLock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// Refuses a file at `path` whose header is not `header` (see the module doc); fine if the
/// file does not exist.
pub fn check_header(path: &Path, header: &str) -> Result<()> {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(e).with_context(|| format!("reading {}", path.display())),
    };
    match header_mismatch(&text, header).with_context(|| format!("reading {}", path.display()))? {
        None => Ok(()),
        Some(why) => bail!(
            "{} cannot take this sweep's rows: {why}\n(written by another version of xtask). \
             Move it away (e.g. `mv {0} {0}.old`) and rerun: finished runs are skipped and their \
             rows written again",
            path.display()
        ),
    }
}

/// Merges `new_rows` into the file at `path` under its lock, written atomically; returns the
/// number of rows the file holds now.
pub fn write_merged(
    path: &Path,
    header: &str,
    new_rows: &[String],
    order: &[&str],
    timeout: Duration,
) -> Result<usize> {
    let _lock = FileLock::acquire(path, timeout)?;
    check_header(path, header)?;
    let existing = match std::fs::read_to_string(path) {
        Ok(t) => Some(t),
        Err(e) if e.kind() == ErrorKind::NotFound => None,
        Err(e) => return Err(e).with_context(|| format!("reading {}", path.display())),
    };
    let merged = merge(header, existing.as_deref(), new_rows, order)
        .with_context(|| format!("merging the rows of {}", path.display()))?;
    runout_output::write_atomic(path, merged.as_bytes())
        .with_context(|| format!("writing {}", path.display()))?;
    Ok(records(&merged)?.len() - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    const H: &str = "case,fidelity,status,value";

    fn temp(test: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("runout-summary-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn rows(text: &str) -> Vec<String> {
        records(text)
            .unwrap()
            .iter()
            .skip(1)
            .map(|r| line(r))
            .collect()
    }

    #[test]
    fn new_rows_replace_their_key_and_keep_the_others_in_matrix_order() {
        let order = ["a", "b", "c"];
        let old = format!(
            "{H}\nc,coarse,Completed,1\ngone,coarse,Completed,9\na,coarse,\"failed: x,\ny\",\n\
             a,smoke,Completed,3\n"
        );
        let merged = merge(
            H,
            Some(&old),
            &["a,coarse,Completed,2".into(), "b,coarse,Completed,5".into()],
            &order,
        )
        .unwrap();
        assert_eq!(
            rows(&merged),
            [
                "a,smoke,Completed,3",
                "a,coarse,Completed,2",
                "b,coarse,Completed,5",
                "c,coarse,Completed,1",
                "gone,coarse,Completed,9",
            ]
        );
        // merging again changes nothing: the order does not depend on the writer
        assert_eq!(merge(H, Some(&merged), &[], &order).unwrap(), merged);
        // a quoted field with a comma and a newline survives the round trip
        let kept = merge(H, Some(&old), &[], &order).unwrap();
        assert!(kept.contains("a,coarse,\"failed: x,\ny\",\n"));
        assert_eq!(
            merge(H, None, &["b,smoke,Completed,1".into()], &order).unwrap(),
            format!("{H}\nb,smoke,Completed,1\n")
        );
        assert!(merge(H, None, &["b,smoke,1".into()], &order)
            .unwrap_err()
            .to_string()
            .contains("3 fields for 4 columns"));
    }

    #[test]
    fn a_file_with_another_header_is_refused_and_left_alone() {
        let dir = temp("header");
        let path = dir.join("summary.csv");
        let old = "case,fidelity,status\na,coarse,Completed\n";
        std::fs::write(&path, old).unwrap();
        let err = write_merged(
            &path,
            H,
            &["b,coarse,Completed,1".into()],
            &[],
            LOCK_TIMEOUT,
        )
        .unwrap_err()
        .to_string();
        assert!(err.contains("cannot take this sweep's rows"), "{err}");
        assert!(err.contains("Move it away"), "{err}");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), old);
        assert!(
            !lock_path(&path).exists(),
            "the lock is released on an error"
        );
        // an empty file is no file
        std::fs::write(&path, "").unwrap();
        check_header(&path, H).unwrap();
        check_header(&dir.join("none.csv"), H).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// The concurrency rule: writers that merge at the same time into one file all keep
    /// their rows (without the lock, one writer's read–merge–write can overwrite another's).
    #[test]
    fn concurrent_writers_lose_no_rows() {
        let dir = temp("concurrent");
        let path = dir.join("summary.csv");
        let writers = 8;
        let rounds = 3;
        let barrier = std::sync::Barrier::new(writers);
        let errors = std::sync::Mutex::new(Vec::new());
        std::thread::scope(|s| {
            for w in 0..writers {
                let (path, barrier, errors) = (&path, &barrier, &errors);
                s.spawn(move || {
                    for r in 0..rounds {
                        // all writers start each round together
                        barrier.wait();
                        let row = format!("case{w}-{r},smoke,Completed,{w}");
                        if let Err(e) = write_merged(path, H, &[row], &[], LOCK_TIMEOUT) {
                            errors.lock().unwrap().push(e.to_string());
                        }
                    }
                });
            }
        });
        assert!(
            errors.lock().unwrap().is_empty(),
            "{:?}",
            errors.lock().unwrap()
        );
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(rows(&text).len(), writers * rounds, "{text}");
        assert!(!lock_path(&path).exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_held_lock_makes_writers_wait_and_then_time_out() {
        let dir = temp("lock");
        let path = dir.join("summary.csv");
        let held = FileLock::acquire(&path, LOCK_TIMEOUT).unwrap();
        let holder = std::fs::read_to_string(lock_path(&path)).unwrap();
        assert!(holder.contains(&format!("pid {}", std::process::id())));
        let err = write_merged(&path, H, &[], &[], Duration::from_millis(50))
            .unwrap_err()
            .to_string();
        assert!(err.contains("has been held for more than"), "{err}");
        assert!(err.contains("delete the lock file and rerun"), "{err}");
        assert!(err.contains(holder.trim()), "{err}");
        assert!(!path.exists(), "nothing was written without the lock");
        // released while another writer waits: that writer goes on
        std::thread::scope(|s| {
            let waiter = s.spawn(|| {
                write_merged(&path, H, &["a,smoke,Completed,1".into()], &[], LOCK_TIMEOUT)
            });
            std::thread::sleep(Duration::from_millis(100));
            drop(held);
            assert_eq!(waiter.join().unwrap().unwrap(), 1);
        });
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
