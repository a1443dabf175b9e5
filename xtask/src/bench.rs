//! `bench`: whole-domain speed, one line per domain and workload, measured
//! on one thread (`criterion` benches in each crate measure the kernels).
//!
//! Each line runs the chapter's workload in five windows and prints the best
//! window's rate and the median: on a shared or virtual machine the best
//! window is the closest to what the code does, the median to what a run
//! will see.

use std::time::Instant;

use anyhow::Result;

use crate::chapters;

const WINDOWS: usize = 5;

pub fn run(quick: bool) -> Result<()> {
    let budget = if quick { 0.05 } else { 0.4 };
    for chapter in chapters::registry() {
        for mut w in chapter.workloads()? {
            let mut seed = 0;
            let mut rates: Vec<f64> = (0..WINDOWS)
                .map(|_| {
                    let (mut done, start) = (0u64, Instant::now());
                    while start.elapsed().as_secs_f64() < budget {
                        done += (w.run)(seed);
                        seed += 1;
                    }
                    done as f64 / start.elapsed().as_secs_f64()
                })
                .collect();
            rates.sort_by(f64::total_cmp);
            println!(
                "{:<9} {:<16} {:>8.2}M {}/s  (median {:.2}M over {WINDOWS} windows)",
                w.domain,
                w.name,
                rates[WINDOWS - 1] / 1e6,
                w.unit,
                rates[WINDOWS / 2] / 1e6
            );
        }
    }
    Ok(())
}
