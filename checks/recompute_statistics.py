#!/usr/bin/env python3
"""Recomputes, with SciPy, the statistics a report prints from the report's own CSV files.

An independent check of rlfd's Rust statistics: it reads nothing but a
report tree (golden/ or reports/), finds each table that names its samples
(the tests in full, the interquartile means, the correlations in full),
recomputes every value from the chapter's data file and compares.

  python3 checks/recompute_statistics.py golden reports

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
  (`pearsonr(...).confidence_interval(0.95)`), to 1e-9.

Exit status: 0 when every row agrees, 1 otherwise (each disagreement on
one line), 2 when a tree lacks the files it should have.
"""

import csv
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
        "sample": lambda row: f"{row['experiment']}/{row['condition']}",
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


def close(ours, theirs, rel=REL):
    if ours == "" or ours is None:
        return theirs is None or (isinstance(theirs, float) and math.isnan(theirs))
    ours = float(ours)
    return abs(ours - theirs) <= rel * max(abs(theirs), 1.0)


class Check:
    def __init__(self):
        self.rows = 0
        self.problems = []

    def expect(self, where, name, ours, theirs, rel=REL):
        if not close(ours, theirs, rel):
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
            check.expect(where, name, row[name], theirs)
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
    for p in check.problems:
        print(p)
    import scipy

    print(f"{check.rows} values recomputed with SciPy {scipy.__version__}: "
          f"{len(check.problems)} disagreements")
    return 1 if check.problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["golden"]))
