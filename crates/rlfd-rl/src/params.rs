//! Parameters of the TD learners, checked once before anything runs.

use thiserror::Error;

/// A parameter outside its domain. The message names the parameter and the value.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("parameter `{name}` = {value} is invalid: {expected}")]
pub struct ParamError {
    /// The parameter's name as written in the struct.
    pub name: &'static str,
    /// The offending value, formatted.
    pub value: String,
    /// What it should be.
    pub expected: &'static str,
}

impl ParamError {
    pub(crate) fn new(name: &'static str, value: impl ToString, expected: &'static str) -> Self {
        ParamError { name, value: value.to_string(), expected }
    }
}

/// Step sizes and discounting of a TD(λ) control learner.
///
/// `alpha` is the step size applied to each active feature's weight, i.e. the
/// thesis's `α / #tiles` already divided: the Maze's `0.25/32` is written
/// `alpha: 0.25 / 32.0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TdParams {
    /// Step size per active feature (for binary features; scaled by the feature value otherwise).
    pub alpha: f64,
    /// Discount factor γ in `[0, 1]`.
    pub gamma: f64,
    /// Trace decay λ in `[0, 1]`.
    pub lambda: f64,
    /// Exploration rate of the ε-greedy behaviour policy, in `[0, 1]`.
    pub epsilon: f64,
}

impl TdParams {
    /// Checks every field; the learners take only checked parameters.
    pub fn check(&self) -> Result<Self, ParamError> {
        check_unit("gamma", self.gamma)?;
        check_unit("lambda", self.lambda)?;
        check_unit("epsilon", self.epsilon)?;
        check_positive("alpha", self.alpha)?;
        Ok(*self)
    }
}

pub(crate) fn check_unit(name: &'static str, v: f64) -> Result<(), ParamError> {
    if (0.0..=1.0).contains(&v) { Ok(()) } else { Err(ParamError::new(name, v, "a number in [0, 1]")) }
}

pub(crate) fn check_positive(name: &'static str, v: f64) -> Result<(), ParamError> {
    if v.is_finite() && v > 0.0 { Ok(()) } else { Err(ParamError::new(name, v, "a finite number > 0")) }
}

pub(crate) fn check_finite(name: &'static str, v: f64) -> Result<(), ParamError> {
    if v.is_finite() { Ok(()) } else { Err(ParamError::new(name, v, "a finite number")) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_names_the_bad_field() {
        let p = TdParams { alpha: 0.1, gamma: 1.5, lambda: 0.5, epsilon: 0.1 };
        let e = p.check().unwrap_err();
        assert_eq!(e.to_string(), "parameter `gamma` = 1.5 is invalid: a number in [0, 1]");
        let p = TdParams { alpha: f64::NAN, gamma: 1.0, lambda: 0.5, epsilon: 0.1 };
        assert_eq!(p.check().unwrap_err().name, "alpha");
        let ok = TdParams { alpha: 0.25 / 32.0, gamma: 1.0, lambda: 0.25, epsilon: 0.02 };
        assert_eq!(ok.check(), Ok(ok));
    }
}
