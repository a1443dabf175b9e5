//! Chapter 6's report content: tables beside the thesis's, figures, claims,
//! parameters, decisions and raw data, built from stored results only.

mod agent_tables;
mod claims;
mod figures;
mod irl;
pub mod mario;
mod metrics;
mod scorecard;

use std::fmt::Write as _;

use rlfd_report::figure::{LegendPosition, LineChart, Series, SeriesStyle};
use rlfd_report::parameters::Parameters;
use rlfd_report::prose::DataFile;
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, ChapterReport, Deviation, Provenance, Section};
use rlfd_stats::curve::episodes_to_surpass;
use rlfd_stats::format::thousands;

use crate::agents::{MazeAgent, MazeTrial};
use crate::experiment::{DemonstrationSource, IrlScaleResults, MazeResults};
use crate::maze::MazeLayout;
use crate::maze::demonstrator::thesis as demo_thesis;
use crate::maze::layout::{ADDED_THIN_WALL, ADDED_WALL_CELLS};
use crate::maze::search::DistanceField;
use crate::{CHAPTER, Ch6Results};
use agent_tables::{MetricColumn, TableText};

pub use metrics::{Metric, MetricTable};

/// The chapter's title.
pub const TITLE: &str = "Chapter 6: Learning from demonstration for shaping through IRL (SIS, DIS)";

/// Random MDPs checked for claim C6.11 in the report.
const SHAPING_CHECK_MDPS: usize = 200;

/// Builds the chapter's report from its results.
pub fn chapter_report(results: &Ch6Results, provenance: &Provenance) -> rlfd_report::Result<ChapterReport> {
    let mut sections = Vec::new();
    if let Some(maze) = &results.maze {
        sections.extend(maze_sections(maze, provenance)?);
    }
    if let Some(k) = &results.irl_scale {
        // Right after the claims, before the domain's details.
        let at = sections.iter().position(|s| s.title.starts_with("Claims")).map_or(sections.len(), |i| i + 1);
        sections.insert(at, irl_scale_section(k, results.maze.as_ref(), provenance)?);
    }
    sections.extend(mario::sections(
        results.mario.as_ref(),
        results.demo_length.as_ref(),
        results.dis_beta.as_ref(),
        provenance,
    )?);
    sections.push(Section::new(
        "Claim C6.11: potential-based shaping keeps the optimal policy",
        vec![Block::Claims(vec![claims::shaping_invariance_claim(SHAPING_CHECK_MDPS)?])],
    ));
    Ok(ChapterReport { slug: CHAPTER.into(), title: TITLE.into(), provenance: provenance.clone(), sections })
}

fn maze_sections(r: &MazeResults, provenance: &Provenance) -> rlfd_report::Result<Vec<Section>> {
    let table = MetricTable::new(&r.trials);
    let hmn = r.demonstrations.hmn();
    let surpass: Vec<(MazeAgent, Option<usize>)> = MazeAgent::ALL
        .iter()
        .filter_map(|&a| r.trials.get(&a).map(|ts| (a, episodes_to_surpass(&metrics::mean_curve(ts).0, hmn))))
        .collect();
    let trials = r.params.trials as usize;
    let steps: u64 = r.trials.values().flatten().map(|t| t.steps.iter().map(|&s| u64::from(s)).sum::<u64>()).sum();
    let failures: u32 = r.trials.values().flatten().map(|t| t.failures).sum();

    let summary = format!(
        "Five agents (SARSA(λ), SIS, DIS, HAT, SBS) learn the modified Dyna Maze for {} episodes, {} trials each, at the *{}* scale with master seed {} ({} agent steps in all; {} episodes hit the 6,000-step cap). \
         Every number below is computed from the stored per-episode returns; the thesis's value stands beside ours in every cell. \
         The demonstrator's mean return is HMN = {} (thesis: −327.5). Initial = first episode, asymptotic = last episode (as the thesis's Table 6.1), cumulative = sum over all episodes.",
        r.params.episodes,
        trials,
        r.scale,
        r.seed,
        thousands(steps as f64, 0),
        thousands(f64::from(failures), 0),
        thousands(hmn, 1).replace('-', "−")
    );

    let mut out = vec![Section::new("Maze: what was run", vec![Block::paragraph(summary)])];
    out.push(Section::new(
        "Table 6.1: initial, asymptotic and cumulative reward",
        vec![Block::Table(table_6_1(&table, hmn, trials)?), Block::Table(surpass_table(&surpass, hmn)?)],
    ));
    out.push(Section::new("Table 6.2: two-sample t-tests", vec![Block::Table(table_6_2(&table, trials)?)]));
    out.push(Section::new(
        "Figure 6.4: learning curves",
        vec![
            Block::Figure {
                file: "figure_6_4.svg".into(),
                caption:
                    "Reward per episode, mean ± standard error over trials, with the demonstrator's mean (dashed)."
                        .into(),
                svg: figures::figure_6_4(r, hmn, None, provenance)?,
            },
            Block::Figure {
                file: "figure_6_4_zoom.svg".into(),
                caption: "The same curves between −3,000 and 0.".into(),
                svg: figures::figure_6_4(r, hmn, Some((-3000.0, 0.0)), provenance)?,
            },
        ],
    ));
    out.push(Section::new(
        "Claims C6.1–C6.5",
        vec![Block::Claims(scorecard::maze_numbers(
            claims::maze_claims(&table, &surpass, hmn, trials, r.scale, maze_diverged(r))?,
            &table,
            &surpass,
            hmn,
        ))],
    ));
    out.push(maze_domain_section(provenance)?);
    out.push(demonstrations_section(r, hmn, provenance)?);
    out.push(learned_inputs_section(r, provenance)?);
    out.push(Section::new("Parameters", vec![Block::Parameters(parameters_table(r)?)]));
    out.push(Section::new("Decisions and deviations", vec![Block::Deviations(deviations()?)]));
    out.push(Section::new(
        "Data",
        vec![
            Block::DataFile {
                file: "maze_returns.csv".into(),
                description: "Every episode of every trial: agent, trial, episode (from 1), return, steps.".into(),
                bytes: returns_csv(r),
            },
            Block::DataFile {
                file: "maze_demonstrations.csv".into(),
                description:
                    "The demonstrations the agents learned from (states x, y; action 0 left, 1 right, 2 up, 3 down)."
                        .into(),
                bytes: demonstrations_csv(r),
            },
        ],
    ));
    Ok(out)
}

/// The sensitivity study: SIS and DIS with the IRL reward scaled by κ.
fn irl_scale_section(
    k: &IrlScaleResults,
    maze: Option<&MazeResults>,
    provenance: &Provenance,
) -> rlfd_report::Result<Section> {
    let mut runs: Vec<(String, &[MazeTrial])> = Vec::new();
    if let Some(m) = maze {
        for agent in [MazeAgent::Sarsa, MazeAgent::Sis, MazeAgent::Dis] {
            if let Some(ts) = m.trials.get(&agent) {
                let label = if agent == MazeAgent::Sarsa {
                    agent.label().to_string()
                } else {
                    format!("{} κ = 1", agent.label())
                };
                runs.push((label, ts.as_slice()));
            }
        }
    }
    for (agent, kappa, ts) in &k.runs {
        runs.push((format!("{} κ = {kappa}", agent.label()), ts.as_slice()));
    }
    let mut t = Table::new(
        "maze_irl_scale",
        "Sensitivity: SIS and DIS with the IRL reward scaled by κ (not in the thesis)",
        "Agent",
    );
    t.caption = "Mean ± sd over trials; κ = 1 and SARSA are the main experiment's runs. The thesis does not give the size of its IRL reward, which sets the size of the shaping; κ scales R_IRL(s) before the shaping scale of 100 applies.".into();
    t.columns = Metric::ALL.iter().map(|m| ColumnGroup::new(m.header())).collect();
    let g = NumFormat::grouped(2);
    for (label, ts) in &runs {
        let cells = Metric::ALL
            .iter()
            .map(|&m| {
                let values: Vec<f64> = ts.iter().map(|t| m.of(t)).collect();
                match rlfd_stats::Summary::of(&values) {
                    Ok(s) => Cell::Num(Num::new(s.mean, g).with_spread(s.sd)),
                    Err(_) => Cell::Empty,
                }
            })
            .collect();
        t.rows.push(Row::new(label.clone(), cells));
    }
    t.check()?;
    let mut chart = LineChart::new(
        "Sensitivity: reward per episode for each κ (mean over trials)",
        "Episode",
        "Reward per episode",
    );
    for (label, ts) in &runs {
        let (mean, _) = metrics::mean_curve(ts);
        chart.series.push(Series {
            name: label.clone(),
            points: mean.iter().enumerate().map(|(e, &y)| ((e + 1) as f64, y)).collect(),
            band: None,
            style: SeriesStyle::Line,
        });
    }
    chart.y_range = Some((-3000.0, 0.0));
    chart.legend = LegendPosition::Outside;
    Ok(Section::new(
        "Sensitivity to the size of the IRL reward (not in the thesis)",
        vec![
            Block::paragraph(
                "RE-IRL fixes the direction of the reward weights θ, not their size; this reproduction keeps θ at unit length, so R_IRL(s) is of order 1 and, with the thesis's shaping scale of 100, SIS's potential differences are about 2 per step and DIS's shaping, which converges to 100 · R_IRL(s) per step, far outweighs the step cost of −1. The thesis's choice of a scale of 100 suggests its IRL reward was much smaller. The same agents with R_IRL multiplied by κ show how the comparison with SARSA depends on that unknown. The main experiment (κ = 1) stays the reproduction's answer: κ was not chosen from these runs.",
            ),
            Block::Table(t),
            Block::Figure {
                file: "figure_maze_irl_scale.svg".into(),
                caption: "Mean reward per episode between −3,000 and 0, SARSA and SIS/DIS at each κ.".into(),
                svg: chart.to_svg(provenance)?,
            },
        ],
    ))
}

/// The Maze's metric columns, in the thesis's order.
fn maze_columns() -> Vec<MetricColumn> {
    Metric::ALL.iter().map(|m| MetricColumn { header: m.header(), key: m.key() }).collect()
}

/// The episodes of divergence as a phrase: "in 3 of 10 trials (episodes 212–340)".
pub(super) fn diverged_phrase(episodes: &[u32], trials: u32) -> String {
    let lo = episodes.iter().min().copied().unwrap_or(0);
    let hi = episodes.iter().max().copied().unwrap_or(0);
    let when = if lo == hi { format!("episode {lo}") } else { format!("episodes {lo}–{hi}") };
    format!("in {} of {trials} trials ({when})", episodes.len())
}

/// The reason of a claim that rests on diverged learners, one part per
/// condition ("DIS in 3 of 10 trials (…)"); none when no part.
pub(super) fn diverged_reason(parts: &[String]) -> Option<String> {
    (!parts.is_empty()).then(|| {
        format!(
            "Not evaluable: the learner diverged (a value or shaping reward became non-finite or exceeded {:e}): {}. Diverged trials are recorded, not tabulated or tested.",
            rlfd_rl::DIVERGENCE_BOUND,
            parts.join("; ")
        )
    })
}

/// Why the Maze's claims cannot be judged, when a learner diverged.
fn maze_diverged(r: &MazeResults) -> Option<String> {
    let parts: Vec<String> =
        r.diverged.iter().map(|(a, eps)| format!("{} {}", a.label(), diverged_phrase(eps, r.params.trials))).collect();
    diverged_reason(&parts)
}

fn table_6_1(table: &MetricTable, hmn: f64, trials: usize) -> rlfd_report::Result<Table> {
    let rows: Vec<(&str, Vec<Vec<f64>>)> = MazeAgent::ALL
        .iter()
        .map(|&a| (a.label(), Metric::ALL.iter().map(|&m| table.values(a, m).to_vec()).collect()))
        .collect();
    agent_tables::means_table(
        TableText {
            id: "table_6_1",
            title: "Table 6.1: Maze, mean reward per agent",
            caption: format!("Mean ± sd over {trials} trials (ours) beside the thesis's mean over 25 trials."),
            thesis_key: "ch6.maze.table_6_1",
            notes: vec!["HMN is the demonstrator's mean return over its ten demonstrations (−1 per recorded step, +10 at the goal), as the thesis counts it.".into()],
        },
        &maze_columns(),
        &rows,
        hmn,
        NumFormat::grouped(2),
    )
}

fn table_6_2(table: &MetricTable, trials: usize) -> rlfd_report::Result<Table> {
    let pairs: Vec<(String, Vec<(Vec<f64>, Vec<f64>)>)> = metrics::thesis_pairs()
        .iter()
        .map(|&(a, b)| {
            let samples = Metric::ALL.iter().map(|&m| (table.values(a, m).to_vec(), table.values(b, m).to_vec()));
            (metrics::pair_label(a, b), samples.collect())
        })
        .collect();
    agent_tables::p_value_table(
        TableText {
            id: "table_6_2",
            title: "Table 6.2: Maze, p-values of two-sample t-tests",
            caption: format!(
                "Pooled-variance Student t-tests (MATLAB ttest2's default, as the thesis) on {trials} trials per agent, beside the thesis's p-values; Welch's test (unequal variances) for comparison."
            ),
            thesis_key: "ch6.maze.table_6_2",
            notes: vec!["* p ≤ 0.05, ** p ≤ 0.01, *** p ≤ 0.001, **** p ≤ 0.0001. p-values are rounded to 4 significant digits. A dash: the test is undefined (both samples constant).".into()],
        },
        &maze_columns(),
        &pairs,
    )
}

fn surpass_table(surpass: &[(MazeAgent, Option<usize>)], hmn: f64) -> rlfd_report::Result<Table> {
    let rows: Vec<(&str, Option<usize>)> = surpass.iter().map(|&(a, e)| (a.label(), e)).collect();
    agent_tables::surpass_table(
        TableText {
            id: "maze_episodes_to_surpass",
            title: "Episodes to surpass the demonstrator",
            caption: format!(
                "The episode from which the trial-mean reward stays above the demonstrator's mean (ours: HMN = {hmn:.1}) to the end of the run; a curve that starts above, dips and recovers counts from its recovery."
            ),
            thesis_key: "ch6.maze.episodes_to_surpass_demonstrator",
            notes: Vec::new(),
        },
        &rows,
    )
}

fn maze_domain_section(provenance: &Provenance) -> rlfd_report::Result<Section> {
    let field = DistanceField::to_goal(&MazeLayout::thesis(), 2);
    let optimal = field.distance(crate::maze::layout::START.0, crate::maze::layout::START.1);
    let dyna = DistanceField::to_goal(&MazeLayout::dyna(), 2)
        .distance(crate::maze::layout::START.0, crate::maze::layout::START.1);
    let added: Vec<String> = ADDED_WALL_CELLS.iter().map(|(r, c)| format!("({r}, {c})")).collect();
    let (x0, y0, x1, y1) = ADDED_THIN_WALL.unit_square();
    let text = format!(
        "The thesis draws its \"modified Dyna Maze\" but does not list the walls; it gives the optimal path's length, 2.665 (133 steps of 0.02). \
         The Dyna Maze of Sutton & Barto scaled to the unit square needs only {dyna} steps, so we kept its walls, start and goal and added the cells {} (row from the top, column) and a thin wall [{x0:.3}, {x1:.3}) × [{y0:.3}, {y1:.3}). \
         A breadth-first search finds the shortest path: {optimal} steps, length {:.2} (the thesis: 133 ± 2 was the target).",
        added.join(", "),
        f64::from(optimal) * 0.02
    );
    Ok(Section::new(
        "The Maze (Figures 6.1 and 6.3)",
        vec![
            Block::paragraph(text),
            Block::Figure {
                file: "figure_6_1.svg".into(),
                caption: "The modified Dyna Maze.".into(),
                svg: figures::figure_6_1(provenance)?,
            },
            Block::Figure {
                file: "figure_6_3.svg".into(),
                caption: "An optimal path, piecewise linear.".into(),
                svg: figures::figure_6_3(provenance)?,
            },
        ],
    ))
}

fn demonstrations_section(r: &MazeResults, hmn: f64, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let d = &r.demonstrations;
    let lengths: Vec<f64> = d.set.lengths().iter().map(|&l| (l - 1) as f64).collect();
    let summary = rlfd_stats::Summary::of(&lengths).ok();
    let mut t = Table::new("maze_demonstration_stats", "The demonstrations, measured", "Statistic");
    t.columns = vec![ColumnGroup::new("Value")];
    let f1 = NumFormat::fixed(1);
    let pct = NumFormat::Percent { decimals: 1 };
    let mut row = |label: &str, ours: f64, theirs: f64, format: NumFormat| {
        t.rows.push(Row::new(label, vec![Cell::compare(Num::new(ours, format), theirs)]))
    };
    row("Demonstrations", lengths.len() as f64, demo_thesis::COUNT as f64, NumFormat::Integer);
    if let Some(s) = &summary {
        row("Shortest (steps)", s.min, demo_thesis::LENGTH_RANGE.0 as f64, NumFormat::Integer);
        row("Longest (steps)", s.max, demo_thesis::LENGTH_RANGE.1 as f64, NumFormat::Integer);
        row("Mean length (steps)", s.mean, demo_thesis::MEAN_LENGTH, f1);
        row("Sd of length (steps)", s.sd, demo_thesis::SD_LENGTH, NumFormat::fixed(2));
    }
    row("Mean return (HMN)", hmn, demo_thesis::HMN, f1);
    if let Some(s) = &d.stats {
        row("Longer than the optimal path", s.longer_than_optimal_pct, demo_thesis::LONGER_THAN_OPTIMAL_PCT, pct);
        row("Suboptimal actions: moves later undone", s.undone_moves_pct, demo_thesis::SUBOPTIMAL_ACTIONS_PCT, pct);
        row(
            "Suboptimal actions: moves away from the goal",
            s.suboptimal_actions_pct,
            demo_thesis::SUBOPTIMAL_ACTIONS_PCT,
            pct,
        );
        row("Moves into a wall", s.wall_touches as f64, 0.0, NumFormat::Integer);
    }
    t.notes = vec![
        "Steps are recorded moves at the demonstrations' resolution of 0.01 (see Decisions). \"Longer than the optimal path\" compares the mean path length with the shortest path at the same resolution. The thesis's \"actions that did not help the agent to navigate toward the goal\" is shown in two readings: a move the demonstrator later undoes (it comes back to the position the move left: the calibrated reading), and a move that increases the shortest-path distance to the goal (which at 27.4 % longer must be about 10.8 %, since every move but a sideways one beside the goal region changes that distance by one).".into(),
        "Calibrated: the slip and drift probabilities, jointly on the mean length (337.5) and on 1.5 % of moves later undone, over simulated demonstrations (never a learner). Everything else in this table is a consequence of the model, not a fit.".into(),
    ];
    t.check()?;
    let source = match &d.source {
        DemonstrationSource::Synthetic => {
            "the synthetic demonstrator (`maze::demonstrator`), seeded from the master seed".to_string()
        }
        DemonstrationSource::File(p) => format!("the file `{}`", p.display()),
    };
    Ok(Section::new(
        "The demonstrations (Figure 6.2)",
        vec![
            Block::paragraph(format!(
                "The ten demonstrations come from {source}. The thesis's demonstrator was a person; ours is a model calibrated on the demonstration statistics the thesis reports, never on a learning result."
            )),
            Block::Table(t),
            Block::Figure {
                file: "figure_6_2.svg".into(),
                caption: "The demonstrations.".into(),
                svg: figures::figure_6_2(r, provenance)?,
            },
        ],
    ))
}

fn learned_inputs_section(r: &MazeResults, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let fit = &r.inputs.irl;
    let s = &r.inputs.irl_settings;
    let irl_text = format!(
        "RE-IRL on the demonstrations padded to {} observations (features x and y, undiscounted counts, {} uniform-policy baseline rollouts, Hoeffding tolerance δ = {} giving ε = {:.2}): θ = ({:.4}, {:.4}), so R_IRL(s) = {:.4}·x {} {:.4}·y. {}",
        r.inputs.horizon,
        s.baseline_trajectories,
        s.delta,
        fit.tolerance[0],
        fit.scaled_weights[0],
        fit.scaled_weights[1],
        fit.weights[0],
        if fit.weights[1] < 0.0 { "−" } else { "+" },
        fit.weights[1].abs(),
        irl::fit_sentence(fit, s)
    );
    let mut rules = String::new();
    for line in r.inputs.agents.rules.to_string().lines() {
        let _ = write!(rules, "`{line}` ");
    }
    let rules_text = format!(
        "RIPPER (Weka JRip's defaults) on the {} demonstrated (x, y) → move pairs gives {} rules plus a default; stratified 10-fold cross-validation accuracy {:.1} %. HAT's initial action values follow this list: {}",
        r.demonstrations.set.state_action_pairs().count(),
        r.inputs.agents.rules.rules.len(),
        100.0 * r.inputs.rules_cv.accuracy,
        rules.trim_end()
    );
    let sbs_text = format!("SBS's potential uses the same pairs with σ = {} in x and y.", r.params.sbs_sigma);
    Ok(Section::new(
        "What the agents learned from",
        vec![
            Block::paragraph(irl_text),
            irl::objective_figure("maze_irl_objective.svg", "The Maze's RE-IRL fit", fit, provenance)?,
            Block::paragraph(rules_text),
            Block::paragraph(sbs_text),
        ],
    ))
}

fn parameters_table(r: &MazeResults) -> rlfd_report::Result<Table> {
    let p = &r.params;
    let mut rows = Parameters::new("maze_parameters", "Maze parameters");
    rows.thesis_says("Trials per agent", p.trials, "{ch6.maze.trials} (paper scale)");
    rows.thesis_says("Episodes per trial", p.episodes, "{ch6.maze.episodes} (paper scale)");
    rows.thesis("Step cap per episode", p.max_steps);
    rows.thesis_says("Tilings", p.tilings, "\"number of tiles = {ch6.maze.params.tilings}\"");
    rows.row("Tile width (x and y)", p.tile_width, "our choice");
    rows.thesis("α per tiling", format!("{} (0.25/32)", p.alpha));
    rows.thesis("β per tiling (DIS)", format!("{} (0.05/32)", p.beta));
    rows.thesis("γ", p.gamma);
    rows.thesis("λ", p.lambda);
    rows.thesis("ε", p.epsilon);
    rows.thesis("Shaping scale (SIS, DIS, SBS)", p.shaping_scale);
    rows.thesis("Shaping scale (HAT)", p.hat_scale);
    rows.row("SBS σ", p.sbs_sigma, "our choice");
    rows.row(
        "Eligibility traces",
        format!("{:?}, dropped below 0.01", p.traces),
        "our choice (Keepaway benchmark convention)",
    );
    rows.row(
        "IRL reward scale κ",
        p.irl_scale,
        "our choice (1: θ at unit length); the sensitivity experiment varies it",
    );
    rows.row("RE-IRL", "see \"What the agents learned from\"", "our choices");
    rows.table()
}

/// The chapter's decisions and deviations, kept as data in
/// `data/deviations.toml` (`maze` and `mario` lists).
pub(crate) const DEVIATIONS: DataFile = DataFile {
    path: "chapters/ch6-irl-shaping/data/deviations.toml",
    text: include_str!("../../data/deviations.toml"),
};

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    DEVIATIONS.deviations("maze")
}

fn returns_csv(r: &MazeResults) -> Vec<u8> {
    let mut s = String::from("agent,trial,episode,return,steps\n");
    for (agent, trials) in &r.trials {
        for (k, t) in trials.iter().enumerate() {
            for (e, (ret, steps)) in t.returns.iter().zip(&t.steps).enumerate() {
                let _ = writeln!(s, "{},{},{},{},{}", agent.label(), k, e + 1, ret, steps);
            }
        }
    }
    s.into_bytes()
}

fn demonstrations_csv(r: &MazeResults) -> Vec<u8> {
    let mut out = Vec::new();
    r.demonstrations.set.write_csv(&mut out).expect("writing to memory");
    out
}
