//! Independent runs at once: `jobs` workers take items from one queue, each worker on a
//! rayon pool of its own with the machine's cores shared out between the workers.
//!
//! Workers that share rayon's global pool slow each other down: a run's parallel stages
//! queue behind the other run's tasks, and each worker's own thread runs its serial stages
//! beside the pool's threads (four threads for two runs on two cores). A worker inside a
//! pool of the workers' size is no better: a run waiting in a parallel stage may steal the
//! next whole run from the queue. Two `wall`-fidelity runs of family S at once took 1.29×
//! the wall time in one shared pool that they took as two one-thread processes
//! (docs/history/performance-log.md, "Runs at once on pools of their own").

use std::sync::Mutex;

use anyhow::{Context, Result};

/// Threads of each of `jobs` runs at once: the threads this process may use shared out,
/// at least one each. Those are `RAYON_NUM_THREADS` if it is set to a positive number (as
/// for rayon's global pool), else the cores of its CPU affinity and cgroup quota
/// (`std::thread::available_parallelism`).
pub fn threads_per_job(jobs: usize) -> usize {
    let from_env = std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0);
    let cores =
        from_env.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    (cores / jobs.max(1)).max(1)
}

/// Calls `work` on every item of `items`, in order of the queue, from `jobs` workers, each
/// running inside a rayon pool of [`threads_per_job`] threads of its own. A worker takes no
/// further item once `keep_going` returns false (a signal, a first error).
pub fn run_queue<T: Send>(
    items: impl IntoIterator<Item = T, IntoIter: Send>,
    jobs: usize,
    keep_going: impl Fn() -> bool + Sync,
    work: impl Fn(T) + Sync,
) -> Result<()> {
    let threads = threads_per_job(jobs);
    let pools = (0..jobs.max(1))
        .map(|_| rayon::ThreadPoolBuilder::new().num_threads(threads).build())
        .collect::<Result<Vec<_>, _>>()
        .context("building the workers' thread pools")?;
    let queue = Mutex::new(items.into_iter());
    std::thread::scope(|scope| {
        for pool in &pools {
            scope.spawn(|| {
                pool.install(|| {
                    while keep_going() {
                        let Some(item) = queue.lock().expect("no poisoned lock").next() else {
                            break;
                        };
                        work(item);
                    }
                })
            });
        }
    });
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Every item is worked once, on a thread of a pool of the shared-out size (not on the
    /// worker's own thread, nor in rayon's global pool).
    #[test]
    fn every_item_runs_once_on_a_pool_of_the_shared_out_size() {
        let jobs = 2;
        let seen = Mutex::new(Vec::new());
        run_queue(
            0..7,
            jobs,
            || true,
            |k| {
                assert!(rayon::current_thread_index().is_some());
                assert_eq!(rayon::current_num_threads(), threads_per_job(jobs));
                seen.lock().unwrap().push(k);
            },
        )
        .unwrap();
        let mut seen = seen.into_inner().unwrap();
        seen.sort();
        assert_eq!(seen, (0..7).collect::<Vec<_>>());
    }

    /// Once `keep_going` turns false no further item is taken.
    #[test]
    fn a_stop_takes_no_further_item() {
        let done = AtomicUsize::new(0);
        run_queue(
            0..100,
            1,
            || done.load(Ordering::SeqCst) < 3,
            |_| {
                done.fetch_add(1, Ordering::SeqCst);
            },
        )
        .unwrap();
        assert_eq!(done.load(Ordering::SeqCst), 3);
    }

    /// The cores are shared out, at least one thread each (the test runner's environment
    /// sets no `RAYON_NUM_THREADS`, or this test is skipped).
    #[test]
    fn threads_per_job_shares_the_cores_out() {
        if std::env::var_os("RAYON_NUM_THREADS").is_some() {
            return;
        }
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        assert_eq!(threads_per_job(1), cores);
        assert_eq!(threads_per_job(cores), 1);
        assert_eq!(threads_per_job(4 * cores), 1);
        assert_eq!(threads_per_job(0), cores);
    }
}
