//! The chapter's calibration, rerun by `cargo xtask calibrate cba-users`:
//! the CBA users' patience scale, fitted on an input count the thesis gives
//! ("three users violated assumption (1) by not providing enough training
//! data for the classifier to confidently make any predictions (minimum of
//! 3 demonstrations of each action)"): the scale at which a study of 31
//! has, on average, 3 users whose classifier never gets its minimum. It
//! counts demonstrations per action, never an accuracy or a correlation.
//!
//! The grid was chosen in two steps, both before any learner's accuracy
//! was looked at: a coarse one (0.1 to 2.0) put the count's crossing of 3
//! between 1.0 (5.9 users) and 1.5 (1.6), and [`GRID`] refines it there.
//!
//! The simulated studies draw their rosters and users from
//! [`CALIBRATION_SEED`], not from the master seed, so the fit does not
//! depend on (or reuse) the reproduction's own users.

use std::fmt::Write;

use rlfd_harness::{Calibration, TrialKey, derive_seed};
use rlfd_rl::random::seeded;

use crate::cba::CbaParams;
use crate::session::{Details, SessionParams, Teacher, cba};
use crate::users::population::PARTICIPANTS;
use crate::users::{Algorithm, Roster, UserModel};

/// Independent studies of 31 simulated per grid point.
pub const CALIBRATION_STUDIES: u32 = 30;
/// The seed of the calibration's studies (fixed before any run).
pub const CALIBRATION_SEED: u64 = 4_031;
/// The patience scales tried, in order.
pub const GRID: [f64; 10] = [0.5, 0.75, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.75, 2.0];
/// The thesis's count: users of 31 who left the classifier without its minimum.
pub const TARGET_PER_31: f64 = 3.0;

/// One grid point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridPoint {
    pub scale: f64,
    /// Users per 31 whose classifier never got 3 demonstrations of each action.
    pub too_little_per_31: f64,
    /// Users per 31 who stopped answering at some point.
    pub gave_up_per_31: f64,
}

/// Every chapter calibration.
pub fn all() -> Vec<Calibration> {
    vec![Calibration {
        model: "cba-users",
        what: "the CBA users' patience scale, fitted on the thesis's count of 3 of 31 users who gave too few demonstrations for the classifier (a count of demonstrations, not an outcome)",
        run: cba_users,
    }]
}

/// Simulates [`GRID`] and returns the scale closest to the target (the
/// first of equals) with every point.
pub fn fit(studies: u32) -> (f64, Vec<GridPoint>) {
    fit_on(studies, &GRID)
}

/// [`fit`] over the scales `grid`.
pub fn fit_on(studies: u32, grid: &[f64]) -> (f64, Vec<GridPoint>) {
    use rayon::prelude::*;
    let session = SessionParams::thesis();
    let cba_params = CbaParams::thesis();
    // One study at one scale is one task (its users' seeds are its own), so
    // the counts are the same sums at any number of threads.
    let study_counts = |scale: f64, s: u32| -> (u32, u32) {
        let mut model = UserModel::thesis();
        model.labelling.patience_scale = scale;
        let (mut too_little, mut gave_up) = (0u32, 0u32);
        let roster = Roster::draw(&mut seeded(derive_seed(
            CALIBRATION_SEED,
            &TrialKey::new(crate::CHAPTER, "calibration", "roster", s),
        )));
        for p in 0..PARTICIPANTS {
            let seed = derive_seed(
                CALIBRATION_SEED,
                &TrialKey::new(crate::CHAPTER, "calibration", "user", s * 100 + p as u32),
            );
            let mut rng = seeded(seed);
            let traits = model.traits.draw(roster.expertise[p], &mut rng);
            let position = roster.orders[p].iter().position(|&a| a == Algorithm::Cba).expect("CBA in every order");
            let teacher = Teacher { traits, session: position, ideal: false };
            let rec = cba::run(&teacher, &model, &session, &cba_params, &mut rng);
            if let Details::Cba { classifier, gave_up: g, .. } = &rec.details {
                too_little += u32::from(classifier.is_none());
                gave_up += u32::from(*g);
            }
        }
        (too_little, gave_up)
    };
    let counts: Vec<(u32, u32)> = grid
        .par_iter()
        .flat_map_iter(|&scale| (0..studies).map(move |s| (scale, s)))
        .map(|(scale, s)| study_counts(scale, s))
        .collect();
    let per_31 = |n: u32| f64::from(n) / f64::from(studies);
    let points: Vec<GridPoint> = grid
        .iter()
        .zip(counts.chunks(studies as usize))
        .map(|(&scale, c)| {
            let (too_little, gave_up) = c.iter().fold((0, 0), |(a, b), &(x, y)| (a + x, b + y));
            GridPoint { scale, too_little_per_31: per_31(too_little), gave_up_per_31: per_31(gave_up) }
        })
        .collect();
    let best = points
        .iter()
        .min_by(|a, b| {
            (a.too_little_per_31 - TARGET_PER_31).abs().total_cmp(&(b.too_little_per_31 - TARGET_PER_31).abs())
        })
        .expect("a grid")
        .scale;
    (best, points)
}

fn cba_users() -> String {
    let (best, points) = fit(CALIBRATION_STUDIES);
    let mut out = String::from("patience scale  too little data (per 31)  gave up (per 31)\n");
    for p in points {
        let _ = writeln!(out, "{:<15} {:<24.2} {:.2}", p.scale, p.too_little_per_31, p.gave_up_per_31);
    }
    let _ = writeln!(
        out,
        "calibrated (closest to {TARGET_PER_31} of 31 over {CALIBRATION_STUDIES} studies): patience scale {best}; shipped: {}",
        crate::users::labelling::PATIENCE_SCALE
    );
    out
}
