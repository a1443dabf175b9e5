//! RIPPER against the real Weka 3.6.14 command line, through the public
//! production API only: `RipperParams::weka_3_6()`, `Ripper::fit`,
//! `DecisionList::predict_by_distribution` and `stratified_cross_validation`.
//!
//! Reference: Debian bookworm's `weka` 3.6.14-3 on OpenJDK 17.0.15
//! (`apt-get install weka default-jre-headless`), run as
//!
//! ```text
//! java -cp /usr/share/java/weka.jar weka.classifiers.rules.JRip \
//!     -F 3 -N 2.0 -O 2 -S 1 -t numeric4.arff -x 10 -s 1
//! ```
//!
//! (JRip's defaults spelled out; `-t`, `-x` and `-s` are `Evaluation`'s
//! options: train on the file, then 10-fold stratified cross-validation
//! seeded with `new Random(1)`). The class is the last attribute. Below each
//! data set are the parts of Weka's printout we compare: the rule listing,
//! the training-set "Correctly Classified Instances" line and confusion
//! matrix, and the cross-validation "Correctly Classified Instances" line,
//! pasted as printed. Weka 3.6's JRip lacks the final `cleanUp` of redundant
//! numeric tests that ours applies; neither listing here holds one, so they
//! compare as printed.
//!
//! The two data sets are integer formulas of a hash (see [`draw`]), computed
//! here; the ARFF files Weka read are [`arff`] of them, written by
//! `RLFD_WEKA_ARFF_DIR=/some/dir cargo test -p rlfd-lfd --test ripper_weka`
//! (each value is a short decimal whose shortest round-trip text Java parses
//! to the same `f64`).
//!
//! Everything sits in `mod ripper_weka` so that the crate's test filter
//! `ripper` selects these tests too.

mod ripper_weka {
    use rlfd_lfd::ripper::{Attribute, AttributeKind, Dataset, Ripper, RipperParams, stratified_cross_validation};

    fn names(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    /// SplitMix64's output function of `i·16 + k + 0x9E37_79B9_7F4A_7C15`,
    /// reduced modulo `m`: the `k`-th draw of instance `i`.
    fn draw(i: u64, k: u64, m: u64) -> u64 {
        let mut z = (i * 16 + k).wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) % m
    }

    /// 400 instances, four numeric attributes, four noisy classes. With
    /// r_k = draw(i, k, ·): a0 = (r0 mod 20001 − 10000)/1000 ∈ [−10, 10],
    /// a1 = (r1 mod 1001)/100, a2 = (r2 mod 2001 − 1000)/100,
    /// a3 = (r3 mod 10001)/1000; class low if a0 < −4, else mid if a1 > 6.5
    /// and a2 < 2, else high if a3 > 7.5 or a2 > 8, else rest; when
    /// draw(i, 4, 100) < 12 the class becomes (class + 1 + draw(i, 5, 3)) mod 4.
    fn numeric4() -> Dataset {
        let mut rows = Vec::new();
        let mut labels = Vec::new();
        for i in 0..400 {
            let a0 = draw(i, 0, 20_001) as i64 - 10_000;
            let a1 = draw(i, 1, 1001) as i64;
            let a2 = draw(i, 2, 2001) as i64 - 1000;
            let a3 = draw(i, 3, 10_001) as i64;
            let base = if a0 < -4000 {
                0
            } else if a1 > 650 && a2 < 200 {
                1
            } else if a3 > 7500 || a2 > 800 {
                2
            } else {
                3
            };
            let label = if draw(i, 4, 100) < 12 { (base + 1 + draw(i, 5, 3)) % 4 } else { base };
            rows.push(vec![a0 as f64 / 1000.0, a1 as f64 / 100.0, a2 as f64 / 100.0, a3 as f64 / 1000.0]);
            labels.push(label as usize);
        }
        let attributes = ["a0", "a1", "a2", "a3"].map(Attribute::numeric).to_vec();
        Dataset::new(attributes, rows, "class", names(&["low", "mid", "high", "rest"]), labels).unwrap()
    }

    /// 300 instances, two nominal attributes and a numeric one, missing
    /// values in two of them, three noisy classes, names with spaces (which
    /// Weka quotes in the text its seed hashes). colour = draw(i, 0, 3) over
    /// {red, green, light blue}, missing when draw(i, 1, 13) = 0; size =
    /// draw(i, 2, 4) over {S, M, L, XL}; weight = (draw(i, 3, 1001))/10,
    /// missing when draw(i, 4, 11) = 0. Class pass if colour = light blue and
    /// (weight missing or > 40), else hold on if size ∈ {L, XL} and (weight
    /// missing or < 30), else keep; when draw(i, 5, 100) < 8 it becomes
    /// (class + 1 + draw(i, 6, 2)) mod 3.
    fn nominal_missing() -> Dataset {
        let mut rows = Vec::new();
        let mut labels = Vec::new();
        for i in 0..300 {
            let colour = draw(i, 0, 3);
            let colour_missing = draw(i, 1, 13) == 0;
            let size = draw(i, 2, 4);
            let weight = draw(i, 3, 1001);
            let weight_missing = draw(i, 4, 11) == 0;
            let base = if !colour_missing && colour == 2 && (weight_missing || weight > 400) {
                1
            } else if size >= 2 && (weight_missing || weight < 300) {
                2
            } else {
                0
            };
            let label = if draw(i, 5, 100) < 8 { (base + 1 + draw(i, 6, 2)) % 3 } else { base };
            rows.push(vec![
                if colour_missing { f64::NAN } else { colour as f64 },
                size as f64,
                if weight_missing { f64::NAN } else { weight as f64 / 10.0 },
            ]);
            labels.push(label as usize);
        }
        let attributes = vec![
            Attribute::nominal("colour", names(&["red", "green", "light blue"])),
            Attribute::nominal("size", names(&["S", "M", "L", "XL"])),
            Attribute::numeric("weight"),
        ];
        Dataset::new(attributes, rows, "class", names(&["keep", "pass", "hold on"]), labels).unwrap()
    }

    /// An ARFF value: quoted when it holds a space (no other special
    /// character occurs here).
    fn arff_name(name: &str) -> String {
        if name.contains(' ') { format!("'{name}'") } else { name.to_string() }
    }

    /// The ARFF file Weka read: the attributes, then the class; `?` for a
    /// missing value; numbers in their shortest round-trip form.
    fn arff(relation: &str, data: &Dataset) -> String {
        let nominal = |values: &[String]| values.iter().map(|v| arff_name(v)).collect::<Vec<_>>().join(",");
        let mut out = format!("@relation {relation}\n\n");
        for attribute in data.attributes() {
            let kind = match &attribute.kind {
                AttributeKind::Numeric => "numeric".to_string(),
                AttributeKind::Nominal { values } => format!("{{{}}}", nominal(values)),
            };
            out.push_str(&format!("@attribute {} {kind}\n", attribute.name));
        }
        out.push_str(&format!("@attribute {} {{{}}}\n\n@data\n", data.class_attribute(), nominal(data.class_names())));
        for i in 0..data.len() {
            for (attribute, &value) in data.attributes().iter().zip(data.row(i)) {
                let text = match &attribute.kind {
                    _ if value.is_nan() => "?".to_string(),
                    AttributeKind::Numeric => format!("{value}"),
                    AttributeKind::Nominal { values } => arff_name(&values[value as usize]),
                };
                out.push_str(&text);
                out.push(',');
            }
            out.push_str(&arff_name(&data.class_names()[data.labels()[i]]));
            out.push('\n');
        }
        out
    }

    /// What Weka printed for one data set.
    struct WekaRun {
        /// The `JRIP rules:` listing, through `Number of Rules`.
        listing: &'static str,
        /// "=== Error on training data ===": correctly classified, count and percent.
        training: (f64, f64),
        /// The training confusion matrix, rows = actual class, columns =
        /// predicted, classes in the ARFF's order.
        training_confusion: &'static [&'static [usize]],
        /// "=== Stratified cross-validation ===": correctly classified, count
        /// and percent.
        cross_validation: (f64, f64),
    }

    /// Fits and cross-validates `data` as Weka's command line does and
    /// compares with what it printed.
    fn check(data: &Dataset, weka: &WekaRun) {
        let params = RipperParams::weka_3_6();
        let list = Ripper::fit(&params, data).unwrap();
        assert_eq!(list.to_weka_string(), weka.listing, "rules\n{list}");

        // Weka's Evaluation classifies with classifyInstance: the covering
        // rule's majority training class
        let classes = data.class_names().len();
        let mut confusion = vec![vec![0; classes]; classes];
        for i in 0..data.len() {
            confusion[data.labels()[i]][list.predict_by_distribution(data.row(i))] += 1;
        }
        let correct = (0..classes).map(|c| confusion[c][c]).sum::<usize>() as f64;
        assert_eq!(confusion, weka.training_confusion, "training confusion matrix");
        assert_percent("training", correct, data.len() as f64, weka.training);

        let cv = stratified_cross_validation(&params, data, 10, 1).unwrap();
        assert_eq!(cv.total, data.len() as f64);
        assert_percent("10-fold cross-validation", cv.correct, cv.total, weka.cross_validation);
        assert_eq!(cv.accuracy, cv.correct / cv.total);
    }

    /// The count must be Weka's; the percentage equal to Weka's to the 4
    /// decimals it prints.
    fn assert_percent(what: &str, correct: f64, total: f64, (weka_correct, weka_percent): (f64, f64)) {
        assert_eq!(correct, weka_correct, "{what}: correctly classified");
        let percent = 100.0 * correct / total;
        assert!((percent - weka_percent).abs() < 5e-5, "{what}: {percent} % where Weka printed {weka_percent} %");
    }

    /// Weka 3.6.14 on numeric4.arff:
    ///
    /// ```text
    /// JRIP rules:
    /// ===========
    ///
    /// (a1 >= 6.54) and (a2 <= 1.97) and (a0 >= -3.839) => class=mid (53.0/1.0)
    /// (a2 >= 5.69) and (a2 <= 5.79) and (a3 <= 2.238) => class=mid (5.0/1.0)
    /// (a3 >= 7.699) and (a0 >= -3.517) => class=high (57.0/3.0)
    /// (a2 >= 7.92) and (a0 >= -3.593) => class=high (17.0/0.0)
    /// (a0 <= -3.974) => class=low (125.0/14.0)
    ///  => class=rest (143.0/14.0)
    ///
    /// Number of Rules : 6
    /// …
    /// === Error on training data ===
    ///
    /// Correctly Classified Instances         367               91.75   %
    /// Incorrectly Classified Instances        33                8.25   %
    /// …
    /// === Confusion Matrix ===
    ///
    ///    a   b   c   d   <-- classified as
    ///  111   2   3   7 |   a = low
    ///    2  56   0   2 |   b = mid
    ///    5   0  71   5 |   c = high
    ///    7   0   0 129 |   d = rest
    ///
    /// === Stratified cross-validation ===
    ///
    /// Correctly Classified Instances         355               88.75   %
    /// Incorrectly Classified Instances        45               11.25   %
    /// ```
    #[test]
    fn numeric4_equals_weka_3_6_command_line() {
        let data = numeric4();
        assert_eq!(data.class_weights(), vec![123.0, 60.0, 81.0, 136.0]);
        check(
            &data,
            &WekaRun {
                listing: "JRIP rules:\n===========\n\n\
                    (a1 >= 6.54) and (a2 <= 1.97) and (a0 >= -3.839) => class=mid (53.0/1.0)\n\
                    (a2 >= 5.69) and (a2 <= 5.79) and (a3 <= 2.238) => class=mid (5.0/1.0)\n\
                    (a3 >= 7.699) and (a0 >= -3.517) => class=high (57.0/3.0)\n\
                    (a2 >= 7.92) and (a0 >= -3.593) => class=high (17.0/0.0)\n\
                    (a0 <= -3.974) => class=low (125.0/14.0)\n \
                    => class=rest (143.0/14.0)\n\nNumber of Rules : 6\n",
                training: (367.0, 91.75),
                training_confusion: &[&[111, 2, 3, 7], &[2, 56, 0, 2], &[5, 0, 71, 5], &[7, 0, 0, 129]],
                cross_validation: (355.0, 88.75),
            },
        );
    }

    /// Weka 3.6.14 on nominal_missing.arff:
    ///
    /// ```text
    /// JRIP rules:
    /// ===========
    ///
    /// (weight <= 29.4) and (size = XL) => class=hold on (28.0/1.0)
    /// (size = L) and (weight <= 29.8) => class=hold on (28.0/3.0)
    /// (colour = light blue) => class=pass (84.0/22.0)
    ///  => class=keep (160.0/17.0)
    ///
    /// Number of Rules : 4
    /// …
    /// === Error on training data ===
    ///
    /// Correctly Classified Instances         257               85.6667 %
    /// Incorrectly Classified Instances        43               14.3333 %
    /// …
    /// === Confusion Matrix ===
    ///
    ///    a   b   c   <-- classified as
    ///  143  18   2 |   a = keep
    ///    7  62   2 |   b = pass
    ///   10   4  52 |   c = hold on
    ///
    /// === Stratified cross-validation ===
    ///
    /// Correctly Classified Instances         256               85.3333 %
    /// Incorrectly Classified Instances        44               14.6667 %
    /// ```
    #[test]
    fn nominal_missing_equals_weka_3_6_command_line() {
        let data = nominal_missing();
        assert_eq!(data.class_weights(), vec![163.0, 71.0, 66.0]);
        check(
            &data,
            &WekaRun {
                listing: "JRIP rules:\n===========\n\n\
                    (weight <= 29.4) and (size = XL) => class=hold on (28.0/1.0)\n\
                    (size = L) and (weight <= 29.8) => class=hold on (28.0/3.0)\n\
                    (colour = light blue) => class=pass (84.0/22.0)\n \
                    => class=keep (160.0/17.0)\n\nNumber of Rules : 4\n",
                training: (257.0, 85.6667),
                training_confusion: &[&[143, 18, 2], &[7, 62, 2], &[10, 4, 52]],
                cross_validation: (256.0, 85.3333),
            },
        );
    }

    /// Writes the ARFF files when `RLFD_WEKA_ARFF_DIR` names a directory (to
    /// rerun Weka); otherwise does nothing.
    #[test]
    fn write_arff_files_when_asked() {
        let Some(dir) = std::env::var_os("RLFD_WEKA_ARFF_DIR") else { return };
        let dir = std::path::PathBuf::from(dir);
        std::fs::write(dir.join("numeric4.arff"), arff("numeric4", &numeric4())).unwrap();
        std::fs::write(dir.join("nominal_missing.arff"), arff("nominal_missing", &nominal_missing())).unwrap();
    }
}
