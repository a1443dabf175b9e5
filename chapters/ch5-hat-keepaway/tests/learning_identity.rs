//! Bit-identity of the keepers learning: short seeded trials of Sarsa(λ)
//! with No Prior and with PPR on Subject A's rules (the chapter's bench
//! workloads), with a jumpstart and a greedy evaluation, digested bit for
//! bit (every training episode's duration, the evaluations' means). The
//! digests were recorded on the simulator of commit 810b689 (before the
//! issue 30 speed-up) and re-recorded with learning behaviour version 5
//! (issue 28's collision sensing and see phases) and 6 (the far sees' ball
//! velocity left out): a change that alters them
//! alters results and needs a behaviour-version bump, not new digests alone.

use ch5_hat_keepaway::inputs::{DemoSetId, prepare};
use ch5_hat_keepaway::learners::{LearnerParams, Method, TrialParams, run_learning_trial};
use ch5_hat_keepaway::teachers::FrequentPasser;

fn digest(words: impl IntoIterator<Item = u64>) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    for w in words {
        for b in w.to_le_bytes() {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    h
}

#[test]
fn learning_trials_are_bit_identical_to_the_recorded_ones() {
    let rules =
        prepare(rlfd_harness::THESIS_MASTER_SEED, FrequentPasser::B).expect("inputs").get(DemoSetId::A20).rules.clone();
    let mut got = Vec::new();
    for method in [Method::NoPrior, Method::POLICY_REUSE] {
        let params = TrialParams {
            hours: 0.2,
            eval_episodes: 20,
            greedy_episodes: 10,
            learner: LearnerParams::thesis(),
            method,
        };
        let r = method.uses_rules().then_some(&rules);
        let t = run_learning_trial(&params, r, 17).expect("valid parameters");
        let words = t
            .durations
            .iter()
            .map(|&d| u64::from(d))
            .chain([t.jumpstart_cycles.to_bits(), t.jumpstart_episodes as u64])
            .chain(t.greedy_cycles.iter().map(|g| g.to_bits()));
        got.push(digest(words));
    }
    println!("{got:#018x?}");
    assert_eq!(got, [0x3691_d11b_bf0d_e500, 0x8b50_35d2_7158_4021], "learning trials differ from the recorded ones");
}
