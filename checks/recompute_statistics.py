#!/usr/bin/env python3
"""Recomputes, with SciPy, the statistics a report prints from the report's own CSV files.

An independent check of rlfd's Rust statistics: it reads nothing but a
report tree (golden/ or reports/), finds each table that names its samples
(the tests in full, the interquartile means, the correlations in full),
recomputes every value from the chapter's data file and compares.

  python3 checks/recompute_statistics.py golden reports
  python3 checks/recompute_statistics.py --pooled TREE...   (robustness runs only)

What it checks, per row:
- t-tests (`*_tests.csv`, `*_tests_full.csv`): the difference, its 95 %
  interval, t, df and the two-sided p of Student's (`scipy.stats.ttest_ind`)
  or Welch's (`equal_var=False`) test, and Hedges' g (Cohen's d with the
  pooled sd times 1 - 3/(4(n1 + n2) - 9)), to a relative 1e-9;
- interquartile means (`*_iqm.csv`): the IQM is rliable's
  (`scipy.stats.trim_mean(x, 0.25)`), to 1e-9; the bootstrap interval is
  compared with `scipy.stats.bootstrap(..., method='percentile')` of the
  same statistic with 20 000 resamples: another generator, so they agree
  within Monte Carlo error, here a tenth of the interval's width (plus a
  hundredth of the data's spread for degenerate resampling distributions);
- correlations (`correlations_tests.csv`): r, t, df, p
  (`scipy.stats.pearsonr`) and r's Fisher interval
  (`pearsonr(...).confidence_interval(0.95)`), to 1e-9;
- the claims' two-sample tests (each chapter's `summary.json`: pooled
  t-tests and pooled TOST of chapters 3, 5 and 6, listed in `CLAIMS` with
  the measure and samples each claim tests): the raw p (printed to four
  digits) and the Holm-adjusted p over the claim's family (full precision;
  Holm's step-down recomputed here), TOST as the larger of the two
  one-sided `ttest_ind` p-values against the shifted sample.

- the pooled verdicts of a robustness run (`robustness_estimates.csv`,
  `robustness_pooled.csv`, where a chapter has them): per claim component,
  at the default reading and at each other level of each axis (each pooled
  over its own replications),
  the one-sample t-test on its replication-level estimates
  (`scipy.stats.ttest_1samp(...).confidence_interval`, 95 %, or 90 % for
  an equivalence component), the power at the thesis's effect
  (`scipy.stats.nct`), the exact binomial interval of a yes/no component
  (`binomtest(...).proportion_ci(method="exact")`), and the verdicts by the
  analysis plan's rules (its d33 and power threshold read from
  `crates/rlfd-report/data/analysis-plan.toml`); and, per level (plan v2),
  the default pooled over the level's own replications and whether the
  level flips the claim (its verdict differs from that matched default).

Exit status: 0 when every row agrees, 1 otherwise (each disagreement on
one line), 2 when a tree lacks the files it should have.
"""

import csv
import json
import math
import sys
from pathlib import Path

import numpy as np
from scipy import stats

REL = 1e-9

# Per chapter: the data file, how a row names its sample, and which data
# column each measure of the tables reads.
CHAPTERS = {
    "ch3-interactive-rl": {
        "data": "sessions.csv",
        # A noise-sweep row names its `perception-noise` level.
        "sample": lambda row: f"{row['experiment']}/{row['condition']}"
        + (f"@{row['sweep_level']}" if row.get("sweep_level") else ""),
        "measures": {
            "#States": "states",
            "#Actions": "actions",
            "Cumul. Rew.": "cumulative_reward",
            "Training Time [min.]": "training_minutes",
            "states": "states",
            "actions": "actions",
            "cumulative_reward": "cumulative_reward",
            "total_guidance": "guidance",
            "training_time_min": "training_minutes",
        },
    },
    "ch4-dbug-study": {
        "data": "dbug_users.csv",
        "sample": lambda row: f"study {row['study']}, {row['algorithm']}",
        "measures": {
            "pickup_zone": "pickup_zone",
            "sweep_zone": "sweep_zone",
            "wait_zone": "wait_zone",
            "overall": "accuracy",
        },
    },
    "ch5-hat-keepaway": {
        "data": "keepaway_trials.csv",
        "sample": lambda row: row["condition"],
        "measures": {"jumpstart": "initial_seconds", "final": "final_seconds", "total": "total"},
    },
    "ch6-irl-shaping": {
        "data": "mario_metrics.csv",
        "sample": lambda row: f"{row['experiment']}/{row['condition']}",
        "measures": {"initial": "initial", "asymptotic": "asymptotic", "cumulative": "cumulative"},
        # The Maze's per-trial metrics come from its per-episode returns.
        "extra": lambda d: maze_metrics(d / "maze_returns.csv"),
    },
}


def maze_metrics(path):
    """Per agent, one row per trial: the first episode's return, the last's, and the sum."""
    episodes = {}
    for row in read(path):
        episodes.setdefault((row["agent"], int(row["trial"])), []).append((int(row["episode"]), float(row["return"])))
    by = {}
    for (agent, _trial), rows in sorted(episodes.items()):
        returns = [r for _, r in sorted(rows)]
        by.setdefault(f"maze/{agent}", []).append(
            {"initial": str(returns[0]), "asymptotic": str(returns[-1]), "cumulative": repr(math.fsum(returns))}
        )
    return by


def read(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def close(ours, theirs, rel=REL, scale=1.0):
    """Agreement to `rel` of the larger of |theirs|, `scale` and 1. An interval bound
    mean ± q·se carries the quantile's relative error times the half-width, so a bound
    near 0 is compared at the half-width's scale (SciPy 1.10.1's t.ppf(0.95, 4) is
    2.13184678134, off by 2e-9 relative: the exact value is 2.13184678633, ours)."""
    if ours == "" or ours is None:
        return theirs is None or (isinstance(theirs, float) and math.isnan(theirs))
    ours = float(ours)
    return abs(ours - theirs) <= rel * max(abs(theirs), scale, 1.0)


class Check:
    def __init__(self):
        self.rows = 0
        self.problems = []

    def expect(self, where, name, ours, theirs, rel=REL, scale=1.0):
        if not close(ours, theirs, rel, scale):
            self.problems.append(f"{where}: {name} is {ours}, SciPy gives {theirs!r}")


def samples_of(chapter_dir, spec):
    by = {}
    for row in read(chapter_dir / spec["data"]):
        by.setdefault(spec["sample"](row), []).append(row)
    if "extra" in spec:
        by.update(spec["extra"](chapter_dir))
    return by


def values(rows, column, shift=0.0):
    return np.array([float(r[column]) - shift for r in rows if r[column] != ""])


def check_tests(path, spec, by, check):
    for i, row in enumerate(read(path)):
        if not row.get("sample_x") or row["t"] == "":
            continue
        column = spec["measures"][row["measure"]]
        x = values(by[row["sample_x"]], column)
        y = values(by[row["sample_y"]], column)
        welch = row["test"] == "Welch"
        res = stats.ttest_ind(x, y, equal_var=not welch)
        n1, n2 = len(x), len(y)
        v1, v2 = x.var(ddof=1), y.var(ddof=1)
        if welch:
            se = math.sqrt(v1 / n1 + v2 / n2)
            df = (v1 / n1 + v2 / n2) ** 2 / ((v1 / n1) ** 2 / (n1 - 1) + (v2 / n2) ** 2 / (n2 - 1))
        else:
            df = n1 + n2 - 2
            se = math.sqrt(((n1 - 1) * v1 + (n2 - 1) * v2) / df * (1 / n1 + 1 / n2))
        d = x.mean() - y.mean()
        q = stats.t.ppf(0.975, df)
        where = f"{path}:{i + 2}"
        for name, theirs in [
            ("n_x", float(n1)),
            ("n_y", float(n2)),
            ("difference", d),
            ("ci_lower", d - q * se),
            ("ci_upper", d + q * se),
            ("t", float(res.statistic)),
            ("df", float(df)),
            ("p", float(res.pvalue)),
        ]:
            # SciPy before 1.11 (Debian 12 has 1.10.1) computes Student-t
            # quantiles at fractional df to about 1e-8 (1.17 agrees with ours to 1e-12).
            check.expect(where, name, row[name], theirs, rel=1e-7 if name.startswith("ci_") else REL)
        if not welch:
            sp = math.sqrt(((n1 - 1) * v1 + (n2 - 1) * v2) / (n1 + n2 - 2))
            check.expect(where, "hedges_g", row["hedges_g"], d / sp * (1 - 3 / (4 * (n1 + n2) - 9)))
        check.rows += 1


def iqm(x):
    return float(stats.trim_mean(x, 0.25))


def check_iqm(path, spec, by, check, shift_of):
    table = read(path)
    keys = [c[: -len("_iqm")] for c in table[0].keys() if c.endswith("_iqm")]
    for i, row in enumerate(table):
        if not row.get("sample"):
            continue
        for key in keys:
            if row[f"{key}_iqm"] == "":
                continue
            x = values(by[row["sample"]], spec["measures"][key], shift_of(key))
            where = f"{path}:{i + 2} {key}"
            check.expect(where, "iqm", row[f"{key}_iqm"], iqm(x))
            boot = stats.bootstrap(
                (x,), lambda s, axis: stats.trim_mean(s, 0.25, axis=axis), vectorized=True,
                n_resamples=20_000, method="percentile",
                confidence_level=0.95, random_state=np.random.default_rng(1),
            )
            lo, hi = float(row[f"{key}_ci_lower"]), float(row[f"{key}_ci_upper"])
            slack = 0.1 * (hi - lo) + 0.01 * (float(np.ptp(x)) if len(x) else 0.0) + 1e-12
            for name, ours, theirs in [
                ("ci_lower", lo, float(boot.confidence_interval.low)),
                ("ci_upper", hi, float(boot.confidence_interval.high)),
            ]:
                if abs(ours - theirs) > slack:
                    check.problems.append(f"{where}: {name} is {ours}, SciPy's bootstrap gives {theirs} (slack {slack:.3g})")
            check.rows += 1


def percentile_bootstrap(samples, statistic, resamples=200_000, chunk=20_000, seed=1):
    """The 95 % percentile-bootstrap interval of `statistic(*resampled)`, each
    sample resampled within itself (numpy's generator, not ours)."""
    rng = np.random.default_rng(seed)
    stats_ = []
    for start in range(0, resamples, chunk):
        b = min(chunk, resamples - start)
        drawn = [x[rng.integers(0, len(x), (b, len(x)))] for x in samples]
        stats_.append(statistic(*drawn))
    return np.percentile(np.concatenate(stats_), [2.5, 97.5])


def printed_interval(text):
    """`(lower, upper)` of the first `[a, b]` in `text`, typographic minus read."""
    inner = text.replace("\u2212", "-").split("[", 1)[1].split("]", 1)[0]
    lo, hi = (float(v) for v in inner.split(","))
    return lo, hi


def check_ch3_bootstraps(path, by, check):
    """C3.3's four-sample bootstrap (large minus small relative time cut) and
    C3.4's per-condition intervals of the mean cumulative reward, recomputed
    from the powered experiment's sessions with 200,000 numpy resamples. The
    printed bounds have one (C3.3) or two (C3.4) decimals; the slack is the
    rounding plus a hundredth of the interval's width (about three Monte Carlo
    standard deviations of the difference at our 100,000 resamples), plus the
    lattice step of a mean of integers."""
    claims = {c["id"]: c for c in json.load(open(path, encoding="utf-8"))["summary"]["claims"]}
    names = ["small-guidance", "small-no-guidance", "large-guidance", "large-no-guidance"]
    rows = {n: by.get(f"sorting-100/{n}", []) for n in names}
    if any(not r for r in rows.values()):
        check.problems.append(f"{path}: no sorting-100 sessions for the bootstrap check")
        return
    minutes = [values(rows[n], "training_minutes") for n in names]
    c33 = next((t for t in claims["C3.3"]["tests"] if "bootstrap" in t["test"]), None)
    if c33 is not None:
        cut = lambda g, u: 100.0 * (1.0 - g.mean(axis=1) / u.mean(axis=1))
        theirs = percentile_bootstrap(minutes, lambda sg, su, lg, lu: cut(lg, lu) - cut(sg, su))
        ours = printed_interval(c33["note"])
        for name, o, t in zip(["ci_lower", "ci_upper"], ours, theirs):
            slack = 0.05 + 0.01 * (ours[1] - ours[0])
            if abs(o - t) > slack:
                check.problems.append(f"{path} C3.3: {name} is {o}, numpy's bootstrap gives {t:.3f} (slack {slack:.3g})")
        check.rows += 1
    evidence = claims["C3.4"]["our_evidence"].replace("\u2212", "-")
    labels = {"small-guidance": "Small, guidance", "small-no-guidance": "Small, no guidance",
              "large-guidance": "Large, guidance", "large-no-guidance": "Large, no guidance"}
    for n in names:
        label = labels[n] + " "
        if label not in evidence:
            check.problems.append(f"{path} C3.4: no interval for {labels[n]}")
            continue
        lo, hi = printed_interval(evidence.split(label, 1)[1])
        reward = values(rows[n], "cumulative_reward")
        theirs = percentile_bootstrap([reward], lambda x: x.mean(axis=1))
        # Integer rewards put the resampled means on a lattice of step 1/n:
        # a percentile can fall on either side of a step.
        lattice = 1.0 / len(reward) if np.all(reward == np.round(reward)) else 0.0
        for name, o, t in zip(["ci_lower", "ci_upper"], (lo, hi), theirs):
            slack = 0.005 + 0.01 * (hi - lo) + lattice
            if abs(o - t) > slack:
                check.problems.append(f"{path} C3.4 {labels[n]}: {name} is {o}, numpy's bootstrap gives {t:.3f} (slack {slack:.3g})")
        check.rows += 1


def check_ch3_noise_sweep(chapter_dir, by, check):
    """The noise sweep's C3.3 column: at each `perception-noise` level, the
    large-minus-small time cut recomputed from the level's sessions (its
    point exactly, its interval with numpy's bootstrap and the slack of
    `check_ch3_bootstraps`), and, where the report has a robustness run, the
    same number as the robustness estimate of that level's master-seed
    replication: the sensitivity table and the robustness cell are one
    computation on the same trials."""
    path = chapter_dir / "noise_reductions.csv"
    if not path.exists():
        return
    estimates = {}
    if (chapter_dir / "robustness_estimates.csv").exists():
        for r in read(chapter_dir / "robustness_estimates.csv"):
            if r["claim"] == "C3.3" and r["replication"] == "0" and r["axis"] in ("", "perception-noise"):
                estimates[r["level"]] = float(r["value"])
    names = ["small-guidance", "small-no-guidance", "large-guidance", "large-no-guidance"]
    for i, row in enumerate(read(path)):
        level = row["shift_probability"]
        where = f"{path}:{i + 2}"
        swept = f"sorting-100/large-guidance@{level}" in by
        rows = {n: by.get(f"sorting-100/{n}" + (f"@{level}" if swept and n.startswith("large") else ""), [])
                for n in names}
        if any(not r for r in rows.values()):
            check.problems.append(f"{where}: no sorting-100 sessions at noise {level}")
            continue
        minutes = [values(rows[n], "training_minutes") for n in names]
        cut = lambda g, u: 100.0 * (1.0 - g.mean(axis=-1) / u.mean(axis=-1))
        point = cut(minutes[2], minutes[3]) - cut(minutes[0], minutes[1])
        check.expect(where, "c33", row["c33"], point)
        lo, hi = printed_interval(row["c33_interval"])
        theirs = percentile_bootstrap(minutes, lambda sg, su, lg, lu: cut(lg, lu) - cut(sg, su))
        for name, o, t in zip(["ci_lower", "ci_upper"], (lo, hi), theirs):
            slack = 0.05 + 0.01 * (hi - lo)
            if abs(o - t) > slack:
                check.problems.append(f"{where} C3.3: {name} is {o}, numpy's bootstrap gives {t:.3f} (slack {slack:.3g})")
        # The robustness run's master-seed estimate at this level (the
        # default level's row has no axis).
        robust = estimates.get(level, estimates.get("") if not swept else None)
        if estimates and robust is None:
            check.problems.append(f"{where}: no robustness estimate of C3.3 at noise {level}")
        elif robust is not None:
            check.expect(where, "c33 (robustness, replication 0)", row["c33"], robust)
        check.rows += 1


def check_correlations(path, chapter_dir, check):
    users = [r for r in read(chapter_dir / "dbug_users.csv") if r["study"] == "0"]
    labels = {"Int-RL": "intrl", "BNets": "bnets", "CBA": "cba"}
    for i, row in enumerate(read(path)):
        algorithm, pair = row["algorithm_pair"].split(": ")
        rows = [r for r in users if r["algorithm"] == labels[algorithm]]
        x = np.array([float(r[pair.split(" vs ")[0]]) for r in rows])
        y = np.array([float(r["accuracy"]) for r in rows])
        if row["r"] == "":
            continue
        res = stats.pearsonr(x, y)
        r = float(res.statistic)
        ci = res.confidence_interval(0.95)
        where = f"{path}:{i + 2}"
        n = len(x)
        for name, theirs in [
            ("n", float(n)),
            ("r", r),
            ("ci_lower", float(ci.low)),
            ("ci_upper", float(ci.high)),
            ("t", r * math.sqrt((n - 2) / (1 - r * r))),
            ("df", float(n - 2)),
            ("p", float(res.pvalue)),
        ]:
            check.expect(where, name, row[name], theirs)
        check.rows += 1


# Per chapter and claim: the measure (a key of the chapter's `measures`)
# each of its pooled tests compares, a TOST margin where the claim tests
# equivalence, and how a test's label names its two samples. Chapter 5's
# C5.7 names the measure in the label ("final Limited vs B").
CH5_SETS = {
    "No Prior": "no-prior", "Value Bonus": "value-bonus-subject-a", "Extra Action": "extra-action-subject-a",
    "PPR": "ppr-subject-a", "Subject A": "ppr-subject-a", "Subject B": "ppr-subject-b", "Subject C": "ppr-subject-c",
    "A (20)": "ppr-subject-a", "A (10)": "ppr-half-subject-a", "C (20)": "ppr-subject-c",
    "A + C Best": "ppr-subjects-a-c-best", "A + C Worst": "ppr-subjects-a-c-worst",
    "B": "ppr-subject-b", "Limited": "ppr-subject-b-limited", "Fast": "ppr-subject-b-fast",
}
CLAIMS = {
    "ch3-interactive-rl": {
        "C3.1": None, "C3.2": None,  # "#States, small space": guided vs unguided in sorting-100
    },
    "ch5-hat-keepaway": {
        "C5.1": ("total", None), "C5.2": ("final", None), "C5.4": ("total", None),
        "C5.5": ("total", None), "C5.7": (None, 1.0), "C5.8": ("total", None),
    },
    "ch6-irl-shaping": {
        "C6.1": ("maze", "cumulative", None), "C6.2": ("maze", "initial", None),
        "C6.3": ("maze", "asymptotic", 32.75), "C6.6": ("mario", "cumulative", None),
        "C6.7": ("mario", "asymptotic", None),
    },
}


def claim_samples(chapter, claim, label):
    """The measure, the two samples and the TOST margin (or None) of one test of a claim."""
    spec = CLAIMS[chapter][claim]
    if chapter == "ch3-interactive-rl":
        measure, space = label.rsplit(", ", 1)
        size = space.split()[0]
        return measure, f"sorting-100/{size}-guidance", f"sorting-100/{size}-no-guidance", None
    if chapter == "ch5-hat-keepaway":
        measure, margin = spec
        if measure is None:
            measure, label = label.split(" ", 1)
            margin = margin if measure == "final" else None
        x, y = label.split(" vs ")
        return measure, CH5_SETS[x], CH5_SETS[y], margin
    half, measure, margin = spec
    x, y = label.split(" vs ")
    return measure, f"{half}/{x}", f"{half}/{y}", margin


def holm(ps):
    order = sorted(range(len(ps)), key=lambda i: ps[i])
    out, running = [0.0] * len(ps), 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (len(ps) - rank) * ps[i]))
        out[i] = running
    return out


def check_claims(path, chapter, spec, by, shift_of, check):
    import json

    claims = json.load(open(path, encoding="utf-8"))["summary"]["claims"]
    for claim in claims:
        if claim["id"] not in CLAIMS.get(chapter, {}):
            continue
        tests = [t for t in claim.get("tests") or [] if "pooled" in t["test"]]
        raw = []
        for t in tests:
            measure, sx, sy, margin = claim_samples(chapter, claim["id"], t["label"])
            if sx not in by or sy not in by:
                # A learner that diverged in every trial: the test is undefined (counts as 1 in Holm).
                raw.append(float("nan"))
                continue
            column = spec["measures"][measure]
            x, y = values(by[sx], column, shift_of(measure)), values(by[sy], column, shift_of(measure))
            if margin is None:
                p = float(stats.ttest_ind(x, y).pvalue)
            else:
                lower = stats.ttest_ind(x + margin, y, alternative="greater").pvalue
                upper = stats.ttest_ind(x - margin, y, alternative="less").pvalue
                p = float(max(lower, upper))
            raw.append(p)
        if not raw:
            continue
        adjusted = holm([1.0 if math.isnan(p) else p for p in raw]) if len(raw) > 1 else raw
        for t, p, q in zip(tests, raw, adjusted):
            where = f"{path} {claim['id']} {t['label']}"
            if math.isnan(p):
                # A test with a missing sample is stored as "undefined" (JSON has no NaN).
                if t.get("p") != "undefined":
                    check.problems.append(f"{where}: p is {t.get('p')}, but a sample is missing (undefined)")
                continue
            if t.get("p") == "undefined":
                check.problems.append(f"{where}: p is stored as undefined, but SciPy gives {p}")
                continue
            if t.get("note", "") and t["note"].startswith("raw p = "):
                check.expect(where, "raw p", t["note"][len("raw p = "):], p, rel=5e-4)
            check.expect(where, "p" if len(raw) == 1 else "Holm p", t["p"], q, rel=1e-7)
            check.rows += 1


PLAN = Path(__file__).resolve().parent.parent / "crates/rlfd-report/data/analysis-plan.toml"


def conjunction(verdicts):
    if not verdicts:
        return "not evaluable"
    if "not reproduced" in verdicts:
        return "not reproduced"
    if "not evaluable" in verdicts:
        return "not evaluable"
    if all(v == "reproduced" for v in verdicts):
        return "reproduced"
    return "inconclusive"


def check_pooled(d, check):
    """Recomputes every pooled component and claim verdict of a chapter's robustness run."""
    if not (d / "robustness_estimates.csv").exists():
        return
    import tomllib

    with open(PLAN, "rb") as f:
        plan = tomllib.load(f)
    conv = plan["conventions"]
    alpha, threshold = conv["alpha"], conv["power_threshold"]
    d33_of = {3: conv["d33"]["n3"], 10: conv["d33"]["n10"], 25: conv["d33"]["n25"], 31: conv["d33"]["r31"]}
    thesis_n = {c["id"]: c["thesis_n"] for c in plan["claim"]}
    rows = read(d / "robustness_estimates.csv")
    # The default reading (axis and level empty) and each other level are
    # pooled apart, each over its own replications.
    run = lambda r: (r.get("axis", ""), r.get("level", ""))
    planned = {}
    for r in rows:
        planned.setdefault(run(r), set()).add(r["replication"])
    groups = {}
    for r in rows:
        groups.setdefault((r["claim"], run(r), r["component"]), []).append(r)
    pooled = {(r["claim"], run(r), r["component"]): r for r in read(d / "robustness_pooled.csv")}
    def decide(claim, rs, planned_n):
        """The plan's verdict of one component from its replications' rows."""
        first = min(rs, key=lambda r: int(r["replication"]))
        kind = first["kind"]
        x = np.array([float(r["value"]) for r in rs if r["value"] != ""])
        sds = [float(r["sd"]) for r in rs if r["sd"] != ""]
        thesis = float(first["thesis"]) if first["thesis"] != "" else None
        n = len(x)
        power = None
        if n < 2 or 2 * n < planned_n:
            verdict, lower, upper = "not evaluable", None, None
        elif kind == "holds":
            k = int((x > 0.5).sum())
            ci = stats.binomtest(k, n).proportion_ci(1 - alpha, method="exact")
            lower, upper = ci.low, ci.high
            verdict = "reproduced" if lower > 0.5 else "not reproduced" if upper < 0.5 else "inconclusive"
        else:
            level = 1 - alpha if kind == "above" else 1 - 2 * alpha
            sd_between = x.std(ddof=1)
            if sd_between > 0:
                ci = stats.ttest_1samp(x, 0.0).confidence_interval(level)
                lower, upper = ci.low, ci.high
            else:
                lower = upper = x.mean()
            if kind == "above":
                if thesis is not None and sd_between > 0:
                    df = n - 1
                    crit = stats.t.ppf(1 - alpha / 2, df)
                    power = float(stats.nct.sf(crit, df, abs(thesis) * math.sqrt(n) / sd_between))
                d33 = d33_of.get(thesis_n.get(claim))
                sesoi = d33 * (sum(sds) / len(sds)) if d33 is not None and sds else 0.0
                powered = power is not None and power >= threshold
                if lower > 0:
                    verdict = "reproduced"
                elif upper < 0 or (powered and upper < sesoi):
                    verdict = "not reproduced"
                else:
                    verdict = "inconclusive"
            else:
                margin = float(first["margin"])
                wide = stats.ttest_1samp(x, 0.0).confidence_interval(1 - alpha) if sd_between > 0 else None
                wlo, whi = (wide.low, wide.high) if wide else (x.mean(), x.mean())
                if lower > -margin and upper < margin:
                    verdict = "reproduced"
                elif wlo > margin or whi < -margin:
                    verdict = "not reproduced"
                else:
                    verdict = "inconclusive"
        return x, n, lower, upper, power, verdict

    claim_verdicts = {}
    for (claim, at, component), rs in groups.items():
        where = f"{d / 'robustness_pooled.csv'} {claim} {' = '.join(at) if at[0] else 'default'} {component}"
        x, n, lower, upper, power, verdict = decide(claim, rs, len(planned[at]))
        claim_verdicts.setdefault((claim, at), []).append(verdict)
        ours = pooled.get((claim, at, component))
        if ours is None:
            check.problems.append(f"{where}: no pooled row")
            continue
        check.expect(where, "replications", ours["replications"], float(n))
        if n:
            check.expect(where, "mean", ours["mean"], float(x.mean()), rel=1e-12)
        if lower is not None:
            half_width = abs(float(upper) - float(lower)) / 2
            check.expect(where, "lower", ours["lower"], float(lower), rel=1e-7, scale=half_width)
            check.expect(where, "upper", ours["upper"], float(upper), rel=1e-7, scale=half_width)
        check.expect(where, "power", ours["power"] or None, power, rel=1e-5)
        if ours["verdict"] != verdict:
            check.problems.append(f"{where}: verdict is {ours['verdict']}, the plan's rule gives {verdict}")
        check.rows += 1
    for (claim, at, _), ours in pooled.items():
        want = conjunction(claim_verdicts.get((claim, at), []))
        if ours["claim_verdict"] != want:
            check.problems.append(f"{d} {claim} {at}: pooled verdict is {ours['claim_verdict']}, the plan's rule gives {want}")
    # Plan v2: each level beside the default pooled over the level's own
    # replications, and whether the level flips the claim.
    if "default_matched" not in next(iter(pooled.values()), {}):
        return
    for (claim, at, _), ours in pooled.items():
        if not at[0]:
            continue
        same = planned[at]
        components = {}
        for r in rows:
            if r["claim"] == claim and run(r) == ("", "") and r["replication"] in same:
                components.setdefault(r["component"], []).append(r)
        want = conjunction([decide(claim, rs, len(same))[5] for rs in components.values()])
        where = f"{d / 'robustness_pooled.csv'} {claim} {' = '.join(at)}"
        if ours["default_matched"] != want:
            check.problems.append(f"{where}: the default over the same replications is {ours['default_matched']}, the plan's rule gives {want}")
        flips = "yes" if ours["claim_verdict"] != want else "no"
        if ours["flips"] != flips:
            check.problems.append(f"{where}: flips is {ours['flips']}, the plan's rule gives {flips}")
        check.rows += 1


def main(trees):
    check = Check()
    for tree in map(Path, trees):
        for chapter, spec in CHAPTERS.items():
            d = tree / chapter
            if not (d / spec["data"]).exists():
                print(f"{d}: no {spec['data']}", file=sys.stderr)
                return 2
            by = samples_of(d, spec)
            shift_of = lambda key: 0.0
            if chapter == "ch5-hat-keepaway":
                prior = values(by["no-prior"], "initial_seconds").mean()
                shift_of = lambda key, prior=prior: prior if key == "jumpstart" else 0.0
            for path in sorted(d.glob("*_tests*.csv")):
                check_tests(path, spec, by, check)
            for path in sorted(d.glob("*_iqm.csv")):
                check_iqm(path, spec, by, check, shift_of)
            if (d / "correlations_tests.csv").exists():
                check_correlations(d / "correlations_tests.csv", d, check)
            check_claims(d / "summary.json", chapter, spec, by, shift_of, check)
            if chapter == "ch3-interactive-rl":
                check_ch3_bootstraps(d / "summary.json", by, check)
                check_ch3_noise_sweep(d, by, check)
            check_pooled(d, check)
    for p in check.problems:
        print(p)
    import scipy

    print(f"{check.rows} values recomputed with SciPy {scipy.__version__}: "
          f"{len(check.problems)} disagreements")
    return 1 if check.problems else 0


def main_pooled(trees):
    """Only the pooled verdicts, in every chapter of `trees` that has a robustness run."""
    check = Check()
    for tree in map(Path, trees):
        for d in sorted(p for p in tree.iterdir() if (p / "robustness_estimates.csv").exists()):
            check_pooled(d, check)
    for p in check.problems:
        print(p)
    print(f"{check.rows} pooled components recomputed with SciPy: {len(check.problems)} disagreements")
    return 1 if check.problems or check.rows == 0 else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["--pooled"]:
        sys.exit(main_pooled(sys.argv[2:]))
    sys.exit(main(sys.argv[1:] or ["golden"]))
