//! The statistics the reproduction reports, as pure functions checked against SciPy.
//!
//! What it is: descriptive summaries ([`Summary::of`], [`mean`],
//! [`sample_sd`], [`standard_error`]); the two-sample t-tests the thesis ran
//! ([`student_t_test`], MATLAB `ttest2`'s pooled default, and
//! [`welch_t_test`]) with p-values accurate far into the tail
//! ([`students_t_two_sided_p`]); Pearson correlation with its t-test
//! ([`pearson`]); seeded percentile-bootstrap intervals ([`Bootstrap`]) and
//! robust centres ([`iqm`], [`trim_mean`], [`quantile`]) in the spirit of
//! rliable; learning-curve metrics ([`curve`]: initial, asymptotic,
//! cumulative, moving average, episode-wise mean and standard error over
//! trials, episodes to surpass a reference); and the renderers reports use
//! for them ([`format::p_value`], [`format::stars`], [`format::thousands`]).
//!
//! What a skeptical reader needs beside each p-value: [`TwoSample`] and
//! [`Comparison`] give, for the pooled and the Welch test, t, df, the
//! two-sided and both one-sided p-values ([`Alternative`]), the mean
//! difference with its t interval (from [`students_t_quantile`]) and Hedges'
//! g ([`hedges_g`]); [`tost()`](fn@tost) tests equivalence within a stated
//! [`Margin`] for "no difference" claims; [`OneSample`] tests a mean against a
//! reference value (and, on one estimate per replication, decides with the
//! replication as the unit: [`one_sample_power`], [`clopper_pearson`]); [`holm`] adjusts a family of p-values; and [`Bootstrap::stratified_iqm_ci`] is rliable's stratified
//! bootstrap interval of the IQM over tasks ([`aggregate_iqm`]), with the
//! Monte Carlo error of each bound so a report prints only digits that do
//! not depend on the random stream ([`StratifiedCi`]). Times to an event
//! that some subjects never reach (censored) get the Kaplan–Meier estimate
//! and the log-rank test ([`kaplan_meier`], [`log_rank`]).
//!
//! What it is not: no plotting, no tables, no IO, no printing, no RL and no
//! knowledge of the thesis's numbers; no global random generator and no
//! clock (the bootstrap takes its seed from the caller). Every function
//! checks its input and returns [`StatsError`] instead of panicking or
//! producing NaN. Sums run sequentially in index order with compensation,
//! so the same input gives the same bits whatever the caller's threading.
//!
//! # Example
//!
//! Two learners' episodes to criterion over ten trials each: the pooled
//! t-test with its 95 % interval for the difference of means and Hedges' g
//! (scipy 1.17.1's `ttest_ind(x, y).confidence_interval(0.95)` gives the
//! same interval, `[-14.644654984553389, -7.955345015446605]`).
//!
//! ```rust
//! use rlfd_stats::{Alternative, TwoSample, Variance, format};
//!
//! let shaped = [41.0, 38.0, 45.0, 36.0, 40.0, 43.0, 39.0, 37.0, 44.0, 42.0];
//! let plain = [52.0, 47.0, 55.0, 49.0, 58.0, 46.0, 51.0, 53.0, 50.0, 57.0];
//! let two = TwoSample::of(&shaped, &plain, 0.95)?;
//! let c = two.comparison(Variance::Pooled);
//! let line = format!(
//!     "t({}) = {:.2}, p = {}, difference {:.2} [{:.2}, {:.2}], g = {:.2}",
//!     c.df,
//!     c.t,
//!     format::p_value(c.p),
//!     c.difference,
//!     c.lower,
//!     c.upper,
//!     two.hedges_g,
//! );
//! assert_eq!(line, "t(18) = -7.10, p = 1.289e-06, difference -11.30 [-14.64, -7.96], g = -3.04");
//! // The claim is directional ("shaping is faster"): its one-sided p is half the two-sided one.
//! assert!(c.p_value(Alternative::Less) < 1e-6);
//! # Ok::<(), rlfd_stats::StatsError>(())
//! ```

pub mod bootstrap;
pub mod compare;
pub mod correlation;
pub mod curve;
pub mod error;
pub mod format;
pub mod multiple;
pub mod one_sample;
pub mod replication;
pub mod robust;
pub mod stratified;
pub mod summary;
pub mod survival;
pub mod tdist;
pub mod tost;
pub mod ttest;

pub use bootstrap::{Bootstrap, BootstrapCi};
pub use compare::{Alternative, Comparison, TwoSample, Variance, hedges_g};
pub use correlation::{Correlation, pearson};
pub use error::{Result, StatsError};
pub use multiple::holm;
pub use one_sample::OneSample;
pub use replication::{clopper_pearson, one_sample_power};
pub use robust::{iqm, quantile, trim_mean};
pub use stratified::{HEADLINE_RESAMPLES, HEADLINE_SEED, StratifiedCi, aggregate_iqm, headline_iqm};
pub use summary::{Summary, mean, sample_sd, sample_variance, standard_error};
pub use survival::{KaplanMeier, LogRank, TimeToEvent, kaplan_meier, log_rank};
pub use tdist::{students_t_cdf, students_t_quantile, students_t_sf, students_t_two_sided_p};
pub use tost::{Margin, OneSidedTest, Tost, tost};
pub use ttest::{TTest, student_t_test, welch_t_test};
