//! Chapter 5's report content: the simulator's validation, the teachers and
//! their rules, Tables 5.1–5.4 and Figures 5.3–5.6 beside the thesis's, the
//! claims, the parameters, the decisions and the data, built from stored
//! results only.

mod claims;
mod figures;
pub mod metrics;
mod tables;

use std::fmt::Write as _;

use rlfd_report::prose::DataFile;
use rlfd_report::{Block, ChapterReport, Deviation, Provenance, Section};

use crate::experiment::{Ch5Results, Condition};
use crate::inputs::DemoSetId;
use crate::keepaway::CYCLES_PER_SECOND;
use crate::learners::Method;
use crate::{CHAPTER, Experiment};

pub use tables::{Analysis, BENCHMARK_RECALLED, LearningRow};

/// The chapter's title.
pub const TITLE: &str = "Chapter 5: Human-Agent Transfer (HAT) in 3 vs 2 Keepaway";

fn a20(method: Method) -> Condition {
    Condition { method, set: Some(DemoSetId::A20) }
}

fn seconds(d: &[u32]) -> Vec<f64> {
    d.iter().map(|&c| f64::from(c) / CYCLES_PER_SECOND).collect()
}

/// Builds the chapter's report from its results.
pub fn chapter_report(results: &Ch5Results, provenance: &Provenance) -> rlfd_report::Result<ChapterReport> {
    let analysis = Analysis::new(results);
    let p = &results.params;
    let mut sections = vec![Section::new("Keepaway: what was run", vec![Block::paragraph(summary(results))])];

    if !results.benchmarks.is_empty() {
        sections.push(Section::new(
            "Simulator validation: the benchmark policies",
            vec![Block::paragraph(validation_text(results)), Block::Table(tables::benchmark_table(results)?)],
        ));
    }

    if let Some(demos) = &results.demos {
        let mut blocks = vec![Block::paragraph(
            "Three people demonstrated in the thesis; here five models of them do (Subjects A, B, C, and B with the simulator five times faster or without Pass2), each deciding from the positions it saw a reaction delay ago, misjudged by perception noise, in a style of its own (see Decisions). Only two kinds of number were fitted, and only to the mean demonstration durations the thesis reports, before any learner ran.",
        )];
        if results.calibration.is_some() {
            blocks.push(Block::Table(tables::calibration_table(results, demos)?));
        }
        blocks.push(Block::Table(tables::demonstrations_table(results, demos)?));
        for s in &demos.sets {
            let mut text = format!(
                "{} ({} pairs, stratified 10-fold CV {:.1} %): ",
                s.id.label(),
                s.set.len(),
                100.0 * s.cv.accuracy
            );
            for line in s.rules.to_string().lines() {
                let _ = write!(text, "`{line}` ");
            }
            blocks.push(Block::paragraph(text.trim_end().to_string()));
        }
        if let Some(traced) = &results.traced {
            blocks.push(Block::Figure {
                file: "keepaway_episode.svg".into(),
                caption: "One episode demonstrated by the Subject A model: the ball (black) and the players' paths; K1–K3 the keepers' and T the takers' starting corners, B the ball's start; grey: outside the 20 m × 20 m region.".into(),
                svg: figures::episode_picture(traced, provenance)?,
            });
        }
        sections.push(Section::new("The teachers, their demonstrations and their rules", blocks));
    }

    let teacher_line = |id: DemoSetId| {
        results.demos.as_ref().map(|d| {
            let mean = d.get(id).set.mean_seconds();
            (format!("{} demonstrations ({mean:.1} s)", id.label()), mean)
        })
    };

    if results.experiments.contains(&Experiment::Hat) {
        let rows = [
            LearningRow { label: "No Prior", thesis: ("ch5.table_5_1", "No Prior"), condition: Condition::NO_PRIOR },
            LearningRow {
                label: "Value Bonus",
                thesis: ("ch5.table_5_1", "Value Bonus"),
                condition: a20(Method::VALUE_BONUS),
            },
            LearningRow {
                label: "Extra Action",
                thesis: ("ch5.table_5_1", "Extra Action"),
                condition: a20(Method::EXTRA_ACTION),
            },
            LearningRow {
                label: "Probabilistic Policy Reuse",
                thesis: ("ch5.table_5_1", "Probabilistic Policy Reuse"),
                condition: a20(Method::POLICY_REUSE),
            },
        ];
        let curves: Vec<(&str, Condition)> = rows.iter().map(|r| (r.label, r.condition)).collect();
        let refs: Vec<(String, f64)> = teacher_line(DemoSetId::A20).into_iter().collect();
        sections.push(Section::new(
            "Table 5.1 and Figure 5.3: three ways to use Subject A's rules",
            vec![
                Block::Table(tables::learning_table(
                    "table_5_1",
                    "Table 5.1: HAT methods with Subject A's 20 demonstrations",
                    &rows,
                    &analysis,
                    p,
                )?),
                Block::Table(tables::welch_table("table_5_1_welch", "Table 5.1, Welch's tests against No Prior", &rows, &analysis)?),
                Block::Figure {
                    file: "figure_5_3.svg".into(),
                    caption: "Figure 5.3: episode duration while learning, No Prior and the three HAT methods with Subject A's rules; dashed: Subject A's mean demonstration.".into(),
                    svg: figures::learning_curves("Figure 5.3: HAT methods, Subject A", results, &curves, &refs, provenance)?,
                },
            ],
        ));
    }

    if results.experiments.contains(&Experiment::Teachers) {
        let rows = [
            LearningRow { label: "No Prior", thesis: ("ch5.table_5_2", "No Prior"), condition: Condition::NO_PRIOR },
            LearningRow {
                label: "Subject A",
                thesis: ("ch5.table_5_2", "Subject A"),
                condition: Condition::ppr(DemoSetId::A20),
            },
            LearningRow {
                label: "Subject B",
                thesis: ("ch5.table_5_2", "Subject B"),
                condition: Condition::ppr(DemoSetId::B),
            },
            LearningRow {
                label: "Subject C",
                thesis: ("ch5.table_5_2", "Subject C"),
                condition: Condition::ppr(DemoSetId::C),
            },
        ];
        let curves: Vec<(&str, Condition)> = rows.iter().map(|r| (r.label, r.condition)).collect();
        let refs: Vec<(String, f64)> =
            [DemoSetId::A20, DemoSetId::B, DemoSetId::C].into_iter().filter_map(teacher_line).collect();
        sections.push(Section::new(
            "Table 5.2 and Figure 5.4: three teachers",
            vec![
                Block::Table(tables::learning_table(
                    "table_5_2",
                    "Table 5.2: PPR with each teacher's 20 demonstrations",
                    &rows,
                    &analysis,
                    p,
                )?),
                Block::Table(tables::welch_table("table_5_2_welch", "Table 5.2, Welch's tests against No Prior", &rows, &analysis)?),
                Block::Figure {
                    file: "figure_5_4.svg".into(),
                    caption: "Figure 5.4: episode duration while learning, No Prior and PPR with Subjects A, B and C; dashed: each teacher's mean demonstration.".into(),
                    svg: figures::learning_curves("Figure 5.4: PPR with three teachers", results, &curves, &refs, provenance)?,
                },
            ],
        ));
    }

    if results.experiments.contains(&Experiment::DemoSets) {
        let t = "ch5.table_5_3";
        let rows = [
            LearningRow { label: "No Prior", thesis: ("ch5.table_5_1", "No Prior"), condition: Condition::NO_PRIOR },
            LearningRow {
                label: "Subject A (20)",
                thesis: (t, "Subject A (20)"),
                condition: Condition::ppr(DemoSetId::A20),
            },
            LearningRow {
                label: "Subject A (10)",
                thesis: (t, "Subject A (10)"),
                condition: Condition::ppr(DemoSetId::A10),
            },
            LearningRow {
                label: "Subject C (20)",
                thesis: (t, "Subject C (20)"),
                condition: Condition::ppr(DemoSetId::C),
            },
            LearningRow {
                label: "Subjects A + C Best",
                thesis: (t, "Subjects A + C Best"),
                condition: Condition::ppr(DemoSetId::AcBest),
            },
            LearningRow {
                label: "Subjects A + C Worst",
                thesis: (t, "Subjects A + C Worst"),
                condition: Condition::ppr(DemoSetId::AcWorst),
            },
        ];
        let curves: Vec<(&str, Condition)> = rows.iter().map(|r| (r.label, r.condition)).collect();
        let best = Condition::ppr(DemoSetId::AcBest);
        let pairs: Vec<(&str, Condition, &str, Condition)> = rows[1..]
            .iter()
            .filter(|r| r.condition != best)
            .map(|r| ("A + C Best", best, r.label, r.condition))
            .chain([("A (10)", Condition::ppr(DemoSetId::A10), "A (20)", Condition::ppr(DemoSetId::A20))])
            .collect();
        sections.push(Section::new(
            "Table 5.3 and Figure 5.5: quantity, quality and several teachers",
            vec![
                Block::Table(tables::learning_table(
                    "table_5_3",
                    "Table 5.3: PPR with five demonstration sets",
                    &rows,
                    &analysis,
                    p,
                )?),
                Block::Table(tables::welch_table("table_5_3_welch", "Table 5.3, Welch's tests against No Prior", &rows, &analysis)?),
                Block::Table(tables::pairwise_table(
                    "table_5_3_pairs",
                    "Table 5.3, pairwise: A + C Best against the other sets, and A (10) against A (20)",
                    &pairs,
                    &analysis,
                )?),
                Block::Figure {
                    file: "figure_5_5.svg".into(),
                    caption: "Figure 5.5: episode duration while learning with PPR from five demonstration sets (and No Prior).".into(),
                    svg: figures::learning_curves("Figure 5.5: PPR with five demonstration sets", results, &curves, &[], provenance)?,
                },
            ],
        ));
    }

    if results.experiments.contains(&Experiment::Handicaps) {
        let t = "ch5.table_5_4";
        let rows = [
            LearningRow { label: "No Prior", thesis: ("ch5.table_5_1", "No Prior"), condition: Condition::NO_PRIOR },
            LearningRow { label: "Subject B", thesis: (t, "Subject B"), condition: Condition::ppr(DemoSetId::B) },
            LearningRow {
                label: "Limited Actions",
                thesis: (t, "Limited Actions"),
                condition: Condition::ppr(DemoSetId::BLimited),
            },
            LearningRow {
                label: "Fast Demonstration",
                thesis: (t, "Fast Demonstration"),
                condition: Condition::ppr(DemoSetId::BFast),
            },
        ];
        let curves: Vec<(&str, Condition)> = rows.iter().map(|r| (r.label, r.condition)).collect();
        let b = Condition::ppr(DemoSetId::B);
        let pairs = [
            ("Limited", Condition::ppr(DemoSetId::BLimited), "B", b),
            ("Fast", Condition::ppr(DemoSetId::BFast), "B", b),
        ];
        let refs: Vec<(String, f64)> =
            [DemoSetId::B, DemoSetId::BLimited, DemoSetId::BFast].into_iter().filter_map(teacher_line).collect();
        sections.push(Section::new(
            "Table 5.4 and Figure 5.6: a handicapped teacher",
            vec![
                Block::Table(tables::learning_table(
                    "table_5_4",
                    "Table 5.4: PPR with Subject B's demonstrations, normal, limited and fast",
                    &rows,
                    &analysis,
                    p,
                )?),
                Block::Table(tables::welch_table("table_5_4_welch", "Table 5.4, Welch's tests against No Prior", &rows, &analysis)?),
                Block::Table(tables::pairwise_table(
                    "table_5_4_pairs",
                    "Table 5.4, pairwise: the handicapped sets against Subject B",
                    &pairs,
                    &analysis,
                )?),
                Block::Figure {
                    file: "figure_5_6.svg".into(),
                    caption: "Figure 5.6: episode duration while learning with PPR from Subject B's three recordings (and No Prior); dashed: each recording's mean.".into(),
                    svg: figures::learning_curves("Figure 5.6: PPR with Subject B handicapped", results, &curves, &refs, provenance)?,
                },
            ],
        ));
    }

    let claims = claims::claims(&analysis, results)?;
    if !claims.is_empty() {
        sections.push(Section::new("Claims C5.1–C5.10", vec![Block::Claims(claims)]));
    }
    sections.push(Section::new("Parameters", vec![Block::Parameters(tables::parameters_table(p)?)]));
    sections.push(Section::new("Decisions and deviations", vec![Block::Deviations(deviations()?)]));
    sections.push(Section::new("Data", data_blocks(results, &analysis)));
    Ok(ChapterReport { slug: CHAPTER.into(), title: TITLE.into(), provenance: provenance.clone(), sections })
}

fn summary(r: &Ch5Results) -> String {
    let p = &r.params;
    let cycles: u64 = r
        .learning
        .values()
        .flat_map(|(_, ts)| ts)
        .map(|t| t.durations.iter().map(|&d| u64::from(d)).sum::<u64>())
        .sum();
    let episodes: usize = r.learning.values().flat_map(|(_, ts)| ts).map(|t| t.durations.len()).sum();
    let names: Vec<&str> = r.experiments.iter().map(|e| e.name()).collect();
    format!(
        "Experiments {} at the *{}* scale with master seed {}: {} learning conditions × {} trials × {} simulated hours ({} training episodes, {} simulator cycles in all). \
         Every number below is computed from the stored trials; the thesis's value stands beside ours wherever it published one. Durations are in seconds of simulated time (10 cycles per second).",
        names.join(", "),
        r.scale,
        r.seed,
        r.learning.len(),
        p.trials,
        p.hours,
        rlfd_stats::format::thousands(episodes as f64, 0),
        rlfd_stats::format::thousands(cycles as f64, 0),
    )
}

fn validation_text(r: &Ch5Results) -> String {
    let means: Vec<f64> = crate::benchmarks::BenchmarkPolicy::ALL
        .iter()
        .map(|pol| r.benchmarks.get(pol).map_or(f64::NAN, |d| metrics::mean_sd(&seconds(d)).0))
        .collect();
    let ordered = means[0] < means[1] && means[1] < means[2];
    let ratios: Vec<String> = means
        .iter()
        .zip(BENCHMARK_RECALLED)
        .zip(["Always Hold", "Random", "Hand-coded"])
        .map(|((m, (p, _)), name)| format!("{name} {:+.2} s (× {:.2})", m - p, m / p))
        .collect();
    format!(
        "The three benchmark keeper policies of the keepaway distribution, played by all three keepers against the hand-coded takers: Always Hold {:.2} s, Random {:.2} s, Hand-coded {:.2} s, against the published (recalled) 3.4, 7.5 and 8.3 s. The order {} the published one. Ours minus published: {}. \
         Two of our simplifications bear on these numbers: our players perceive every position exactly (the benchmark's see noisy, partial and delayed information) and our server has no collisions. Exact information most helps a policy that passes only into lanes it judges open, as the hand-coded one does; Random uses no information at all.",
        means[0],
        means[1],
        means[2],
        if ordered { "reproduces" } else { "does not reproduce" },
        ratios.join(", ")
    )
}

/// The chapter's decisions and deviations, kept as data in `data/deviations.toml`.
const DEVIATIONS: DataFile = DataFile {
    path: "chapters/ch5-hat-keepaway/data/deviations.toml",
    text: include_str!("../../data/deviations.toml"),
};

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    DEVIATIONS.deviations("deviation")
}

fn data_blocks(r: &Ch5Results, a: &Analysis) -> Vec<Block> {
    let mut out = Vec::new();
    if !r.learning.is_empty() {
        let mut s = String::from("condition,trial,hour,sliding_mean_seconds\n");
        let mut t = String::from("condition,trial,initial_seconds,final_seconds,total,episodes,hours\n");
        for (slug, (_, trials)) in &r.learning {
            if let Some(m) = a.metrics.get(slug) {
                for (k, curve) in m.hourly.iter().enumerate() {
                    for (h, v) in curve.iter().enumerate() {
                        let _ = writeln!(s, "{slug},{k},{h},{v:.4}");
                    }
                }
                for (k, trial) in trials.iter().enumerate() {
                    let _ = writeln!(
                        t,
                        "{slug},{k},{:.4},{:.4},{:.4},{},{:.4}",
                        m.initial[k],
                        m.final_reward[k],
                        m.total[k],
                        trial.durations.len(),
                        trial.hours()
                    );
                }
            }
        }
        out.push(Block::DataFile {
            file: "keepaway_hourly.csv".into(),
            description: "Each trial's learning curve at the integral simulated hours (hour 0: the jumpstart evaluation), seconds.".into(),
            bytes: s.into_bytes(),
        });
        out.push(Block::DataFile {
            file: "keepaway_trials.csv".into(),
            description: "Each trial's metrics: initial (jumpstart evaluation) mean, final reward, total reward, training episodes, simulated hours.".into(),
            bytes: t.into_bytes(),
        });
    }
    if !r.benchmarks.is_empty() {
        let mut s = String::from("policy,episode,duration_cycles\n");
        for (policy, d) in &r.benchmarks {
            for (e, c) in d.iter().enumerate() {
                let _ = writeln!(s, "{},{},{c}", policy.slug(), e + 1);
            }
        }
        out.push(Block::DataFile {
            file: "keepaway_benchmark_episodes.csv".into(),
            description: "Every episode of the benchmark policies (duration in 100 ms cycles).".into(),
            bytes: s.into_bytes(),
        });
    }
    if let Some(demos) = &r.demos {
        let mut s = String::from("set,teacher,episode,duration_cycles,decisions,hold,pass1,pass2\n");
        for set in &demos.sets {
            for e in &set.set.episodes {
                let mut c = [0usize; 3];
                for &x in &e.actions {
                    c[usize::from(x).min(2)] += 1;
                }
                let _ = writeln!(
                    s,
                    "{},{},{},{},{},{},{},{}",
                    set.id.slug(),
                    e.teacher,
                    e.index,
                    e.duration,
                    e.actions.len(),
                    c[0],
                    c[1],
                    c[2]
                );
            }
        }
        out.push(Block::DataFile {
            file: "keepaway_demonstration_episodes.csv".into(),
            description: "Every demonstrated episode of every set: duration, decisions and actions taken.".into(),
            bytes: s.into_bytes(),
        });
    }
    if !r.rules_only.is_empty() {
        let mut s = String::from("set,episodes,mean_seconds,sd_seconds\n");
        for (id, d) in &r.rules_only {
            let (m, sd) = metrics::mean_sd(&seconds(d));
            let _ = writeln!(s, "{},{},{m:.4},{sd:.4}", id.slug(), d.len());
        }
        out.push(Block::DataFile {
            file: "keepaway_rules_alone.csv".into(),
            description: "Each set's rules played alone by every keeper: episodes, mean and sd of the duration.".into(),
            bytes: s.into_bytes(),
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use rlfd_harness::Scale;
    use rlfd_report::claims::Verdict;

    use super::*;
    use crate::experiment::Ch5Params;
    use crate::learners::LearningTrial;

    /// A trial at `first` seconds per episode until `switch` hours, then
    /// `second`, with a per-trial wobble of a cycle so that t-tests are defined.
    fn trial(jump: f64, first: f64, second: f64, switch: f64, k: u32) -> LearningTrial {
        let mut durations = Vec::new();
        let mut used = 0u64;
        for (level, until) in [(first, (switch * 36_000.0) as u64), (second, 1_080_000)] {
            while used < until {
                let d = (level * 10.0) as u32 + (k + durations.len() as u32) % 3;
                used += u64::from(d);
                durations.push(d);
            }
        }
        LearningTrial { jumpstart_cycles: jump * 10.0 + f64::from(k % 4), jumpstart_episodes: 1000, durations }
    }

    fn results(levels: &[(Condition, f64, f64, f64, f64)]) -> Ch5Results {
        let mut learning = BTreeMap::new();
        for &(c, jump, first, second, switch) in levels {
            learning.insert(c.slug(), (c, (0..10).map(|k| trial(jump, first, second, switch, k)).collect()));
        }
        Ch5Results {
            scale: Scale::Paper,
            seed: 1,
            params: Ch5Params::paper(),
            experiments: vec![Experiment::Hat],
            demos: None,
            benchmarks: BTreeMap::new(),
            calibration: None,
            rules_only: BTreeMap::new(),
            traced: None,
            learning,
            computed: 0,
            reused: 0,
        }
    }

    fn verdicts(r: &Ch5Results) -> BTreeMap<String, Verdict> {
        let a = Analysis::new(r);
        claims::claims(&a, r).unwrap().into_iter().map(|c| (c.id, c.verdict)).collect()
    }

    #[test]
    fn verdicts_follow_the_data() {
        let np = Condition::NO_PRIOR;
        let (vb, ea, ppr) = (a20(Method::VALUE_BONUS), a20(Method::EXTRA_ACTION), a20(Method::POLICY_REUSE));
        // HAT learns sooner (PPR first); only Extra Action better at the end: C5.1–C5.3 hold.
        let good = results(&[
            (np, 5.0, 10.0, 14.5, 20.0),
            (vb, 5.0, 12.0, 14.5, 15.0),
            (ea, 5.0, 12.0, 15.0, 12.0),
            (ppr, 5.0, 12.0, 14.5, 8.0),
        ]);
        let v = verdicts(&good);
        assert_eq!(v["C5.1"], Verdict::Reproduced);
        assert_eq!(v["C5.2"], Verdict::Reproduced);
        assert_eq!(v["C5.3"], Verdict::Reproduced);
        // No gain from the rules: C5.1 and C5.3 fail; all finals equal: C5.2 fails.
        let flat = results(&[
            (np, 5.0, 12.0, 14.5, 15.0),
            (vb, 5.0, 12.0, 14.5, 15.0),
            (ea, 5.0, 12.0, 14.5, 15.0),
            (ppr, 5.0, 12.0, 14.5, 15.0),
        ]);
        let v = verdicts(&flat);
        assert_eq!(v["C5.1"], Verdict::NotReproduced);
        assert_eq!(v["C5.2"], Verdict::NotReproduced);
        assert_eq!(v["C5.3"], Verdict::NotReproduced);
        // At the quick scale the tests are not taken as evidence.
        let mut quick = good;
        quick.scale = Scale::Quick;
        assert!(verdicts(&quick).values().all(|&v| v == Verdict::NotEvaluable));
        // The report builds from such results.
        let report = chapter_report(&flat, &Provenance::new("test", "0")).unwrap();
        assert!(report.sections.iter().any(|s| s.title.starts_with("Table 5.1")));
    }
}
