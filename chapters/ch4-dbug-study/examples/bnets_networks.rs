//! Prints study 0's final behaviour networks (nodes in order, links by
//! type) with each user's policy per zone:
//! `cargo run --release -p ch4-dbug-study --example bnets_networks`.

use ch4_dbug_study::experiment::{StudyParams, roster_seed, run_participant};
use ch4_dbug_study::session::Details;
use ch4_dbug_study::users::{Algorithm, Roster};
use rlfd_harness::{TrialKey, derive_seed};
use rlfd_rl::random::seeded;

fn main() {
    let params = StudyParams::paper();
    let roster = Roster::draw(&mut seeded(roster_seed(20160501, 0)));
    for p in 0..31u32 {
        let key = TrialKey::new(ch4_dbug_study::CHAPTER, "study", "study-000", p);
        let r = run_participant(&params, &roster, 0, p, derive_seed(20160501, &key));
        let s = r.session(Algorithm::BNets);
        if let Details::BNets { branches, erasures, both_arms, gave_up, .. } = &s.details {
            println!(
                "user {p} {} controlled={} acc={:.1} zones={:?} demos={} erasures={erasures} both={both_arms} gave_up={gave_up}",
                r.traits.expertise.label(),
                s.controlled,
                s.accuracy.overall,
                s.accuracy.per_zone,
                s.interactions
            );
            for b in branches {
                let nodes: Vec<String> =
                    b.nodes.iter().map(|n| format!("{}@{}-{}", n.behavior.abbreviation(), n.start, n.end)).collect();
                let links: Vec<String> = b
                    .links
                    .iter()
                    .filter(|l| l.kind != ch4_dbug_study::bnets::LinkKind::Ordering)
                    .map(|l| format!("{}->{}:{:?}", l.from, l.to, l.kind))
                    .collect();
                println!("   [{}]  {}", nodes.join(" "), links.join(" "));
            }
        }
    }
}
