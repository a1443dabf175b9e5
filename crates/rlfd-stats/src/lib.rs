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
//! What it is not: no plotting, no tables, no IO, no printing, no RL and no
//! knowledge of the thesis's numbers; no global random generator and no
//! clock (the bootstrap takes its seed from the caller). Every function
//! checks its input and returns [`StatsError`] instead of panicking or
//! producing NaN. Sums run sequentially in index order with compensation,
//! so the same input gives the same bits whatever the caller's threading.

pub mod bootstrap;
pub mod correlation;
pub mod curve;
pub mod error;
pub mod format;
pub mod robust;
pub mod summary;
pub mod tdist;
pub mod ttest;

pub use bootstrap::{Bootstrap, BootstrapCi};
pub use correlation::{Correlation, pearson};
pub use error::{Result, StatsError};
pub use robust::{iqm, quantile, trim_mean};
pub use summary::{Summary, mean, sample_sd, sample_variance, standard_error};
pub use tdist::students_t_two_sided_p;
pub use ttest::{TTest, student_t_test, welch_t_test};
