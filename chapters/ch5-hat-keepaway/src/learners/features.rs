//! The keepers' function approximation: Gaussian radial basis features, one
//! set of one-dimensional bumps per state variable (no conjunctions).
//!
//! The thesis uses "Gaussian RBF function approximation, as in \[92\]" (Stone,
//! Kuhlmann, Taylor & Liu 2006) without giving the centres or widths; no
//! public source for them was found. This is a documented reconstruction
//! (`domains.md` 1.7 and 6.1): variable `i`'s centres lie on the benchmark's
//! tile-width grid `0, wᵢ, 2wᵢ, …` over its range `[0, rangeᵢ]` (the widths
//! and ranges of `keeperStateRangesAndResolutions`), and each bump has
//! `σᵢ = wᵢ / 2`, so neighbouring bumps cross at `exp(−1/2)` and a state
//! activates about three per variable (those within `3σ`; the rest are below
//! `exp(−4.5) ≈ 0.011` and left out, as the shared [`RbfFeatures`] does).

use rlfd_rl::features::{FeatureMap, RbfFeatures, RbfParams};
use serde::{Deserialize, Serialize};

use crate::keepaway::state::{RANGES, STATE_VARS, TILE_WIDTHS};

/// The RBF layout's free choices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RbfLayout {
    /// σ as a fraction of the variable's tile width.
    pub sigma_per_width: f64,
    /// Centres farther than `cutoff · σ` from the input are inactive.
    pub cutoff: f64,
}

impl RbfLayout {
    /// σ = half a tile width, bumps cut at 3σ (the reconstruction above).
    pub fn reconstruction() -> Self {
        RbfLayout { sigma_per_width: 0.5, cutoff: 3.0 }
    }

    /// The feature map over the 13 state variables.
    pub fn features(&self) -> RbfFeatures {
        let vars = (0..STATE_VARS)
            .map(|i| {
                let w = TILE_WIDTHS[i];
                RbfParams {
                    first_centre: 0.0,
                    spacing: w,
                    count: (RANGES[i] / w).ceil() as usize + 1,
                    sigma: self.sigma_per_width * w,
                }
            })
            .collect();
        RbfFeatures::new(vars, self.cutoff).expect("the RBF layout is valid")
    }
}

/// Number of features of the reconstruction (per action).
pub fn num_features(layout: &RbfLayout) -> usize {
    layout.features().num_features()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::features::ActiveFeatures;

    #[test]
    fn about_three_bumps_per_variable_cover_the_ranges() {
        let layout = RbfLayout::reconstruction();
        let f = layout.features();
        // 10 + 19 + 13 + 19 + 13 + 10 + 7 + 7 + 7 + 6 + 6 + 19 + 19 centres.
        assert_eq!(f.num_features(), 155);
        let mut a = ActiveFeatures::default();
        let state = [7.3, 5.0, 11.2, 3.1, 6.6, 8.0, 9.9, 4.4, 7.7, 2.0, 5.5, 33.0, 71.0];
        f.features(&state, &mut a);
        assert!(a.len() >= 3 * STATE_VARS && a.len() <= 4 * STATE_VARS, "{}", a.len());
        // Each variable's bumps sum to about √(2π) σ / w = 1.25.
        let total: f64 = a.values.iter().sum();
        assert!((total / STATE_VARS as f64 - 1.2533).abs() < 0.05, "{total}");
        assert!(a.values.iter().all(|&v| v > 0.01 && v <= 1.0));
    }
}
