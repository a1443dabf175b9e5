//! The trial plan: the one place a chapter turns (experiment, condition,
//! trial, what determines the result) into a [`TrialSpec`], so seeds and the
//! trial's identity are derived the same way everywhere.
//!
//! A trial's identity (its fingerprint) is
//! `FNV-1a("rlfd-trial/v2" ‖ build identity ‖ behaviour version ‖ determinants)`,
//! where the build identity is the chapter's (`RLFD_BUILD_IDENTITY`, set by
//! `chapters/build_identity.rs`: the rustc release and the versions of the
//! crates in the chapter's dependency closure), the behaviour version is the
//! experiment's declared one ([`crate::experiments!`]), and the determinants
//! are what the chapter feeds in: the trial's parameters and inputs. A
//! non-default [`Reading`] of the axes that change the experiment joins the
//! identity (its seed stays the same: common random numbers across readings).

use crate::experiment::ExperimentId;
use crate::fingerprint::Fingerprint;
use crate::readings::Reading;
use crate::runner::{RunOptions, TrialSpec};
use crate::seed::{TrialKey, derive_seed};

/// A chapter as its stored trials name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChapterId {
    /// The crate's slug, e.g. `ch6-irl-shaping`.
    pub slug: &'static str,
    /// Its build identity: pass [`crate::BUILD_IDENTITY`].
    pub build: &'static str,
}

/// Specs for the trials of one experiment.
#[derive(Clone, Debug)]
pub struct TrialPlan {
    chapter: ChapterId,
    experiment: &'static str,
    behaviour: u32,
    master_seed: u64,
    reading: Reading,
}

impl TrialPlan {
    /// The plan of `experiment` in `chapter` under `options`.
    pub fn new(options: &RunOptions, chapter: ChapterId, experiment: impl ExperimentId) -> Self {
        TrialPlan {
            chapter,
            experiment: experiment.name(),
            behaviour: experiment.behaviour(),
            master_seed: options.master_seed,
            reading: options.reading.clone(),
        }
    }

    /// The experiment's name.
    pub fn experiment(&self) -> &'static str {
        self.experiment
    }

    /// Trial `trial` of `condition`, whose result is determined by
    /// `determinants` (the parameters and inputs, fingerprinted by the
    /// caller), carrying `params` to the closure that runs it.
    pub fn spec<P>(&self, condition: &str, trial: u32, determinants: Fingerprint, params: P) -> TrialSpec<P> {
        let key = TrialKey::new(self.chapter.slug, self.experiment, condition, trial);
        let reading = self.reading.restricted_to(self.experiment, condition);
        let mut identity =
            Fingerprint::new().str("rlfd-trial/v2").str(self.chapter.build).u64(u64::from(self.behaviour));
        if !reading.is_default() {
            identity = identity.str(&reading.label());
        }
        let fingerprint = identity.u64(determinants.value()).hex();
        TrialSpec {
            seed: derive_seed(self.master_seed, &key),
            key,
            behaviour: self.behaviour,
            build: self.chapter.build,
            reading,
            fingerprint,
            params,
        }
    }
}
