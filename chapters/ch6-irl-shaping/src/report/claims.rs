//! Claim C6.11, which belongs to neither half: potential-based shaping
//! keeps the optimal policy, checked on random MDPs; and the trial floor
//! both halves' claims share.

use rlfd_report::claims::{Claim, TestFloor, Verdict};
use rlfd_rl::mdp::check_potential_shaping;
use rlfd_rl::random::seeded;

/// Trials below which a significance test is not taken as evidence: 10, as
/// the thesis tested ([`TestFloor::ThesisTested`]); shared by both halves.
pub(crate) const MIN_TRIALS_FOR_TESTS: usize = TestFloor::ThesisTested.trials();

/// Claim C6.11 from the shaping theorem checked on random MDPs (the same
/// check the property tests of `rlfd-rl` run, here on a fixed sample).
pub fn shaping_invariance_claim(mdps: usize) -> rlfd_report::Result<Claim> {
    let report = check_potential_shaping(&mut seeded(0x6e67_3939), mdps);
    let holds = report.greedy_mismatches == 0 && report.max_shift_error < 1e-9;
    let evidence = format!(
        "Value iteration on {} random MDPs (half with cycles and γ < 1, half episodic with γ = 1), with and without potential-based shaping (Φ = 0 on terminal states): greedy action sets differ in {} of {} states; largest |Q′ − (Q* − Φ)| = {:.1e}. The property tests of `rlfd-rl` check the same on fresh MDPs at every test run, plus the look-ahead form, Φ ≡ 0 and a non-zero terminal potential that does change the policy.",
        report.mdps, report.greedy_mismatches, report.states_compared, report.max_shift_error
    );
    let (verdict, reason) = if holds {
        (
            Verdict::Reproduced,
            "Potential-based shaping left every optimal policy unchanged and shifted every value by exactly −Φ.",
        )
    } else {
        (Verdict::NotReproduced, "Shaping changed an optimal policy or the value shift.")
    };
    Claim::from_spec(
        "C6.11",
        "Cited from Ng et al. (1999), Wiewiora et al. (2003) and Devlin & Kudenko (2012); not tested in the thesis.",
        evidence,
        verdict,
        reason,
    )
}
