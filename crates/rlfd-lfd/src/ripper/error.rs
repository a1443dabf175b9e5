//! The one error type of the RIPPER module, [`RipperError`]: what is wrong
//! with a data set built in memory, with a parameter set, or with a
//! cross-validation request.
//!
//! It is not a learning failure: once the data and the parameters are valid,
//! fitting always succeeds (the learner has no "should never happen" exits;
//! see the module docs for where Weka's JRip would throw and we do not).
//!
//! Every `Display` is one sentence on one line without a trailing period,
//! ready to be printed after "error: " or a caller's "RIPPER: " (so it does
//! not name RIPPER itself). It holds no `source`: the whole story is in the
//! one line. Names that came from the user are printed quoted and escaped
//! (`{:?}`) so that a stray newline cannot break the line.
//!
//! Source: the checks Weka makes before JRip runs (JRip.java, Weka commit
//! 0b4f0571: `getCapabilities`, at least `folds` instances; `Instances.stratify`
//! and `trainCV`: at least 2 folds, no more folds than instances).

use thiserror::Error;

/// Why a [`Dataset`](super::Dataset), a [`RipperParams`](super::RipperParams)
/// or a cross-validation request was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RipperError {
    /// A data set holds at least one instance.
    #[error("the data set has no instances")]
    EmptyData,
    /// The class attribute needs at least one value.
    #[error("the class attribute has no values")]
    NoClasses,
    /// A nominal attribute needs at least one value.
    #[error("nominal attribute {attribute:?} has no values")]
    EmptyNominal {
        /// The attribute's name.
        attribute: String,
    },
    /// Every row holds one value per attribute.
    #[error("row {row} has {found} values but there are {expected} attributes")]
    RowLength {
        /// The row's index (0-based).
        row: usize,
        /// The number of attributes.
        expected: usize,
        /// The row's length.
        found: usize,
    },
    /// One label per row.
    #[error("{labels} class labels were given for {rows} rows")]
    LabelCount {
        /// The number of rows.
        rows: usize,
        /// The number of labels.
        labels: usize,
    },
    /// A label indexes the class names.
    #[error("row {row}: class label {label} is out of range ({classes} classes)")]
    LabelOutOfRange {
        /// The row's index (0-based).
        row: usize,
        /// The label found.
        label: usize,
        /// The number of class names.
        classes: usize,
    },
    /// Numeric values are finite; a missing value is written as NaN.
    #[error("row {row}, attribute {attribute:?}: {value} is not finite (write a missing value as NaN)")]
    NonFinite {
        /// The row's index (0-based).
        row: usize,
        /// The attribute's name.
        attribute: String,
        /// The value found.
        value: f64,
    },
    /// Nominal values are indices into the attribute's values, or NaN.
    #[error("row {row}, attribute {attribute:?}: {value} is not the index of one of its {count} values")]
    BadNominal {
        /// The row's index (0-based).
        row: usize,
        /// The attribute's name.
        attribute: String,
        /// The value found.
        value: f64,
        /// The number of values the attribute declares.
        count: usize,
    },
    /// One weight per row.
    #[error("{weights} weights were given for {rows} rows")]
    WeightCount {
        /// The number of rows.
        rows: usize,
        /// The number of weights.
        weights: usize,
    },
    /// Weights are finite and strictly positive.
    #[error("row {row}: weight {weight} is not finite and positive")]
    BadWeight {
        /// The row's index (0-based).
        row: usize,
        /// The weight found.
        weight: f64,
    },
    /// A parameter outside its domain.
    #[error("parameter {name}: {reason}")]
    InvalidParameter {
        /// The parameter's field name in [`RipperParams`](super::RipperParams).
        name: &'static str,
        /// What the value must be.
        reason: String,
    },
    /// JRip declares `folds` as its minimum number of training instances.
    #[error("the data set has {}, but at least {required} are needed (one per grow/prune fold)", count_instances(.provided))]
    TooFewInstances {
        /// The minimum (the number of grow/prune folds).
        required: usize,
        /// The number of instances given.
        provided: usize,
    },
    /// Every training part of a cross-validation needs the minimum of
    /// [`Self::TooFewInstances`].
    #[error(
        "{folds}-fold cross-validation of {} trains on as few as {training}, but at least {required} are needed (one per grow/prune fold)",
        count_instances(.instances)
    )]
    TrainingPartTooSmall {
        /// The number of cross-validation folds.
        folds: usize,
        /// The number of instances cross-validated.
        instances: usize,
        /// The number of instances in the smallest training part.
        training: usize,
        /// The minimum (the number of grow/prune folds).
        required: usize,
    },
    /// Cross-validation needs 2 ≤ folds ≤ instances.
    #[error("cross-validation needs between 2 and {instances} folds, got {folds}")]
    CrossValidationFolds {
        /// The number of folds asked for.
        folds: usize,
        /// The number of instances.
        instances: usize,
    },
}

/// "1 instance", "2 instances".
fn count_instances(n: &usize) -> String {
    if *n == 1 { "1 instance".to_string() } else { format!("{n} instances") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn too_few_instances_is_one_sentence() {
        let error = RipperError::TooFewInstances { required: 3, provided: 1 };
        assert_eq!(
            error.to_string(),
            "the data set has 1 instance, but at least 3 are needed (one per grow/prune fold)"
        );
        assert!(std::error::Error::source(&error).is_none());
        let error = RipperError::TrainingPartTooSmall { folds: 4, instances: 4, training: 3, required: 4 };
        assert_eq!(
            error.to_string(),
            "4-fold cross-validation of 4 instances trains on as few as 3, but at least 4 are needed \
             (one per grow/prune fold)"
        );
    }
}
