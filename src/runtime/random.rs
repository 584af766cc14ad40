//! The random source of sensor noise: C's `rand()`, as 2.2.2 draws it (the loader seeds it).

/// Two independent standard normal samples.
pub fn standard_normal() -> (f64, f64) {
    // SAFETY: rand() has no preconditions.
    crate::math::misc::standard_normal(|| unsafe { libc::rand() }, libc::RAND_MAX)
}

/// Seeds the generator (2.2.2's compiler seeds it with 123).
pub fn seed(s: u32) {
    // SAFETY: srand() has no preconditions.
    unsafe { libc::srand(s) }
}
