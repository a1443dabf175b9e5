//! `--robustness`: every claim's verdict recomputed at every replication
//! and reading run point of a chapter, from the claims alone (no figure, no
//! bootstrap table is drawn for them), gathered for the report.

use std::collections::BTreeMap;

use rlfd_harness::RunMode;
use rlfd_report::claims::{Claim, Verdict};
use rlfd_report::robustness::{AxisInfo, ClaimRobustness, LevelInfo, ReadingVerdict, Robustness};

use rlfd_stats::clopper_pearson;

use crate::Machine;
use crate::chapter::AnyChapter;
use crate::command::{Role, RunPoint, Selection, replication_seed};
use crate::error::RunnerError;
use crate::pooled::pool;

/// The claims of every robustness run point of `chapter`, in running order.
pub struct PointClaims {
    /// Per point, its claims.
    pub points: Vec<(RunPoint, Vec<Claim>)>,
    /// Trials the points read, over every point.
    pub read: usize,
    /// Of those, the ones read from records of another version:
    /// (behaviour version, build identity) → count.
    pub other_versions: BTreeMap<(u32, String), usize>,
}

/// Runs (or loads, as `mode` says) `chapter`'s replication and reading
/// points and keeps their claims; `log` hears one line per point.
pub fn run(
    selection: &Selection<'_>,
    chapter: &dyn AnyChapter,
    machine: &Machine,
    mode: &RunMode,
    log: &mut dyn FnMut(String),
) -> Result<PointClaims, RunnerError> {
    let named = selection.named();
    let given = selection.inputs();
    let mut points = Vec::new();
    let (mut read, mut other_versions) = (0, BTreeMap::new());
    for point in selection.points(chapter) {
        if !point.role.is_robustness() {
            continue;
        }
        let options = machine.options(mode.clone());
        let ran =
            chapter.run(&given, &point.experiments(&named), &point.context(selection.command.scale), &options, None)?;
        let (computed, reused, _, _) = options.tally.totals();
        for t in options.tally.experiments().into_values() {
            read += t.keys.len();
            for (version, n) in t.other_versions {
                *other_versions.entry(version).or_insert(0) += n;
            }
        }
        // After `reproduce`'s computing pass a run point computes nothing,
        // and that pass has said what it did.
        if computed > 0 || !matches!(mode, RunMode::Run) {
            log(format!(
                "{}: seed {}, reading {}: {computed} trials computed, {reused} reused",
                chapter.slug(),
                point.seed,
                point.reading
            ));
        }
        points.push((point, ran.claims));
    }
    Ok(PointClaims { points, read, other_versions })
}

impl PointClaims {
    /// The banner's part for the replications and readings when some of
    /// their trials were read from records of another version (`None` when
    /// none was).
    pub fn other_versions_part(&self) -> Option<String> {
        (!self.other_versions.is_empty()).then(|| {
            let made: Vec<String> = self
                .other_versions
                .iter()
                .map(|((behaviour, build), n)| {
                    format!("{n} from another behaviour version {behaviour} built by {build}")
                })
                .collect();
            format!(
                "the robustness section's replications and readings (--robustness): of the {} trials they read, {}",
                self.read,
                made.join("; ")
            )
        })
    }

    /// As the report's robustness section shows it: per claim of `headline`,
    /// its verdict at each replication seed (the headline's first) and at
    /// each other level of each axis (at the master seed).
    pub fn robustness(&self, selection: &Selection<'_>, chapter: &dyn AnyChapter, headline: &[Claim]) -> Robustness {
        let replications = selection.command.robustness.map_or(1, |r| r.seeds);
        let seeds: Vec<u64> = (0..replications).map(|k| replication_seed(selection.command.seed, k)).collect();
        let axes = chapter
            .readings()
            .iter()
            .map(|axis| AxisInfo {
                name: axis.name().into(),
                question: axis.question().into(),
                default: axis.default_level().into(),
                why_default: axis.why_default().into(),
                levels: axis
                    .level_texts()
                    .into_iter()
                    .map(|(name, meaning, source)| LevelInfo {
                        name: name.into(),
                        meaning: meaning.into(),
                        source: source.into(),
                    })
                    .collect(),
            })
            .collect();
        let plan = rlfd_report::plan::analysis_plan();
        let verdict_of = |claims: &[Claim], id: &str| {
            claims.iter().find(|c| c.id == id).map_or(Verdict::NotEvaluable, |c| c.verdict)
        };
        let claims = headline
            .iter()
            .map(|c| {
                let mut by_seed = vec![c.verdict];
                let mut instances: Vec<Option<&Claim>> = vec![Some(c)];
                for k in 1..replications {
                    let found = self.points.iter().find(|(p, _)| p.role == Role::Replication(k));
                    by_seed.push(found.map_or(Verdict::NotEvaluable, |(_, claims)| verdict_of(claims, &c.id)));
                    instances.push(found.and_then(|(_, claims)| claims.iter().find(|x| x.id == c.id)));
                }
                // Each other level of each axis, in the order the points ran:
                // pooled over the level's replications when the claim has
                // estimates, else its verdict at the master seed.
                let mut levels: Vec<(String, String)> = Vec::new();
                for (p, _) in &self.points {
                    if let Some((axis, level, _)) = p.role.other_reading()
                        && !levels.contains(&(axis.clone(), level.clone()))
                    {
                        levels.push((axis, level));
                    }
                }
                let readings = levels
                    .into_iter()
                    .map(|(axis, level)| {
                        let at: Vec<(u32, &Vec<Claim>)> = self
                            .points
                            .iter()
                            .filter_map(|(p, claims)| match p.role.other_reading() {
                                Some((a, l, replication)) if a == axis && l == level => Some((replication, claims)),
                                _ => None,
                            })
                            .collect();
                        let at_level: Vec<Option<&Claim>> =
                            at.iter().map(|(_, claims)| claims.iter().find(|x| x.id == c.id)).collect();
                        let pooled = (at_level.len() >= 2).then(|| pool(plan, &at_level)).flatten();
                        // The default at the same replications (plan v2): a
                        // level is compared with what the default gives on
                        // the seeds the level ran, not on all K.
                        let same: Vec<Option<&Claim>> =
                            at.iter().map(|(r, _)| instances.get(*r as usize).copied().flatten()).collect();
                        let matched = pooled.as_ref().and_then(|_| pool(plan, &same));
                        let verdict = pooled.as_ref().map(|p| p.verdict).unwrap_or_else(|| {
                            at.iter()
                                .find(|(r, _)| *r == 0)
                                .map_or(Verdict::NotEvaluable, |(_, cl)| verdict_of(cl, &c.id))
                        });
                        let estimates = at
                            .iter()
                            .zip(&at_level)
                            .flat_map(|((r, _), claim)| {
                                claim
                                    .iter()
                                    .flat_map(move |c| c.estimates.iter().map(move |e| (*r as usize, e.clone())))
                            })
                            .collect();
                        ReadingVerdict { axis, level, verdict, pooled, estimates, matched }
                    })
                    .collect();
                let held = by_seed.iter().filter(|v| **v == Verdict::Reproduced).count();
                let evaluable = by_seed.iter().filter(|v| **v != Verdict::NotEvaluable).count();
                ClaimRobustness {
                    id: c.id.clone(),
                    seeds: by_seed,
                    readings,
                    pooled: (replications >= 2).then(|| pool(plan, &instances)).flatten(),
                    held_interval: clopper_pearson(held, evaluable.max(1), 0.95).ok().filter(|_| evaluable > 0),
                    estimates: instances
                        .iter()
                        .enumerate()
                        .flat_map(|(k, claim)| {
                            claim.iter().flat_map(move |c| c.estimates.iter().map(move |e| (k, e.clone())))
                        })
                        .collect(),
                }
            })
            .collect();
        Robustness { seeds, axes, claims }
    }
}
