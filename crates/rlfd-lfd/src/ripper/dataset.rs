//! The learner's input: a checked table of instances, the counterpart of a
//! Weka `Instances` object with a nominal class.
//!
//! What it is: attributes (numeric or nominal), one `f64` row per instance
//! (a nominal value is the index of the value, NaN is missing), one class
//! label per instance (an index into the class names) and one weight per
//! instance (1 unless given). Construction checks every shape and value, so
//! the learner never meets a malformed table.
//!
//! What it is not: a file reader. Demonstration files are parsed elsewhere
//! (`crate::demonstration`) and turned into a `Dataset` by their caller.
//!
//! Source: what JRip accepts (`getCapabilities` in JRip.java, Weka commit
//! 0b4f0571: numeric and nominal attributes, missing values, a nominal
//! class; weighted instances), with NaN as Weka's missing value.

use serde::{Deserialize, Serialize};

use super::RipperError;

/// The type of an attribute.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub enum AttributeKind {
    /// Real values; rules test them with `<=` and `>=`.
    Numeric,
    /// A finite set of named values; a row stores the value's index, and
    /// rules test them with `=`.
    Nominal {
        /// The values' names, in index order.
        values: Vec<String>,
    },
}

/// One input variable.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Attribute {
    /// The name printed in rules (the thesis writes `state_11`).
    pub name: String,
    /// Numeric or nominal.
    pub kind: AttributeKind,
}

impl Attribute {
    /// A numeric attribute.
    pub fn numeric(name: impl Into<String>) -> Self {
        Self { name: name.into(), kind: AttributeKind::Numeric }
    }

    /// A nominal attribute with the given value names.
    pub fn nominal(name: impl Into<String>, values: Vec<String>) -> Self {
        Self { name: name.into(), kind: AttributeKind::Nominal { values } }
    }
}

/// Checked instances with a nominal class: see the module docs.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    attributes: Vec<Attribute>,
    /// Row-major, `attributes.len()` values per instance.
    values: Vec<f64>,
    class_attribute: String,
    class_names: Vec<String>,
    labels: Vec<usize>,
    weights: Vec<f64>,
}

impl Dataset {
    /// Checks and stores the instances, each with weight 1.
    ///
    /// `class_attribute` names the class variable (the thesis prints
    /// `Action`); `labels[i]` indexes `class_names` and is the class of
    /// `rows[i]`. Numeric values must be finite or NaN (missing); nominal
    /// values must be the index of a declared value, or NaN.
    pub fn new(
        attributes: Vec<Attribute>,
        rows: Vec<Vec<f64>>,
        class_attribute: impl Into<String>,
        class_names: Vec<String>,
        labels: Vec<usize>,
    ) -> Result<Self, RipperError> {
        if rows.is_empty() {
            return Err(RipperError::EmptyData);
        }
        if class_names.is_empty() {
            return Err(RipperError::NoClasses);
        }
        if labels.len() != rows.len() {
            return Err(RipperError::LabelCount { rows: rows.len(), labels: labels.len() });
        }
        for attribute in &attributes {
            if let AttributeKind::Nominal { values } = &attribute.kind
                && values.is_empty()
            {
                return Err(RipperError::EmptyNominal { attribute: attribute.name.clone() });
            }
        }
        let width = attributes.len();
        let mut values = Vec::with_capacity(rows.len() * width);
        for (row, (x, &label)) in rows.iter().zip(&labels).enumerate() {
            if x.len() != width {
                return Err(RipperError::RowLength { row, expected: width, found: x.len() });
            }
            if label >= class_names.len() {
                return Err(RipperError::LabelOutOfRange { row, label, classes: class_names.len() });
            }
            for (attribute, &value) in attributes.iter().zip(x) {
                check_value(row, attribute, value)?;
            }
            values.extend_from_slice(x);
        }
        let weights = vec![1.0; rows.len()];
        Ok(Self { attributes, values, class_attribute: class_attribute.into(), class_names, labels, weights })
    }

    /// Replaces the unit weights with the given ones (finite, > 0), for
    /// data that Weka would carry as weighted instances.
    pub fn with_weights(mut self, weights: Vec<f64>) -> Result<Self, RipperError> {
        if weights.len() != self.labels.len() {
            return Err(RipperError::WeightCount { rows: self.labels.len(), weights: weights.len() });
        }
        if let Some((row, &weight)) = weights.iter().enumerate().find(|&(_, &w)| !(w.is_finite() && w > 0.0)) {
            return Err(RipperError::BadWeight { row, weight });
        }
        self.weights = weights;
        Ok(self)
    }

    /// The attributes, in column order.
    pub fn attributes(&self) -> &[Attribute] {
        &self.attributes
    }

    /// The class variable's name.
    pub fn class_attribute(&self) -> &str {
        &self.class_attribute
    }

    /// The class values' names; labels index this list.
    pub fn class_names(&self) -> &[String] {
        &self.class_names
    }

    /// The number of instances (never 0).
    pub fn len(&self) -> usize {
        self.labels.len()
    }

    /// Always false: construction refuses empty data. Present for the
    /// `len`/`is_empty` pair.
    pub fn is_empty(&self) -> bool {
        self.labels.is_empty()
    }

    /// The attribute values of instance `i`.
    ///
    /// # Panics
    /// If `i >= self.len()`.
    pub fn row(&self, i: usize) -> &[f64] {
        let width = self.attributes.len();
        &self.values[i * width..(i + 1) * width]
    }

    /// The class labels, one per instance.
    pub fn labels(&self) -> &[usize] {
        &self.labels
    }

    /// The instance weights, one per instance.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The total weight of each class, indexed like [`Self::class_names`].
    pub fn class_weights(&self) -> Vec<f64> {
        let mut totals = vec![0.0; self.class_names.len()];
        for (&label, &weight) in self.labels.iter().zip(&self.weights) {
            totals[label] += weight;
        }
        totals
    }

    /// The instances at `indices`, in that order, with the same header.
    /// The caller guarantees the indices are in range and not empty.
    pub(crate) fn select(&self, indices: &[usize]) -> Self {
        let width = self.attributes.len();
        let mut values = Vec::with_capacity(indices.len() * width);
        for &i in indices {
            values.extend_from_slice(self.row(i));
        }
        Self {
            attributes: self.attributes.clone(),
            values,
            class_attribute: self.class_attribute.clone(),
            class_names: self.class_names.clone(),
            labels: indices.iter().map(|&i| self.labels[i]).collect(),
            weights: indices.iter().map(|&i| self.weights[i]).collect(),
        }
    }
}

fn check_value(row: usize, attribute: &Attribute, value: f64) -> Result<(), RipperError> {
    if value.is_nan() {
        return Ok(());
    }
    match &attribute.kind {
        AttributeKind::Numeric if !value.is_finite() => {
            Err(RipperError::NonFinite { row, attribute: attribute.name.clone(), value })
        }
        AttributeKind::Numeric => Ok(()),
        AttributeKind::Nominal { values } => {
            let is_index = value >= 0.0 && value.fract() == 0.0 && value < values.len() as f64;
            if is_index {
                Ok(())
            } else {
                Err(RipperError::BadNominal { row, attribute: attribute.name.clone(), value, count: values.len() })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(n: usize) -> Vec<String> {
        (0..n).map(|i| i.to_string()).collect()
    }

    fn one_numeric(rows: Vec<Vec<f64>>, labels: Vec<usize>) -> Result<Dataset, RipperError> {
        Dataset::new(vec![Attribute::numeric("x")], rows, "c", names(2), labels)
    }

    #[test]
    fn accepts_missing_values_and_stores_rows() {
        let data = one_numeric(vec![vec![1.5], vec![f64::NAN]], vec![0, 1]).unwrap();
        assert_eq!(data.len(), 2);
        assert_eq!(data.row(0), &[1.5]);
        assert!(data.row(1)[0].is_nan());
        assert_eq!(data.weights(), &[1.0, 1.0]);
        assert_eq!(data.class_weights(), vec![1.0, 1.0]);
    }

    #[test]
    fn refuses_empty_data_and_empty_classes() {
        assert_eq!(one_numeric(vec![], vec![]), Err(RipperError::EmptyData));
        let no_classes = Dataset::new(vec![], vec![vec![]], "c", vec![], vec![0]);
        assert_eq!(no_classes, Err(RipperError::NoClasses));
    }

    #[test]
    fn refuses_bad_shapes() {
        assert_eq!(
            one_numeric(vec![vec![1.0], vec![1.0, 2.0]], vec![0, 1]),
            Err(RipperError::RowLength { row: 1, expected: 1, found: 2 })
        );
        assert_eq!(one_numeric(vec![vec![1.0]], vec![0, 1]), Err(RipperError::LabelCount { rows: 1, labels: 2 }));
        assert_eq!(
            one_numeric(vec![vec![1.0]], vec![2]),
            Err(RipperError::LabelOutOfRange { row: 0, label: 2, classes: 2 })
        );
    }

    #[test]
    fn refuses_infinite_numeric_values() {
        let err = one_numeric(vec![vec![0.0], vec![f64::INFINITY]], vec![0, 1]).unwrap_err();
        assert!(matches!(err, RipperError::NonFinite { row: 1, .. }));
        assert_eq!(err.to_string(), "row 1, attribute \"x\": inf is not finite (write a missing value as NaN)");
    }

    #[test]
    fn refuses_nominal_values_that_are_not_indices() {
        let attrs = || vec![Attribute::nominal("colour", names(3))];
        for bad in [3.0, -1.0, 0.5, f64::INFINITY] {
            let err = Dataset::new(attrs(), vec![vec![bad]], "c", names(2), vec![0]).unwrap_err();
            assert!(matches!(err, RipperError::BadNominal { count: 3, .. }), "{bad}");
        }
        assert!(Dataset::new(attrs(), vec![vec![2.0]], "c", names(2), vec![0]).is_ok());
        let empty = Dataset::new(vec![Attribute::nominal("e", vec![])], vec![vec![f64::NAN]], "c", names(2), vec![0]);
        assert!(matches!(empty, Err(RipperError::EmptyNominal { .. })));
    }

    #[test]
    fn checks_weights() {
        let data = || one_numeric(vec![vec![0.0], vec![1.0]], vec![0, 1]).unwrap();
        assert_eq!(data().with_weights(vec![1.0]), Err(RipperError::WeightCount { rows: 2, weights: 1 }));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let err = data().with_weights(vec![1.0, bad]).unwrap_err();
            assert!(matches!(err, RipperError::BadWeight { row: 1, .. }), "{bad}");
        }
        let weighted = data().with_weights(vec![0.5, 2.0]).unwrap();
        assert_eq!(weighted.class_weights(), vec![0.5, 2.0]);
    }

    #[test]
    fn select_keeps_the_header_and_the_order() {
        let data = one_numeric(vec![vec![0.0], vec![1.0], vec![2.0]], vec![0, 1, 0]).unwrap();
        let picked = data.select(&[2, 0]);
        assert_eq!(picked.len(), 2);
        assert_eq!(picked.row(0), &[2.0]);
        assert_eq!(picked.labels(), &[0, 0]);
        assert_eq!(picked.class_names(), data.class_names());
    }
}
