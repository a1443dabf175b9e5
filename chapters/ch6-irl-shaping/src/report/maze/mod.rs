//! The Maze's report sections (section 6.3.1): Tables 6.1 and 6.2 beside
//! the thesis's, Figures 6.1–6.4, the episodes to surpass the demonstrator,
//! claims C6.1–C6.5, the irl-scale sensitivity, the domain, the
//! demonstrations, what the agents learned from, parameters, decisions and
//! data. Built from stored results only.
//!
//! Metrics per trial: initial = the first episode's reward; asymptotic = the
//! last episode's (the thesis's "asymptotic (last episode)"); cumulative =
//! the sum over all episodes.

mod claims;
mod figures;
mod scorecard;

use std::fmt::Write as _;

use rlfd_report::data_file::csv_of;
use serde::Serialize;

use rlfd_report::parameters::Parameters;
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, Deviation, Provenance, Section};
use rlfd_stats::curve::{self, episodes_to_surpass};
use rlfd_stats::format::thousands;

use super::agent_tables::{self, TableText, metric_columns};
use super::levels::{self, LevelText};
use super::metrics::{Metric, MetricTable, Scored};
use super::{family, irl};
use crate::maze::MazeLayout;
use crate::maze::demonstrator::thesis as demo_thesis;
use crate::maze::experiment::{DemonstrationSource, MazeResults};
use crate::maze::layout::LayoutId;
use crate::maze::params::{BASELINE, MazeTrial};
use crate::maze::search::DistanceField;
use crate::readings::HmnUnits;
use crate::shaping::trials::{LevelRun, LevelRuns};
use crate::shaping::{Agent, HatBonus};

impl Scored for MazeTrial {
    const ASYMPTOTIC_HEADER: &'static str = "Asymptotic";

    fn metric(&self, m: Metric) -> f64 {
        let r = &self.returns;
        match m {
            Metric::Initial => curve::initial(r).unwrap_or(f64::NAN),
            Metric::Asymptotic => curve::asymptotic_last(r).unwrap_or(f64::NAN),
            Metric::Cumulative => curve::cumulative(r).unwrap_or(f64::NAN),
        }
    }
}

/// The trial-mean learning curve and its standard error, per episode.
pub fn mean_curve(trials: &[MazeTrial]) -> (Vec<f64>, Vec<f64>) {
    let curves: Vec<&[f64]> = trials.iter().map(|t| t.returns.as_slice()).collect();
    let mean = curve::mean_curve(&curves).unwrap_or_default();
    let se = curve::se_curve(&curves).unwrap_or_else(|_| vec![0.0; mean.len()]);
    (mean, se)
}

/// When the mean curve of `trials` rises above `hmn`: the episode from
/// which it stays above, and the first episode above it.
fn crossings(trials: &[MazeTrial], hmn: f64) -> (Option<usize>, Option<usize>) {
    let curve = mean_curve(trials).0;
    (episodes_to_surpass(&curve, hmn), curve.iter().position(|&v| v > hmn).map(|i| i + 1))
}

/// The readings this run follows that the Maze report's text depends on, as a sentence.
fn readings_sentence(r: &MazeResults) -> String {
    let units = match r.demonstrations.hmn_units {
        HmnUnits::Recorded => "counted per recorded step of 0.01, as the thesis (reading hmn-units=recorded)".to_string(),
        HmnUnits::AgentSteps => "counted at the agents' step of 0.02, half the recorded steps (reading hmn-units=agent-steps; the thesis counts per recorded step)".to_string(),
    };
    let hat = match r.params.hat_bonus {
        HatBonus::QInit => "HAT initialises its action values from the rules (reading hat-bonus=q-init)".to_string(),
        HatBonus::Persistent { forced_episodes } => format!(
            "HAT adds its bonus to the rules' action at every choice and takes the rules' action for the first {forced_episodes} episodes (reading hat-bonus=persistent)"
        ),
    };
    format!(
        "The maze is the {} layout (reading maze-layout={}); HMN is {units}; {hat}.",
        r.params.layout.name(),
        r.params.layout.name()
    )
}

/// Which agents stay above HMN from which episode, and first rise above it.
fn surpassing(r: &MazeResults, hmn: f64) -> Vec<(Agent, Option<usize>, Option<usize>)> {
    Agent::ALL
        .iter()
        .filter_map(|&a| {
            r.trials.get(&a).map(|ts| {
                let (stays, first) = crossings(ts, hmn);
                (a, stays, first)
            })
        })
        .collect()
}

/// Claims C6.1–C6.5, from the results alone (no figure, no bootstrap).
pub fn claims_of(r: &MazeResults) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
    let table = MetricTable::new(&r.trials);
    let hmn = r.hmn();
    let surpass = surpassing(r, hmn);
    let trials = r.params.trials as usize;
    Ok(scorecard::maze_numbers(
        claims::maze_claims(&table, &surpass, hmn, trials, r.scale, maze_diverged(r))?,
        &table,
        &surpass,
        hmn,
    ))
}

/// The Maze sections.
pub fn sections(r: &MazeResults, provenance: &Provenance) -> rlfd_report::Result<Vec<Section>> {
    let table = MetricTable::new(&r.trials);
    let hmn = r.hmn();
    let surpass = surpassing(r, hmn);
    let trials = r.params.trials as usize;
    let steps: u64 = r.trials.values().flatten().map(|t| t.steps.iter().map(|&s| u64::from(s)).sum::<u64>()).sum();
    let failures: u32 = r.trials.values().flatten().map(|t| t.ends.failures).sum();

    let summary = format!(
        "Five agents (SARSA(λ), SIS, DIS, HAT, SBS) learn the modified Dyna Maze for {} episodes, {} trials each, at the *{}* scale with master seed {} ({} agent steps in all; {} episodes hit the 6,000-step cap). \
         Every number below is computed from the stored per-episode returns; the thesis's value stands beside ours in every cell. \
         The demonstrator's mean return is HMN = {} (thesis: −327.5). Initial = first episode, asymptotic = last episode (as the thesis's Table 6.1), cumulative = sum over all episodes. {}",
        r.params.episodes,
        trials,
        r.scale,
        r.seed,
        thousands(steps as f64, 0),
        thousands(f64::from(failures), 0),
        thousands(hmn, 1).replace('-', "−"),
        readings_sentence(r)
    );

    let mut out = vec![Section::new("Maze: what was run", vec![Block::paragraph(summary)])];
    out.push(Section::new(
        "Table 6.1: initial, asymptotic and cumulative reward",
        vec![
            Block::Table(table_6_1(&table, hmn, trials)?),
            Block::Table(agent_tables::iqm_table::<MazeTrial>(
                TableText {
                    id: "table_6_1_iqm",
                    title: "Table 6.1 as interquartile means",
                    caption: "The interquartile mean over trials of each agent's metric, robust to a few odd trials, beside the thesis's mean over its 25. Sample: the agent's rows of maze_returns.csv (initial: episode 0's return; asymptotic: the last episode's; cumulative: the sum).".into(),
                    thesis_key: "ch6.maze.table_6_1",
                    notes: Vec::new(),
                },
                &table,
                &Agent::ALL,
                BASELINE,
                |a| format!("maze/{}", a.label(BASELINE)),
                2,
            )?),
            Block::Table(surpass_table(&surpass, hmn)?),
        ],
    ));
    out.push(Section::new(
        "Table 6.2: two-sample t-tests",
        vec![
            Block::Table(table_6_2(&table, trials)?),
            Block::Table(agent_tables::full_tests_table(
                TableText {
                    id: "table_6_2_tests",
                    title: "Table 6.2, every test in full",
                    caption: "The tests behind the p-values above: the first-named agent's mean minus the second's. Samples: the agents' rows of maze_returns.csv (metrics as in the IQM table).".into(),
                    thesis_key: "ch6.maze.table_6_2",
                    notes: Vec::new(),
                },
                &table,
                BASELINE,
                |a| format!("maze/{}", a.label(BASELINE)),
                2,
            )?),
        ],
    ));
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
        vec![Block::paragraph(super::how_claims_are_tested()), Block::Claims(claims_of(r)?)],
    ));
    out.push(irl_scale_section(&r.levels, r, provenance)?);
    out.push(maze_domain_section(r.params.layout, provenance)?);
    out.push(demonstrations_section(r, hmn, provenance)?);
    out.push(learned_inputs_section(r, provenance)?);
    out.push(Section::new("Parameters", vec![Block::Parameters(parameters_table(r)?)]));
    out.push(Section::new("Decisions and deviations", vec![Block::Deviations(deviations()?)]));
    out.push(Section::new(
        "Data",
        vec![
            Block::DataFile {
                file: "maze_returns.csv".into(),
                description: "Every episode of every trial: agent, trial, episode (from 1), return, steps, goal (1: the episode reached the goal; 0: it hit the 6,000-step cap).".into(),
                bytes: returns_csv(r),
            },
            Block::DataFile {
                file: "maze_irl_scale_returns.csv".into(),
                description: "SIS and DIS at the other levels of the irl-scale reading (the sensitivity section's runs), every episode: agent, κ, trial, episode, return, steps, goal.".into(),
                bytes: irl_scale_csv(&r.levels),
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

/// SIS and DIS at every level of the `irl-scale` reading.
fn irl_scale_section(
    k: &LevelRuns<MazeTrial>,
    maze: &MazeResults,
    provenance: &Provenance,
) -> rlfd_report::Result<Section> {
    let baseline = maze.trials.get(&Agent::Baseline).map(|ts| (Agent::Baseline.label(BASELINE), ts.as_slice()));
    let label = |run: &LevelRun<MazeTrial>| {
        format!("{} κ = {}{}", run.agent.label(BASELINE), run.value, if run.main { " (this run)" } else { "" })
    };
    let curve = |ts: &[MazeTrial]| mean_curve(ts).0.iter().enumerate().map(|(e, &y)| ((e + 1) as f64, y)).collect();
    let paragraph = format!(
        "RE-IRL fixes the direction of the reward weights θ, not their size; by default this reproduction keeps θ at unit length, so R_IRL(s) is of order 1 and, with the thesis's shaping scale of 100, SIS's potential differences are about 2 per step and DIS's shaping, which converges to 100 · R_IRL(s) per step, far outweighs the step cost of −1. The thesis's choice of a scale of 100 suggests its IRL reward was much smaller. These are the irl-scale reading's levels: SIS and DIS with R_IRL multiplied by κ, the same trials the robustness run's verdicts at each level rest on. The default (κ = 1) stays the reproduction's answer: κ was not chosen from these runs. {} {}",
        goal_avoidance_sentence(maze),
        goal_shares_sentence(baseline, k, maze.params.max_steps)
    );
    let text = LevelText {
        title: "Sensitivity to the size of the IRL reward (the irl-scale reading)",
        text: &paragraph,
        table: TableText {
            id: "maze_irl_scale",
            title: "Sensitivity: SIS and DIS at each level of the irl-scale reading (the size κ of the IRL reward)",
            caption: "Mean ± sd over the trials that ran to the end; SARSA and the run's own level are the main experiment's trials. The thesis does not give the size of its IRL reward, which sets the size of the shaping; κ scales R_IRL(s) before the shaping scale of 100 applies.".into(),
            thesis_key: "",
            notes: Vec::new(),
        },
        diverged_tail: "",
        format: NumFormat::grouped(2),
        label: &label,
        figure: (
            "figure_maze_irl_scale.svg",
            "Sensitivity: reward per episode for each κ (mean over trials)".into(),
            "Reward per episode",
            Some((-3000.0, 0.0)),
            "Mean reward per episode between −3,000 and 0, SARSA and SIS/DIS at each κ.",
        ),
        curve: &curve,
    };
    levels::section(text, baseline, k, maze.params.trials, provenance)
}

/// Where DIS's shaping pays most and the κ above which pacing there beats
/// reaching the goal. Uncorrected dynamic potential-based advice learns to
/// maximise r + scale · κ · R_IRL(s) per step (its shaping converges to
/// that reward), so once scale · κ · R_IRL(s) exceeds the step cost's 1 at a
/// state the agent can reach, walking there until the step cap is worth
/// more than the goal's +10. The maximum is over the positions of the
/// agents' 0.02 grid that connect to the goal, the goal region left out.
fn goal_avoidance_sentence(maze: &MazeResults) -> String {
    match largest_irl_reward(&maze.inputs.irl.weights, maze.params.layout) {
        Some((r, (x, y))) if r > 0.0 => {
            let threshold = 1.0 / (maze.params.shaping_scale * r);
            let scale = thousands(maze.params.shaping_scale, 0);
            format!(
                "Why DIS avoids the goal: uncorrected dynamic advice (as published) learns to maximise r + {scale} · κ · R_IRL(s) per step, and R_IRL is largest at ({x:.2}, {y:.2}), {r:.3} (over the positions that connect to the goal). Pacing there until the step cap pays more per step than the step costs once κ > 1 / ({scale} · {r:.3}) ≈ {threshold:.4}: above that threshold finishing is no longer the optimum DIS learns towards (how far it gets there within the run shows in the shares below), below it finishing is."
            )
        }
        _ => "R_IRL is nowhere positive on the positions that connect to the goal, so DIS's shaping never pays for staying away from it.".to_string(),
    }
}

/// The largest R_IRL(s) = w·(x, y) over the positions of the agents' 0.02
/// grid that connect to the goal (the goal region left out), and where.
fn largest_irl_reward(w: &[f64], layout: LayoutId) -> Option<(f64, (f64, f64))> {
    use crate::maze::layout::LATTICE;
    let field = DistanceField::to_goal(&MazeLayout::of(layout), 2);
    let lattice = f64::from(LATTICE);
    (0..LATTICE)
        .flat_map(|iy| (0..LATTICE).map(move |ix| (ix, iy)))
        .filter(|&(ix, iy)| {
            let d = field.distance(ix, iy);
            d != crate::maze::search::UNREACHABLE && d > 0
        })
        .map(|(ix, iy)| {
            let (x, y) = (f64::from(ix) / lattice, f64::from(iy) / lattice);
            (w[0] * x + w[1] * y, (x, y))
        })
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The share of the last ten episodes that reach the goal, per run.
fn goal_shares_sentence(baseline: Option<(&str, &[MazeTrial])>, k: &LevelRuns<MazeTrial>, cap: usize) -> String {
    const LAST: usize = 10;
    let share = |ts: &[MazeTrial]| -> Option<f64> {
        let mut reached = 0usize;
        let mut counted = 0usize;
        for t in ts {
            let episodes = t.returns.len();
            for e in episodes.saturating_sub(LAST) + 1..=episodes {
                counted += 1;
                reached += usize::from(t.ends.reached_goal(e as u32));
            }
        }
        (counted > 0).then(|| reached as f64 / counted as f64)
    };
    let mut parts: Vec<String> = Vec::new();
    let mut push = |label: String, ts: &[MazeTrial]| {
        if let Some(v) = share(ts) {
            parts.push(format!("{label} {v:.2}"));
        }
    };
    if let Some((label, ts)) = baseline {
        push(label.to_string(), ts);
    }
    for run in &k.runs {
        push(format!("{} κ = {}", run.agent.label(BASELINE), run.value), &run.trials);
    }
    if parts.is_empty() {
        return String::new();
    }
    format!(
        "Share of the last {LAST} episodes that reach the goal (the rest hit the {}-step cap): {}.",
        thousands(cap as f64, 0),
        parts.join("; ")
    )
}

/// Why the Maze's claims cannot be judged, when a learner diverged.
fn maze_diverged(r: &MazeResults) -> Option<String> {
    super::diverged_agents(&r.diverged, &Agent::ALL, BASELINE, r.params.trials)
}

fn table_6_1(table: &MetricTable, hmn: f64, trials: usize) -> rlfd_report::Result<Table> {
    let rows = agent_tables::means_rows(table, &Agent::ALL, BASELINE);
    agent_tables::means_table(
        TableText {
            id: "table_6_1",
            title: "Table 6.1: Maze, mean reward per agent",
            caption: format!("Mean ± sd over {trials} trials (ours) beside the thesis's mean over 25 trials."),
            thesis_key: "ch6.maze.table_6_1",
            notes: vec!["HMN is the demonstrator's mean return over its ten demonstrations (−1 per recorded step, +10 at the goal), as the thesis counts it.".into()],
        },
        &metric_columns::<MazeTrial>(),
        &rows,
        hmn,
        NumFormat::grouped(2),
    )
}

fn table_6_2(table: &MetricTable, trials: usize) -> rlfd_report::Result<Table> {
    let pairs = agent_tables::pair_rows(table, BASELINE);
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
        &metric_columns::<MazeTrial>(),
        &pairs,
    )
}

fn surpass_table(surpass: &[(Agent, Option<usize>, Option<usize>)], hmn: f64) -> rlfd_report::Result<Table> {
    let rows: Vec<(&str, Option<usize>, Option<usize>)> =
        surpass.iter().map(|&(a, e, f)| (a.label(BASELINE), e, f)).collect();
    agent_tables::surpass_table(
        TableText {
            id: "maze_episodes_to_surpass",
            title: "Episodes to surpass the demonstrator",
            caption: format!(
                "The episode from which the trial-mean reward stays above the demonstrator's mean (ours: HMN = {}) to the end of the run (the claims' reading; a curve that starts above, dips and recovers counts from its recovery), and the first episode whose trial-mean reward is above it.",
                family::num(hmn, 1)
            ),
            thesis_key: "ch6.maze.episodes_to_surpass_demonstrator",
            notes: Vec::new(),
        },
        &rows,
    )
}

/// The walls a layout adds, in words.
fn layout_text(layout: LayoutId) -> String {
    let cells: Vec<String> = layout.added_cells().iter().map(|(r, c)| format!("({r}, {c})")).collect();
    let thin: Vec<String> = layout
        .thin_walls()
        .iter()
        .map(|w| {
            let (x0, y0, x1, y1) = w.unit_square();
            format!("[{x0:.3}, {x1:.3}) × [{y0:.3}, {y1:.3})")
        })
        .collect();
    let route = match layout {
        LayoutId::LowDetour => {
            "The way leads over column 2, down the middle to the bottom row, through the narrow gap under column 6 and up the goal column: a detour along the bottom, along which a linear potential over (x, y) can follow only x."
        }
        LayoutId::HighDetour => {
            "The way leads over column 2, right along the top, left along row 1, right along row 2, down column 6 past column 7's lengthened wall and up the goal column: a detour under the top edge (designed before any learner ran on it so that the route does not run along the bottom row, where a linear (x, y) potential reduces to x alone; RE-IRL's potential is x alone here too)."
        }
        LayoutId::FloorRoute => {
            "The way leads down the start column to the floor, under column 2, over column 5 into row 2, down column 6, under column 7 and up the goal column: a route in the lower half (designed before any learner ran on it so that RE-IRL's potential has a y component)."
        }
    };
    format!(
        "This run's layout ({}, reading maze-layout={}) adds the cells {} (row from the top, column) and the thin walls {}. {route}",
        layout.name(),
        layout.name(),
        cells.join(", "),
        thin.join(", ")
    )
}

fn maze_domain_section(layout: LayoutId, provenance: &Provenance) -> rlfd_report::Result<Section> {
    let start = crate::maze::layout::START;
    let field = DistanceField::to_goal(&MazeLayout::of(layout), 2);
    let optimal = field.distance(start.0, start.1);
    let dyna = DistanceField::to_goal(&MazeLayout::dyna(), 2).distance(start.0, start.1);
    let others: Vec<String> = LayoutId::ALL
        .iter()
        .filter(|&&l| l != layout)
        .map(|&l| {
            let steps = DistanceField::to_goal(&MazeLayout::of(l), 2).distance(start.0, start.1);
            format!("the {} layout needs {steps} steps", l.name())
        })
        .collect();
    let text = format!(
        "The thesis draws its \"modified Dyna Maze\" but does not list the walls; it gives the optimal path's length, 2.665 (133 steps of 0.02). \
         The Dyna Maze of Sutton & Barto scaled to the unit square needs only {dyna} steps, so we kept its walls, start and goal and added walls; which walls is the maze-layout reading. {} \
         A breadth-first search finds the shortest path: {optimal} steps, length {:.2} (133 ± 2 was the target; {}).",
        layout_text(layout),
        f64::from(optimal) * 0.02,
        others.join(", ")
    );
    Ok(Section::new(
        "The Maze (Figures 6.1 and 6.3)",
        vec![
            Block::paragraph(text),
            Block::Figure {
                file: "figure_6_1.svg".into(),
                caption: "The modified Dyna Maze.".into(),
                svg: figures::figure_6_1(layout, provenance)?,
            },
            Block::Figure {
                file: "figure_6_3.svg".into(),
                caption: "An optimal path, piecewise linear.".into(),
                svg: figures::figure_6_3(layout, provenance)?,
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
    row("Mean return (HMN, this run's units)", hmn, demo_thesis::HMN, f1);
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
    for units in [HmnUnits::Recorded, HmnUnits::AgentSteps] {
        let label = match units {
            HmnUnits::Recorded => "Mean return per recorded step of 0.01",
            HmnUnits::AgentSteps => "Mean return at the agents' step of 0.02",
        };
        t.rows.push(Row::new(label, vec![Cell::ours_only(Num::new(d.hmn(units), f1))]));
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
                "The ten demonstrations come from {source}, on the {} layout. The thesis's demonstrator was a person; ours is a model calibrated on the demonstration statistics the thesis reports, never on a learning result. It was calibrated on the default (low-detour) layout; on another layout the same person (the same slip and drift) follows that layout's route, and the table shows what comes of it.",
                r.params.layout.name()
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
        "RIPPER as the thesis ran it, Weka 3.6's JRip with its defaults (-F 3 -N 2.0 -O 2 -S 1, drawing from Weka's own random stream, so these are the rules Weka prints for this data), on the {} demonstrated (x, y) → move pairs gives {} rules plus a default; Weka's stratified 10-fold cross-validation (-x 10 -s 1) accuracy {:.1} %. HAT's bonus follows this list: {}",
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
            Block::paragraph(irl::draws_sentence(fit, &r.inputs.irl_draws, s)),
            Block::Table(irl::draws_table(
                "maze_irl_draws",
                "The Maze's θ over baseline draws",
                &["x", "y"],
                fit,
                &r.inputs.irl_draws,
            )?),
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
    rows.row("Tile width (x and y)", p.tile_width, "the tile-width reading (default 0.1, our choice before any run)");
    rows.thesis("α per tiling", format!("{} (0.25/32)", p.alpha));
    rows.thesis("β per tiling (DIS)", format!("{} (0.05/32)", p.beta));
    rows.thesis("γ", p.gamma);
    rows.thesis("λ", p.lambda);
    rows.thesis("ε", p.epsilon);
    rows.thesis("Shaping scale (SIS, DIS, SBS)", p.shaping_scale);
    rows.thesis("Shaping scale (HAT)", p.hat_scale);
    rows.row("SBS σ", p.sbs_sigma, "the sbs-sigma reading (default: 0.05, half a tile, fixed before any run)");
    super::terminal_rows(&mut rows, "the goal", p.terminal_potential, p.advice_terminal);
    rows.row(
        "Eligibility traces",
        format!("{:?}, dropped below 0.01", p.traces),
        "our choice (Keepaway benchmark convention)",
    );
    rows.row("IRL reward scale κ", p.irl_scale, "the irl-scale reading (default 1: θ at unit length)");
    rows.row("Layout", p.layout.name(), "the maze-layout reading (default low-detour, fixed before any run)");
    rows.row(
        "HAT's Value Bonus",
        match p.hat_bonus {
            HatBonus::QInit => "Q-initialisation".to_string(),
            HatBonus::Persistent { forced_episodes } => {
                format!("bonus at every choice, rules' action forced for {forced_episodes} episodes")
            }
        },
        "the hat-bonus reading (default q-init, chapter 6's text)",
    );
    rows.row(
        "HMN counted",
        match r.demonstrations.hmn_units {
            HmnUnits::Recorded => "per recorded step of 0.01",
            HmnUnits::AgentSteps => "at the agents' step of 0.02",
        },
        "the hmn-units reading (default recorded, Table 6.1)",
    );
    rows.row(
        "Equivalence margin (C6.3)",
        format!("±{}", family::num(family::MAZE_MARGIN, 2)),
        "our choice before the run: a tenth of the thesis's |HMN|",
    );
    rows.row("RE-IRL", "see \"What the agents learned from\"", "our choices");
    rows.table()
}

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    super::DEVIATIONS.deviations("maze")
}

/// One row of `returns.csv` or `irl_scale.csv`: one episode of one trial
/// (`kappa` only in the sweep's file).
#[derive(Serialize)]
struct EpisodeRow<'a> {
    agent: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    kappa: Option<f64>,
    trial: usize,
    episode: usize,
    #[serde(rename = "return")]
    points: f64,
    steps: u32,
    goal: u8,
}

/// The episode rows of `trials` (the agent's, at `kappa` in the sweep).
fn episode_rows<'a>(
    agent: &'a str,
    kappa: Option<f64>,
    trials: &'a [MazeTrial],
) -> impl Iterator<Item = EpisodeRow<'a>> {
    trials.iter().enumerate().flat_map(move |(trial, t)| {
        t.returns.iter().zip(&t.steps).enumerate().map(move |(e, (&points, &steps))| EpisodeRow {
            agent,
            kappa,
            trial,
            episode: e + 1,
            points,
            steps,
            goal: u8::from(t.ends.reached_goal((e + 1) as u32)),
        })
    })
}

fn returns_csv(r: &MazeResults) -> Vec<u8> {
    csv_of(r.trials.iter().flat_map(|(agent, trials)| episode_rows(agent.label(BASELINE), None, trials)))
}

fn irl_scale_csv(k: &LevelRuns<MazeTrial>) -> Vec<u8> {
    csv_of(
        k.runs
            .iter()
            .filter(|run| !run.main)
            .flat_map(|run| episode_rows(run.agent.label(BASELINE), Some(run.value), &run.trials)),
    )
}

fn demonstrations_csv(r: &MazeResults) -> Vec<u8> {
    let mut out = Vec::new();
    r.demonstrations.set.write_csv(&mut out).expect("writing to memory");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maze::params::MazeEnds;

    #[test]
    fn the_largest_irl_reward_leaves_the_goal_region_out() {
        // x + y peaks in the goal's corner (1.96 at (0.98, 0.98)); outside the
        // goal region (x ≥ 0.9 and y ≥ 0.9) the best free grid point is
        // (0.98, 0.88): (0.88, 0.98) lies in the Dyna wall of column 7.
        let (r, (x, y)) = largest_irl_reward(&[1.0, 1.0], LayoutId::LowDetour).unwrap();
        assert!((r - 1.86).abs() < 1e-12, "{r}");
        assert_eq!((x, y), (0.98, 0.88));
        // Pointing away: the start's sublattice reaches (0, 0).
        let (r, _) = largest_irl_reward(&[-1.0, -1.0], LayoutId::LowDetour).unwrap();
        assert_eq!(r, 0.0);
    }

    #[test]
    fn goal_shares_count_the_last_ten_episodes() {
        let trial = |capped: Vec<u32>| MazeTrial {
            returns: vec![0.0; 12],
            steps: vec![1; 12],
            ends: MazeEnds { failures: capped.len() as u32, capped },
            diverged_at: None,
        };
        // Of twelve episodes, 1 and 2 are not among the last ten; the capped
        // 3 and (in the second trial) 12 are: 18 of 20 reach the goal.
        let ts = [trial(vec![1, 2, 3]), trial(vec![12])];
        let s = goal_shares_sentence(Some(("SAR", &ts)), &LevelRuns::default(), 6000);
        assert_eq!(s, "Share of the last 10 episodes that reach the goal (the rest hit the 6,000-step cap): SAR 0.90.");
        assert_eq!(goal_shares_sentence(None, &LevelRuns::default(), 6000), "");
    }
}
