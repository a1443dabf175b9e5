//! Cross-check against Weka itself (test only): with
//! [`RipperRandom::Weka`](super::RipperRandom::Weka), the learner must print
//! exactly the rule lists Weka's JRip prints, derive the same effective
//! seeds, and cross-validate to the same per-fold counts.
//!
//! The reference is Weka 3.6.14 (Debian package `weka` 3.6.14-3) run by a
//! small Java program on OpenJDK 17. Its JRip is the reference commit's
//! (0b4f0571) algorithm except for the final `cleanUp`, which it lacks. The
//! listings of the first three data sets hold no redundant numeric test, so
//! they compare as printed; the `family` listings are cleaned first. The data sets are
//! integer formulas that the Java program computes the same way (see each
//! generator). "effective seed" is JRip's `m_Random` seed, which Weka derives
//! from `-S` and the text of a random instance
//! (`Instances.getRandomNumberGenerator`): the Java program printed it as
//! `new Random(S).nextInt(n)`-th instance's `toStringNoWeight().hashCode() + S`.
//! Each check asserts that [`JavaRandom::for_instances`] derives it from the
//! data, then fits through the public [`Ripper::fit`].
//!
//! The cross-validation replays `Evaluation.crossValidateModel(jrip, data,
//! 10, new Random(1))` (the Java program checked its manual replay against
//! `Evaluation.correct()`), each fold's JRip seeded as Weka seeds it: the
//! fold seeds the Java program printed must be the ones derived from each
//! training part, and the public [`stratified_cross_validation`] must give
//! the same result.
//!
//! The `family` sets (two numeric attributes, one nominal, missing values,
//! three noisy classes) were compared in bulk: of 6,000 of them (30 to 505
//! instances), 5,999 listings were identical; the one difference (s = 1065)
//! is an exact tie of two information gains, 4·log₂ 1.8 = 2·log₂ 3.24, which
//! Java's `Math.log` (a HotSpot intrinsic) rounds to equal values and the
//! portable fdlibm `log` used here (Java's `StrictMath.log`) does not. The
//! seven kept below are those that fail when the optimisation stage's
//! tie-breaking (old, then revision, then replacement) or `cleanUp` is
//! changed. Weka 3.6 does not clean up, so its raw listings are cleaned here
//! with [`clean_up`] before comparing; the bulk comparison covered 1,015
//! listings that cleaning changes.

use super::cv::cross_validate_with;
use super::rule::clean_up;
use super::{
    Attribute, AttributeKind, Condition, Dataset, JavaRandom, Operator, Ripper, RipperParams,
    stratified_cross_validation,
};

fn class_names(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| s.to_string()).collect()
}

/// Java: x = ((i*7919+13) % 1000)/100.0, y = ((i*104729+7) % 1000)/100.0,
/// z = (i*31+3) % 13; class x < 3 → c0, else y < 5 → c1, else c2; when
/// h = (i*2654435761) % 97 < 10 the class becomes (class + 1 + h % 2) % 3.
fn noisy3() -> Dataset {
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for i in 0..300_u64 {
        let x = ((i * 7919 + 13) % 1000) as f64 / 100.0;
        let y = ((i * 104_729 + 7) % 1000) as f64 / 100.0;
        let z = ((i * 31 + 3) % 13) as f64;
        let base: u64 = if x < 3.0 {
            0
        } else if y < 5.0 {
            1
        } else {
            2
        };
        let h = (i * 2_654_435_761) % 97;
        let label = if h < 10 { (base + 1 + h % 2) % 3 } else { base };
        rows.push(vec![x, y, z]);
        labels.push(label as usize);
    }
    let attributes = ["x", "y", "z"].map(Attribute::numeric).to_vec();
    Dataset::new(attributes, rows, "class", class_names(&["c0", "c1", "c2"]), labels).unwrap()
}

/// Java: x = ((i*613+5) % 500)/50.0, missing when i % 17 == 0; colour =
/// i % 3 over {r, g, b}; pos when (x > 6 and colour = g) or x < 1 (when x
/// is missing: when colour = b); flipped when (i*40503) % 89 < 7.
fn nominal2() -> Dataset {
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for i in 0..240_u64 {
        let missing = i.is_multiple_of(17);
        let x = if missing { f64::NAN } else { ((i * 613 + 5) % 500) as f64 / 50.0 };
        let colour = (i % 3) as usize;
        let base = if missing { colour == 2 } else { (x > 6.0 && colour == 1) || x < 1.0 };
        let flipped = (i * 40503) % 89 < 7;
        rows.push(vec![x, colour as f64]);
        labels.push(usize::from(base != flipped));
    }
    let attributes = vec![Attribute::numeric("x"), Attribute::nominal("colour", class_names(&["r", "g", "b"]))];
    Dataset::new(attributes, rows, "class", class_names(&["neg", "pos"]), labels).unwrap()
}

/// Java: state_k = ((i*P[k] + k) % 1000)/10.0 for 13 multipliers P; Action
/// 1 when state_11 > 70 and state_3 < 60, else 2 when state_3 < 48 and
/// state_0 > 73, else 0; when h = (i*2654435761) % 101 < 12 the action
/// becomes (action + 1 + h % 2) % 3. A stand-in for chapter 5's 13 Keepaway
/// state variables and 3 actions.
fn keepaway_like() -> Dataset {
    const P: [u64; 13] = [7919, 104_729, 1_299_709, 15_485_863, 3, 7, 11, 13, 17, 19, 23, 29, 31];
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for i in 0..600_u64 {
        let v: Vec<f64> = (0..13).map(|k| ((i * P[k] + k as u64) % 1000) as f64 / 10.0).collect();
        let base: u64 = if v[11] > 70.0 && v[3] < 60.0 {
            1
        } else if v[3] < 48.0 && v[0] > 73.0 {
            2
        } else {
            0
        };
        let h = (i * 2_654_435_761) % 101;
        labels.push((if h < 12 { (base + 1 + h % 2) % 3 } else { base }) as usize);
        rows.push(v);
    }
    let attributes = (0..13).map(|k| Attribute::numeric(format!("state_{k}"))).collect();
    Dataset::new(attributes, rows, "Action", class_names(&["0", "1", "2"]), labels).unwrap()
}

/// Checks that JRip's `-S` seed gives Weka's effective seed on `data`, fits
/// with it through the public API, and compares the listing.
fn check_fit(data: &Dataset, jrip_seed: u64, effective_seed: i64, weka: &str) {
    assert_eq!(JavaRandom::for_instances(data, jrip_seed as i64), JavaRandom::new(effective_seed));
    let params = RipperParams::weka_3_6().with_seed(jrip_seed);
    let list = Ripper::fit(&params, data).unwrap();
    assert_eq!(list.to_weka_string(), weka);
}

/// Replays Weka's 10-fold cross-validation, checks each fold's effective
/// seed, and compares per-fold counts; the public entry point must agree.
fn check_cv(data: &Dataset, fold_seeds: [i64; 10], fold_correct: [f64; 10]) {
    let params = RipperParams::weka_3_6();
    let cv = cross_validate_with(&params, data, 10, JavaRandom::new(1), |fold, train| {
        let rng = JavaRandom::for_instances(train, 1);
        assert_eq!(rng, JavaRandom::new(fold_seeds[fold]), "fold {fold}");
        rng
    })
    .unwrap();
    let ours: Vec<f64> = cv.per_fold.iter().map(|f| f.correct).collect();
    assert_eq!(ours, fold_correct);
    assert_eq!(cv.correct, fold_correct.iter().sum::<f64>());
    assert_eq!(stratified_cross_validation(&params, data, 10, 1).unwrap(), cv);
}

#[test]
fn noisy3_rules_equal_wekas() {
    let data = noisy3();
    // Weka: class counts [85, 111, 104]
    assert_eq!(data.class_weights(), vec![85.0, 111.0, 104.0]);
    check_fit(
        &data,
        1,
        -2_017_380_557,
        "JRIP rules:\n===========\n\n\
         (x <= 2.96) => class=c0 (90.0/10.0)\n\
         (y >= 4.82) => class=c2 (104.0/11.0)\n \
         => class=c1 (106.0/9.0)\n\nNumber of Rules : 3\n",
    );
    check_fit(
        &data,
        7,
        731_480_228,
        "JRIP rules:\n===========\n\n\
         (x <= 2.96) => class=c0 (90.0/10.0)\n\
         (y >= 5.01) => class=c2 (100.0/9.0)\n \
         => class=c1 (110.0/11.0)\n\nNumber of Rules : 3\n",
    );
}

#[test]
fn noisy3_cross_validation_equals_wekas() {
    // Weka: cv correct 266.0
    check_cv(
        &noisy3(),
        [
            -899_606_337,
            229_691_656,
            -988_807_988,
            242_500_449,
            -174_978_935,
            1_222_768_343,
            -525_529_158,
            -1_663_060_149,
            1_507_088_028,
            604_772_080,
        ],
        [24.0, 28.0, 25.0, 27.0, 27.0, 27.0, 29.0, 26.0, 26.0, 27.0],
    );
}

#[test]
fn nominal2_rules_equal_wekas() {
    let data = nominal2();
    assert_eq!(data.class_weights(), vec![166.0, 74.0]);
    check_fit(
        &data,
        1,
        -1_788_915_928,
        "JRIP rules:\n===========\n\n\
         (x <= 0.9) => class=pos (22.0/0.0)\n\
         (colour = g) and (x >= 6.1) => class=pos (29.0/1.0)\n \
         => class=neg (189.0/24.0)\n\nNumber of Rules : 3\n",
    );
    check_fit(
        &data,
        7,
        -1_727_839_295,
        "JRIP rules:\n===========\n\n\
         (x <= 0.96) => class=pos (23.0/0.0)\n\
         (colour = g) and (x >= 6.1) => class=pos (29.0/1.0)\n \
         => class=neg (188.0/23.0)\n\nNumber of Rules : 3\n",
    );
}

#[test]
fn nominal2_cross_validation_equals_wekas() {
    // Weka: cv correct 213.0
    check_cv(
        &nominal2(),
        [
            -327_183_948,
            1_919_121_005,
            -287_498_455,
            1_429_766_750,
            -917_238_365,
            1_062_798_772,
            -2_029_794_888,
            -1_475_836_163,
            -891_815_306,
            1_434_384_355,
        ],
        [23.0, 21.0, 23.0, 20.0, 21.0, 22.0, 20.0, 20.0, 21.0, 22.0],
    );
}

#[test]
fn keepaway_like_rules_equal_wekas() {
    let data = keepaway_like();
    assert_eq!(data.class_weights(), vec![398.0, 109.0, 93.0]);
    check_fit(
        &data,
        1,
        -2_082_275_017,
        "JRIP rules:\n===========\n\n\
         (state_0 >= 73.1) and (state_3 <= 47.7) => Action=2 (83.0/27.0)\n\
         (state_11 >= 70.8) and (state_3 <= 58.6) => Action=1 (75.0/10.0)\n\
         (state_11 >= 58.1) and (state_11 <= 58.4) => Action=1 (4.0/0.0)\n\
         (state_11 >= 50.9) and (state_11 <= 51.1) => Action=1 (3.0/0.0)\n\
         (state_11 >= 65.1) and (state_11 <= 65.6) => Action=1 (5.0/0.0)\n \
         => Action=0 (430.0/40.0)\n\nNumber of Rules : 6\n",
    );
    check_fit(
        &data,
        7,
        -508_418_222,
        "JRIP rules:\n===========\n\n\
         (state_0 >= 73.4) and (state_3 <= 46.4) and (state_11 <= 62.6) => Action=2 (50.0/4.0)\n\
         (state_11 >= 70.8) and (state_3 <= 58.6) => Action=1 (101.0/14.0)\n\
         (state_11 >= 65.1) and (state_11 <= 65.6) => Action=1 (6.0/1.0)\n \
         => Action=0 (443.0/53.0)\n\nNumber of Rules : 4\n",
    );
}

#[test]
fn keepaway_like_cross_validation_equals_wekas() {
    // Weka: cv correct 522.0
    check_cv(
        &keepaway_like(),
        [
            -136_054_685,
            -1_977_521_280,
            -1_208_490_489,
            -1_832_188_619,
            1_353_382_780,
            -1_648_570_075,
            -2_061_048_768,
            20_062_195,
            1_829_292_327,
            -1_165_025_461,
        ],
        [52.0, 47.0, 58.0, 52.0, 50.0, 51.0, 55.0, 54.0, 52.0, 51.0],
    );
}

/// Java: n = 30 + (s % 7)·15 (+ (s % 11)·40 when s ≥ 2000) instances; for
/// each i: a0 = (i·7919 + 131s + 1) % 100, a1 = (i·104729 + 17s + 2) % 100,
/// a2 = (i·1299709 + 7s + 3) % 50, c = (13i + s) % 4; x0 = a0/10 (missing when
/// (i + s) % 23 = 0), x1 = a1/10, x2 = a2/5, n = c over {a, b, c, d}; class
/// c % 3 when x0 is missing, else 0 if a0 < 35, else 1 if a1 ≥ 60, else 2 if
/// c = 2, else a2 % 3; when h = ((i + 1000s)·2654435761) % 13 < 2 the class
/// becomes (class + 1 + h) % 3.
fn family(s: u64) -> Dataset {
    let n = 30 + (s % 7) * 15 + if s >= 2000 { (s % 11) * 40 } else { 0 };
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for i in 0..n {
        let a0 = (i * 7919 + s * 131 + 1) % 100;
        let a1 = (i * 104_729 + s * 17 + 2) % 100;
        let a2 = (i * 1_299_709 + s * 7 + 3) % 50;
        let c = (i * 13 + s) % 4;
        let missing = (i + s).is_multiple_of(23);
        let base = if missing {
            c % 3
        } else if a0 < 35 {
            0
        } else if a1 >= 60 {
            1
        } else if c == 2 {
            2
        } else {
            a2 % 3
        };
        let h = ((i + s * 1000) * 2_654_435_761) % 13;
        let label = if h < 2 { (base + 1 + h) % 3 } else { base };
        let x0 = if missing { f64::NAN } else { a0 as f64 / 10.0 };
        rows.push(vec![x0, a1 as f64 / 10.0, a2 as f64 / 5.0, c as f64]);
        labels.push(label as usize);
    }
    let attributes = vec![
        Attribute::numeric("x0"),
        Attribute::numeric("x1"),
        Attribute::numeric("x2"),
        Attribute::nominal("n", class_names(&["a", "b", "c", "d"])),
    ];
    Dataset::new(attributes, rows, "class", class_names(&["k0", "k1", "k2"]), labels).unwrap()
}

/// Applies JRip's `cleanUp` to a Weka 3.6 listing: parses each rule's
/// antecedents `(name op value)`, cleans them, prints them back.
fn cleaned_listing(data: &Dataset, weka: &str) -> String {
    let attributes = data.attributes();
    let number = |v: f64| {
        let text = format!("{v:.6}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    };
    let mut out = String::new();
    for line in weka.lines() {
        let Some((lhs, rhs)) = line.split_once(" => ").filter(|(lhs, _)| !lhs.is_empty()) else {
            out.push_str(line);
            out.push('\n');
            continue;
        };
        let mut conditions: Vec<Condition> = lhs
            .split(" and ")
            .map(|text| {
                let text = text.trim_start_matches('(').trim_end_matches(')');
                let mut parts = text.split(' ');
                let (name, op, value) = (parts.next().unwrap(), parts.next().unwrap(), parts.next().unwrap());
                let attribute = attributes.iter().position(|a| a.name == name).unwrap();
                let (op, value) = match (op, &attributes[attribute].kind) {
                    ("<=", _) => (Operator::LessEq, value.parse().unwrap()),
                    (">=", _) => (Operator::GreaterEq, value.parse().unwrap()),
                    (_, AttributeKind::Nominal { values }) => {
                        (Operator::Equal, values.iter().position(|v| v == value).unwrap() as f64)
                    }
                    _ => unreachable!("numeric `=`"),
                };
                Condition { attribute, op, value }
            })
            .collect();
        clean_up(&mut conditions, attributes.len());
        let antecedents: Vec<String> = conditions
            .iter()
            .map(|c| {
                let name = &attributes[c.attribute].name;
                match (&c.op, &attributes[c.attribute].kind) {
                    (Operator::LessEq, _) => format!("({name} <= {})", number(c.value)),
                    (Operator::GreaterEq, _) => format!("({name} >= {})", number(c.value)),
                    (_, AttributeKind::Nominal { values }) => {
                        format!("({name} = {})", values[c.value as usize])
                    }
                    _ => unreachable!("numeric `=`"),
                }
            })
            .collect();
        out.push_str(&format!("{} => {rhs}\n", antecedents.join(" and ")));
    }
    out
}

#[test]
fn cleaned_listing_applies_clean_up() {
    let data = family(0);
    let weka = "(x1 <= 5) and (x0 >= 5.5) and (x1 <= 3.2) => class=k2 (17.0/5.0)\n";
    assert_eq!(cleaned_listing(&data, weka), "(x0 >= 5.5) and (x1 <= 3.2) => class=k2 (17.0/5.0)\n");
}

#[test]
fn family_rules_equal_wekas_after_clean_up() {
    // (s, effective seed, Weka 3.6.14's listing as printed)
    let cases: [(u64, i64, &str); 7] = [
        (
            2,
            1_054_027_334,
            "JRIP rules:\n===========\n\n\
             (n = c) and (x1 <= 4.4) => class=k2 (7.0/0.0)\n\
             (x1 >= 6.4) and (x0 >= 5.6) => class=k1 (10.0/0.0)\n \
             => class=k0 (43.0/16.0)\n\nNumber of Rules : 3\n",
        ),
        (
            18,
            2_075_435_943,
            "JRIP rules:\n===========\n\n\
             (n = c) and (x1 <= 5.6) and (x0 >= 3.5) => class=k2 (10.0/0.0)\n\
             (x0 >= 3.7) and (x1 >= 6.2) => class=k1 (23.0/3.0)\n \
             => class=k0 (57.0/21.0)\n\nNumber of Rules : 3\n",
        ),
        (
            69,
            -21_651_217,
            "JRIP rules:\n===========\n\n\
             (n = c) and (x0 >= 3.5) and (x1 <= 5.2) => class=k2 (13.0/1.0)\n\
             (x0 >= 3.8) and (x1 >= 6.2) => class=k1 (29.0/2.0)\n\
             (x0 >= 5.4) and (n = d) => class=k1 (10.0/1.0)\n \
             => class=k0 (68.0/19.0)\n\nNumber of Rules : 4\n",
        ),
        (
            117,
            -818_439_226,
            "JRIP rules:\n===========\n\n\
             (n = c) and (x0 >= 3.5) and (x1 <= 5.6) => class=k2 (11.0/1.0)\n\
             (x0 >= 3.6) and (x1 >= 6.1) => class=k1 (25.0/3.0)\n\
             (x0 >= 6.6) and (n = d) => class=k1 (6.0/0.0)\n \
             => class=k0 (63.0/20.0)\n\nNumber of Rules : 4\n",
        ),
        (
            76,
            -1_663_528_601,
            "JRIP rules:\n===========\n\n\
             (x1 <= 5) and (x0 >= 5.5) and (x1 <= 3.2) => class=k2 (17.0/5.0)\n\
             (x0 >= 5.7) and (x1 >= 6.8) => class=k1 (19.0/1.0)\n\
             (x0 >= 6.2) and (x2 >= 4.2) => class=k1 (8.0/0.0)\n\
             (x1 >= 8.3) and (x2 <= 5) => class=k1 (7.0/1.0)\n \
             => class=k0 (69.0/21.0)\n\nNumber of Rules : 5\n",
        ),
        (
            305,
            -1_631_142_131,
            "JRIP rules:\n===========\n\n\
             (x0 >= 4.9) and (x1 <= 6.9) and (x1 >= 3.6) and (x1 <= 5.3) => class=k2 (9.0/1.0)\n\
             (n = c) and (x1 <= 4) and (x0 >= 3.9) => class=k2 (6.0/0.0)\n\
             (x2 >= 8.2) and (x2 <= 8.4) => class=k2 (4.0/1.0)\n\
             (x0 >= 3.6) => class=k1 (38.0/11.0)\n \
             => class=k0 (33.0/4.0)\n\nNumber of Rules : 5\n",
        ),
        (
            2031,
            160_266_987,
            "JRIP rules:\n===========\n\n\
             (x1 <= 4) and (x0 >= 7.2) and (x1 >= 1.4) and (x1 <= 3) => class=k2 (15.0/0.0)\n\
             (x1 <= 6.3) and (x0 >= 3) and (x1 >= 5) and (x0 >= 7) and (x1 <= 5.8) => class=k2 (10.0/0.0)\n\
             (n = c) and (x1 <= 4.8) and (x0 >= 3.9) => class=k2 (28.0/6.0)\n\
             (x1 <= 3.7) and (n = d) and (x1 >= 2.9) and (x0 >= 5) => class=k2 (6.0/0.0)\n\
             (x0 >= 4.4) and (x1 >= 6.4) => class=k1 (64.0/7.0)\n\
             (x0 >= 3.5) and (x0 >= 8.2) and (x2 >= 3.2) => class=k1 (12.0/0.0)\n \
             => class=k0 (190.0/51.0)\n\nNumber of Rules : 7\n",
        ),
    ];
    for (s, effective_seed, weka) in cases {
        let data = family(s);
        assert_eq!(JavaRandom::for_instances(&data, 1), JavaRandom::new(effective_seed), "family {s}");
        let list = Ripper::fit(&RipperParams::weka_3_6(), &data).unwrap();
        assert_eq!(list.to_weka_string(), cleaned_listing(&data, weka), "family {s}");
    }
}
