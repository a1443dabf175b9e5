//! Chapter 6's Mario report content (section 6.3.2): Tables 6.3 and 6.4
//! beside the thesis's, Figures 6.5–6.7, the episodes to surpass the
//! demonstrator, claims C6.6–C6.10, the level and demonstration picture, the
//! demonstrator's measurements, parameters, decisions and binned data. Built
//! from stored results only, on the chapter's shared metrics and tables;
//! the verdicts of C6.6–C6.9 in `claims`, their key numbers in
//! `scorecard`, the level picture in [`level_svg`].
//!
//! Metrics per trial: initial = the first episode's points; asymptotic = the
//! mean of the last 100 episodes (of all of them when a trial has fewer);
//! cumulative = the sum over all episodes.

mod claims;
pub mod level_svg;
mod scorecard;
pub(crate) mod validation;

use std::fmt::Write as _;

use rlfd_report::data_file::csv_of;
use serde::Serialize;

use rlfd_harness::Scale;
use rlfd_report::claims::{Check, Claim};
use rlfd_report::figure::{BarChart, Bracket, HLine, LegendPosition, LineChart, Series, SeriesStyle, Stroke};
use rlfd_report::parameters::Parameters;
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, Deviation, Provenance, Section};
use rlfd_stats::curve::episodes_to_surpass;
use rlfd_stats::format::{p_value, thousands};
use rlfd_stats::{Summary, student_t_test};

use super::agent_tables::{self, TableText, metric_columns};
use super::claims::MIN_TRIALS_FOR_TESTS;
use super::family::{Family, MARIO_MARGIN, num};
use super::levels::{self, LevelText};
use super::metrics::{Metric, MetricTable, Scored, values};
use crate::mario::World;
use crate::mario::demonstrator::{self, Demonstration, thesis as demo_thesis};
use crate::mario::experiment::{DEMO_LENGTHS, DemoLengthResults, MarioResults};
use crate::mario::level::{Level, tile};
use crate::mario::observation::NAMES;
use crate::mario::params::{BASELINE, MarioTrial};
use crate::shaping::Agent;
use crate::shaping::trials::{LevelRun, LevelRuns};
use level_svg::outcome;
pub use level_svg::{level_scene, render_level};

/// Episodes averaged for the asymptote.
pub const ASYMPTOTE_EPISODES: usize = 100;

impl Scored for MarioTrial {
    const ASYMPTOTIC_HEADER: &'static str = "Asymptotic (last 100)";

    fn metric(&self, m: Metric) -> f64 {
        let r = &self.returns;
        match m {
            Metric::Initial => r.first().map_or(f64::NAN, |&v| f64::from(v)),
            Metric::Asymptotic => {
                let k = ASYMPTOTE_EPISODES.min(r.len()).max(1);
                r[r.len().saturating_sub(k)..].iter().map(|&v| f64::from(v)).sum::<f64>() / k as f64
            }
            Metric::Cumulative => r.iter().map(|&v| f64::from(v)).sum(),
        }
    }
}

/// Episodes per bin of the smoothed curves and the binned data.
pub fn bin_size(episodes: usize) -> usize {
    if episodes >= 2000 { 100 } else { (episodes / 20).max(1) }
}

/// Per trial, the mean return of each bin of `bin` episodes (a last partial bin included).
fn binned(t: &MarioTrial, bin: usize) -> Vec<f64> {
    t.returns.chunks(bin).map(|c| c.iter().map(|&v| f64::from(v)).sum::<f64>() / c.len() as f64).collect()
}

/// The trial-mean binned curve.
pub(super) fn mean_binned(ts: &[MarioTrial], bin: usize) -> Vec<f64> {
    let curves: Vec<Vec<f64>> = ts.iter().map(|t| binned(t, bin)).collect();
    rlfd_stats::curve::mean_curve(&curves).unwrap_or_default()
}

/// The episodes (ends of bins) from which the smoothed mean curve stays
/// above `hmn`, and at which it first rises above it.
fn surpass(ts: &[MarioTrial], bin: usize, hmn: f64) -> (Option<usize>, Option<usize>) {
    let curve = mean_binned(ts, bin);
    let end = |b: usize| (b * bin).min(ts.first().map_or(0, |t| t.returns.len()));
    (episodes_to_surpass(&curve, hmn).map(end), curve.iter().position(|&v| v > hmn).map(|i| end(i + 1)))
}

/// Raw episodes shipped per trial from its start (the binned data hide the
/// first episodes' course, e.g. HAT's first 250 episodes).
pub const FIRST_EPISODES: usize = 500;

/// The Mario sections (each part present when its experiment ran).
pub fn sections(
    main: Option<&MarioResults>,
    study: Option<&DemoLengthResults>,
    provenance: &Provenance,
) -> rlfd_report::Result<Vec<Section>> {
    let mut out = Vec::new();
    if let Some(r) = main {
        out.extend(main_sections(r, provenance)?);
        out.push(dis_beta_section(&r.levels, r, provenance)?);
    }
    if let Some(s) = study {
        out.push(study_section(s, main, provenance)?);
    }
    if let Some(r) = main {
        out.push(level_section(r, provenance)?);
        out.push(demonstrations_section(r)?);
        out.push(learned_section(r, provenance)?);
        out.push(Section::new("Mario parameters", vec![Block::Parameters(parameters_table(r)?)]));
        out.push(Section::new("Mario decisions and deviations", vec![Block::Deviations(deviations()?)]));
        out.push(Section::new(
            "Mario data",
            vec![
                Block::DataFile {
                    file: "mario_returns_binned.csv".into(),
                    description: format!(
                        "Per agent and trial, the mean points and ticks of each bin of {} episodes (episodes from 1); the raw per-episode records stay in the result store.",
                        bin_size(r.params.episodes)
                    ),
                    bytes: binned_csv(r, study),
                },
                Block::DataFile {
                    file: "mario_metrics.csv".into(),
                    description: "Per agent and trial: initial, asymptotic (mean of the last 100 episodes) and cumulative points, levels won, ticks played.".into(),
                    bytes: metrics_csv(r, study),
                },
                Block::DataFile {
                    file: "mario_first_episodes.csv".into(),
                    description: format!(
                        "Per agent and trial, the first {FIRST_EPISODES} episodes one by one: points and ticks (the binned file hides the early course)."
                    ),
                    bytes: first_episodes_csv(r, study),
                },
                Block::DataFile {
                    file: "mario_demonstration_scores.csv".into(),
                    description: "The ten demonstrations: level seed, start mode, observations (ticks), points and outcome.".into(),
                    bytes: demonstration_scores_csv(r),
                },
                Block::DataFile {
                    file: "mario_demonstrations.csv".into(),
                    description: "The ten demonstrations: the 27 state variables and the action (0..12, Liao et al.'s order) of every observation.".into(),
                    bytes: {
                        let mut b = Vec::new();
                        r.demonstrations.set.write_csv(&mut b).expect("writing to memory");
                        b
                    },
                },
            ],
        ));
    }
    Ok(out)
}

/// DIS at each level of the `dis-beta` reading, beside the main experiment's QLR.
fn dis_beta_section(
    b: &LevelRuns<MarioTrial>,
    main: &MarioResults,
    provenance: &Provenance,
) -> rlfd_report::Result<Section> {
    let baseline = main.trials.get(&Agent::Baseline).map(|ts| (Agent::Baseline.label(BASELINE), ts.as_slice()));
    let label = |run: &LevelRun<MarioTrial>| {
        format!("DIS β = {} ({}{})", run.value, run.level, if run.main { ", this run" } else { "" })
    };
    let bin = bin_size(main.params.episodes);
    let curve = |ts: &[MarioTrial]| {
        mean_binned(ts, bin).iter().enumerate().map(|(k, &y)| (((k + 1) * bin) as f64, y)).collect()
    };
    let text = LevelText {
        title: "Mario: sensitivity to DIS's β (the dis-beta reading)",
        text: "The thesis gives DIS's secondary step size as \"β = 0.05\" for Mario but \"β = 0.05/#tiles\" for the Maze. The default reading follows the Mario text: 0.05 per active feature, which over 32 tilings moves Φ†(s, a) by 1.6 times the TD error per update, an overshooting step. The per-tiling level reads β as 0.05/32, the Maze's convention, with everything else the same. These are the dis-beta reading's own trials, on which the robustness run's verdicts at each level rest. The default stays the reproduction's answer; β was not chosen from these runs.",
        table: TableText {
            id: "mario_dis_beta",
            title: "Sensitivity: DIS at each level of the dis-beta reading",
            caption: "Mean ± sd over the trials that ran to the end; QLR and the run's own level are the main experiment's trials. Asymptotic = mean of the last 100 episodes.".into(),
            thesis_key: "",
            notes: Vec::new(),
        },
        diverged_tail: " A level none of whose trials ran to the end has no numbers.",
        format: NumFormat::grouped(1),
        label: &label,
        figure: (
            "figure_mario_dis_beta.svg",
            format!("Sensitivity: DIS's β, mean points per bin of {bin} episodes"),
            "Points per episode",
            None,
            "Mean points per episode, binned, for QLR and DIS at both readings of β.",
        ),
        curve: &curve,
    };
    levels::section(text, baseline, b, main.params.trials, provenance)
}

/// Which agents' smoothed curves stay above HMN from which episode, and first rise above it.
fn surpassing(r: &MarioResults, hmn: f64) -> Vec<(Agent, Option<usize>, Option<usize>)> {
    let bin = bin_size(r.params.episodes);
    Agent::ALL
        .iter()
        .filter_map(|&a| {
            r.trials.get(&a).map(|ts| {
                let (stays, first) = surpass(ts, bin, hmn);
                (a, stays, first)
            })
        })
        .collect()
}

/// Claims C6.6–C6.9, from the results alone (no figure, no bootstrap).
pub fn main_claims_of(r: &MarioResults) -> rlfd_report::Result<Vec<Claim>> {
    let hmn = r.demonstrations.stats.mean_score;
    claims::main_claims(r, &surpassing(r, hmn), hmn)
}

fn main_sections(r: &MarioResults, provenance: &Provenance) -> rlfd_report::Result<Vec<Section>> {
    let trials = r.params.trials as usize;
    let hmn = r.demonstrations.stats.mean_score;
    let bin = bin_size(r.params.episodes);
    let steps: u64 = r.trials.values().flatten().map(MarioTrial::total_steps).sum();
    let episodes: usize = r.trials.values().flatten().map(|t| t.returns.len()).sum();
    let wins: u64 = r.trials.values().flatten().map(|t| u64::from(t.ends.wins)).sum();
    let summary = format!(
        "Five agents (Q(λ), SIS, DIS, HAT, SBS) play Mario for {} episodes, {} trials each, at the *{}* scale with master seed {}: {} episodes, {} agent steps (one per game tick), {:.0} ticks per episode on average, {} levels finished. \
         Every episode is a new random level with a random start mode. Initial = the first episode's points; *asymptotic = the mean of the last 100 episodes* (the thesis's table says \"asymptotic\" without a definition; with 20,000 noisy episodes one episode would be mostly noise); cumulative = the sum over all episodes. \
         The demonstrator's mean score is HMN = {} (thesis: 1,224).",
        r.params.episodes,
        trials,
        r.scale,
        r.seed,
        thousands(episodes as f64, 0),
        thousands(steps as f64, 0),
        steps as f64 / episodes.max(1) as f64,
        thousands(wins as f64, 0),
        thousands(hmn, 1)
    );
    let mut run = vec![Block::paragraph(summary)];
    if let Some(why) = super::diverged_agents(&r.diverged, &Agent::ALL, BASELINE, r.params.trials) {
        run.push(Block::paragraph(format!(
            "Diverged learners: {} Every table, figure and test below uses the trials that ran to the end; an agent none of whose trials did is absent from them.",
            why.replacen("Not evaluable: the", "The", 1)
        )));
    }
    let mut out = vec![Section::new("Mario: what was run", run)];
    out.push(Section::new(
        "Table 6.3: Mario, initial, asymptotic and cumulative points",
        vec![
            Block::Table(table_6_3(r, hmn)?),
            Block::Table(agent_tables::iqm_table::<MarioTrial>(
                TableText {
                    id: "table_6_3_iqm",
                    title: "Table 6.3 as interquartile means",
                    caption: "The interquartile mean over trials of each agent's metric, robust to a few odd trials, beside the thesis's mean over its 10. Sample: experiment/condition of mario_metrics.csv.".into(),
                    thesis_key: "ch6.mario.table_6_3",
                    notes: Vec::new(),
                },
                &MetricTable::new(&r.trials),
                &Agent::ALL.into_iter().filter(|a| r.trials.contains_key(a)).collect::<Vec<_>>(),
                BASELINE,
                |a| format!("mario/{}", a.label(BASELINE)),
                1,
            )?),
            Block::Table(surpass_table(&surpassing(r, hmn), hmn, bin)?),
        ],
    ));
    out.push(Section::new(
        "Table 6.4: Mario, two-sample t-tests",
        vec![
            Block::Table(table_6_4(r)?),
            Block::Table(agent_tables::full_tests_table(
                TableText {
                    id: "table_6_4_tests",
                    title: "Table 6.4, every test in full",
                    caption: "The tests behind the p-values above: the first-named agent's mean minus the second's. Samples: experiment/condition of mario_metrics.csv.".into(),
                    thesis_key: "ch6.mario.table_6_4",
                    notes: Vec::new(),
                },
                &MetricTable::new(&r.trials),
                BASELINE,
                |a| format!("mario/{}", a.label(BASELINE)),
                1,
            )?),
        ],
    ));
    out.push(Section::new(
        "Figure 6.5: Mario learning curves",
        vec![Block::Figure {
            file: "figure_6_5.svg".into(),
            caption: format!(
                "Points per episode, mean over trials of the mean of each {bin} episodes, with the demonstrator's mean (dashed)."
            ),
            svg: figure_6_5(r, hmn, bin, provenance)?,
        }],
    ));
    out.push(Section::new(
        "Claims C6.6–C6.9",
        vec![Block::paragraph(super::how_claims_are_tested()), Block::Claims(main_claims_of(r)?)],
    ));
    Ok(out)
}

fn table_6_3(r: &MarioResults, hmn: f64) -> rlfd_report::Result<Table> {
    let ran: Vec<Agent> = Agent::ALL.into_iter().filter(|a| r.trials.contains_key(a)).collect();
    let rows = agent_tables::means_rows(&MetricTable::new(&r.trials), &ran, BASELINE);
    agent_tables::means_table(
        TableText {
            id: "table_6_3",
            title: "Table 6.3: Mario, mean points per agent",
            caption: format!(
                "Mean ± sd over {} trials (ours) beside the thesis's mean over 10 trials. Asymptotic: the mean of the last 100 episodes of each trial.",
                r.params.trials
            ),
            thesis_key: "ch6.mario.table_6_3",
            notes: vec!["HMN is the demonstrator's mean score over its ten demonstrations.".into()],
        },
        &metric_columns::<MarioTrial>(),
        &rows,
        hmn,
        NumFormat::grouped(1),
    )
}

fn table_6_4(r: &MarioResults) -> rlfd_report::Result<Table> {
    let pairs = agent_tables::pair_rows(&MetricTable::new(&r.trials), BASELINE);
    agent_tables::p_value_table(
        TableText {
            id: "table_6_4",
            title: "Table 6.4: Mario, p-values of two-sample t-tests",
            caption: format!(
                "Pooled-variance Student t-tests (as the thesis) on {} trials per agent beside the thesis's p-values; Welch's test for comparison.",
                r.params.trials
            ),
            thesis_key: "ch6.mario.table_6_4",
            notes: vec!["* p ≤ 0.05, ** p ≤ 0.01, *** p ≤ 0.001, **** p ≤ 0.0001. p-values are rounded to 4 significant digits. A dash: the test is undefined.".into()],
        },
        &metric_columns::<MarioTrial>(),
        &pairs,
    )
}

fn surpass_table(s: &[(Agent, Option<usize>, Option<usize>)], hmn: f64, bin: usize) -> rlfd_report::Result<Table> {
    let rows: Vec<(&str, Option<usize>, Option<usize>)> =
        s.iter().map(|&(a, e, f)| (a.label(BASELINE), e, f)).collect();
    agent_tables::surpass_table(
        TableText {
            id: "mario_episodes_to_surpass",
            title: "Mario: episodes to surpass the demonstrator",
            caption: format!(
                "The episode (end of a {bin}-episode bin) from which the trial-mean curve, smoothed as in Figure 6.5, stays above the demonstrator's mean (ours: HMN = {hmn:.1}) to the end of the run (the claims' reading), and the first bin above it."
            ),
            thesis_key: "ch6.mario.episodes_to_surpass_demonstrator",
            notes: Vec::new(),
        },
        &rows,
    )
}

fn figure_6_5(r: &MarioResults, hmn: f64, bin: usize, provenance: &Provenance) -> rlfd_report::Result<String> {
    let mut chart = LineChart::new(
        format!("Figure 6.5: Mario, points per episode (mean over {} trials, {bin}-episode means)", r.params.trials),
        "Episode",
        "Points per episode",
    );
    for agent in Agent::ALL {
        let Some(ts) = r.trials.get(&agent) else { continue };
        let curve = mean_binned(ts, bin);
        let points = curve.iter().enumerate().map(|(k, &y)| (((k + 1) * bin) as f64, y)).collect();
        chart.series.push(Series { name: agent.label(BASELINE).into(), points, band: None, style: SeriesStyle::Line });
    }
    chart.reference_lines.push(HLine { name: "HMN (demonstrator mean)".into(), y: hmn, stroke: Stroke::Dashed });
    chart.legend = LegendPosition::Outside;
    chart.to_svg(provenance)
}

/// The pooled two-sided p of each pair of lengths (0 vs 1, 1 vs 2, 0 vs 2) on `m`.
fn pairwise_p(s: &DemoLengthResults, m: Metric) -> Vec<(usize, usize, f64)> {
    [(0usize, 1usize), (1, 2), (0, 2)]
        .into_iter()
        .map(|(a, b)| {
            (a, b, student_t_test(&values(&s.runs[a].2, m), &values(&s.runs[b].2, m)).map_or(f64::NAN, |t| t.p))
        })
        .collect()
}

/// Claim C6.10, from the length study's results alone.
pub fn length_claim(s: &DemoLengthResults) -> rlfd_report::Result<Claim> {
    let trials = s.trials as usize;
    let ok = trials >= MIN_TRIALS_FOR_TESTS && s.scale == Scale::Paper;
    let pairs = [(0usize, 1usize), (1, 2), (0, 2)];
    let texts = |m: Metric| -> Vec<String> {
        pairwise_p(s, m)
            .into_iter()
            .map(|(a, b, p)| format!("{} vs {}: p = {}", DEMO_LENGTHS[a], DEMO_LENGTHS[b], p_value(p)))
            .collect()
    };
    let (asym_p, cum_p) = (texts(Metric::Asymptotic), texts(Metric::Cumulative));
    // C6.10: cumulative rises 100 < 500 < 953 with significant steps; the
    // asymptotes are equivalent within the margin (TOST). One family of five.
    let run = |k: usize, m: Metric| values(&s.runs[k].2, m);
    let mut family = Family::new();
    for (a, b) in [(1usize, 0usize), (2, 1)] {
        family.above(
            format!("cumulative {} vs {}", DEMO_LENGTHS[a], DEMO_LENGTHS[b]),
            &run(a, Metric::Cumulative),
            &run(b, Metric::Cumulative),
            0.05,
        );
    }
    for &(a, b) in &pairs {
        family.equivalent(
            format!("asymptote {} vs {}", DEMO_LENGTHS[a], DEMO_LENGTHS[b]),
            &run(a, Metric::Asymptotic),
            &run(b, Metric::Asymptotic),
            MARIO_MARGIN,
        );
    }
    let rising = family.holds_within(0..2);
    let flat = family.holds_within(2..5);
    let diverged: Vec<String> = s
        .runs
        .iter()
        .zip(&s.diverged)
        .filter(|(_, d)| !d.is_empty())
        .map(|((l, _, _), d)| format!("DIS on {l} observations {}", super::diverged_phrase(d, s.trials)))
        .collect();
    let check = match super::diverged_reason(&diverged) {
        Some(why) => Check::Undecidable(why),
        None => claims::check(ok, trials),
    };
    let (v, why) = check.verdict(
        rising && flat,
        "Cumulative points rise significantly from 100 to 500 to 953 observations while the asymptotes are equivalent within the margin (Holm-adjusted p < 0.05 throughout).",
        match (rising, flat) {
            (false, false) => "Cumulative points do not rise significantly at each step, and the asymptotes cannot be shown equivalent within the margin (Holm-adjusted).",
            (false, true) => "Cumulative points do not rise significantly at each step from 100 to 500 to 953 observations (Holm-adjusted).",
            _ => "The asymptotes cannot be shown equivalent within the margin (TOST, Holm-adjusted): they may differ by more than it.",
        },
    );
    Ok(Claim::from_spec(
        "C6.10",
        crate::report::evidence("C6.10")?,
        format!(
            "{}, asymptotes equivalent within ±{} (a tenth of the thesis's 1,224, fixed before the run): {}. (Pairwise two-sided p as in the figures: cumulative {}; asymptote {}.)",
            family.rule(),
            num(MARIO_MARGIN, 1),
            family.texts(1).join("; "),
            cum_p.join(", "),
            asym_p.join(", ")
        ),
        v,
        why,
    )?
    .with_number(scorecard::study_means(s, Metric::Cumulative))
    .with_number(scorecard::study_means(s, Metric::Asymptotic))
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}

fn study_section(
    s: &DemoLengthResults,
    main: Option<&MarioResults>,
    provenance: &Provenance,
) -> rlfd_report::Result<Section> {
    let trials = s.trials as usize;
    let labels: Vec<String> = s
        .runs
        .iter()
        .map(|(l, irl, _)| if irl.horizon == *l { format!("{l}") } else { format!("{l} (cut at {})", irl.horizon) })
        .collect();
    let mut t =
        Table::new("mario_demo_length", "DIS with demonstrations cut to 100, 500 and 953 observations", "Observations");
    t.caption = format!(
        "Mean ± sd over {trials} trials; RE-IRL on the first n observations of each of the ten demonstrations. Asymptotic: mean of the last 100 episodes."
    );
    t.columns = vec![
        ColumnGroup::new("Asymptotic (last 100)").with_key("asymptotic"),
        ColumnGroup::new("Cumulative").with_key("cumulative"),
    ];
    let g = NumFormat::grouped(1);
    for ((_, _, ts), label) in s.runs.iter().zip(&labels) {
        let cells = [Metric::Asymptotic, Metric::Cumulative]
            .iter()
            .map(|&m| {
                Summary::of(&values(ts, m)).map_or(Cell::Empty, |x| Cell::Num(Num::new(x.mean, g).with_spread(x.sd)))
            })
            .collect();
        t.rows.push(Row::new(label.clone(), cells));
    }
    t.check()?;
    let chart = |m: Metric, title: &str, y: &str| -> rlfd_report::Result<String> {
        let mut c = BarChart::new(title, "Observations per demonstration", y);
        c.categories = labels.clone();
        let summaries: Vec<Option<Summary>> =
            s.runs.iter().map(|(_, _, ts)| Summary::of(&values(ts, m)).ok()).collect();
        c.values = summaries.iter().map(|x| x.as_ref().map_or(0.0, |x| x.mean)).collect();
        c.errors = Some(summaries.iter().map(|x| x.as_ref().map_or(0.0, |x| x.se)).collect());
        for (a, b, p) in pairwise_p(s, m) {
            c.brackets.push(Bracket { from: a, to: b, label: format!("p = {}", p_value(p)) });
        }
        c.to_svg(provenance)
    };
    let fig66 = chart(
        Metric::Asymptotic,
        "Figure 6.6: DIS asymptote vs demonstration length",
        "Mean points, last 100 episodes",
    )?;
    let fig67 =
        chart(Metric::Cumulative, "Figure 6.7: DIS cumulative points vs demonstration length", "Cumulative points")?;
    let claim = length_claim(s)?;
    let mut text = String::from(
        "The thesis ran DIS with demonstrations of 100, 500 and 953 observations (10 trials each). Here each length is its own condition with its own trials and seeds; RE-IRL is refitted on the first n observations of each demonstration, RIPPER and SBS are unused by DIS.",
    );
    if main.is_some() {
        text.push_str(" The main experiment's DIS (all 953) is a separate sample of the same agent.");
    }
    Ok(Section::new(
        "Figures 6.6 and 6.7: DIS and the length of the demonstrations",
        vec![
            Block::paragraph(text),
            Block::Table(t),
            Block::Figure { file: "figure_6_6.svg".into(), caption: "DIS's asymptote (mean of the last 100 episodes) per demonstration length, mean ± s.e. over trials, with the pooled t-tests' p-values.".into(), svg: fig66 },
            Block::Figure { file: "figure_6_7.svg".into(), caption: "DIS's cumulative points per demonstration length, mean ± s.e. over trials, with the pooled t-tests' p-values.".into(), svg: fig67 },
            Block::Claims(vec![claim]),
        ],
    ))
}

fn level_section(r: &MarioResults, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let d: &Demonstration = &r.demonstrations.episodes[0];
    let level = Level::generate(r.params.level, d.level_seed);
    let title = format!(
        "Demonstration 1: level {} from {:?} mode, {} ticks, {} points, {}",
        d.level_seed,
        d.start_mode,
        d.len(),
        d.score,
        outcome(d.outcome)
    );
    let svg = level_scene(&level, &d.path, &title).to_svg(provenance)?;
    let world = World::new(level.clone(), d.start_mode);
    let counts = world.level().tile_counts();
    let text = format!(
        "Our simulator (`mario`) re-implements the Mario AI Benchmark 0.2.0's level generator (the version whose intermediate reward is the thesis's reward table), Mario's physics and the enemies in the benchmark's units (16 px cells, ticks of 1/24 s at the default frame rate), the benchmark's intermediate scoring and the 200-Mario-second timer (3,000 ticks). \
         Levels are {} cells long at difficulty {}, without hidden blocks, the benchmark's defaults (see Decisions); over 1,000 of our levels a level holds 42.4 goombas, 141 coin tiles, 47.8 question blocks and 86.6 bricks, beside the real benchmark's 42.6, 139, 47 and 86 (measured on it with the oracle's `LevelStats`; tested in `rlfd-mario`'s `oracle_levels`). This level has {} coins, {} question blocks, {} bricks, {} hidden blocks and {} enemy templates; the exit is at column {}. \
         `cargo xtask render mario --level-seed S` draws any level the same way.",
        r.params.level.width,
        r.params.level.difficulty,
        counts[tile::COIN as usize],
        counts[tile::QUESTION_COIN as usize]
            + counts[tile::QUESTION_POWERUP as usize]
            + counts[tile::QUESTION_COINS as usize],
        counts[tile::BRICK as usize] + counts[tile::BRICK_COIN as usize] + counts[tile::BRICK_POWERUP as usize],
        counts[tile::HIDDEN as usize],
        level.templates().len(),
        level.x_exit()
    );
    Ok(Section::new(
        "The Mario domain",
        vec![
            Block::paragraph(text),
            Block::Figure {
                file: "figure_mario_level.svg".into(),
                caption: "A generated level (solid tiles grey, the exit green; g goomba, gk/rk green/red koopa, s spiky, p piranha plant) and the path of the first demonstration.".into(),
                svg,
            },
        ],
    ))
}

fn demonstrations_section(r: &MarioResults) -> rlfd_report::Result<Section> {
    let s = &r.demonstrations.stats;
    let mut t = Table::new("mario_demonstration_stats", "The Mario demonstrations, measured", "Statistic");
    t.columns = vec![ColumnGroup::new("Value")];
    let g = NumFormat::grouped(1);
    t.rows.push(Row::new(
        "Demonstrations",
        vec![Cell::compare(Num::new(s.lengths.len() as f64, NumFormat::Integer), demo_thesis::COUNT as f64)],
    ));
    t.rows.push(Row::new("Mean score (HMN)", vec![Cell::compare(Num::new(s.mean_score, g), demo_thesis::MEAN_SCORE)]));
    t.rows.push(Row::new(
        "10th-longest (observations)",
        vec![Cell::compare(Num::new(s.tenth_longest as f64, NumFormat::Integer), demo_thesis::TENTH_LONGEST as f64)],
    ));
    t.rows.push(Row::new("Levels finished", vec![Cell::ours_only(Num::new(s.wins as f64, NumFormat::Integer))]));
    t.rows.push(Row::new("Deaths", vec![Cell::ours_only(Num::new(s.deaths as f64, NumFormat::Integer))]));
    t.rows.push(Row::new(
        "Timeouts (3,000 ticks)",
        vec![Cell::ours_only(Num::new(s.timeouts as f64, NumFormat::Integer))],
    ));
    t.rows.push(Row::new("Stuck, escapes tried", vec![Cell::ours_only(Num::new(s.stuck as f64, NumFormat::Integer))]));
    let lengths: Vec<String> = s.lengths.iter().map(|l| l.to_string()).collect();
    let scores: Vec<String> = s.scores.iter().map(|x| format!("{x:.0}")).collect();
    t.notes = vec![format!("Lengths: {}. Scores: {}.", lengths.join(", "), scores.join(", "))];
    t.check()?;
    let model = demonstrator::MarioDemonstrator::thesis();
    let text = format!(
        "The thesis's demonstrator was a person; ours (`mario::demonstrator`) is a scripted expert that looks {} ticks ahead on a copy of the game every {} ticks, walking right and choosing among walking, jumping (three heights, three delays), waiting and a run-up, preferring to stay alive, then unhurt, then to gain ground and points; in fire mode it throws fireballs at enemies ahead. \
         Points weigh {} against pixels gained. Noise: with probability {} per tick it presses a random one of the 12 actions, and at each plan made on the ground it pauses for {} ticks with probability {} where standing still is safe. When its farthest position has not grown by a cell in {} ticks of play it backs up and tries escapes instead of pressing into the obstacle: run-ups (walking or running), hop-backs out of a narrow pit, double jumps and jumps straight up that break a brick overhead; when two escapes in a row have failed, it fiddles (the best of 256 imagined random key sequences of 200 ticks). \
         Calibrated on the thesis's inputs only (`mario::demonstrator::calibrate`, rerun by a test): slip, pause and the weight of points jointly on a grid, minimising the squared relative errors of the mean score (1,224) and of the expected 10th-longest of ten episodes (953), over {} episodes on fixed calibration levels, every episode kept. A won level is worth about 2,000 points here, so the thesis's two figures together need about four episodes in ten to fail late; the calibrated player fails mostly by slowness (timeouts).",
        demonstrator::HORIZON,
        demonstrator::DECISION_TICKS,
        model.greed,
        model.slip,
        demonstrator::PAUSE_TICKS,
        model.pause_start,
        demonstrator::STUCK_TICKS,
        demonstrator::CALIBRATION_DEMOS
    );
    let choice = format!(
        "The set is the first ten episodes the demonstrator plays from the master seed: every episode is kept as it ends (won, died or timed out); none is redone and no set is chosen among others, so nothing is selected by its length or its outcome. \
         It holds {} won, {} died and {} timed-out episodes; the player found itself stuck {} times in all and tried an escape each time (see the table).",
        s.wins, s.deaths, s.timeouts, s.stuck
    );
    Ok(Section::new(
        "The Mario demonstrations",
        vec![Block::paragraph(text), Block::paragraph(choice), Block::Table(t)],
    ))
}

fn learned_section(r: &MarioResults, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let irl = &r.inputs.irl;
    let mut theta: Vec<(f64, &str)> = irl.fit.scaled_weights.iter().copied().zip(NAMES).collect();
    theta.sort_by(|a, b| b.0.abs().total_cmp(&a.0.abs()));
    let top: Vec<String> = theta.iter().take(6).map(|(w, n)| format!("{n} {w:.3}")).collect();
    let irl_text = format!(
        "RE-IRL on the first {} observations of each demonstration (features: the 27 variables, scaled to their ranges; undiscounted counts; 1,000 uniform-policy baseline rollouts on random levels; Hoeffding tolerance δ = 0.05). The largest weights over the scaled variables: {}. {}",
        irl.horizon,
        top.join(", "),
        super::irl::fit_sentence(&irl.fit, &crate::shaping::IrlSettings::thesis())
    );
    let mut rules = String::new();
    for line in r.inputs.agents.rules.to_string().lines() {
        let _ = write!(rules, "`{line}` ");
    }
    let rules_text = format!(
        "RIPPER as the thesis ran it, Weka 3.6's JRip with its defaults (drawing from Weka's own random stream, so these are the rules Weka prints for this data), on the {} demonstrated pairs gives {} rules plus a default (training accuracy {:.1} %); HAT's bonus follows them: {}",
        r.demonstrations.set.state_action_pairs().count(),
        r.inputs.agents.rules.rules.len(),
        100.0 * r.inputs.rules_accuracy,
        rules.trim_end()
    );
    Ok(Section::new(
        "What the Mario agents learned from",
        vec![
            Block::paragraph(irl_text),
            Block::Table(super::irl::weights_table("mario_irl_weights", "Mario's RE-IRL weights", &NAMES, &irl.fit)?),
            super::irl::objective_figure("mario_irl_objective.svg", "Mario's RE-IRL fit", &irl.fit, provenance)?,
            Block::paragraph(super::irl::draws_sentence(
                &irl.fit,
                &r.inputs.irl_draws,
                &crate::shaping::IrlSettings::thesis(),
            )),
            Block::Table(super::irl::draws_table(
                "mario_irl_draws",
                "Mario's θ over baseline draws",
                &NAMES,
                &irl.fit,
                &r.inputs.irl_draws,
            )?),
            Block::paragraph(rules_text),
        ],
    ))
}

fn parameters_table(r: &MarioResults) -> rlfd_report::Result<Table> {
    let p = &r.params;
    let mut rows = Parameters::new("mario_parameters", "Mario parameters");
    rows.thesis_says("Trials per agent", p.trials, "{ch6.mario.trials} (paper scale)");
    rows.thesis_says("Episodes per trial", p.episodes, "{ch6.mario.episodes:,0} (paper scale)");
    rows.row("Level width (cells)", p.level.width, "the benchmark 0.2.0's default (-ll 256, exit at 255)");
    rows.row("Level difficulty", p.level.difficulty, "our choice, from the demonstrator (see Decisions)");
    rows.row("Timer", "200 Mario seconds = 3,000 ticks", "thesis / benchmark");
    rows.thesis_says("Tilings", p.tilings, "\"number of tiles = {ch6.mario.params.tilings}\"");
    rows.row("Tile width: booleans and directions", p.boolean_width, "our choice");
    rows.row("Tile width: closest enemy's offsets (cells)", p.distance_width, "our choice");
    rows.row("Hashed weights per action", p.hash_size, "our choice");
    rows.thesis("α per tiling", format!("{} (0.01/32)", p.alpha));
    rows.thesis_says("β (DIS) per active feature", p.beta, "\"β = {ch6.mario.params.beta}\"");
    rows.thesis("γ", p.gamma);
    rows.thesis("λ", p.lambda);
    rows.thesis("ε", p.epsilon);
    rows.thesis("Shaping scale (SIS, DIS, SBS)", p.shaping_scale);
    rows.row("HAT's bonus B", p.hat_scale, "the hat-scale reading (default 10, chapter 5's B; the thesis gives none)");
    super::terminal_rows(&mut rows, "a terminal state", p.terminal_potential, p.advice_terminal);
    rows.row(
        "HAT's Value Bonus",
        match p.hat_bonus {
            crate::shaping::HatBonus::QInit => "Q-initialisation".to_string(),
            crate::shaping::HatBonus::Persistent { forced_episodes } => {
                format!("bonus at every choice, rules' action forced for {forced_episodes} episodes")
            }
        },
        "the hat-bonus reading (default q-init, chapter 6's text)",
    );
    rows.row(
        "Equivalence margin (C6.10)",
        format!("±{}", num(MARIO_MARGIN, 1)),
        "our choice before the run: a tenth of the thesis's 1,224",
    );
    rows.row("SBS σ: booleans and directions", p.sbs_sigma_boolean, "the sbs-sigma reading (default: half a tile)");
    rows.row("SBS σ: closest enemy's offsets", p.sbs_sigma_distance, "the sbs-sigma reading (default: half a tile)");
    rows.row("Eligibility traces", format!("{:?}, dropped below 0.01", p.traces), "our choice");
    rows.calibrated("Demonstrator slip", demonstrator::MarioDemonstrator::thesis().slip, "");
    rows.calibrated("Demonstrator pause", demonstrator::MarioDemonstrator::thesis().pause_start, "");
    rows.table()
}

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    super::DEVIATIONS.deviations("mario")
}

/// Calls `write(experiment, condition, trials)` for every condition the
/// data files list: the main agents, DIS at the other dis-beta levels, the
/// length study's runs.
fn each_condition(
    r: &MarioResults,
    study: Option<&DemoLengthResults>,
    mut write: impl FnMut(&str, &str, &[MarioTrial]),
) {
    for (agent, ts) in &r.trials {
        write("mario", agent.label(BASELINE), ts);
    }
    for run in r.levels.runs.iter().filter(|run| !run.main) {
        write("mario", &format!("DIS dis-beta={}", run.level), &run.trials);
    }
    if let Some(st) = study {
        for (l, _, ts) in &st.runs {
            write("mario-demo-length", &format!("DIS-{l}"), ts);
        }
    }
}

/// One row of `binned.csv`: a trial's mean points and ticks over a bin of episodes.
#[derive(Serialize)]
struct BinRow {
    experiment: String,
    condition: String,
    trial: usize,
    first_episode: usize,
    last_episode: usize,
    mean_points: f64,
    mean_ticks: f64,
}

fn binned_csv(r: &MarioResults, study: Option<&DemoLengthResults>) -> Vec<u8> {
    let bin = bin_size(r.params.episodes);
    let mut rows = Vec::new();
    let write = |experiment: &str, condition: &str, ts: &[MarioTrial]| {
        for (trial, t) in ts.iter().enumerate() {
            for (b, chunk) in t.returns.chunks(bin).enumerate() {
                let first = b * bin;
                let steps = &t.steps[first..first + chunk.len()];
                rows.push(BinRow {
                    experiment: experiment.to_owned(),
                    condition: condition.to_owned(),
                    trial,
                    first_episode: first + 1,
                    last_episode: first + chunk.len(),
                    mean_points: chunk.iter().map(|&v| f64::from(v)).sum::<f64>() / chunk.len() as f64,
                    mean_ticks: steps.iter().map(|&v| f64::from(v)).sum::<f64>() / steps.len() as f64,
                });
            }
        }
    };
    each_condition(r, study, write);
    csv_of(rows)
}

/// One row of `metrics.csv`: a trial's three metrics, wins and ticks.
#[derive(Serialize)]
struct MetricsRow {
    experiment: String,
    condition: String,
    trial: usize,
    initial: f64,
    asymptotic: f64,
    cumulative: f64,
    wins: u32,
    ticks: u64,
}

fn metrics_csv(r: &MarioResults, study: Option<&DemoLengthResults>) -> Vec<u8> {
    let mut rows = Vec::new();
    let write = |experiment: &str, condition: &str, ts: &[MarioTrial]| {
        for (trial, t) in ts.iter().enumerate() {
            rows.push(MetricsRow {
                experiment: experiment.to_owned(),
                condition: condition.to_owned(),
                trial,
                initial: t.metric(Metric::Initial),
                asymptotic: t.metric(Metric::Asymptotic),
                cumulative: t.metric(Metric::Cumulative),
                wins: t.ends.wins,
                ticks: t.total_steps(),
            });
        }
    };
    each_condition(r, study, write);
    csv_of(rows)
}

/// One row of `first_episodes.csv`.
#[derive(Serialize)]
struct FirstEpisodeRow {
    experiment: String,
    condition: String,
    trial: usize,
    episode: usize,
    points: i32,
    ticks: u16,
}

fn first_episodes_csv(r: &MarioResults, study: Option<&DemoLengthResults>) -> Vec<u8> {
    let mut rows = Vec::new();
    let write = |experiment: &str, condition: &str, ts: &[MarioTrial]| {
        for (trial, t) in ts.iter().enumerate() {
            for (e, (&points, &ticks)) in t.returns.iter().zip(&t.steps).take(FIRST_EPISODES).enumerate() {
                rows.push(FirstEpisodeRow {
                    experiment: experiment.to_owned(),
                    condition: condition.to_owned(),
                    trial,
                    episode: e + 1,
                    points,
                    ticks,
                });
            }
        }
    };
    each_condition(r, study, write);
    csv_of(rows)
}

/// One row of `demonstration_scores.csv`.
#[derive(Serialize)]
struct DemonstrationRow {
    demonstration: usize,
    level_seed: u64,
    start_mode: String,
    observations: usize,
    points: f64,
    outcome: &'static str,
}

fn demonstration_scores_csv(r: &MarioResults) -> Vec<u8> {
    csv_of(r.demonstrations.episodes.iter().enumerate().map(|(k, d)| DemonstrationRow {
        demonstration: k + 1,
        level_seed: d.level_seed,
        start_mode: format!("{:?}", d.start_mode),
        observations: d.len(),
        points: d.score,
        outcome: outcome(d.outcome),
    }))
}
