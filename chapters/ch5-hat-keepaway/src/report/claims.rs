//! Verdicts on the thesis's chapter-5 claims (C5.1–C5.10), computed from
//! the data with the tests `claims.md` names. Nothing here knows the
//! thesis's outcome; the verdicts follow from our numbers alone.

use rlfd_harness::Scale;
use rlfd_report::claims::{Check, Claim, TestFloor};
use rlfd_stats::format::p_value;

use rlfd_report::published::published;

use super::metrics::{Metric, mean_sd};
use super::tables::{Analysis, thesis_demo_mean};
use crate::experiment::{Ch5Results, Condition};
use crate::inputs::DemoSetId;
use crate::keepaway::CYCLES_PER_SECOND;
use crate::learners::Method;

/// Trials below which a significance test is not taken as evidence: 10, as
/// the thesis tested ([`TestFloor::ThesisTested`]).
const MIN_TRIALS_FOR_TESTS: usize = TestFloor::ThesisTested.trials();

struct Ctx<'a> {
    a: &'a Analysis,
    /// Claims decided by a test: enough trials at paper scale.
    tests: Check,
    /// Claims about final values or hours: paper scale.
    paper: Check,
}

fn too_few(a: &Analysis, results: &Ch5Results) -> String {
    format!(
        "{} trials of {} simulated hours are too few for the thesis's tests ({} trials of {} hours); the evidence is shown for the record",
        a.trials,
        results.params.hours,
        thesis_number("ch5.trials"),
        thesis_number("ch5.sim_hours")
    )
}

fn short(results: &Ch5Results) -> String {
    format!(
        "{} simulated hours are not the thesis's {}, so final values are not comparable; the evidence is shown for the record",
        results.params.hours,
        thesis_number("ch5.sim_hours")
    )
}

/// A published number as the thesis writes it (`10`, `30`).
fn thesis_number(path: &str) -> f64 {
    published().number(path).unwrap_or(f64::NAN)
}

/// "`label` m vs No Prior m (p = …)", and whether it is above and significant.
fn against(ctx: &Ctx, label: &str, c: &Condition, base: (&str, &Condition), m: Metric) -> (String, bool, bool) {
    let (x, _) = ctx.a.summary(c, m).unwrap_or((f64::NAN, 0.0));
    let (y, _) = ctx.a.summary(base.1, m).unwrap_or((f64::NAN, 0.0));
    let p = ctx.a.p(c, base.1, m).0;
    (format!("{label} {x:.2} vs {} {y:.2} (p = {})", base.0, p_value(p)), x > y, p < 0.05)
}

/// The claim that each `(label, condition)` of `rows` collects significantly
/// more total reward than `base` (C5.1, C5.4, C5.5, C5.8 share this test).
fn all_above_in_total(
    ctx: &Ctx,
    id: &str,
    thesis_evidence: &str,
    rows: &[(&str, &Condition)],
    base: (&str, &Condition),
    yes: &str,
    no: &str,
) -> rlfd_report::Result<Claim> {
    let mut text = Vec::new();
    let mut holds = true;
    for &(label, c) in rows {
        let (t, above, sig) = against(ctx, label, c, base, Metric::Total);
        text.push(t);
        holds &= above && sig;
    }
    let (v, why) = ctx.tests.verdict(holds, yes, no);
    Claim::from_spec(id, thesis_evidence, format!("Total: {}.", text.join("; ")), v, why)
}

fn a20(method: Method) -> Condition {
    Condition { method, set: Some(DemoSetId::A20) }
}

/// Every chapter-5 claim whose experiments ran.
pub fn claims(a: &Analysis, results: &Ch5Results) -> rlfd_report::Result<Vec<Claim>> {
    let ctx = Ctx {
        a,
        tests: Check::when(a.trials >= MIN_TRIALS_FOR_TESTS && results.scale == Scale::Paper, || too_few(a, results)),
        paper: Check::when(results.scale == Scale::Paper, || short(results)),
    };
    let np = ("No Prior", &Condition::NO_PRIOR);
    let ran = |c: &Condition| a.of(c).is_some();
    let mut out = Vec::new();
    let hat = [
        ("Value Bonus", a20(Method::VALUE_BONUS)),
        ("Extra Action", a20(Method::EXTRA_ACTION)),
        ("PPR", a20(Method::POLICY_REUSE)),
    ];

    if hat.iter().all(|(_, c)| ran(c)) && ran(&Condition::NO_PRIOR) {
        out.push(all_above_in_total(
            &ctx,
            "C5.1",
            "Total reward: No Prior 380; Value Bonus 401, Extra Action 407, PPR 411, all significant (Table 5.1).",
            &hat.iter().map(|(l, c)| (*l, c)).collect::<Vec<_>>(),
            np,
            "All three HAT variants collect significantly more total reward than No Prior.",
            "At least one HAT variant does not collect significantly more total reward than No Prior.",
        )?);

        // C5.2: the thesis says "only Extra Action has a statistically
        // significant improvement over No Prior": the test is the set of
        // methods whose final reward is significantly *above* No Prior's (a
        // significant drop is not an improvement; it is reported beside).
        let mut text = Vec::new();
        let mut improved = Vec::new();
        let mut dropped = Vec::new();
        for (l, c) in &hat {
            let (t, above, sig) = against(&ctx, l, c, np, Metric::Final);
            text.push(t);
            match (sig, above) {
                (true, true) => improved.push(*l),
                (true, false) => dropped.push(*l),
                _ => {}
            }
        }
        let holds = improved == ["Extra Action"];
        let drops = if dropped.is_empty() {
            String::new()
        } else {
            format!(" Significantly below No Prior (not an improvement): {}.", dropped.join(", "))
        };
        let (v, why) = ctx.tests.verdict(
            holds,
            &format!("Only Extra Action's final reward is significantly above No Prior's.{drops}"),
            &if improved.is_empty() {
                format!("No method's final reward is significantly above No Prior's.{drops}")
            } else {
                format!("Significantly above No Prior in final reward: {}.{drops}", improved.join(", "))
            },
        );
        out.push(Claim::from_spec(
            "C5.2",
            "Final: No Prior 14.3; Value Bonus 15.1, Extra Action 16.0, PPR 15.2; only Extra Action significant.",
            format!("Final: {}.", text.join("; ")),
            v,
            why,
        )?);

        // C5.3
        let hours = |c: &Condition| a.hours(c);
        let fmt = |h: Option<f64>| h.map_or("not reached".to_string(), |h| format!("{h:.2} h"));
        let base = hours(&Condition::NO_PRIOR).unwrap_or(f64::INFINITY);
        let hat_hours: Vec<f64> = hat.iter().map(|(_, c)| hours(c).unwrap_or(f64::INFINITY)).collect();
        let ppr = hat_hours[2];
        let sooner = hat_hours.iter().all(|&h| h < base);
        let ppr_first = ppr.is_finite() && hat_hours[..2].iter().all(|&h| ppr < h);
        let first = hat_hours.iter().copied().fold(f64::INFINITY, f64::min);
        let no = if !sooner {
            "Not every HAT variant reaches the threshold before No Prior.".to_string()
        } else if hat_hours.iter().all(|&h| h == first) {
            "Every HAT curve is at the threshold from its first sample (the rules alone keep the ball longer), so none is first; HAT is sooner than No Prior but the PPR-first part is undecided.".to_string()
        } else {
            "HAT reaches the threshold before No Prior, but PPR is not the first.".to_string()
        };
        let (v, why) = ctx.paper.verdict(
            sooner && ppr_first,
            "Every HAT variant reaches the threshold before No Prior, PPR first.",
            &no,
        );
        out.push(Claim::from_spec(
            "C5.3",
            "Hours to 14 s: No Prior 13.5, Value Bonus 10.1, Extra Action 8.57, PPR 7.9.",
            format!(
                "Hours to {} s on the trial-mean training curve: No Prior {}, Value Bonus {}, Extra Action {}, PPR {}.",
                results.params.threshold_seconds,
                fmt(hours(&Condition::NO_PRIOR)),
                fmt(hours(&hat[0].1)),
                fmt(hours(&hat[1].1)),
                fmt(hours(&hat[2].1))
            ),
            v,
            why,
        )?);
    }

    let teachers = [
        ("Subject A", Condition::ppr(DemoSetId::A20)),
        ("Subject B", Condition::ppr(DemoSetId::B)),
        ("Subject C", Condition::ppr(DemoSetId::C)),
    ];
    if teachers.iter().all(|(_, c)| ran(c)) && ran(&Condition::NO_PRIOR) {
        out.push(all_above_in_total(
            &ctx,
            "C5.4",
            "Total: No Prior 380; Subjects A 411, B 423, C 424, all significant (Table 5.2).",
            &teachers.iter().map(|(l, c)| (*l, c)).collect::<Vec<_>>(),
            np,
            "PPR with each teacher's demonstrations collects significantly more total reward than No Prior.",
            "At least one teacher's demonstrations do not raise total reward significantly.",
        )?);
    }

    let sets = [
        ("A (20)", Condition::ppr(DemoSetId::A20)),
        ("A (10)", Condition::ppr(DemoSetId::A10)),
        ("C (20)", Condition::ppr(DemoSetId::C)),
        ("A + C Best", Condition::ppr(DemoSetId::AcBest)),
        ("A + C Worst", Condition::ppr(DemoSetId::AcWorst)),
    ];
    if sets.iter().all(|(_, c)| ran(c)) {
        let best = sets[3];
        let mut text = Vec::new();
        let mut holds = true;
        for other in sets.iter().filter(|(l, _)| *l != "A + C Best") {
            let (t, above, sig) = against(&ctx, best.0, &best.1, (other.0, &other.1), Metric::Total);
            text.push(t);
            holds &= above && sig;
        }
        let (v, why) = ctx.tests.verdict(
            holds,
            "A + C Best collects significantly more total reward than every other demonstration set.",
            "A + C Best is not significantly above every other set in total reward.",
        );
        out.push(Claim::from_spec(
            "C5.5",
            "Total: A + C Best 431 against A (20) 411, A (10) 407, C (20) 424, A + C Worst 419; significant against all.",
            format!("Total: {}.", text.join("; ")),
            v,
            why,
        )?);

        let (tj, above_j, _) = against(&ctx, "A (10)", &sets[1].1, ("A (20)", &sets[0].1), Metric::Jumpstart);
        let (tt, above_t, sig_t) = against(&ctx, "A (10)", &sets[1].1, ("A (20)", &sets[0].1), Metric::Total);
        let holds = !above_j && !above_t && sig_t;
        let (v, why) = ctx.tests.verdict(
            holds,
            "Half of A's demonstrations give a lower jumpstart and a significantly lower total reward.",
            "Halving A's demonstrations does not lower both jumpstart and total reward (the latter significantly).",
        );
        out.push(Claim::from_spec(
            "C5.6",
            "Jumpstart −2.23 vs −0.30 and total 407 vs 411 for A (10) vs A (20), both significant.",
            format!("Jumpstart: {tj}; total: {tt}."),
            v,
            why,
        )?);
    }

    let handicaps = [
        ("B", Condition::ppr(DemoSetId::B)),
        ("Limited", Condition::ppr(DemoSetId::BLimited)),
        ("Fast", Condition::ppr(DemoSetId::BFast)),
    ];
    if handicaps.iter().all(|(_, c)| ran(c)) && ran(&Condition::NO_PRIOR) {
        let b = (handicaps[0].0, &handicaps[0].1);
        let mut text = Vec::new();
        let mut holds = true;
        for (l, c) in &handicaps[1..] {
            let (tf, _, sig_f) = against(&ctx, l, c, b, Metric::Final);
            let (tj, above_j, sig_j) = against(&ctx, l, c, b, Metric::Jumpstart);
            let (tt, above_t, sig_t) = against(&ctx, l, c, b, Metric::Total);
            text.push(format!("final {tf}; jumpstart {tj}; total {tt}"));
            holds &= !sig_f && !above_j && sig_j && !above_t && sig_t;
        }
        let (v, why) = ctx.tests.verdict(holds,
            "Against B, both handicaps leave final reward unchanged and lower jumpstart and total reward significantly.",
            "At least one handicap changes final reward significantly, or does not lower jumpstart or total reward significantly.");
        out.push(Claim::from_spec(
            "C5.7",
            "Final 16.0 and 16.0 vs 15.7 (n.s.); jumpstart −1.26 and −2.37 vs 3.35, total 404 and 401 vs 423 (significant).",
            text.join(" | "),
            v,
            why,
        )?);

        out.push(all_above_in_total(
            &ctx,
            "C5.8",
            "Total 404 (Limited) and 401 (Fast) against No Prior 380, significant.",
            &handicaps[1..].iter().map(|(l, c)| (*l, c)).collect::<Vec<_>>(),
            np,
            "Both handicapped demonstration sets still give significantly more total reward than No Prior.",
            "At least one handicapped set does not beat No Prior significantly in total reward.",
        )?);
    }

    // C5.9: every condition that ran against its teacher's mean demonstration.
    if let Some(demos) = &results.demos
        && !results.learning.is_empty()
    {
        let mut text = Vec::new();
        let mut below = Vec::new();
        for (slug, (c, _)) in &results.learning {
            let set = c.set.unwrap_or(DemoSetId::A20);
            let teacher = demos.get(set).set.mean_seconds();
            let (f, _) = a.summary(c, Metric::Final).unwrap_or((f64::NAN, 0.0));
            text.push(format!("{slug} {f:.2} vs {teacher:.2}"));
            if f.is_nan() || f <= teacher {
                below.push(slug.clone());
            }
        }
        let (v, why) = ctx.paper.verdict(
            below.is_empty(),
            "Every condition's final reward exceeds its teacher's mean demonstration duration.",
            &format!("Below their teacher: {}.", below.join(", ")),
        );
        out.push(Claim::from_spec(
            "C5.9",
            "All final rewards (14.3–16.2 s) exceed the teachers' means (10.4–11.3 s; No Prior is compared with Subject A).",
            format!("Final vs the teacher's mean demonstration (s; No Prior against Subject A): {}.", text.join("; ")),
            v,
            why,
        )?);
    }

    // C5.10: Subject A's rules alone against No Prior's final reward.
    if let (Some(rules), true) = (results.rules_only.get(&DemoSetId::A20), ran(&Condition::NO_PRIOR)) {
        let secs: Vec<f64> = rules.iter().map(|&c| f64::from(c) / CYCLES_PER_SECOND).collect();
        let (alone, _) = mean_sd(&secs);
        let (f, _) = a.summary(&Condition::NO_PRIOR, Metric::Final).unwrap_or((f64::NAN, 0.0));
        let others: Vec<String> = results
            .rules_only
            .iter()
            .map(|(id, d)| {
                let s: Vec<f64> = d.iter().map(|&c| f64::from(c) / CYCLES_PER_SECOND).collect();
                format!("{} {:.2}", id.label(), mean_sd(&s).0)
            })
            .collect();
        let (v, why) = ctx.paper.verdict(
            alone < f,
            "Subject A's rules played alone keep the ball for less time than No Prior learns to.",
            "Subject A's rules played alone do as well as No Prior's final policy or better.",
        );
        out.push(Claim::from_spec(
            "C5.10",
            format!(
                "\"Without employing independent learning, just following the learned rules, results in poor performance\" (Subject A; teacher {} s).",
                thesis_demo_mean(DemoSetId::A20)
            ),
            format!("Rules alone (A) {alone:.2} s vs No Prior final {f:.2} s. All sets' rules alone: {}.", others.join(", ")),
            v,
            why,
        )?);
    }
    Ok(out)
}
