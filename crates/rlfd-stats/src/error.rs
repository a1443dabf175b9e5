//! The crate's error type, [`StatsError`], and the input checks shared by every statistic.

use thiserror::Error;

/// Result alias used by every fallible function of this crate.
pub type Result<T> = std::result::Result<T, StatsError>;

/// Why a statistic could not be computed.
///
/// Every public function checks its input and returns one of these instead of
/// panicking or returning NaN. `input` names the argument at fault (`"x"`,
/// `"y"`, `"curve"`, …) so that a caller can say which sample was wrong.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum StatsError {
    /// The sample is shorter than the statistic needs (e.g. a standard
    /// deviation needs two values, a correlation three).
    #[error("too few samples in `{input}`: need at least {needed}, got {got}")]
    TooFewSamples {
        /// The argument at fault.
        input: &'static str,
        /// The minimum length the statistic needs.
        needed: usize,
        /// The length it got.
        got: usize,
    },
    /// A value is NaN or infinite.
    #[error("non-finite value (NaN or infinite) in `{input}` at index {index}")]
    NonFinite {
        /// The argument at fault.
        input: &'static str,
        /// Zero-based position of the first non-finite value.
        index: usize,
    },
    /// A value of one trial of a set of learning curves is NaN or infinite.
    #[error("non-finite value (NaN or infinite) in trial {trial} at episode index {episode}")]
    NonFiniteInTrial {
        /// Zero-based trial index.
        trial: usize,
        /// Zero-based episode index within that trial.
        episode: usize,
    },
    /// A stratum (a task's runs) of a stratified bootstrap holds no values.
    #[error("stratum {stratum} is empty")]
    EmptyStratum {
        /// Zero-based index of the stratum.
        stratum: usize,
    },
    /// A value of one stratum of a stratified bootstrap is NaN or infinite.
    #[error("non-finite value (NaN or infinite) in stratum {stratum} at index {index}")]
    NonFiniteInStratum {
        /// Zero-based index of the stratum.
        stratum: usize,
        /// Zero-based position of the first non-finite value within it.
        index: usize,
    },
    /// Two paired samples (e.g. the two inputs of a correlation) differ in length.
    #[error("length mismatch: left has {left} values, right has {right}")]
    LengthMismatch {
        /// Length of the first argument.
        left: usize,
        /// Length of the second argument.
        right: usize,
    },
    /// A set of learning curves whose trials differ in length.
    #[error("ragged trials: trial {trial} has {got} episodes, trial 0 has {expected}")]
    RaggedTrials {
        /// Zero-based index of the first trial whose length differs.
        trial: usize,
        /// Length of trial 0.
        expected: usize,
        /// Length of the offending trial.
        got: usize,
    },
    /// The statistic divides by a variance that is zero (constant samples).
    #[error("zero variance: the statistic is undefined for constant samples")]
    ZeroVariance,
    /// An intermediate result exceeded the range of `f64` (inputs near ±1e308).
    #[error("overflow: an intermediate result exceeded the range of f64")]
    Overflow,
    /// A statistic supplied by the caller returned NaN or an infinity on a
    /// bootstrap resample.
    #[error("the bootstrap statistic returned a non-finite value on {}", describe_resample(*.resample))]
    NonFiniteStatistic {
        /// Zero-based index of the resample, `None` for the original sample.
        resample: Option<usize>,
    },
    /// A parameter is outside its domain; the message says which and why.
    #[error("invalid parameter: {0}")]
    InvalidParameter(&'static str),
}

fn describe_resample(resample: Option<usize>) -> String {
    match resample {
        Some(i) => format!("resample {i}"),
        None => "the original sample".to_owned(),
    }
}

/// Fails with [`StatsError::TooFewSamples`] if `x` has fewer than `needed` values.
pub(crate) fn check_len(input: &'static str, x: &[f64], needed: usize) -> Result<()> {
    if x.len() < needed {
        return Err(StatsError::TooFewSamples { input, needed, got: x.len() });
    }
    Ok(())
}

/// Fails with [`StatsError::NonFinite`] at the first NaN or infinity in `x`.
pub(crate) fn check_finite(input: &'static str, x: &[f64]) -> Result<()> {
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(StatsError::NonFinite { input, index }),
        None => Ok(()),
    }
}

/// Both checks at once: at least `needed` values, all finite.
pub(crate) fn check_sample(input: &'static str, x: &[f64], needed: usize) -> Result<()> {
    check_len(input, x, needed)?;
    check_finite(input, x)
}

/// Passes a finite value through and turns an infinity or NaN into [`StatsError::Overflow`].
pub(crate) fn finite(v: f64) -> Result<f64> {
    if v.is_finite() { Ok(v) } else { Err(StatsError::Overflow) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_report_the_first_problem() {
        assert_eq!(check_sample("x", &[1.0], 2), Err(StatsError::TooFewSamples { input: "x", needed: 2, got: 1 }));
        assert_eq!(
            check_sample("y", &[1.0, f64::NAN, f64::INFINITY], 2),
            Err(StatsError::NonFinite { input: "y", index: 1 })
        );
        assert_eq!(check_sample("x", &[1.0, 2.0], 2), Ok(()));
        assert_eq!(finite(f64::INFINITY), Err(StatsError::Overflow));
        assert_eq!(finite(-3.0), Ok(-3.0));
    }

    #[test]
    fn messages_name_the_input() {
        let e = StatsError::NonFinite { input: "curve", index: 4 };
        assert_eq!(e.to_string(), "non-finite value (NaN or infinite) in `curve` at index 4");
    }
}
