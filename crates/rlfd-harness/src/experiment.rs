//! How a chapter declares its experiments: one [`experiments!`] invocation
//! gives the enum, `ALL`, `name()` (the `--experiment` value and the store's
//! folder), `behaviour()` (the declared behaviour version that keys every
//! stored trial of the experiment) and `FromStr` with a typed
//! [`UnknownExperiment`] error that lists the valid names.
//!
//! The behaviour version is the contract that replaces hashing source text:
//! a change to what an experiment computes (its simulator, learner, teacher
//! model, or any library code it runs) bumps its number in the same commit;
//! comments, tests, report code and unrelated crates never do. A forgotten
//! bump is caught by the golden record digests (`golden/records.tsv`,
//! checked by `xtask`'s golden test).

use thiserror::Error;

/// What the harness needs to know of an experiment.
pub trait ExperimentId: Copy + 'static {
    /// Its name on the command line and in the store, e.g. `maze`.
    fn name(self) -> &'static str;
    /// Its declared behaviour version (≥ 1).
    fn behaviour(self) -> u32;
}

/// An experiment name a chapter does not have.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("unknown experiment \"{name}\" for {chapter} (expected one of: {})", expected.join(", "))]
pub struct UnknownExperiment {
    /// The chapter asked.
    pub chapter: &'static str,
    /// The name given.
    pub name: String,
    /// The chapter's experiments.
    pub expected: Vec<&'static str>,
}

/// Declares a chapter's experiments.
///
/// ```
/// const CHAPTER: &str = "ch0-toy";
/// rlfd_harness::experiments! {
///     /// The experiments of a toy chapter.
///     pub enum Experiment for CHAPTER {
///         /// The main run.
///         Main = "main", behaviour 1,
///         /// A study around it.
///         Study = "study", behaviour 3,
///     }
/// }
/// use rlfd_harness::ExperimentId;
/// assert_eq!(Experiment::ALL, [Experiment::Main, Experiment::Study]);
/// assert_eq!(Experiment::Study.name(), "study");
/// assert_eq!(Experiment::Study.behaviour(), 3);
/// assert_eq!("main".parse::<Experiment>(), Ok(Experiment::Main));
/// let e = "mian".parse::<Experiment>().unwrap_err();
/// assert_eq!(e.to_string(), "unknown experiment \"mian\" for ch0-toy (expected one of: main, study)");
/// ```
#[macro_export]
macro_rules! experiments {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident for $chapter:path {
            $( $(#[$vmeta:meta])* $variant:ident = $slug:literal, behaviour $behaviour:expr ),+ $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        $vis enum $name {
            $( $(#[$vmeta])* $variant, )+
        }

        impl $name {
            /// Every experiment of the chapter, in the order the report shows them.
            pub const ALL: [$name; [$($slug),+].len()] = [$($name::$variant),+];

            /// The name on the command line and in the store.
            pub const fn name(self) -> &'static str {
                match self { $( $name::$variant => $slug, )+ }
            }

            /// The declared behaviour version of its trials.
            pub const fn behaviour(self) -> u32 {
                match self { $( $name::$variant => $behaviour, )+ }
            }
        }

        impl $crate::ExperimentId for $name {
            fn name(self) -> &'static str {
                $name::name(self)
            }
            fn behaviour(self) -> u32 {
                $name::behaviour(self)
            }
        }

        impl ::std::str::FromStr for $name {
            type Err = $crate::UnknownExperiment;

            fn from_str(s: &str) -> ::std::result::Result<Self, Self::Err> {
                $name::ALL.into_iter().find(|e| e.name() == s).ok_or_else(|| $crate::UnknownExperiment {
                    chapter: $chapter,
                    name: s.to_string(),
                    expected: $name::ALL.iter().map(|e| e.name()).collect(),
                })
            }
        }
    };
}
