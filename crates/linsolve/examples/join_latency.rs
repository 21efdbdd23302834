//! What one rayon fork/join costs on this machine, right after another join and after a
//! serial stretch long enough for the pool's other thread to fall asleep (the reason for
//! `team.rs`; docs/history/performance-log.md,
//! "The multigrid solve on a team that stays awake").
//!
//! `cargo run --release -p runout-linsolve --example join_latency`
//!
//! Each line: a serial busy stretch of `gap` µs, then a join of two 10 µs halves on a pool
//! of two threads, timed (ideal 10 µs, serial 20 µs), mean of 2 000; `inside` runs the
//! loop on a pool thread (as `runout run` does), otherwise the main thread calls into the
//! global pool.

use std::time::{Duration, Instant};

fn busy(d: Duration) {
    let t = Instant::now();
    while t.elapsed() < d {
        std::hint::spin_loop();
    }
}

fn measure(inside: bool) {
    for gap_us in [0u64, 5, 20, 50, 100, 500] {
        let n = 2000;
        let mut total = 0.0;
        for _ in 0..n {
            busy(Duration::from_micros(gap_us));
            let t = Instant::now();
            rayon::join(
                || busy(Duration::from_micros(10)),
                || busy(Duration::from_micros(10)),
            );
            total += t.elapsed().as_secs_f64();
        }
        println!(
            "inside the pool {inside:5}, serial gap {gap_us:3} µs: join of 2 × 10 µs takes {:5.1} µs",
            total / n as f64 * 1e6
        );
    }
}

fn main() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a pool of two threads");
    pool.install(|| rayon::scope(|_| {}));
    pool.install(|| measure(true));
    // from the main thread: the global pool (two threads on this machine)
    measure(false);
}
