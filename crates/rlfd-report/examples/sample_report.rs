//! Renders a sample chapter report (made-up numbers shaped like chapter 6's
//! maze) and the top-level index into a directory, so a person can open
//! `<dir>/index.html` in a browser and look at tables, figures and the
//! scorecard. Usage: `cargo run --release -p rlfd-report --example
//! sample_report -- <dir>`. The only file-writing code of this crate.

use std::path::PathBuf;

use rlfd_report::claims::{Claim, Verdict};
use rlfd_report::figure::{
    BarChart, Bracket, Fit, HLine, LegendPosition, LineChart, Marker, PathEmphasis, Rect, ScatterGroup, ScatterPlot,
    Scene, ScenePath, Series, SeriesStyle, Stroke,
};
use rlfd_report::published::published;
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, ChapterReport, Deviation, Provenance, Section, render_chapter, render_index};

const AGENTS: [&str; 5] = ["SAR", "SIS", "DIS", "HAT", "SBS"];

/// A smooth made-up learning curve with a wobble, per agent.
fn curve(agent: usize, episode: usize) -> f64 {
    let e = episode as f64;
    let start = [-3700.0, -8000.0, -3500.0, -165.0, -324.0][agent];
    let end = [-222.0, -166.0, -268.0, -222.0, -186.0][agent];
    let rate = [0.08, 0.3, 0.12, 0.02, 0.03][agent];
    let wobble = 25.0 * ((e * 0.37 + agent as f64).sin());
    end + (start - end) / (1.0 + rate * e * e) + wobble
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir: PathBuf = std::env::args_os().nth(1).ok_or("usage: sample_report <output directory>")?.into();
    let p = published();
    let provenance = Provenance::new(
        "cargo xtask reproduce --chapter ch6-irl-shaping --scale quick --seed 20160501",
        env!("CARGO_PKG_VERSION"),
    );

    // Table 6.1 with made-up "ours".
    let mut t61 = Table::new("table_6_1", "Maze: initial, asymptotic and cumulative reward (Table 6.1)", "Agent");
    t61.caption = "Mean ± sd over 25 trials; the thesis's values in grey.".into();
    t61.columns = vec![ColumnGroup::new("Initial"), ColumnGroup::new("Asymptotic"), ColumnGroup::new("Cumulative")];
    for (i, agent) in AGENTS.iter().chain(["HMN"].iter()).enumerate() {
        let g = NumFormat::grouped(2);
        let mut cells = Vec::new();
        for (k, column) in ["initial", "asymptotic", "cumulative"].iter().enumerate() {
            let thesis = p.table_value("ch6.maze.table_6_1", column, agent)?;
            let ours = if *agent == "HMN" && k == 2 { f64::NAN } else { thesis * (1.0 + 0.03 * (i as f64 - 2.0)) };
            let spread = (thesis.abs() * 0.1).max(1.0);
            cells.push(Cell::compare(Num::new(ours, g).with_spread(spread), thesis));
        }
        t61.rows.push(Row::new(*agent, cells));
    }
    t61.notes = vec!["HMN is the human demonstrator; it has no cumulative reward.".into()];

    // Table 6.2: p-values.
    let mut t62 = Table::new("table_6_2", "Maze: p-values of two-sample t-tests (Table 6.2)", "Pair");
    t62.columns = vec![ColumnGroup::new("Initial"), ColumnGroup::new("Asymptotic"), ColumnGroup::new("Cumulative")];
    for pair in p.row_labels("ch6.maze.table_6_2")? {
        let mut cells = Vec::new();
        for column in ["initial", "asymptotic", "cumulative"] {
            let thesis = p.table_value("ch6.maze.table_6_2", column, &pair)?;
            cells.push(Cell::compare(Num::p_value((thesis * 3.7).min(1.0)), thesis));
        }
        t62.rows.push(Row::new(pair, cells));
    }
    t62.notes = vec!["* p ≤ 0.05, ** p ≤ 0.01, *** p ≤ 0.001, **** p ≤ 0.0001.".into()];

    // Figure 6.4: learning curves with standard-error bands.
    let mut fig = LineChart::new("Maze: reward per episode (mean ± s.e., 25 trials)", "Episode", "Reward");
    for (i, agent) in AGENTS.iter().enumerate() {
        let points: Vec<(f64, f64)> = (0..150).map(|e| (e as f64, curve(i, e))).collect();
        let band = points
            .iter()
            .map(|(e, y)| {
                let se = 40.0 + y.abs() * 0.08 / (1.0 + e * 0.05);
                (y - se, y + se)
            })
            .collect();
        fig.series.push(Series { name: (*agent).into(), points, band: Some(band), style: SeriesStyle::Line });
    }
    fig.reference_lines.push(HLine { name: "HMN (demonstrator mean)".into(), y: -327.5, stroke: Stroke::Dashed });
    fig.y_range = Some((-2000.0, 0.0));
    let fig_curves = fig.to_svg(&provenance)?;
    fig.y_range = None;
    fig.legend = LegendPosition::Outside;
    fig.title = "Maze: reward per episode, full range".into();
    let fig_full = fig.to_svg(&provenance)?;

    // Figure 6.1: the maze.
    let mut maze = Scene::new("Maze: optimal path and the ten demonstrations", Rect::UNIT);
    maze.walls = vec![Rect::new(0.25, 0.0, 0.3, 0.7), Rect::new(0.55, 0.3, 0.6, 1.0), Rect::new(0.75, 0.0, 0.8, 0.6)];
    maze.goal = Some(Rect::new(0.9, 0.9, 1.0, 1.0));
    maze.paths.push(ScenePath {
        name: Some("optimal path".into()),
        points: vec![(0.08, 0.6), (0.15, 0.8), (0.4, 0.8), (0.45, 0.2), (0.68, 0.2), (0.7, 0.75), (0.95, 0.95)],
        emphasis: PathEmphasis::Primary,
    });
    for k in 0..10 {
        let d = 0.006 * k as f64 - 0.03;
        maze.paths.push(ScenePath {
            name: (k == 0).then(|| "demonstrations (10)".into()),
            points: vec![
                (0.08, 0.6),
                (0.13 + d, 0.83 + d),
                (0.42 + d, 0.83 + d),
                (0.47 + d, 0.17 + d),
                (0.67 + d, 0.2 + d),
                (0.69 + d, 0.78 + d),
                (0.93 + d / 3.0, 0.94 + d / 3.0),
            ],
            emphasis: PathEmphasis::Light,
        });
    }
    maze.markers = vec![Marker { label: "S".into(), at: (0.08, 0.6) }, Marker { label: "G".into(), at: (0.95, 0.95) }];
    let fig_maze = maze.to_svg(&provenance)?;

    let mut bars =
        BarChart::new("DIS asymptote by demonstration length", "Demonstration length (steps)", "Asymptotic reward");
    bars.categories = vec!["100".into(), "500".into(), "953".into()];
    bars.values = vec![1380.0, 1402.5, 1398.8];
    bars.errors = Some(vec![40.0, 35.0, 30.0]);
    bars.brackets = vec![
        Bracket { from: 0, to: 1, label: "p = 0.2338".into() },
        Bracket { from: 1, to: 2, label: "p = 0.8123".into() },
        Bracket { from: 0, to: 2, label: "p = 0.4410".into() },
    ];
    let fig_bars = bars.to_svg(&provenance)?;

    let mut scatter = ScatterPlot::new("Interactions vs accuracy", "Interactions", "Accuracy (%)");
    for (i, name) in ["Int-RL", "BNets", "CBA"].iter().enumerate() {
        let points: Vec<(f64, f64)> = (0..10)
            .map(|k| {
                let x = 5.0 + k as f64 * 4.0 + i as f64 * 2.0;
                (x, 10.0 + 20.0 * i as f64 + x * (0.3 + 0.4 * i as f64) + 6.0 * ((k * 7 + i) as f64).sin())
            })
            .collect();
        scatter.groups.push(ScatterGroup {
            name: (*name).into(),
            points,
            labels: Vec::new(),
            fit: Some(Fit {
                slope: 0.3 + 0.4 * i as f64,
                intercept: 10.0 + 20.0 * i as f64,
                label: format!("r = {:.2}", [0.35, 0.48, 0.64][i]),
            }),
        });
    }
    let fig_scatter = scatter.to_svg(&provenance)?;

    let mut params = Table::new("parameters", "Maze agents' parameters", "Parameter");
    params.columns = vec![ColumnGroup::new("Ours"), ColumnGroup::new("Thesis")];
    for (name, key) in [("alpha", "alpha"), ("beta", "beta")] {
        let thesis = p.string(&format!("ch6.maze.params.{key}"))?;
        params.rows.push(Row::new(name, vec![Cell::text(thesis), Cell::text(thesis)]));
    }
    for key in ["gamma", "lambda", "epsilon"] {
        let thesis = p.number(&format!("ch6.maze.params.{key}"))?;
        params.rows.push(Row::new(
            key,
            vec![Cell::Num(Num::new(thesis, NumFormat::fixed(2))), Cell::Num(Num::new(thesis, NumFormat::fixed(2)))],
        ));
    }

    let claims = vec![
        Claim::from_spec(
            "C6.1",
            "p < 1e-17 for every pair (Table 6.2)",
            "all p < 1e-20",
            Verdict::Reproduced,
            "SIS and DIS beat SARSA, HAT and SBS with p < 1e-4.",
        )?,
        Claim::from_spec(
            "C6.2",
            "p ≈ 1e-13",
            "p = 2e-3",
            Verdict::NotReproduced,
            "HAT starts better, SBS does not reach p < 1e-4.",
        )?,
        Claim::from_spec(
            "C6.3",
            "all pairs n.s.",
            "5 trials only",
            Verdict::NotEvaluable,
            "Quick scale has too few trials for a non-significance claim.",
        )?,
    ];

    let data: String = std::iter::once("agent,trial,episode,return\n".to_owned())
        .chain((0..5).flat_map(|a| (0..3).map(move |e| format!("{},0,{e},{:.2}\n", AGENTS[a], curve(a, e)))))
        .collect();

    let report = ChapterReport {
        slug: "ch6-irl-shaping".into(),
        title: "Chapter 6: IRL-based reward shaping (sample)".into(),
        provenance: provenance.clone(),
        sections: vec![
            Section::new(
                "What was run",
                vec![
                    Block::paragraph(
                        "A *sample* report with made-up numbers: five agents in the maze, 150 episodes, rerun with `cargo xtask reproduce`.",
                    ),
                    Block::Deviations(vec![Deviation {
                        topic: "Trials".into(),
                        thesis: "25 per agent".into(),
                        ours: "5 per agent (quick scale)".into(),
                        reason: "The quick scale keeps the golden test fast; `--scale paper` runs 25.".into(),
                    }]),
                    Block::Parameters(params),
                ],
            ),
            Section::new(
                "Maze",
                vec![
                    Block::Figure {
                        file: "figure_6_1.svg".into(),
                        caption: "The maze, the optimal path and the ten demonstrations.".into(),
                        svg: fig_maze,
                    },
                    Block::Table(t61),
                    Block::Table(t62),
                    Block::Figure {
                        file: "figure_6_4.svg".into(),
                        caption: "Reward per episode, mean ± s.e. over trials; dashed: the demonstrator's mean.".into(),
                        svg: fig_curves,
                    },
                    Block::Figure {
                        file: "figure_6_4_full.svg".into(),
                        caption: "The same, full range, legend outside.".into(),
                        svg: fig_full,
                    },
                    Block::Figure {
                        file: "figure_6_9.svg".into(),
                        caption: "Bars with brackets.".into(),
                        svg: fig_bars,
                    },
                    Block::Figure { file: "scatter.svg".into(), caption: "A scatter plot.".into(), svg: fig_scatter },
                    Block::DataFile {
                        file: "maze_returns.csv".into(),
                        description: "Return per episode and trial (excerpt).".into(),
                        bytes: data.into_bytes(),
                    },
                ],
            ),
            Section::new("Claims", vec![Block::Claims(claims)]),
        ],
    };

    let mut files = render_chapter(&report)?;
    files.extend(render_index(
        &[report.summary()],
        &Provenance::new("cargo xtask reproduce --scale quick --seed 20160501", env!("CARGO_PKG_VERSION")),
    )?);
    for f in files {
        let path = dir.join(&f.path);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, &f.bytes)?;
        println!("{}", path.display());
    }
    Ok(())
}
