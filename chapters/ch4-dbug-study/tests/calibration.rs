//! The shipped CBA patience scale is the calibration's choice: among it and
//! its neighbours on the grid, it gives the count of users without the
//! classifier's minimum closest to the thesis's 3 of 31 (the whole grid is
//! `cargo xtask calibrate cba-users`).

use ch4_dbug_study::calibrations::{CALIBRATION_STUDIES, GRID, TARGET_PER_31, fit_on};
use ch4_dbug_study::users::labelling::PATIENCE_SCALE;

#[test]
fn the_shipped_patience_scale_is_the_closest_to_three_of_31() {
    let k = GRID.iter().position(|&g| g == PATIENCE_SCALE).expect("the shipped scale is a grid point");
    let around = &GRID[k.saturating_sub(1)..(k + 2).min(GRID.len())];
    let (best, points) = fit_on(CALIBRATION_STUDIES, around);
    assert_eq!(best, PATIENCE_SCALE, "{points:?}");
    let at = points.iter().find(|p| p.scale == PATIENCE_SCALE).expect("evaluated");
    assert!((at.too_little_per_31 - TARGET_PER_31).abs() < 0.5, "{at:?}");
    // The count falls as patience grows.
    assert!(points.windows(2).all(|w| w[0].too_little_per_31 >= w[1].too_little_per_31), "{points:?}");
}
