//! A team of the rayon pool's threads that stays awake for one linear solve.
//!
//! Rayon's fork/join costs about a microsecond while the pool's threads are busy, but a
//! thread that has found no work for some tens of microseconds goes to sleep, and waking it
//! costs ~15 µs on this kind of machine (`cargo run --release -p runout-linsolve --example
//! join_latency`; docs/history/performance-log.md, "The multigrid solve on a team that stays
//! awake": a join of two 10 µs halves takes 10.8 µs right after other work and 24–27 µs
//! after a serial stretch of 20 µs or more). A multigrid cycle alternates short parallel
//! sweeps with serial stretches (the coarse levels, the coarsest solve), so rayon's threads
//! fall asleep between the sweeps of the coarse levels and those levels run no faster on two
//! threads than on one.
//!
//! [`Team::run`] keeps the pool's other threads spinning for the duration of a closure:
//! each [`Team::for_each`] publishes a job of `n` chunks, which every member (the calling
//! thread and the helpers) claims one at a time, and returns when all are done. The
//! helpers are ordinary rayon jobs, so nothing can deadlock: a helper that is never
//! started (every other thread busy elsewhere) leaves all chunks to the calling thread,
//! and when the closure ends the helpers still queued return at once (rayon runs a
//! join's second half on the calling thread when no other thread took it). Which member runs a
//! chunk never changes its arithmetic, so results do not depend on the number of threads
//! (the kernels of [`crate::kernels`] and [`crate::stencil`] fix their chunks by length,
//! not by team size).
//!
//! Outside [`Team::run`], [`Team::RAYON`] sends the same loops to rayon's parallel
//! iterators, so one kernel serves both.

use std::any::Any;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicPtr, AtomicU32, AtomicU64, Ordering};
use std::sync::Mutex;

use rayon::prelude::*;

use crate::kernels::PAR_MIN_LEN;

/// With a team, loops over fewer entries than this run on the calling thread alone: below
/// it, handing the job out and moving the data between the cores' caches cost more than
/// the second thread saves (the 400 × 100 pressure solve's 2 500-cell level took 246 µs
/// per outer iteration on two threads, 164 µs on one; docs/studies/performance.md,
/// "The y lines split in two").
pub(crate) const TEAM_MIN_LEN: usize = 1 << 13;
/// With a team, the entries of one chunk of a loop at least (rayon: [`PAR_MIN_LEN`] per
/// task of a row loop).
pub(crate) const TEAM_MIN_CHUNK: usize = 1 << 10;

/// Spin iterations of a waiting member before it starts yielding its core.
const SPINS_BEFORE_YIELD: u32 = 1 << 14;
/// Largest number of chunks of one job (16 bits of the job word).
pub(crate) const MAX_CHUNKS: usize = (1 << 16) - 1;

/// Who runs the chunks of a loop.
#[derive(Clone, Copy)]
pub(crate) struct Team<'a> {
    mode: Mode<'a>,
}

#[derive(Clone, Copy)]
enum Mode<'a> {
    /// rayon's parallel iterators (outside [`Team::run`])
    Rayon,
    /// the calling thread alone (a pool of one thread)
    Serial,
    /// the calling thread and spinning helpers
    Spinning(&'a Shared),
}

/// A chunk loop as the helpers see it: `f(c)` for every chunk c.
type Job<'f> = &'f (dyn Fn(usize) + Sync);

/// The state the members share.
struct Shared {
    /// epoch (32 bits) | first (16) | end (16) of the chunks not yet claimed: the calling
    /// thread claims from the front, the helpers from the back, so that each member keeps
    /// running the same part of every loop (its data stays in that core's cache)
    word: AtomicU64,
    /// the current job: a pointer to a [`Job`] on the calling thread's stack
    job: AtomicPtr<()>,
    /// chunks of the current job finished
    done: AtomicU32,
    /// set when the closure of [`Team::run`] has returned (or unwound)
    finished: AtomicBool,
    /// the first panic of a chunk, re-raised on the calling thread
    panic: Mutex<Option<Box<dyn Any + Send>>>,
}

const fn pack(epoch: u32, first: usize, end: usize) -> u64 {
    ((epoch as u64) << 32) | ((first as u64) << 16) | end as u64
}

const fn unpack(word: u64) -> (u32, usize, usize) {
    (
        (word >> 32) as u32,
        ((word >> 16) & 0xffff) as usize,
        (word & 0xffff) as usize,
    )
}

impl Shared {
    fn new() -> Self {
        Self {
            word: AtomicU64::new(0),
            job: AtomicPtr::new(std::ptr::null_mut()),
            done: AtomicU32::new(0),
            finished: AtomicBool::new(false),
            panic: Mutex::new(None),
        }
    }

    /// Claims the first (or, `from_back`, the last) chunk not yet claimed of the job
    /// published in `word`, if any is left.
    fn claim(&self, word: u64, from_back: bool) -> Option<usize> {
        let (epoch, first, end) = unpack(word);
        if first >= end {
            return None;
        }
        let (claimed, rest) = if from_back {
            (end - 1, pack(epoch, first, end - 1))
        } else {
            (first, pack(epoch, first + 1, end))
        };
        self.word
            .compare_exchange_weak(word, rest, Ordering::AcqRel, Ordering::Relaxed)
            .ok()
            .map(|_| claimed)
    }

    /// Runs chunk `c` of `job`, keeping a panic for the calling thread.
    fn run_chunk(&self, job: Job<'_>, c: usize) {
        if let Err(payload) = catch_unwind(AssertUnwindSafe(|| job(c))) {
            let mut slot = self.panic.lock().unwrap_or_else(|e| e.into_inner());
            slot.get_or_insert(payload);
        }
        self.done.fetch_add(1, Ordering::Release);
    }

    /// A helper's loop: claim and run chunks of whatever job is published until the team
    /// is finished.
    fn help(&self) {
        let mut idle = 0u32;
        while !self.finished.load(Ordering::Acquire) {
            let word = self.word.load(Ordering::Acquire);
            let job = self.job.load(Ordering::Acquire);
            if let Some(c) = self.claim(word, true) {
                // SAFETY: the claim succeeded on the epoch whose job pointer was read
                // after the word: the calling thread keeps that job alive until all of its
                // chunks are done and publishes the next one only after (module doc).
                let job: Job<'_> = unsafe { *(job as *const Job<'_>) };
                self.run_chunk(job, c);
                idle = 0;
            } else {
                wait(&mut idle);
            }
        }
    }
}

/// One round of a busy wait: spin, and after a while yield the core.
fn wait(idle: &mut u32) {
    if *idle < SPINS_BEFORE_YIELD {
        *idle += 1;
        std::hint::spin_loop();
    } else {
        std::thread::yield_now();
    }
}

/// Sets `finished` when the closure of [`Team::run`] ends, also by unwinding.
struct FinishOnDrop<'a>(&'a Shared);

impl Drop for FinishOnDrop<'_> {
    fn drop(&mut self) {
        self.0.finished.store(true, Ordering::Release);
    }
}

impl Team<'static> {
    /// Loops go to rayon's parallel iterators.
    pub(crate) const RAYON: Team<'static> = Team { mode: Mode::Rayon };
}

impl<'a> Team<'a> {
    /// Runs `body` on the calling thread with a team of the current rayon pool's threads
    /// (module doc); a pool of one thread gives a serial team.
    pub(crate) fn run<R: Send>(body: impl FnOnce(&Team<'_>) -> R + Send) -> R {
        let helpers = rayon::current_num_threads().saturating_sub(1);
        if helpers == 0 {
            return body(&Team { mode: Mode::Serial });
        }
        let shared = Shared::new();
        with_helpers(helpers, &shared, || {
            body(&Team {
                mode: Mode::Spinning(&shared),
            })
        })
    }

    /// [`Team::run`] for loops of at most `len` entries: below [`TEAM_MIN_LEN`] no loop
    /// would be shared, so the pool's other threads are not woken (a serial team, whose
    /// chunks and results are the same).
    pub(crate) fn run_for<R: Send>(len: usize, body: impl FnOnce(&Team<'_>) -> R + Send) -> R {
        if len < TEAM_MIN_LEN {
            return body(&Team { mode: Mode::Serial });
        }
        Self::run(body)
    }

    /// Loops over fewer entries than this run serially: rayon's fork/join pays from
    /// [`PAR_MIN_LEN`] entries, a team's job from [`TEAM_MIN_LEN`]. Serial and spinning
    /// teams share every granularity, so their chunks, and results, are the same.
    pub(crate) fn min_len(&self) -> usize {
        match self.mode {
            Mode::Rayon => PAR_MIN_LEN,
            Mode::Serial | Mode::Spinning(_) => TEAM_MIN_LEN,
        }
    }

    /// The entries of one chunk of a loop at least (of a row loop's blocks of rows, and of
    /// the fixed chunks of a reduction with a team).
    pub(crate) fn min_chunk(&self) -> usize {
        match self.mode {
            Mode::Rayon => PAR_MIN_LEN,
            Mode::Serial | Mode::Spinning(_) => TEAM_MIN_CHUNK,
        }
    }

    /// Whether loops go to rayon's parallel iterators ([`Team::RAYON`]).
    pub(crate) fn is_rayon(&self) -> bool {
        matches!(self.mode, Mode::Rayon)
    }

    /// Calls `f(c)` for every chunk c in 0..n, the chunks shared among the team's members;
    /// returns when all have run. One chunk runs on the calling thread alone.
    pub(crate) fn for_each(&self, n: usize, f: impl Fn(usize) + Sync) {
        match self.mode {
            _ if n <= 1 => (0..n).for_each(f),
            Mode::Serial => (0..n).for_each(f),
            Mode::Rayon => (0..n).into_par_iter().for_each(&f),
            Mode::Spinning(shared) => run_job(shared, n, &f),
        }
    }

    /// Calls `f(c, chunk)` for every chunk of `chunk_len` entries of `data` (the last one
    /// shorter), the chunks shared among the team's members.
    pub(crate) fn for_each_chunk_mut<T: Send>(
        &self,
        data: &mut [T],
        chunk_len: usize,
        f: impl Fn(usize, &mut [T]) + Sync,
    ) {
        let (len, chunk_len) = (data.len(), chunk_len.max(1));
        let base = SendPtr(data.as_mut_ptr());
        self.for_each(len.div_ceil(chunk_len), |c| {
            let start = c * chunk_len;
            let end = (start + chunk_len).min(len);
            // SAFETY: chunk c is data[start..end]; the chunks are disjoint and each index
            // is run exactly once, while `data` is borrowed mutably for the whole loop.
            let chunk =
                unsafe { std::slice::from_raw_parts_mut(base.get().add(start), end - start) };
            f(c, chunk)
        });
    }
}

/// Runs `body` on the calling thread beside `helpers` rayon jobs that help `shared`'s jobs
/// until `body` ends; nested joins rather than a scope, which would allocate a job per
/// helper (the solves allocate nothing, tests/no_alloc.rs).
fn with_helpers<R: Send>(helpers: usize, shared: &Shared, body: impl FnOnce() -> R + Send) -> R {
    if helpers == 0 {
        let _finish = FinishOnDrop(shared);
        return body();
    }
    rayon::join(|| with_helpers(helpers - 1, shared, body), || shared.help()).0
}

/// A pointer to the entries of a slice split into disjoint chunks.
struct SendPtr<T>(*mut T);
impl<T> SendPtr<T> {
    fn get(&self) -> *mut T {
        self.0
    }
}
// SAFETY: each member dereferences only its own disjoint chunk ([`Team::for_each_chunk_mut`]).
unsafe impl<T: Send> Sync for SendPtr<T> {}

/// Publishes the job `f` of `n` chunks, runs chunks on the calling thread until none is
/// left to claim, waits for the helpers' ones, and re-raises a chunk's panic.
fn run_job(shared: &Shared, n: usize, f: &(dyn Fn(usize) + Sync)) {
    assert!(
        n <= MAX_CHUNKS,
        "a team job has at most {MAX_CHUNKS} chunks, not {n}"
    );
    let job: Job<'_> = f;
    let (epoch, _, _) = unpack(shared.word.load(Ordering::Relaxed));
    shared.done.store(0, Ordering::Relaxed);
    shared
        .job
        .store(&job as *const Job<'_> as *mut (), Ordering::Release);
    shared
        .word
        .store(pack(epoch.wrapping_add(1), 0, n), Ordering::Release);
    loop {
        let word = shared.word.load(Ordering::Acquire);
        match shared.claim(word, false) {
            Some(c) => shared.run_chunk(job, c),
            None if unpack(word).1 >= unpack(word).2 => break,
            None => {} // lost a race for the chunk: try the next
        }
    }
    let mut idle = 0;
    while shared.done.load(Ordering::Acquire) < n as u32 {
        wait(&mut idle);
    }
    let payload = shared
        .panic
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .take();
    if let Some(payload) = payload {
        resume_unwind(payload);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;

    /// Every chunk runs exactly once, on a pool of one, two and three threads, over many
    /// jobs of different sizes in one team.
    #[test]
    fn every_chunk_runs_once() {
        for threads in 1..=3 {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| {
                Team::run(|team| {
                    for n in [0, 1, 2, 3, 17, 1000, MAX_CHUNKS] {
                        let counts: Vec<AtomicUsize> =
                            (0..n).map(|_| AtomicUsize::new(0)).collect();
                        team.for_each(n, |c| {
                            counts[c].fetch_add(1, Ordering::Relaxed);
                        });
                        assert!(counts.iter().all(|c| c.load(Ordering::Relaxed) == 1));
                    }
                })
            });
        }
    }

    /// Chunks write disjoint parts of one vector; the team's and rayon's loops agree.
    #[test]
    fn chunked_writes_cover_the_vector() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let mut by_team = vec![0usize; 10_007];
        let mut by_rayon = vec![0usize; 10_007];
        pool.install(|| {
            Team::run(|team| {
                team.for_each_chunk_mut(&mut by_team, 64, |c, s| {
                    s.iter_mut().enumerate().for_each(|(i, v)| *v = 64 * c + i)
                })
            });
            Team::RAYON.for_each_chunk_mut(&mut by_rayon, 64, |c, s| {
                s.iter_mut().enumerate().for_each(|(i, v)| *v = 64 * c + i)
            });
        });
        assert!(by_team.iter().enumerate().all(|(i, &v)| v == i));
        assert_eq!(by_team, by_rayon);
    }

    /// A panicking chunk is re-raised on the calling thread after the job, and the team
    /// ends (no helper is left spinning).
    #[test]
    fn a_panic_in_a_chunk_reaches_the_caller() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let result = pool.install(|| {
            catch_unwind(AssertUnwindSafe(|| {
                Team::run(|team| team.for_each(100, |c| assert!(c != 57, "chunk 57")))
            }))
        });
        assert!(result.is_err());
        // the pool still works
        let chunks_run = AtomicUsize::new(0);
        pool.install(|| {
            Team::run(|team| {
                team.for_each(10, |_| {
                    chunks_run.fetch_add(1, Ordering::Relaxed);
                })
            })
        });
        assert_eq!(chunks_run.into_inner(), 10);
    }

    /// A team inside a job of a pool whose other thread is busy (it spins until the team is
    /// done, or 2 s) does all chunks on the calling thread instead of deadlocking.
    #[test]
    fn a_busy_pool_leaves_the_chunks_to_the_caller() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let sum = AtomicUsize::new(0);
        let team_done = AtomicBool::new(false);
        pool.install(|| {
            rayon::join(
                || {
                    let t = std::time::Instant::now();
                    while !team_done.load(Ordering::Acquire)
                        && t.elapsed() < std::time::Duration::from_secs(2)
                    {
                        std::hint::spin_loop();
                    }
                },
                || {
                    Team::run(|team| {
                        team.for_each(1000, |c| {
                            sum.fetch_add(c, Ordering::Relaxed);
                        })
                    });
                    team_done.store(true, Ordering::Release);
                },
            )
        });
        assert_eq!(sum.load(Ordering::Relaxed), 999 * 1000 / 2);
    }
}
