//! `merge STORE...`: result stores (each shard's, when the machines share no
//! file system) merged into one (see [`rlfd_harness::merge`]): checked whole
//! first, nothing written on a refusal, unreadable records left out and named.

use std::collections::BTreeSet;
use std::path::PathBuf;

use anyhow::Result;
use rlfd_harness::Scale;
use rlfd_runner::replication_seed;

/// What `merge` was asked.
#[derive(Clone, Debug)]
pub struct Options {
    /// The stores to merge.
    pub sources: Vec<PathBuf>,
    /// The store to merge into.
    pub into: PathBuf,
    /// The run's scale.
    pub scale: Scale,
    /// The run's master seed.
    pub seed: u64,
}

/// The largest `--seeds` the command line accepts: the replication seeds a
/// store of the run may hold are the first this many.
const MAX_REPLICATIONS: u32 = 1000;

pub fn run(o: &Options) -> Result<()> {
    let seeds: BTreeSet<u64> = (0..MAX_REPLICATIONS).map(|k| replication_seed(o.seed, k)).collect();
    let m = rlfd_harness::merge::merge(&o.sources, &o.into, o.scale, o.seed, &seeds)?;
    for (path, reason) in &m.unreadable {
        eprintln!(
            "warning: {} is not merged: {reason}; its trial is recomputed by a rerun of its shard",
            path.display()
        );
    }
    let mut line = format!(
        "merge: {} records from {} stores into {}: {} new, {} already there",
        m.records,
        o.sources.len(),
        o.into.display(),
        m.new,
        m.present
    );
    if m.replaced > 0 {
        line.push_str(&format!(", {} unreadable ones there replaced", m.replaced));
    }
    if m.duplicates > 0 {
        line.push_str(&format!(", {} found in more than one store", m.duplicates));
    }
    if !m.unreadable.is_empty() {
        line.push_str(&format!(", {} unreadable left out", m.unreadable.len()));
    }
    if m.temporary > 0 {
        line.push_str(&format!(", {} temporary files of interrupted writers ignored", m.temporary));
    }
    eprintln!("{line}");
    Ok(())
}
