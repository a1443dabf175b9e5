//! `calibrate [MODEL]`: rerun a synthetic human's (or a model's)
//! calibration and print it; without a model, list them. Each chapter
//! declares its calibrations ([`rlfd_harness::Calibration`]); this only
//! finds and runs them.

use anyhow::{Result, bail};

use crate::chapters;

pub fn run(model: Option<&str>) -> Result<()> {
    let all: Vec<(&'static str, rlfd_harness::Calibration)> =
        chapters::registry().iter().flat_map(|c| c.calibrations().into_iter().map(move |k| (c.slug(), k))).collect();
    let Some(model) = model else {
        for (slug, c) in &all {
            println!("{:<20} {slug}: {}", c.model, c.what);
        }
        return Ok(());
    };
    let Some((slug, c)) = all.iter().find(|(_, c)| c.model == model) else {
        let names: Vec<&str> = all.iter().map(|(_, c)| c.model).collect();
        bail!("unknown model \"{model}\" (expected one of: {})", names.join(", "));
    };
    eprintln!("{slug}: {}", c.what);
    print!("{}", (c.run)());
    Ok(())
}
