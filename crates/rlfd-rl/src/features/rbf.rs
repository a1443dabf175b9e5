//! Gaussian radial basis features, one set per state variable.
//!
//! Each state variable `i` has centres `c_i0 < c_i1 < …` on a regular grid and
//! a width `σ_i`; feature `(i, k)` has value `exp(-(s_i - c_ik)² / (2 σ_i²))`.
//! Features are per variable (no conjunctions), as the tile coding of the
//! Keepaway benchmark is per variable. To keep the feature vector sparse, only
//! centres within `cutoff · σ_i` of the input are active (the neglected values
//! are below `exp(-cutoff²/2)`).

use super::{ActiveFeatures, FeatureMap};
use crate::params::{ParamError, check_finite, check_positive};

/// The grid of centres and the width for one state variable.
#[derive(Clone, Debug, PartialEq)]
pub struct RbfParams {
    /// First centre.
    pub first_centre: f64,
    /// Distance between neighbouring centres.
    pub spacing: f64,
    /// Number of centres.
    pub count: usize,
    /// Gaussian width σ.
    pub sigma: f64,
}

/// Per-variable Gaussian RBF features.
#[derive(Clone, Debug)]
pub struct RbfFeatures {
    vars: Vec<RbfParams>,
    offsets: Vec<usize>,
    cutoff: f64,
    total: usize,
    max_active: usize,
}

impl RbfFeatures {
    /// Features for each variable's grid; centres farther than `cutoff · σ` are inactive.
    pub fn new(vars: Vec<RbfParams>, cutoff: f64) -> Result<Self, ParamError> {
        check_positive("cutoff", cutoff)?;
        if vars.is_empty() {
            return Err(ParamError::new("vars", "[]", "at least one state variable"));
        }
        let mut offsets = Vec::with_capacity(vars.len());
        let mut total = 0;
        let mut max_active = 0;
        for v in &vars {
            check_finite("first_centre", v.first_centre)?;
            check_positive("spacing", v.spacing)?;
            check_positive("sigma", v.sigma)?;
            if v.count == 0 {
                return Err(ParamError::new("count", 0, "at least one centre per variable"));
            }
            offsets.push(total);
            total += v.count;
            let reach = (2.0 * cutoff * v.sigma / v.spacing).floor() as usize + 1;
            max_active += reach.min(v.count);
        }
        Ok(RbfFeatures { vars, offsets, cutoff, total, max_active })
    }
}

impl FeatureMap for RbfFeatures {
    fn num_features(&self) -> usize {
        self.total
    }

    fn max_active(&self) -> usize {
        self.max_active
    }

    fn features(&self, state: &[f64], out: &mut ActiveFeatures) {
        assert_eq!(
            state.len(),
            self.vars.len(),
            "rbf: state has {} variables, the features {}",
            state.len(),
            self.vars.len()
        );
        out.clear();
        for (i, (v, &x)) in self.vars.iter().zip(state).enumerate() {
            let reach = self.cutoff * v.sigma;
            let lo = (((x - reach) - v.first_centre) / v.spacing).ceil().max(0.0);
            let hi = (((x + reach) - v.first_centre) / v.spacing).floor().min((v.count - 1) as f64);
            if lo > hi {
                continue;
            }
            for k in lo as usize..=hi as usize {
                let d = x - (v.first_centre + k as f64 * v.spacing);
                out.indices.push((self.offsets[i] + k) as u32);
                out.values.push(libm::exp(-d * d / (2.0 * v.sigma * v.sigma)));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_gaussian_and_cut_off() {
        let f =
            RbfFeatures::new(vec![RbfParams { first_centre: 0.0, spacing: 1.0, count: 11, sigma: 0.5 }], 3.0).unwrap();
        let mut a = ActiveFeatures::default();
        f.features(&[2.25], &mut a);
        // Centres within 1.5 of 2.25: 1, 2, 3.
        assert_eq!(a.indices, vec![1, 2, 3]);
        let expect = |c: f64| libm::exp(-(2.25 - c) * (2.25 - c) / 0.5);
        for (k, c) in [1.0, 2.0, 3.0].into_iter().enumerate() {
            assert!((a.values[k] - expect(c)).abs() < 1e-15);
        }
        assert!(a.len() <= f.max_active());
    }

    #[test]
    fn variables_have_disjoint_blocks() {
        let p = RbfParams { first_centre: 0.0, spacing: 1.0, count: 5, sigma: 0.5 };
        let f = RbfFeatures::new(vec![p.clone(), p], 3.0).unwrap();
        let mut a = ActiveFeatures::default();
        f.features(&[0.0, 4.0], &mut a);
        assert_eq!(a.indices, vec![0, 1, 8, 9]);
        assert_eq!(f.num_features(), 10);
    }

    #[test]
    fn far_inputs_are_clipped_to_the_grid() {
        let f =
            RbfFeatures::new(vec![RbfParams { first_centre: 0.0, spacing: 1.0, count: 3, sigma: 0.5 }], 3.0).unwrap();
        let mut a = ActiveFeatures::default();
        f.features(&[100.0], &mut a);
        assert!(a.is_empty());
        f.features(&[-0.5], &mut a);
        assert_eq!(a.indices, vec![0, 1]);
    }

    #[test]
    fn bad_parameters_are_rejected() {
        let ok = RbfParams { first_centre: 0.0, spacing: 1.0, count: 3, sigma: 0.5 };
        assert!(RbfFeatures::new(vec![], 3.0).is_err());
        assert!(RbfFeatures::new(vec![ok.clone()], 0.0).is_err());
        assert!(RbfFeatures::new(vec![RbfParams { sigma: -1.0, ..ok.clone() }], 3.0).is_err());
        assert!(RbfFeatures::new(vec![RbfParams { count: 0, ..ok }], 3.0).is_err());
    }
}
