//! Runs one study of 31 participants (no result store) and prints each
//! participant's accuracy, interactions and satisfaction per algorithm: `cargo run --release -p ch4-dbug-study --example one_study [study]`.

use ch4_dbug_study::experiment::{StudyParams, roster_seed, run_participant};
use ch4_dbug_study::users::{Algorithm, Roster};
use rlfd_harness::{TrialKey, derive_seed};
use rlfd_rl::random::seeded;

fn main() {
    let study: u32 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(0);
    let params = StudyParams::paper();
    let roster = Roster::draw(&mut seeded(roster_seed(20160501, study)));
    println!("user expertise  | Int-RL acc int sat | BNets acc int sat | CBA acc int sat");
    for p in 0..31u32 {
        let key = TrialKey::new(ch4_dbug_study::CHAPTER, "study", &format!("study-{study:03}"), p);
        let r = run_participant(&params, &roster, study, p, derive_seed(20160501, &key));
        let cell = |a: Algorithm| {
            let s = r.session(a);
            format!("{:5.1} {:4} {}", s.accuracy.overall, s.interactions, s.satisfaction)
        };
        println!(
            "{p:4} {:8} | {} | {} | {}",
            r.traits.expertise.label(),
            cell(Algorithm::IntRl),
            cell(Algorithm::BNets),
            cell(Algorithm::Cba)
        );
    }
}
