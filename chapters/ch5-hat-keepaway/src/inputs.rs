//! What the learners take from the teachers (sections 5.2 and 5.4): the
//! demonstration sets and their rule summaries.
//!
//! 1. Each teacher model records 20 episodes ([`DEMO_EPISODES`]) from a seed
//!    derived from the master seed.
//! 2. The thesis's derived sets: "Subject A (10)", ten of A's episodes drawn
//!    at random (its own seed); "Subjects A + C Best/Worst", the ten longest
//!    or shortest episodes of A and of C together.
//! 3. RIPPER as Weka 3.6's JRip runs it (`-F 3 -N 2.0 -O 2 -S 1`, drawing
//!    from a `java.util.Random` seeded as JRip seeds it:
//!    [`RipperParams::weka_3_6`]) summarises each set's (13 state variables →
//!    action) pairs as a decision list over `state_0 … state_12` with classes
//!    0 (Hold), 1 (Pass1) and 2 (Pass2); Weka's stratified 10-fold
//!    cross-validation (`-x 10 -s 1`) measures how well the list predicts the
//!    teacher. These are the rules and accuracies Weka prints for the same data.
//!
//! [`thesis_a_rules`] is the decision list the thesis prints for its Subject A
//! (the `a-rules=thesis` reading, the default).

use rlfd_harness::{TrialKey, derive_seed};
use rlfd_lfd::ripper::{
    Attribute, CrossValidation, Dataset, DecisionList, Ripper, RipperError, RipperParams, stratified_cross_validation,
};
use rlfd_rl::random::seeded;
use serde::{Deserialize, Serialize};

use crate::CHAPTER;
use crate::keepaway::state::STATE_NAMES;
use crate::teachers::{DemonstrationSet, FrequentPasser, Teacher, record};

/// Episodes each teacher records (thesis: 20).
pub const DEMO_EPISODES: usize = 20;

/// Episodes of A's half set (thesis: 10).
pub const HALF_EPISODES: usize = 10;

/// Episodes of each teacher in the A + C sets (thesis: 10).
pub const EXTREME_EPISODES: usize = 10;

/// The experiment name under which the demonstrations' seeds are derived.
pub const DEMONSTRATION_EXPERIMENT: &str = "keepaway-demonstrations";

/// The thesis's demonstration sets (Tables 5.1–5.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum DemoSetId {
    /// Subject A's 20 episodes.
    A20,
    /// Ten of A's episodes at random.
    A10,
    /// Subject B's 20 episodes.
    B,
    /// Subject C's 20 episodes.
    C,
    /// The ten longest of A and of C.
    AcBest,
    /// The ten shortest of A and of C.
    AcWorst,
    /// Subject B at five times real time.
    BFast,
    /// Subject B with Hold and Pass1 only.
    BLimited,
}

impl DemoSetId {
    /// Every set, in the report's order.
    pub const ALL: [DemoSetId; 8] = [
        DemoSetId::A20,
        DemoSetId::A10,
        DemoSetId::B,
        DemoSetId::C,
        DemoSetId::AcBest,
        DemoSetId::AcWorst,
        DemoSetId::BFast,
        DemoSetId::BLimited,
    ];

    /// The name in result paths.
    pub fn slug(self) -> &'static str {
        match self {
            DemoSetId::A20 => "subject-a",
            DemoSetId::A10 => "half-subject-a",
            DemoSetId::B => "subject-b",
            DemoSetId::C => "subject-c",
            DemoSetId::AcBest => "subjects-a-c-best",
            DemoSetId::AcWorst => "subjects-a-c-worst",
            DemoSetId::BFast => "subject-b-fast",
            DemoSetId::BLimited => "subject-b-limited",
        }
    }

    /// Whether the set holds Subject B's or C's episodes, whose styles the
    /// `bc-styles` reading assigns (A (20) and A (10) hold A's alone).
    pub fn depends_on_bc_styles(self) -> bool {
        !matches!(self, DemoSetId::A20 | DemoSetId::A10)
    }

    /// The thesis's name.
    pub fn label(self) -> &'static str {
        match self {
            DemoSetId::A20 => "Subject A (20)",
            DemoSetId::A10 => "Subject A (10)",
            DemoSetId::B => "Subject B",
            DemoSetId::C => "Subject C (20)",
            DemoSetId::AcBest => "Subjects A + C Best",
            DemoSetId::AcWorst => "Subjects A + C Worst",
            DemoSetId::BFast => "Fast Demonstration",
            DemoSetId::BLimited => "Limited Actions",
        }
    }
}

/// One demonstration set with its rules.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DemoSetInputs {
    /// Which set.
    pub id: DemoSetId,
    /// The episodes.
    pub set: DemonstrationSet,
    /// RIPPER's decision list.
    pub rules: DecisionList,
    /// Its stratified 10-fold cross-validation.
    pub cv: CrossValidation,
}

/// Every set, in [`DemoSetId::ALL`] order.
#[derive(Clone, Debug, PartialEq)]
pub struct DemoInputs {
    /// The sets.
    pub sets: Vec<DemoSetInputs>,
}

impl DemoInputs {
    /// The set `id`.
    pub fn get(&self, id: DemoSetId) -> &DemoSetInputs {
        self.sets.iter().find(|s| s.id == id).expect("every set is prepared")
    }
}

/// The (state, action) pairs of a set as a RIPPER dataset.
pub fn dataset(set: &DemonstrationSet) -> Result<Dataset, RipperError> {
    let attributes = STATE_NAMES.iter().map(|n| Attribute::numeric(*n)).collect();
    let (rows, labels): (Vec<Vec<f64>>, Vec<usize>) = set.pairs().map(|(s, a)| (s.to_vec(), usize::from(a))).unzip();
    Dataset::new(attributes, rows, "Action", vec!["0".into(), "1".into(), "2".into()], labels)
}

/// RIPPER's rules and their cross-validation for a set.
pub fn summarise(set: &DemonstrationSet) -> Result<(DecisionList, CrossValidation), RipperError> {
    let data = dataset(set)?;
    let params = RipperParams::weka_3_6();
    let rules = Ripper::fit(&params, &data)?;
    let cv = stratified_cross_validation(&params, &data, 10, 1)?;
    Ok((rules, cv))
}

/// The five teachers' recordings from the master seed, B's and C's styles
/// as `passer` assigns them (each teacher's seed is the same whatever the
/// assignment: common random numbers across the `bc-styles` reading).
pub fn record_teachers(master_seed: u64, passer: FrequentPasser) -> Vec<(Teacher, DemonstrationSet)> {
    Teacher::ALL
        .iter()
        .map(|&t| {
            let seed = derive_seed(master_seed, &TrialKey::new(CHAPTER, DEMONSTRATION_EXPERIMENT, t.slug(), 0));
            (t, record(&t.model(passer), t.label(), DEMO_EPISODES, &mut seeded(seed)))
        })
        .collect()
}

/// Records every set and summarises it.
pub fn prepare(master_seed: u64, passer: FrequentPasser) -> Result<DemoInputs, RipperError> {
    let recorded = record_teachers(master_seed, passer);
    let get = |t: Teacher| recorded.iter().find(|(r, _)| *r == t).map(|(_, s)| s.clone()).expect("recorded");
    let (a, b, c, fast, limited) =
        (get(Teacher::A), get(Teacher::B), get(Teacher::C), get(Teacher::BFast), get(Teacher::BLimited));
    let half_seed = derive_seed(master_seed, &TrialKey::new(CHAPTER, DEMONSTRATION_EXPERIMENT, "half-subject-a", 0));
    let a10 = a.random_subset(DemoSetId::A10.label(), HALF_EPISODES, &mut seeded(half_seed));
    let best = DemonstrationSet::extremes(DemoSetId::AcBest.label(), &[&a, &c], EXTREME_EPISODES, true);
    let worst = DemonstrationSet::extremes(DemoSetId::AcWorst.label(), &[&a, &c], EXTREME_EPISODES, false);
    let sets = [
        (DemoSetId::A20, a),
        (DemoSetId::A10, a10),
        (DemoSetId::B, b),
        (DemoSetId::C, c),
        (DemoSetId::AcBest, best),
        (DemoSetId::AcWorst, worst),
        (DemoSetId::BFast, fast),
        (DemoSetId::BLimited, limited),
    ];
    let mut out = Vec::with_capacity(sets.len());
    for (id, set) in sets {
        let (rules, cv) = summarise(&set)?;
        out.push(DemoSetInputs { id, set, rules, cv });
    }
    Ok(DemoInputs { sets: out })
}

/// The decision list the thesis prints for Subject A's 20 demonstrations
/// (section 5.4), over `state_0 … state_12`, classes 0 (Hold), 1, 2:
///
/// ```text
/// if (state_11 >= 74.84 and state_3 <= 5.99 and state_11 <= 76.26) -> Action = 1
/// elseif (state_11 >= 53.97 and state_4 <= 5.91 and state_0 >= 8.45 and state_8 <= 7.06) -> Action = 1
/// elseif (state_3 <= 4.84 and state_0 >= 7.33 and state_12 >= 43.66 and state_8 <= 5.57) -> Action = 2
/// else -> Action = 0
/// ```
///
/// The thesis prints no coverage; the list's coverage fields are zero.
pub fn thesis_a_rules() -> DecisionList {
    let cond =
        |attribute: usize, op: &str, value: f64| serde_json::json!({"attribute": attribute, "op": op, "value": value});
    let (ge, le) = ("GreaterEq", "LessEq");
    let none = serde_json::json!({"covered": 0.0, "false_positives": 0.0, "class_weights": [0.0, 0.0, 0.0]});
    let rule = |conditions: Vec<serde_json::Value>, class: usize| serde_json::json!({"conditions": conditions, "class": class, "coverage": none});
    let attributes: Vec<serde_json::Value> =
        STATE_NAMES.iter().map(|n| serde_json::json!({"name": n, "kind": "Numeric"})).collect();
    let list = serde_json::json!({
        "rules": [
            rule(vec![cond(11, ge, 74.84), cond(3, le, 5.99), cond(11, le, 76.26)], 1),
            rule(vec![cond(11, ge, 53.97), cond(4, le, 5.91), cond(0, ge, 8.45), cond(8, le, 7.06)], 1),
            rule(vec![cond(3, le, 4.84), cond(0, ge, 7.33), cond(12, ge, 43.66), cond(8, le, 5.57)], 2),
        ],
        "default_class": 0,
        "default_coverage": none,
        "attributes": attributes,
        "class_attribute": "Action",
        "class_names": ["0", "1", "2"],
    });
    serde_json::from_value(list).expect("the printed list is a decision list")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_separable_set_gives_exact_rules() {
        use crate::teachers::DemoEpisode;
        let mut states = Vec::new();
        let mut actions = Vec::new();
        for i in 0..60 {
            let mut s = [1.0; 13];
            s[3] = f64::from(i % 12);
            states.push(s);
            actions.push(u8::from(s[3] < 4.0));
        }
        let set = DemonstrationSet {
            name: "toy".into(),
            episodes: vec![DemoEpisode { teacher: "T".into(), index: 0, duration: 60, states, actions }],
        };
        let (rules, cv) = summarise(&set).unwrap();
        assert_eq!(rules.to_string(), "if (state_3 <= 3.00) -> Action = 1\nelse -> Action = 0");
        assert_eq!(cv.accuracy, 1.0);
    }

    #[test]
    fn the_thesis_list_reads_as_printed() {
        let list = thesis_a_rules();
        assert_eq!(
            list.to_string(),
            "if (state_11 >= 74.84 and state_3 <= 5.99 and state_11 <= 76.26) -> Action = 1\n\
             elseif (state_11 >= 53.97 and state_4 <= 5.91 and state_0 >= 8.45 and state_8 <= 7.06) -> Action = 1\n\
             elseif (state_3 <= 4.84 and state_0 >= 7.33 and state_12 >= 43.66 and state_8 <= 5.57) -> Action = 2\n\
             else -> Action = 0"
        );
        let mut s = [0.0; 13];
        s[11] = 75.0;
        s[3] = 5.0;
        assert_eq!(list.predict(&s), 1);
        s[11] = 10.0;
        assert_eq!(list.predict(&s), 0);
    }
}
