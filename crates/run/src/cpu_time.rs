//! The CPU time of this process, for timing runs (user + system, all threads; getrusage).

/// CPU time of this process so far (user + system, all threads) [s]; NaN if getrusage
/// fails.
pub fn cpu_seconds() -> f64 {
    // SAFETY: getrusage writes into the zeroed struct we own.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let rc = unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) };
    if rc != 0 {
        return f64::NAN;
    }
    let tv = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    tv(usage.ru_utime) + tv(usage.ru_stime)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_time_is_finite_and_grows() {
        let before = cpu_seconds();
        let mut x = 0.0_f64;
        for k in 0..2_000_000 {
            x += (k as f64).sqrt();
        }
        std::hint::black_box(x);
        let after = cpu_seconds();
        assert!(before.is_finite() && before >= 0.0);
        assert!(after >= before);
    }
}
