//! The report's section on `mario-validation`: our simulator under the
//! oracle's two fixed policies beside the real Mario AI Benchmark 0.2.0
//! (`data/mario-oracle.toml`), with the criteria of issue 27 and which hold.

use rlfd_mario::baseline::{FixedPolicy, Outcome};
use rlfd_mario::observation::NAMES;
use rlfd_report::data_file::csv_of;
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, Section};
use serde::Serialize;

use crate::mario::validation::{MarioValidation, Oracle, POLICIES, PolicyRun, label, oracle, slug};

/// Relative criterion on means and shares (issue 27): within 10 %.
pub const RELATIVE: f64 = 0.10;
/// Level contents: within 15 %.
pub const CONTENTS: f64 = 0.15;
/// P(1) of a variable under the forward-jumping policy: within 0.03.
pub const P_ONE: f64 = 0.03;

fn mark(within: bool) -> Cell {
    Cell::text(if within { "✓" } else { "✗" })
}

/// A row: ours, the benchmark's, the difference (relative when `relative`)
/// and whether it is within `criterion`.
fn row(label: &str, ours: f64, theirs: f64, relative: Option<f64>, absolute: Option<f64>, decimals: usize) -> Row {
    let num = |x: f64| Cell::Num(Num::new(x, NumFormat::fixed(decimals)));
    let (difference, within) = match (relative, absolute) {
        (Some(c), _) if theirs != 0.0 => {
            let d = ours / theirs - 1.0;
            (Cell::Num(Num::new(100.0 * d, NumFormat::fixed(1))), Some(d.abs() <= c))
        }
        (_, Some(c)) | (Some(c), None) => (num(ours - theirs), Some((ours - theirs).abs() <= c)),
        (None, None) => (num(ours - theirs), None),
    };
    let criterion = match (relative, absolute) {
        (Some(c), _) if theirs != 0.0 => format!("±{:.0} %", 100.0 * c),
        (_, Some(c)) | (Some(c), None) => format!("±{c}"),
        (None, None) => "shown".into(),
    };
    Row::new(label, vec![num(ours), num(theirs), difference, Cell::text(criterion), within.map_or(Cell::Empty, mark)])
}

fn columns() -> Vec<ColumnGroup> {
    vec![
        ColumnGroup::new("Ours").with_key("ours"),
        ColumnGroup::new("Benchmark").with_key("benchmark"),
        ColumnGroup::new("Difference (% or absolute)").with_key("difference"),
        ColumnGroup::new("Criterion").with_key("criterion"),
        ColumnGroup::new("Within").with_key("within"),
    ]
}

/// A policy's episodes against the benchmark's.
fn policy_table(policy: FixedPolicy, run: &PolicyRun, o: &Oracle) -> rlfd_report::Result<Table> {
    let b = o.policy(policy);
    let mut t = Table::new(
        format!("mario_validation_{}", slug(policy).replace('-', "_")),
        format!("Validation: {} ({} episodes; the benchmark's {})", label(policy), run.episodes.len(), b.episodes),
        "Per episode",
    );
    t.caption = "Means per episode and shares of episodes. Relative differences in %, shares and P(·) in absolute terms where the benchmark's figure is 0. The timeout share under the forward-jumping policy is rare (18 of 1,000 on the benchmark): 10 % of it is about a third of a binomial standard error. Stomps: ours count every stomp (a winged goomba loses its wings), the benchmark's its stomp kills.".into();
    t.columns = columns();
    let mean = |f: &dyn Fn(&crate::mario::validation::ValidationEpisode) -> f64| run.mean(f);
    t.rows = vec![
        row("points", mean(&|e| e.points), b.points, Some(RELATIVE), None, 1),
        row("won", run.share(Outcome::Won), b.won, Some(RELATIVE), Some(0.0), 3),
        row("died", run.share(Outcome::Died), b.died, Some(RELATIVE), None, 3),
        row("timed out", run.share(Outcome::TimedOut), b.timed_out, Some(RELATIVE), None, 3),
        row("ticks", mean(&|e| f64::from(e.ticks)), b.ticks, Some(RELATIVE), None, 0),
        row("stomps", mean(&|e| f64::from(e.stomps)), b.stomps, None, None, 2),
        row("coins", mean(&|e| f64::from(e.coins)), b.coins, Some(RELATIVE), None, 1),
        row("hurts", mean(&|e| f64::from(e.hurts)), b.hurts, Some(RELATIVE), None, 2),
        row("distance (cells)", mean(&|e| f64::from(e.distance)), b.distance, Some(RELATIVE), None, 1),
        row("P(no enemy in the 22 × 22 grid)", run.p_no_enemy(), b.p_no_enemy, None, Some(P_ONE), 3),
    ];
    t.check()?;
    Ok(t)
}

/// P(1) of each variable under both policies, ours beside the benchmark's.
fn p_one_table(v: &MarioValidation, o: &Oracle) -> rlfd_report::Result<Table> {
    let mut t = Table::new(
        "mario_validation_p_one",
        "Validation: P(1) of the 27 variables over the decision states (x-dir, y-dir: P(+1))",
        "Variable",
    );
    t.caption = format!(
        "The criterion (issue 27) is under the forward-jumping policy: every P(1) within {P_ONE}. se: the standard error of ours with the trials (100 episodes each) as clusters, since one episode's states are not independent draws; the benchmark's own figure, from one run of 1,000 episodes, carries an error of the same kind, which the oracle did not measure. Under random play the benchmark's figures come from 200 episodes (seed 3). The closest-enemy offsets are not 0/1 variables and are left out."
    );
    t.columns = vec![
        ColumnGroup::new("Forward-jumping: ours").with_key("fwd_ours"),
        ColumnGroup::new("se").with_key("fwd_ours_se"),
        ColumnGroup::new("benchmark").with_key("fwd_benchmark"),
        ColumnGroup::new("within").with_key("fwd_within"),
        ColumnGroup::new("Random: ours").with_key("random_ours"),
        ColumnGroup::new("benchmark").with_key("random_benchmark"),
    ];
    let p = |x: f64| Cell::Num(Num::new(x, NumFormat::fixed(4)));
    let empty = PolicyRun::default();
    let fwd = v.runs.get(&FixedPolicy::ForwardJump).unwrap_or(&empty);
    let random = v.runs.get(&FixedPolicy::Random).unwrap_or(&empty);
    for (k, name) in NAMES.iter().enumerate() {
        let (Some(&bf), Some(&br)) = (o.forward_jump.p_one.get(*name), o.random.p_one.get(*name)) else { continue };
        let ours = fwd.p_one(k);
        let se = fwd.p_one_se(k);
        let se = if se.is_nan() { Cell::Empty } else { p(se) };
        t.rows.push(Row::new(
            *name,
            vec![p(ours), se, p(bf), mark((ours - bf).abs() <= P_ONE), p(random.p_one(k)), p(br)],
        ));
    }
    t.check()?;
    Ok(t)
}

/// What the P(1) misses are, measured: each miss with ours' standard error,
/// and the share of the forward-jumping decision states that the timed-out
/// episodes hold (a few long episodes that move these ratios).
fn p_one_misses(v: &MarioValidation, o: &Oracle) -> Option<String> {
    let fwd = v.runs.get(&FixedPolicy::ForwardJump)?;
    let misses: Vec<String> = NAMES
        .iter()
        .enumerate()
        .filter_map(|(k, name)| {
            let bf = *o.forward_jump.p_one.get(*name)?;
            let ours = fwd.p_one(k);
            ((ours - bf).abs() > P_ONE).then(|| {
                format!(
                    "{name} {ours:.4} against {bf:.4} (ours' se {:.4}, the gap {:.1} se)",
                    fwd.p_one_se(k),
                    (ours - bf).abs() / fwd.p_one_se(k)
                )
            })
        })
        .collect();
    if misses.is_empty() {
        return None;
    }
    let timeouts = fwd.episodes.iter().filter(|e| e.outcome == Outcome::TimedOut).count();
    Some(format!(
        "P(1) outside the criterion under the forward-jumping policy: {}. These are ratios over decision states, and a few long episodes dominate them: the {timeouts} timed-out episodes of our {} (the benchmark's: {:.0} of {}) hold {:.0} % of our decision states. The obstacle P(1) move with that count: six further runs of 1,000 episodes on our simulator (`cargo run --release -p rlfd-mario --example oracle_policies -- fwdjump 1000 SEED`, seeds 1–6, 6 December 2026) gave obstacle-below 0.306–0.356 and obstacle-feet 0.144–0.204, lowest with 10 timeouts and highest with 20, both within 0.03 of the benchmark's in five of six. Split by where Mario stands in his cell, our obstacle P(1) and the benchmark's agree within 0.04 in every quarter (one 1,000-episode run each; the counts are in `data/mario-oracle.toml`). So these misses are the sampling spread of one run on each side, not a mechanism that differs.",
        misses.join("; "),
        fwd.episodes.len(),
        o.forward_jump.timed_out * f64::from(o.forward_jump.episodes),
        o.forward_jump.episodes,
        100.0 * fwd.tick_share(Outcome::TimedOut),
    ))
}

/// Level contents per level, ours over the episodes' levels.
fn contents_table(v: &MarioValidation, o: &Oracle) -> rlfd_report::Result<Table> {
    let mut t = Table::new("mario_validation_levels", "Validation: level contents per level", "Per level");
    let levels: Vec<[u32; 5]> = v.runs.values().flat_map(|r| r.episodes.iter().map(|e| e.contents)).collect();
    t.caption = format!(
        "Ours over the {} levels the two policies played; the benchmark's over 1,000 levels of its generator at the same options (`LevelStats`). Criterion: within {:.0} % (plants, rare, shown only).",
        levels.len(),
        100.0 * CONTENTS
    );
    t.columns = columns();
    let mean = |k: usize| levels.iter().map(|c| f64::from(c[k])).sum::<f64>() / levels.len().max(1) as f64;
    let l = &o.levels;
    t.rows = vec![
        row("goombas", mean(0), l.goombas, Some(CONTENTS), None, 1),
        row("coin tiles", mean(1), l.coin_tiles, Some(CONTENTS), None, 1),
        row("question blocks", mean(2), l.question_blocks, Some(CONTENTS), None, 1),
        row("bricks", mean(3), l.bricks, Some(CONTENTS), None, 1),
        row("piranha plants", mean(4), l.plants, None, None, 2),
    ];
    t.check()?;
    Ok(t)
}

/// One row of `mario_validation_episodes.csv`.
#[derive(Serialize)]
struct EpisodeRow<'a> {
    policy: &'a str,
    level_seed: u64,
    start_mode: &'a str,
    points: f64,
    ticks: u32,
    outcome: Outcome,
    stomps: u32,
    coins: u32,
    hurts: u32,
    distance: i32,
    goombas: u32,
    coin_tiles: u32,
    question_blocks: u32,
    bricks: u32,
    plants: u32,
}

fn episodes_csv(v: &MarioValidation) -> Vec<u8> {
    csv_of(v.runs.iter().flat_map(|(&policy, run)| {
        run.episodes.iter().map(move |e| EpisodeRow {
            policy: slug(policy),
            level_seed: e.level_seed,
            start_mode: &e.start_mode,
            points: e.points,
            ticks: e.ticks,
            outcome: e.outcome,
            stomps: e.stomps,
            coins: e.coins,
            hurts: e.hurts,
            distance: e.distance,
            goombas: e.contents[0],
            coin_tiles: e.contents[1],
            question_blocks: e.contents[2],
            bricks: e.contents[3],
            plants: e.contents[4],
        })
    }))
}

/// The validation section.
pub fn section(v: &MarioValidation) -> rlfd_report::Result<Section> {
    let o = oracle().map_err(|reason| rlfd_report::Error::DataFile {
        file: crate::mario::validation::ORACLE.path.into(),
        entry: "(the file)".into(),
        reason,
    })?;
    let mut blocks = vec![Block::paragraph(
        "The thesis's Mario is the Mario AI Benchmark 0.2.0 (its reward table exists only there). The oracle built the real benchmark from its source and played two fixed policies on it at its defaults (difficulty 0, overground, length 256, 200 s, no hidden blocks, random start mode); `mario-validation` plays the same two policies on our simulator. Our levels come from our own random numbers, so the comparison is of distributions. The criteria are issue 27's, fixed before this run; where one is not met the table says so.",
    )];
    for policy in POLICIES {
        if let Some(run) = v.runs.get(&policy) {
            blocks.push(Block::Table(policy_table(policy, run, &o)?));
        }
    }
    blocks.push(Block::Table(contents_table(v, &o)?));
    blocks.push(Block::Table(p_one_table(v, &o)?));
    if let Some(text) = p_one_misses(v, &o) {
        blocks.push(Block::paragraph(&text));
    }
    blocks.push(Block::DataFile {
        file: "mario_validation_episodes.csv".into(),
        description: "Every validation episode: policy, level seed, start mode, points, ticks, outcome, stomps, coins, hurts, distance (cells) and the level's contents, to compare with the oracle's own per-episode CSV.".into(),
        bytes: episodes_csv(v),
    });
    Ok(Section::new("Simulator validation against the real Mario AI Benchmark 0.2.0", blocks))
}
