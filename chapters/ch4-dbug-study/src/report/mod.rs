//! Chapter 4's report content: Figures 4.2–4.8, the six correlations beside
//! the thesis's, their spread over independent studies, claims C4.1–C4.9,
//! the user model, parameters, decisions and the per-user data, built from
//! stored results only.

mod claims;
mod data;
mod figures;
mod model_tables;
mod stats;

use rlfd_report::prose::DataFile;
use rlfd_report::published::published;
use rlfd_report::table::statistics::{self, IqmRow};
use rlfd_report::table::{Cell, ColumnGroup, Num, NumFormat, Row, Table};
use rlfd_report::{Block, ChapterReport, Deviation, Provenance, Section};
use rlfd_stats::format::signed;
use rlfd_stats::students_t_two_sided_p;

use crate::dbug::Zone;
use crate::experiment::ParticipantRecord;
use crate::session::Details;
use crate::users::{Algorithm, Expertise};
use crate::{CHAPTER, IdealResults, Results, StudyResults};
use data::{ideal_csv, users_csv};
use stats::{Pair, correlation, median, overall_values, spread, zone_values};

/// The chapter's title.
pub const TITLE: &str = "Chapter 4: Three LfD algorithms taught by naïve and expert users (DBug)";

/// The chapter's claims C4.1–C4.9, from its results alone (none without the study).
pub fn claims(results: &Results) -> rlfd_report::Result<Vec<rlfd_report::claims::Claim>> {
    match &results.study {
        Some(r) => claims::claims(&r.studies, results.ideal.as_ref()),
        None => Ok(Vec::new()),
    }
}

/// Builds the chapter's report from its results.
pub fn chapter_report(results: &Results, provenance: &Provenance) -> rlfd_report::Result<ChapterReport> {
    let mut sections = Vec::new();
    if let Some(s) = &results.study {
        sections.extend(study_sections(s, results.ideal.as_ref(), provenance)?);
    }
    if let Some(i) = &results.ideal {
        sections.push(ideal_section(i)?);
    }
    if results.study.is_none() {
        sections.push(Section::new(
            "Claims C4.1–C4.9",
            vec![Block::paragraph("The study did not run; its claims need the `study` experiment.")],
        ));
    }
    sections.push(model_tables::user_model_section()?);
    sections.push(Section::new("Parameters", vec![Block::Parameters(model_tables::parameters_table()?)]));
    sections.push(Section::new("Decisions and deviations", vec![Block::Deviations(deviations()?)]));
    if let Some(s) = &results.study {
        sections.push(Section::new(
            "Data",
            vec![Block::DataFile {
                file: "dbug_users.csv".into(),
                description: format!(
                    "One row per user and algorithm over all {} studies, at full precision: traits, order, accuracy (overall and per zone, %), interactions, satisfaction, whether the user controlled the bugs, and the per-algorithm details every observation and per-study count of the chapter is counted from (Int-RL: untied cells, reward-strategy changes; BNets: branches, erasures, both-arm demonstrations, giving up; CBA: whether the classifier reached its minimum, its Gaussians, demonstrations per action, requests, corrections, late corrections, autonomous actions, unanswered requests, giving up).",
                    s.studies.len()
                ),
                bytes: users_csv(s),
            }],
        ));
    }
    Ok(ChapterReport { slug: CHAPTER.into(), title: TITLE.into(), provenance: provenance.clone(), sections })
}

fn thesis_r(a: Algorithm, pair: Pair) -> f64 {
    published().number(&format!("ch4.{}.{}", pair.key(), a.key())).unwrap_or(f64::NAN)
}

/// The two-sided p of a published r for n users (the thesis gives r only).
fn implied_p(r: f64, n: usize) -> f64 {
    let df = n as f64 - 2.0;
    students_t_two_sided_p(r * (df / ((1.0 - r) * (1.0 + r))).sqrt(), df).unwrap_or(f64::NAN)
}

fn study_sections(
    r: &StudyResults,
    ideal: Option<&IdealResults>,
    provenance: &Provenance,
) -> rlfd_report::Result<Vec<Section>> {
    let s0 = &r.studies[0];
    let n_studies = r.studies.len();
    let mut out = Vec::new();
    let summary = format!(
        "{n_studies} independent studies of 31 synthetic users each (6 expert, 14 novice, 11 without robotics background; orders 10 / 10 / 11), every user teaching Int-RL, Behavior Networks and CBA for ten simulated minutes on the simulated DBug table, at the *{}* scale with master seed {}. \
         Study 0 is the reproduction of the thesis's single study: its figures and claims come first; the other studies draw new users from the same model and show how much one study of 31 varies. \
         The users are a model built from the chapter's descriptions of how people taught (see \"The user model\"), fixed before any learner ran and never tuned to an outcome.",
        r.scale, r.seed
    );
    out.push(Section::new("What was run", vec![Block::paragraph(summary)]));

    out.push(Section::new(
        "Figure 4.2: correct actions per algorithm",
        vec![
            Block::Figure {
                file: "figure_4_2.svg".into(),
                caption: "Study 0: share of each zone's states where the final policy takes the zone's action, one box per algorithm (median bar, box from the first to the third quartile, whiskers to the furthest data within 1.5 IQR, circles beyond).".into(),
                svg: figures::figure_4_2(s0, provenance)?,
            },
            Block::Table(per_action_table(r)?),
            Block::Table(per_action_iqm_table(r)?),
        ],
    ));

    out.push(Section::new(
        "The six correlations (Figures 4.4, 4.6, 4.8)",
        vec![
            Block::Table(correlation_table(r)?),
            Block::Table(correlation_tests_table(r)?),
            Block::Figure {
                file: "figure_correlation_spread.svg".into(),
                caption: format!("Each correlation over {n_studies} independent studies (boxes), the thesis's value (diamond) and study 0's (cross)."),
                svg: figures::correlation_spread(&correlation_values(r), &thesis_values(), n_studies, provenance)?,
            },
        ],
    ));
    for a in Algorithm::ALL {
        let (number, name) = match a {
            Algorithm::IntRl => ("4.4", "Int-RL user statistics"),
            Algorithm::BNets => ("4.6", "BNets user statistics"),
            Algorithm::Cba => ("4.8", "CBA user statistics"),
        };
        let mut blocks = Vec::new();
        for pair in Pair::ALL {
            let part = if pair == Pair::Interactions { "a" } else { "b" };
            blocks.push(Block::Figure {
                file: format!("figure_{}_{part}.svg", number.replace('.', "_")),
                caption: format!(
                    "Study 0, {}: {} (least-squares line; r in the legend). Points are spread sideways so users with equal values show apart; the line and r use the exact values.",
                    a.label(),
                    pair.label()
                ),
                svg: figures::scatter(s0, a, pair, thesis_r(a, pair), provenance)?,
            });
        }
        out.push(Section::new(format!("Figure {number}: {name}"), blocks));
    }

    out.push(policies_section(s0, provenance)?);
    out.push(Section::new("Claims C4.1–C4.9", vec![Block::Claims(claims::claims(&r.studies, ideal)?)]));
    out.push(Section::new(
        "What the users did, beside the thesis's observations",
        vec![
            Block::Table(observations_table(r)?),
            Block::Table(per_study_counts_table(r)?),
            Block::Table(bnets_levels_table(r)?),
            Block::paragraph("How to read the correlations: in this model a user who controls the bugs in Int-RL or CBA (most experts, a few others) shows the robot one clean case at a time, so CBA becomes confident sooner and asks less; a user who lets the bugs roam is asked about scattered states and answers with noisier labels. In BNets a third of the participants, whatever their expertise (reading bnets-bug-control), switch the bugs off after START and displace one into the pick-up or sweep zone, without clearing the table; the others demonstrate with the bugs roaming, so preconditions are met by chance; every participant moves the pick-up arm with every sweep (reading bnets-both-arms, the thesis's \"pickup action after every sweep\", taught \"by every user\"). The authors' two-demonstration plan (table cleared, one bug placed before START, one arm each) is the scripted ideal teacher's alone. The table below splits study 0 by control; it is the model's account of its own numbers, not a fit to the thesis's."),
            Block::Table(control_table(&r.studies[0])?),
        ],
    ));
    Ok(out)
}

fn per_action_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let mut t = Table::new("figure_4_2_medians", "Median % correct per action (Figure 4.2's median bars)", "Algorithm");
    t.caption = format!(
        "Study 0's median per zone and overall, and, in brackets, the median of the {} studies' medians. The thesis prints no numbers for Figure 4.2, only the ordering (claims C4.1–C4.3).",
        r.studies.len()
    );
    t.columns = Zone::ALL
        .iter()
        .map(|z| {
            ColumnGroup::new(format!("{} zone", z.label())).with_key(format!("{}_zone", z.label().replace('-', "")))
        })
        .chain([ColumnGroup::new("Overall")])
        .collect();
    let f = NumFormat::Percent { decimals: 1 };
    for a in Algorithm::ALL {
        let mut cells = Vec::new();
        for z in Zone::ALL {
            let m0 = median(&zone_values(&r.studies[0], a, z));
            let all: Vec<f64> = r.studies.iter().map(|s| median(&zone_values(s, a, z))).collect();
            cells.push(Cell::text(format!("{m0:.1} % ({:.1} %)", median(&all))));
        }
        let o0 = median(&overall_values(&r.studies[0], a));
        cells.push(Cell::Num(Num::new(o0, f)));
        t.rows.push(Row::new(a.label(), cells));
    }
    t.check()?;
    Ok(t)
}

/// Study 0's interquartile mean per zone and overall, with 95 %
/// stratified-bootstrap intervals (the thesis prints no means here).
fn per_action_iqm_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let s0 = &r.studies[0];
    let rows: Vec<IqmRow> = Algorithm::ALL
        .iter()
        .map(|&a| {
            let samples = Zone::ALL.iter().map(|&z| zone_values(s0, a, z)).chain([overall_values(s0, a)]);
            IqmRow {
                label: a.label().into(),
                iqm: samples.map(|v| rlfd_stats::headline_iqm(&v).ok()).collect(),
                thesis_mean: vec![None; Zone::ALL.len() + 1],
                sample: Some(format!("study 0, {}", a.key())),
            }
        })
        .collect();
    let headers: Vec<(String, String)> = Zone::ALL
        .iter()
        .map(|z| (format!("{} zone", z.label()), format!("{}_zone", z.label().replace('-', ""))))
        .chain([("Overall".to_string(), "overall".to_string())])
        .collect();
    let measures: Vec<(&str, &str)> = headers.iter().map(|(h, k)| (h.as_str(), k.as_str())).collect();
    let t = statistics::iqm_table(
        "figure_4_2_iqm",
        "Interquartile mean % correct per action, study 0",
        "The interquartile mean over study 0's users of each zone's % correct and the overall accuracy; the thesis prints neither means nor medians for Figure 4.2, so there is no thesis column. Sample: the rows of dbug_users.csv with study 0 and that algorithm.",
        "Algorithm",
        &measures,
        &rows,
        1,
    );
    t.check()?;
    Ok(t)
}

/// Study 0's six correlations in full: n, r, t, df, p and r's 95 % interval.
fn correlation_tests_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let mut t = Table::new("correlations_tests", "The correlations' tests in full, study 0", "Algorithm, pair");
    t.caption = "Pearson's r with its two-sided t-test (t = r √(df / (1 − r²)), df = n − 2) and its 95 % interval by Fisher's z transformation (scipy's pearsonr confidence_interval).".into();
    t.columns = vec![
        ColumnGroup::new("n"),
        ColumnGroup::new("r"),
        ColumnGroup::new("95 % CI low").with_key("ci_lower"),
        ColumnGroup::new("95 % CI high").with_key("ci_upper"),
        ColumnGroup::new("t"),
        ColumnGroup::new("df"),
        ColumnGroup::new("p"),
    ];
    let f2 = NumFormat::fixed(2);
    for a in Algorithm::ALL {
        for pair in Pair::ALL {
            let cells = match correlation(&r.studies[0], a, pair) {
                Some(c) => {
                    let (lo, hi) = c.confidence_interval(0.95).unwrap_or((f64::NAN, f64::NAN));
                    vec![
                        Cell::Num(Num::new(c.n as f64, NumFormat::Integer)),
                        Cell::Num(Num::new(c.r, f2)),
                        Cell::Num(Num::new(lo, f2)),
                        Cell::Num(Num::new(hi, f2)),
                        Cell::Num(Num::new(c.t, f2)),
                        Cell::Num(Num::new(c.df, NumFormat::Integer)),
                        Cell::Num(Num::p_value(c.p)),
                    ]
                }
                None => vec![Cell::Empty; 7],
            };
            t.rows.push(Row::new(format!("{}: {}", a.label(), pair.label()), cells));
        }
    }
    t.notes = vec!["A dash: r is undefined (a constant column).".into()];
    t.check()?;
    Ok(t)
}

fn correlation_values(r: &StudyResults) -> [[Vec<f64>; 2]; 3] {
    Algorithm::ALL.map(|a| {
        Pair::ALL.map(|pair| r.studies.iter().map(|s| correlation(s, a, pair).map_or(f64::NAN, |c| c.r)).collect())
    })
}

fn thesis_values() -> [[f64; 2]; 3] {
    Algorithm::ALL.map(|a| Pair::ALL.map(|pair| thesis_r(a, pair)))
}

fn correlation_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let n = r.studies.len();
    let mut t = Table::new("correlations", "Pearson correlations with the final policy's accuracy", "Algorithm, pair");
    t.caption = format!(
        "Study 0 (31 users) beside the thesis (31 participants). The thesis reports r only; its p is the two-sided t-test p implied by r with n = 31. The last columns summarise r over {n} independent studies: median and the 5th–95th percentile range, and the share of studies with the thesis's sign."
    );
    t.columns = vec![
        ColumnGroup::new("r"),
        ColumnGroup::new("p"),
        ColumnGroup::new("Median r over studies").with_key("median_r"),
        ColumnGroup::new("5–95 % range").with_key("range_r"),
        ColumnGroup::new("Same sign as thesis").with_key("same_sign"),
    ];
    let values = correlation_values(r);
    for a in Algorithm::ALL {
        for (k, pair) in Pair::ALL.iter().enumerate() {
            let theirs = thesis_r(a, *pair);
            let c = correlation(&r.studies[0], a, *pair);
            let sp = spread(&values[a.index()][k]);
            let same = values[a.index()][k].iter().filter(|v| v.is_finite() && v.signum() == theirs.signum()).count();
            t.rows.push(Row::new(
                format!("{}: {}", a.label(), pair.label()),
                vec![
                    c.map_or(Cell::ours_only(Num::new(f64::NAN, NumFormat::fixed(2))), |c| {
                        Cell::compare(Num::new(c.r, NumFormat::fixed(2)), theirs)
                    }),
                    c.map_or(Cell::ours_only(Num::p_value(f64::NAN)), |c| {
                        Cell::compare(Num::p_value(c.p), implied_p(theirs, 31))
                    }),
                    Cell::Num(Num::new(sp.median, NumFormat::fixed(2))),
                    Cell::text(format!("{} to {}", signed(sp.p05, 2), signed(sp.p95, 2))),
                    Cell::text(format!("{same} of {n}")),
                ],
            ));
        }
    }
    t.notes = vec![
        "Interactions: rewards given (Int-RL), START…DONE demonstrations (BNets), demonstrations and corrections (CBA), the counts the thesis plots. A dash: r is undefined in that study (a constant column).".into(),
        "* p ≤ 0.05, ** p ≤ 0.01, *** p ≤ 0.001, **** p ≤ 0.0001; p-values rounded to 4 significant digits.".into(),
    ];
    t.check()?;
    Ok(t)
}

fn policies_section(s0: &[ParticipantRecord], provenance: &Provenance) -> rlfd_report::Result<Section> {
    let by = |a: Algorithm| {
        let mut v: Vec<&ParticipantRecord> = s0.iter().collect();
        v.sort_by(|x, y| {
            x.session(a)
                .accuracy
                .overall
                .total_cmp(&y.session(a).accuracy.overall)
                .then(x.participant.cmp(&y.participant))
        });
        (*v.last().expect("users"), v[0])
    };
    let mut blocks = Vec::new();
    let (best, worst) = by(Algorithm::IntRl);
    for (part, what, p) in [("a", "a successful", best), ("b", "an unsuccessful", worst)] {
        if let Details::IntRl { policy, .. } = &p.session(Algorithm::IntRl).details {
            blocks.push(Block::Figure {
                file: format!("figure_4_3_{part}.svg"),
                caption: format!("Study 0's {} Int-RL policy: each untied cell's greedy action (triangle, tinted cell); tied cells empty, acted in at random.", if part == "a" { "most accurate" } else { "least accurate" }),
                svg: figures::figure_4_3(part, what, p, policy, provenance)?,
            });
        }
    }
    let bnets: Vec<&ParticipantRecord> = s0.iter().collect();
    let simple = bnets
        .iter()
        .filter(|p| matches!(&p.session(Algorithm::BNets).details, Details::BNets { branches, .. } if branches.iter().map(|b| b.nodes.len()).sum::<usize>() > 0))
        .min_by_key(|p| {
            let s = p.session(Algorithm::BNets);
            let nodes = match &s.details { Details::BNets { branches, .. } => branches.iter().map(|b| b.nodes.len()).sum::<usize>(), _ => 0 };
            (s.accuracy.zone(Zone::Pickup) < 100.0, nodes, p.participant)
        });
    let complex = bnets.iter().max_by_key(|p| {
        let nodes = match &p.session(Algorithm::BNets).details {
            Details::BNets { branches, .. } => branches.iter().map(|b| b.nodes.len()).sum::<usize>(),
            _ => 0,
        };
        (nodes, std::cmp::Reverse(p.participant))
    });
    for (part, label, p) in [("a", "a simple network", simple), ("b", "the most complicated network", complex)] {
        if let Some(p) = p
            && let Details::BNets { branches, .. } = &p.session(Algorithm::BNets).details
        {
            let s = p.session(Algorithm::BNets);
            blocks.push(Block::Figure {
                file: format!("figure_4_5_{part}.svg"),
                caption: format!(
                    "Study 0, user {} ({}): {label} ({} kept demonstration{}, {:.1} % correct; FBIPZ/FBISZ: found a bug in the pick-up/sweep zone, P-UP: pick-up). Only links between consecutive behaviours and the enabling and permanent links are drawn; every earlier behaviour also orders every later one.",
                    p.participant,
                    p.traits.expertise.label(),
                    branches.len(),
                    if branches.len() == 1 { "" } else { "s" },
                    s.accuracy.overall
                ),
                svg: figures::figure_4_5(part, &format!("{label}, user {}", p.participant), branches, provenance)?,
            });
        }
    }
    let (best, worst) = by(Algorithm::Cba);
    for (part, what, p) in [("a", "a successful", best), ("b", "an unsuccessful", worst)] {
        if let Details::Cba { classifier, .. } = &p.session(Algorithm::Cba).details {
            blocks.push(Block::Figure {
                file: format!("figure_4_7_{part}.svg"),
                caption: format!("Study 0's {} CBA policy: the classifier's action on a 16-pixel lattice (tinted), every Gaussian's 2σ ellipse (1σ dashed) in its action's colour.", if part == "a" { "most accurate" } else { "least accurate" }),
                svg: figures::figure_4_7(part, what, p, classifier.as_deref(), provenance)?,
            });
        }
    }
    Ok(Section::new("Figures 4.3, 4.5 and 4.7: example policies and networks", blocks))
}

fn observations_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let s0 = &r.studies[0];
    let mut t = Table::new("observations", "Descriptive numbers: the thesis's beside study 0's", "Observation");
    t.caption = format!("Study 0, and in brackets the median over the {} studies.", r.studies.len());
    t.columns = vec![ColumnGroup::new("Ours"), ColumnGroup::new("Thesis")];
    let over = |f: &dyn Fn(&[ParticipantRecord]) -> f64| -> (f64, f64) {
        let all: Vec<f64> = r.studies.iter().map(|s| f(s)).collect();
        (f(s0), median(&all))
    };
    let intrl_max =
        |s: &[ParticipantRecord]| overall_values(s, Algorithm::IntRl).into_iter().fold(f64::NEG_INFINITY, f64::max);
    let untied_best = |s: &[ParticipantRecord]| {
        let best = s
            .iter()
            .max_by(|a, b| {
                a.session(Algorithm::IntRl).accuracy.overall.total_cmp(&b.session(Algorithm::IntRl).accuracy.overall)
            })
            .expect("users");
        match &best.session(Algorithm::IntRl).details {
            Details::IntRl { untied, .. } => f64::from(*untied),
            _ => f64::NAN,
        }
    };
    let too_few = |s: &[ParticipantRecord]| {
        s.iter().filter(|p| matches!(&p.session(Algorithm::Cba).details, Details::Cba { classifier: None, .. })).count()
            as f64
    };
    let sweepers = |s: &[ParticipantRecord]| {
        s.iter().filter(|p| p.session(Algorithm::BNets).accuracy.zone(Zone::Sweep) > 0.0).count() as f64
    };
    let gaussians = |s: &[ParticipantRecord]| {
        let v: Vec<f64> = s
            .iter()
            .filter_map(|p| match &p.session(Algorithm::Cba).details {
                Details::Cba { classifier: Some(c), .. } => {
                    Some(c.models.iter().map(|g| g.components.len()).sum::<usize>() as f64)
                }
                _ => None,
            })
            .collect();
        median(&v)
    };
    let late = |s: &[ParticipantRecord]| {
        s.iter().filter(|p| matches!(&p.session(Algorithm::Cba).details, Details::Cba { late_corrections, .. } if *late_corrections > 0)).count() as f64
    };
    let stopped = |s: &[ParticipantRecord]| {
        s.iter().filter(|p| matches!(&p.session(Algorithm::IntRl).details, Details::IntRl { strategy_changes, .. } if *strategy_changes > 0)).count() as f64
    };
    let expert_bnets_demos = |s: &[ParticipantRecord]| {
        let v: Vec<f64> = s
            .iter()
            .filter(|p| p.traits.expertise == Expertise::Expert)
            .map(|p| f64::from(p.session(Algorithm::BNets).interactions))
            .collect();
        median(&v)
    };
    let rows: Vec<(&str, (f64, f64), &str, usize)> = vec![
        ("Best Int-RL accuracy (%)", over(&intrl_max), "≈ 22", 1),
        ("Untied cells of the best Int-RL policy (of 100)", over(&untied_best), "≈ 20", 0),
        ("Int-RL users who changed reward strategy", over(&stopped), "\"some\"", 0),
        ("BNets users whose final policy sweeps", over(&sweepers), "0", 0),
        ("Median BNets demonstrations of the experts", over(&expert_bnets_demos), "2 (an expert roboticist)", 1),
        ("CBA users with < 3 demonstrations of an action", over(&too_few), "3", 0),
        ("CBA users with a late correction", over(&late), "\"several\"", 0),
        (
            "Median Gaussians per CBA classifier (all actions)",
            over(&gaussians),
            "3–4 ideal; users \"multiple\" per action",
            1,
        ),
    ];
    for (label, (ours, all), theirs, decimals) in rows {
        t.rows.push(Row::new(
            label,
            vec![Cell::text(format!("{ours:.decimals$} ({all:.decimals$})")), Cell::text(theirs)],
        ));
    }
    t.check()?;
    Ok(t)
}

/// In how many of the studies each count occurs: BNets users whose final
/// network sweeps (the thesis: none), expert participants among them, and
/// CBA users whose classifier never got its minimum (the thesis: 3).
fn per_study_counts_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let counts = |f: &dyn Fn(&ParticipantRecord) -> bool| -> Vec<usize> {
        r.studies.iter().map(|s| s.iter().filter(|p| f(p)).count()).collect()
    };
    let sweeps = |p: &ParticipantRecord| p.session(Algorithm::BNets).accuracy.zone(Zone::Sweep) > 0.0;
    let series = [
        counts(&sweeps),
        counts(&|p| p.traits.expertise == Expertise::Expert && sweeps(p)),
        counts(&|p| matches!(&p.session(Algorithm::Cba).details, Details::Cba { classifier: None, .. })),
        counts(&|p| matches!(&p.session(Algorithm::Cba).details, Details::Cba { gave_up: true, .. })),
    ];
    let mut t = Table::new(
        "per_study_counts",
        "How many users, in each of the studies: BNets users who teach sweep, CBA users who gave too little",
        "Users in a study",
    );
    t.caption = format!(
        "Each cell: the number of the {} studies of 31 in which exactly that many users did it. The thesis: no BNets user taught sweep in the correct states; 3 CBA users gave too few demonstrations (fewer than 3 of an action). Study 0 (the reproduction): {} BNets users sweep ({} of them experts), {} CBA users gave too little, {} stopped answering.",
        r.studies.len(),
        series[0][0],
        series[1][0],
        series[2][0],
        series[3][0]
    );
    t.columns = vec![
        ColumnGroup::new("BNets users whose network sweeps").with_key("bnets_sweep"),
        ColumnGroup::new("of them expert participants").with_key("bnets_sweep_experts"),
        ColumnGroup::new("CBA users with too little data").with_key("cba_too_little"),
        ColumnGroup::new("CBA users who stopped answering").with_key("cba_gave_up"),
    ];
    let top = series.iter().flatten().copied().max().unwrap_or(0);
    for n in 0..=top {
        let cells = series
            .iter()
            .map(|v| Cell::Num(Num::new(v.iter().filter(|&&c| c == n).count() as f64, NumFormat::Integer)))
            .collect();
        t.rows.push(Row::new(n.to_string(), cells));
    }
    t.check()?;
    Ok(t)
}

/// The BNets accuracy levels the users' final networks reach, over every
/// study, beside the thesis's three (0 %, 10.4 %, 77.1 %, Figure 4.6(a)).
fn bnets_levels_table(r: &StudyResults) -> rlfd_report::Result<Table> {
    let acc = |p: &ParticipantRecord| p.session(Algorithm::BNets).accuracy.overall;
    let mut levels: Vec<f64> = r.studies.iter().flatten().map(acc).collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let thesis = claims::thesis_levels();
    let n_users: usize = r.studies.iter().map(Vec::len).sum();
    let mut t =
        Table::new("bnets_levels", "BNets accuracy levels over all studies, beside the thesis's three", "Accuracy");
    t.caption = format!(
        "Every accuracy a BNets final network reaches in the {} studies ({n_users} users): how many users reach it, in how many studies it occurs, and the number of users at it per study (median, range). The thesis's Figure 4.6(a) has three levels: 0 %, 10.4 % (the pick-up zone) and 77.1 % (the wait zone).",
        r.studies.len()
    );
    t.columns = vec![
        ColumnGroup::new("Users").with_key("users"),
        ColumnGroup::new("Share of users").with_key("share"),
        ColumnGroup::new("Studies where it occurs").with_key("studies"),
        ColumnGroup::new("Users per study: median (range)").with_key("per_study"),
        ColumnGroup::new("A thesis level").with_key("thesis_level"),
    ];
    for l in levels {
        let at = |p: &ParticipantRecord| (acc(p) - l).abs() < 1e-9;
        let mut per: Vec<usize> = r.studies.iter().map(|s| s.iter().filter(|p| at(p)).count()).collect();
        let users: usize = per.iter().sum();
        let studies = per.iter().filter(|&&c| c > 0).count();
        per.sort_unstable();
        let m = median(&per.iter().map(|&c| c as f64).collect::<Vec<_>>());
        t.rows.push(Row::new(
            format!("{l:.1} %"),
            vec![
                Cell::Num(Num::new(users as f64, NumFormat::Integer)),
                Cell::Num(Num::new(100.0 * users as f64 / n_users as f64, NumFormat::Percent { decimals: 1 })),
                Cell::Num(Num::new(studies as f64, NumFormat::Integer)),
                Cell::text(format!("{m} ({}–{})", per[0], per[per.len() - 1])),
                Cell::text(if thesis.iter().any(|v| (v - l).abs() < 1e-9) { "yes" } else { "no" }),
            ],
        ));
    }
    t.check()?;
    Ok(t)
}

fn control_table(s0: &[ParticipantRecord]) -> rlfd_report::Result<Table> {
    let mut t = Table::new(
        "controlled_bugs",
        "Study 0: users who controlled the bugs and users who let them roam",
        "Algorithm, users",
    );
    t.columns =
        vec![ColumnGroup::new("Users"), ColumnGroup::new("Mean interactions"), ColumnGroup::new("Mean accuracy")];
    for a in Algorithm::ALL {
        for controlled in [true, false] {
            let group: Vec<&ParticipantRecord> = s0.iter().filter(|p| p.session(a).controlled == controlled).collect();
            let mean = |f: &dyn Fn(&ParticipantRecord) -> f64| {
                if group.is_empty() { f64::NAN } else { group.iter().map(|p| f(p)).sum::<f64>() / group.len() as f64 }
            };
            t.rows.push(Row::new(
                format!("{}, {}", a.label(), if controlled { "controlled" } else { "roaming" }),
                vec![
                    Cell::Num(Num::new(group.len() as f64, NumFormat::Integer)),
                    Cell::Num(Num::new(mean(&|p| f64::from(p.session(a).interactions)), NumFormat::fixed(1))),
                    Cell::Num(Num::new(mean(&|p| p.session(a).accuracy.overall), NumFormat::Percent { decimals: 1 })),
                ],
            ));
        }
    }
    t.check()?;
    Ok(t)
}

fn ideal_section(i: &IdealResults) -> rlfd_report::Result<Section> {
    let mut t = Table::new("ideal_teacher", "The scripted ideal teacher (the thesis's authors)", "Algorithm");
    t.caption = format!(
        "Accuracy after ten minutes, {} sessions per algorithm (mean ± sd; lowest). The teacher knows each algorithm: it shows Int-RL every grid cell with one bug and guides and rewards without error, gives BNets the expert's two demonstrations with the bugs placed by hand, and shows CBA a lattice of spots over every zone, answering each request at once.",
        i.params.trials
    );
    t.columns = vec![ColumnGroup::new("Accuracy"), ColumnGroup::new("Lowest"), ColumnGroup::new("Interactions")];
    for a in Algorithm::ALL {
        let acc: Vec<f64> = i.sessions[a.index()].iter().map(|r| r.accuracy.overall).collect();
        let inter: Vec<f64> = i.sessions[a.index()].iter().map(|r| f64::from(r.interactions)).collect();
        let s = rlfd_stats::Summary::of(&acc).ok();
        t.rows.push(Row::new(
            a.label(),
            vec![
                s.map_or(Cell::Empty, |s| {
                    Cell::Num(Num::new(s.mean, NumFormat::Percent { decimals: 1 }).with_spread(s.sd))
                }),
                Cell::Num(Num::new(
                    acc.iter().copied().fold(f64::INFINITY, f64::min),
                    NumFormat::Percent { decimals: 1 },
                )),
                Cell::Num(Num::new(median(&inter), NumFormat::Integer)),
            ],
        ));
    }
    t.notes = vec![
        "The 10 × 10 grid caps Int-RL at 96.6 %: cells that straddle a zone border cannot be right everywhere.".into(),
    ];
    t.check()?;
    Ok(Section::new(
        "The authors: a scripted ideal teacher",
        vec![
            Block::paragraph(
                "\"the authors of this chapter, who are familiar with the inner workings of the algorithms, were able to teach the task using all three methods within this time frame\" (BNets \"under a minute\"). The same sessions, table and learners, taught by a script that knows the algorithms; claim C4.9 is decided on it.",
            ),
            Block::Table(t),
            Block::DataFile {
                file: "ideal_teacher_sessions.csv".into(),
                description: "Every session of the scripted ideal teacher: accuracy overall and per zone, interactions, and the same per-algorithm details as `dbug_users.csv`.".into(),
                bytes: ideal_csv(i),
            },
        ],
    ))
}

/// The chapter's decisions and deviations, kept as data in `data/deviations.toml`.
const DEVIATIONS: DataFile =
    DataFile { path: "chapters/ch4-dbug-study/data/deviations.toml", text: include_str!("../../data/deviations.toml") };

fn deviations() -> rlfd_report::Result<Vec<Deviation>> {
    DEVIATIONS.deviations("deviation")
}
