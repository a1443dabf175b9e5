//! `render mario --level-seed S`: the SVG of a generated Mario level with the
//! calibrated demonstrator's path (from small Mario), drawn by chapter 6's
//! report code; the file names the command that made it.

use std::path::Path;

use anyhow::{Context, Result};
use ch6_irl_shaping::mario::{LevelParams, Mode};
use rlfd_report::Provenance;

/// Writes the level of `level_seed` (the experiment's level settings) to `out`.
pub fn mario(level_seed: u64, out: &Path) -> Result<()> {
    let provenance =
        Provenance::new(format!("cargo xtask render mario --level-seed {level_seed}"), env!("CARGO_PKG_VERSION"));
    let svg = ch6_irl_shaping::report::mario::level_svg::render_level(
        LevelParams::EXPERIMENT,
        level_seed,
        Mode::Small,
        &provenance,
    )
    .context("drawing the level")?;
    rlfd_harness::write_atomically(out, svg.as_bytes()).with_context(|| format!("writing {}", out.display()))?;
    eprintln!("mario level {level_seed}: {}", out.display());
    Ok(())
}
