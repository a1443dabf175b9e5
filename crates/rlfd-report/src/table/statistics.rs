//! Two tables every chapter prints beside its headline tables, built from
//! statistics the chapter computed (this crate computes none):
//!
//! - [`full_tests`]: each two-sample t-test whose p a table or claim shows,
//!   in full: the sizes, the mean difference with its 95 % interval,
//!   t, df, p (and the Holm-adjusted p where a claim's family decides on
//!   it) and Hedges' g; one row per test (Student's pooled test, the
//!   thesis's, and Welch's where the chapter prints it too);
//! - [`iqm_table`]: per condition and measure, the interquartile mean with
//!   its stratified-bootstrap 95 % interval (rliable's method) beside the
//!   thesis's mean, and in a note the largest Monte Carlo error of a bound.
//!
//! Both are ordinary [`Table`]s: the CSV keeps every value at full
//! precision, so a reader recomputes each row from the chapter's trial data.

use rlfd_stats::{StratifiedCi, TwoSample, Variance};

use super::{Cell, ColumnGroup, Num, NumFormat, Row, Table};

/// One compared pair on one measure.
#[derive(Debug, Clone, PartialEq)]
pub struct TestRow {
    /// The pair as the table names it, `Value Bonus vs No Prior`; the first
    /// named is `x` (the difference is `x̄ − ȳ`).
    pub pair: String,
    /// The measure, `jumpstart`.
    pub measure: String,
    /// The two samples' comparison; `None` where the test is undefined
    /// (a sample too small, or both constant), shown as dashes.
    pub two: Option<TwoSample>,
    /// The Holm-adjusted p of the test that decides a claim, and which test that is.
    pub holm: Option<(Variance, f64)>,
    /// Where the two samples are in the report's data files (e.g. the
    /// condition column's values), so a reader can recompute the row;
    /// shown as the table's last two columns.
    pub samples: Option<[String; 2]>,
}

/// The full-statistics table `id` of `rows`, differences written with
/// `decimals` places; `welch` adds each pair's Welch test after Student's.
pub fn full_tests(id: &str, title: &str, caption: &str, rows: &[TestRow], decimals: usize, welch: bool) -> Table {
    let mut table = Table::new(id, title, "Pair");
    table.caption = caption.to_string();
    let holm = rows.iter().any(|r| r.holm.is_some());
    let mut columns = vec![
        ColumnGroup::new("Measure"),
        ColumnGroup::new("Test"),
        ColumnGroup::new("n₁").with_key("n_x"),
        ColumnGroup::new("n₂").with_key("n_y"),
        ColumnGroup::new("Difference").with_key("difference"),
        ColumnGroup::new("95 % CI low").with_key("ci_lower"),
        ColumnGroup::new("95 % CI high").with_key("ci_upper"),
        ColumnGroup::new("t"),
        ColumnGroup::new("df"),
        ColumnGroup::new("p"),
    ];
    if holm {
        columns.push(ColumnGroup::new("Holm p").with_key("p_holm"));
    }
    columns.push(ColumnGroup::new("Hedges' g").with_key("hedges_g"));
    let samples = rows.iter().any(|r| r.samples.is_some());
    if samples {
        columns.push(ColumnGroup::new("Sample 1").with_key("sample_x"));
        columns.push(ColumnGroup::new("Sample 2").with_key("sample_y"));
    }
    table.columns = columns;
    let models: &[Variance] = if welch { &[Variance::Pooled, Variance::Welch] } else { &[Variance::Pooled] };
    for r in rows {
        for &variance in models {
            let name = match variance {
                Variance::Pooled => "Student",
                Variance::Welch => "Welch",
            };
            let mut cells = vec![Cell::text(&r.measure), Cell::text(name)];
            let num = |v: f64, d: usize| Cell::Num(Num::new(v, NumFormat::fixed(d)));
            let grouped = |v: f64| Cell::Num(Num::new(v, NumFormat::grouped(decimals)));
            match &r.two {
                Some(two) => {
                    let c = two.comparison(variance);
                    let df_decimals = if variance == Variance::Pooled { 0 } else { 2 };
                    cells.extend([
                        Cell::Num(Num::new(two.n_x as f64, NumFormat::Integer)),
                        Cell::Num(Num::new(two.n_y as f64, NumFormat::Integer)),
                        grouped(c.difference),
                        grouped(c.lower),
                        grouped(c.upper),
                        num(c.t, 2),
                        num(c.df, df_decimals),
                        Cell::Num(Num::p_value(c.p)),
                    ]);
                }
                None => cells.extend((0..8).map(|_| Cell::Empty)),
            }
            if holm {
                cells.push(match r.holm {
                    Some((v, p)) if v == variance => Cell::Num(Num::p_value(p)),
                    _ => Cell::Empty,
                });
            }
            cells.push(match &r.two {
                Some(two) if variance == Variance::Pooled => num(two.hedges_g, 2),
                _ => Cell::Empty,
            });
            if samples {
                match &r.samples {
                    Some([x, y]) => cells.extend([Cell::text(x), Cell::text(y)]),
                    None => cells.extend([Cell::Empty, Cell::Empty]),
                }
            }
            table.rows.push(Row::new(&r.pair, cells));
        }
    }
    table.notes.push(format!(
        "Difference: the first-named mean minus the second's, with the t interval of the test's own variance model; \
         Hedges' g = Cohen's d (pooled standard deviation) × (1 − 3/(4(n₁ + n₂) − 9)), on Student's row. Two-sided p{}. \
         An empty row: the test is undefined for these samples.",
        if holm { "; Holm p: adjusted over the claim's family, on the test the claim is decided by" } else { "" }
    ));
    table
}

/// One condition's interquartile means, one per measure (`None` where it
/// has no runs), and the thesis's means (`None` where it prints none).
#[derive(Debug, Clone, PartialEq)]
pub struct IqmRow {
    pub label: String,
    pub iqm: Vec<Option<StratifiedCi>>,
    pub thesis_mean: Vec<Option<f64>>,
    /// Where the row's runs are in the report's data files (shown as the
    /// table's last column), so a reader can recompute it.
    pub sample: Option<String>,
}

/// The IQM table `id`: for each of `measures` (header, CSV key) the IQM,
/// its interval and the thesis's mean (a column only for a measure the
/// thesis gives some mean of), written with `decimals` places; a
/// note gives the largest Monte Carlo standard error of any bound.
pub fn iqm_table(
    id: &str,
    title: &str,
    caption: &str,
    stub_header: &str,
    measures: &[(&str, &str)],
    rows: &[IqmRow],
    decimals: usize,
) -> Table {
    let mut table = Table::new(id, title, stub_header);
    table.caption = caption.to_string();
    // A measure gets a thesis column only where the thesis prints some mean.
    let thesis: Vec<bool> =
        (0..measures.len()).map(|m| rows.iter().any(|r| r.thesis_mean.get(m).copied().flatten().is_some())).collect();
    for ((header, key), &with_thesis) in measures.iter().zip(&thesis) {
        table.columns.extend([
            ColumnGroup::new(format!("{header} IQM")).with_key(format!("{key}_iqm")),
            ColumnGroup::new("95 % CI low").with_key(format!("{key}_ci_lower")),
            ColumnGroup::new("95 % CI high").with_key(format!("{key}_ci_upper")),
        ]);
        if with_thesis {
            table.columns.push(ColumnGroup::new("Thesis mean").with_key(format!("{key}_thesis_mean")));
        }
    }
    let samples = rows.iter().any(|r| r.sample.is_some());
    if samples {
        table.columns.push(ColumnGroup::new("Sample"));
    }
    let mut worst = 0.0_f64;
    let mut resamples = None;
    for r in rows {
        let mut cells = Vec::new();
        for (m, _) in measures.iter().enumerate() {
            let fixed = |v: f64| Cell::Num(Num::new(v, NumFormat::grouped(decimals)));
            match r.iqm.get(m).copied().flatten() {
                Some(s) => {
                    worst = worst.max(s.lower_mcse).max(s.upper_mcse);
                    resamples = Some((s.ci.resamples, s.ci.seed));
                    cells.extend([fixed(s.ci.estimate), fixed(s.ci.lower), fixed(s.ci.upper)]);
                }
                None => cells.extend([Cell::Empty, Cell::Empty, Cell::Empty]),
            }
            if thesis[m] {
                cells.push(r.thesis_mean.get(m).copied().flatten().map_or(Cell::Empty, fixed));
            }
        }
        if samples {
            cells.push(r.sample.as_ref().map_or(Cell::Empty, Cell::text));
        }
        table.rows.push(Row::new(&r.label, cells));
    }
    if let Some((b, seed)) = resamples {
        table.notes.push(format!(
            "IQM: the mean of the middle half of a condition's runs (rliable's aggregate_iqm, a 25 % trimmed mean); \
             interval: stratified percentile bootstrap at 95 % (rliable's method, one stratum per condition), \
             {} resamples drawn by ChaCha8 from seed {seed}; the largest Monte Carlo standard error of a bound here is {}.",
            rlfd_stats::format::thousands(b as f64, 0),
            format_mcse(worst)
        ));
    }
    table
}

/// `worst` with two significant digits.
fn format_mcse(worst: f64) -> String {
    if worst == 0.0 {
        return "0".into();
    }
    let digits = (1 - libm::floor(libm::log10(worst)) as i32).max(0) as usize;
    format!("{worst:.digits$}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::to_csv;

    #[test]
    fn a_test_row_shows_student_and_welch_in_full() {
        // The samples of rlfd-stats' comparison test. Reference, scipy 1.17.1:
        //   r = ttest_ind(a, b): t -7.098017333436189, p 1.288616438074683e-06, df 18,
        //     r.confidence_interval(0.95) = (-14.644654984553389, -7.955345015446605)
        //   w = ttest_ind(a, b, equal_var=False): t -7.09801733343619, p 1.9648672407042505e-06,
        //     df 16.720453152064888, CI (-14.663096254667398, -7.936903745332597)
        //   Hedges' g, d·(1 − 3/(4·20 − 9)) with the pooled sd: -3.040203239116585
        let shaped = [41.0, 38.0, 45.0, 36.0, 40.0, 43.0, 39.0, 37.0, 44.0, 42.0];
        let plain = [52.0, 47.0, 55.0, 49.0, 58.0, 46.0, 51.0, 53.0, 50.0, 57.0];
        let two = TwoSample::of(&shaped, &plain, 0.95).unwrap();
        let rows = [
            TestRow {
                pair: "A vs B".into(),
                measure: "steps".into(),
                two: Some(two),
                holm: Some((Variance::Pooled, 2.6e-6)),
                samples: Some(["a".into(), "b".into()]),
            },
            TestRow { pair: "A vs C".into(), measure: "steps".into(), two: None, holm: None, samples: None },
        ];
        let t = full_tests("t", "Tests", "", &rows, 2, true);
        t.check().unwrap();
        assert_eq!(t.rows.len(), 4);
        let csv = to_csv(&t);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "pair,measure,test,n_x,n_y,difference,ci_lower,ci_upper,t,df,p,p_holm,hedges_g,sample_x,sample_y"
        );
        let fields = |line: &str| line.split(',').map(str::to_string).collect::<Vec<_>>();
        let close = |field: &str, reference: f64| {
            let v: f64 = field.parse().unwrap();
            assert!((v - reference).abs() <= 1e-12 * reference.abs().max(1.0), "{v} vs {reference}");
        };
        let student = fields(lines[1]);
        assert_eq!(student[..5], ["A vs B", "steps", "Student", "10", "10"]);
        let scipy = [-11.3, -14.644654984553389, -7.955345015446605, -7.098017333436189, 18.0, 1.288616438074683e-06];
        for (field, reference) in student[5..11].iter().zip(scipy) {
            close(field, reference);
        }
        assert_eq!(student[11], "2.6e-6");
        close(&student[12], -3.040203239116585);
        assert_eq!(student[13..], ["a", "b"]);
        let welch = fields(lines[2]);
        assert_eq!(welch[..5], ["A vs B", "steps", "Welch", "10", "10"]);
        let scipy = [
            -11.3,
            -14.663096254667398,
            -7.936903745332597,
            -7.09801733343619,
            16.720453152064888,
            1.9648672407042505e-06,
        ];
        for (field, reference) in welch[5..11].iter().zip(scipy) {
            close(field, reference);
        }
        assert_eq!(welch[11..], ["", "", "a", "b"], "Holm and g on Student's row only");
        assert_eq!(lines[3], "A vs C,steps,Student,,,,,,,,,,,,");
    }

    #[test]
    fn an_iqm_row_carries_its_interval_errors_and_the_thesis_mean() {
        let s = rlfd_stats::headline_iqm(&[8.21, 7.95, 8.60, 8.02, 8.33, 7.71, 8.48, 8.19, 8.90, 7.88]).unwrap();
        let rows = [IqmRow {
            label: "No Prior".into(),
            iqm: vec![Some(s), None],
            thesis_mean: vec![Some(14.3), None],
            sample: Some("no-prior".into()),
        }];
        let t = iqm_table("t", "IQM", "", "Method", &[("Final", "final"), ("Total", "total")], &rows, 2);
        t.check().unwrap();
        let csv = to_csv(&t);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "method,final_iqm,final_ci_lower,final_ci_upper,final_thesis_mean,total_iqm,total_ci_lower,total_ci_upper,sample"
        );
        assert!(lines[1].starts_with("No Prior,8.196666666666667,"), "{}", lines[1]);
        assert!(lines[1].ends_with(",14.3,,,,no-prior"), "{}", lines[1]);
        assert!(t.notes[0].contains("10,000 resamples") && t.notes[0].contains("seed 20160501"), "{}", t.notes[0]);
        assert_eq!(format_mcse(0.0012345), "0.0012");
        assert_eq!(format_mcse(0.5), "0.50");
        assert_eq!(format_mcse(12.0), "12");
    }
}
