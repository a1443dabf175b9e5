//! Adapters for the chapters whose command line is only a choice of
//! experiments: chapters 3, 4 and 5. Each crate exposes the same surface
//! (`CHAPTER`, `Experiment` with `ALL`/`name`/`FromStr`, `reproduce`,
//! `report::chapter_report`, `bench_workloads`), so one macro writes the
//! three adapters; chapter 6, which also takes a demonstration file, has
//! its own.

/// Declares `$ty`, the adapter of chapter crate `$krate`, known on the
/// command line by its slug and by `$alias`.
macro_rules! simple_chapter {
    ($(#[$doc:meta])* $ty:ident, $krate:ident, $alias:literal) => {
        $(#[$doc])*
        pub struct $ty;

        impl super::Chapter for $ty {
            fn slug(&self) -> &'static str {
                $krate::CHAPTER
            }

            fn alias(&self) -> &'static str {
                $alias
            }

            fn experiments(&self) -> Vec<&'static str> {
                $krate::Experiment::ALL.iter().map(|e| e.name()).collect()
            }

            fn run(
                &self,
                _settings: &crate::cli::RunSettings,
                experiment: Option<&str>,
                options: &rlfd_harness::RunOptions,
                provenance: &rlfd_report::Provenance,
            ) -> anyhow::Result<super::ChapterRun> {
                let experiments: Vec<$krate::Experiment> = match experiment {
                    None => $krate::Experiment::ALL.to_vec(),
                    Some(e) => vec![e.parse::<$krate::Experiment>()?],
                };
                let results = $krate::reproduce(options, &experiments)?;
                let report = $krate::report::chapter_report(&results, provenance)?;
                Ok(super::ChapterRun { report })
            }

            fn workloads(&self) -> anyhow::Result<Vec<rlfd_harness::Workload<'static>>> {
                Ok($krate::bench_workloads()?)
            }
        }
    };
}

simple_chapter!(
    /// Chapter 3: interactive RL with teacher guidance on the Nao sorting task.
    Ch3,
    ch3_interactive_rl,
    "ch3"
);
simple_chapter!(
    /// Chapter 4: the DBug user study (Int-RL, Behavior Networks, CBA).
    Ch4,
    ch4_dbug_study,
    "ch4"
);
simple_chapter!(
    /// Chapter 5: Human-Agent Transfer in 3 vs 2 Keepaway.
    Ch5,
    ch5_hat_keepaway,
    "ch5"
);
