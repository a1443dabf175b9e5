//! `verify`: recompute a sample of stored trials and compare each with its
//! record byte for byte (see [`rlfd_runner::verify`]).

use anyhow::Result;
use rlfd_runner::Selection;

use crate::chapters::registry;
use crate::cli::RunSettings;

pub fn run(s: &RunSettings, n: usize, sample_seed: u64) -> Result<()> {
    let registry = registry();
    let selection = Selection::new(s.command.clone(), &registry)?;
    let v = rlfd_runner::verify::verify(&selection, &s.machine, n, sample_seed)?;
    let per_reading = if v.records > v.chosen {
        format!(" ({} records: a trial kept under several readings is recomputed under each)", v.records)
    } else {
        String::new()
    };
    eprintln!(
        "verify: {} trials recomputed from {} experiments{per_reading}, each byte-identical to its record ({} stored trials checked current)",
        v.chosen, v.experiments, v.total
    );
    Ok(())
}
