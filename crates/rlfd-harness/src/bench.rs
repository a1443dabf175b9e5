//! Benchmark workloads: deterministic work a chapter offers for `cargo
//! xtask bench` to time. The chapter says what the work is; only the
//! command line reads the clock.

/// A unit of work that can be repeated: `run(seed)` does one batch and
/// returns how many `unit`s it did (steps, ticks, cycles).
pub struct Workload<'a> {
    /// The domain, e.g. `maze`.
    pub domain: &'static str,
    /// What runs, e.g. `sarsa-lambda` or `simulator`.
    pub name: String,
    /// What is counted, e.g. `steps`.
    pub unit: &'static str,
    /// One batch for a seed; returns the units done.
    pub run: Box<dyn FnMut(u64) -> u64 + 'a>,
}

impl std::fmt::Debug for Workload<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Workload({} {} in {})", self.domain, self.name, self.unit)
    }
}
