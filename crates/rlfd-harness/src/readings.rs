//! Readings: the thesis's open choices, declared as data.
//!
//! Where the thesis leaves a choice open (a tile width, the size of the IRL
//! reward, the terminal potential, how a policy is scored), a chapter
//! declares an [`Axis`]: its name, its levels with the sentence of the
//! thesis or the cited paper behind each, and the default with its reason
//! (the rule: the thesis's literal text, then the cited original paper or
//! software, then a value fixed before any run). A [`Reading`] picks one
//! level per axis; the empty reading is every axis at its default.
//!
//! A non-default reading is part of a trial's identity and of its place in
//! the store (`<scale>/seed-<master>/reading-<label>/…`), but not of its seed:
//! the same trial under two readings draws the same random numbers, so a
//! difference between readings is the reading's, not the stream's.

use std::collections::BTreeMap;
use std::fmt;

use thiserror::Error;

/// One level of an axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Level {
    /// Its name on the command line and in the store (`[a-z0-9.-]+`).
    pub name: &'static str,
    /// What the level means, in one sentence.
    pub meaning: &'static str,
    /// The sentence of the thesis or the paper behind it (quoted), or why
    /// it is a plausible alternative.
    pub source: &'static str,
}

/// An open choice of the thesis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Axis {
    /// Its name (`[a-z0-9-]+`), e.g. `terminal-potential`.
    pub name: &'static str,
    /// The choice, as a question.
    pub question: &'static str,
    /// Its levels, the default among them.
    pub levels: &'static [Level],
    /// The default level's name.
    pub default: &'static str,
    /// Why that level is the default, by the rule for defaults.
    pub why_default: &'static str,
    /// The trials it changes: `experiment` (all its conditions) or
    /// `experiment:prefix` (the conditions whose name starts with `prefix`).
    /// Empty: the axis changes no trial, only what the chapter's report
    /// computes from them (the chapter reads the level from its run's
    /// [`RunOptions::reading`](crate::RunOptions) and carries it into its
    /// results); a run at its levels reuses every trial and recomputes the
    /// verdicts, so the robustness run shows it like any other axis.
    pub experiments: &'static [&'static str],
}

impl Axis {
    /// The level called `name`.
    pub fn level(&self, name: &str) -> Option<&'static Level> {
        self.levels.iter().find(|l| l.name == name)
    }

    /// Whether the axis changes the trials of `condition` in `experiment`.
    pub fn changes(&self, experiment: &str, condition: &str) -> bool {
        self.experiments.iter().any(|e| match e.split_once(':') {
            None => *e == experiment,
            Some((x, prefix)) => x == experiment && condition.starts_with(prefix),
        })
    }

    /// The levels other than the default, in declared order.
    pub fn alternatives(&self) -> impl Iterator<Item = &'static Level> + '_ {
        self.levels.iter().filter(move |l| l.name != self.default)
    }
}

/// A choice of levels: the axes not named are at their defaults.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Reading(BTreeMap<&'static str, (&'static Axis, &'static str)>);

/// A reading a chapter cannot take.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ReadingError {
    /// No such axis.
    #[error("unknown reading axis \"{axis}\" (expected one of: {})", expected.join(", "))]
    Axis {
        /// The name given.
        axis: String,
        /// The declared axes.
        expected: Vec<&'static str>,
    },
    /// No such level.
    #[error("unknown level \"{level}\" of reading axis {axis} (expected one of: {})", expected.join(", "))]
    Level {
        /// The axis.
        axis: &'static str,
        /// The level given.
        level: String,
        /// Its levels.
        expected: Vec<&'static str>,
    },
    /// Not of the form `axis=level`.
    #[error("a reading is written axis=level, got \"{0}\"")]
    Form(String),
}

impl Reading {
    /// Every axis at its default.
    pub fn defaults() -> Self {
        Reading(BTreeMap::new())
    }

    /// This reading with `axis` at `level` (the default level removes it).
    pub fn with(mut self, axis: &'static Axis, level: &Level) -> Self {
        if level.name == axis.default {
            self.0.remove(axis.name);
        } else {
            self.0.insert(axis.name, (axis, level.name));
        }
        self
    }

    /// Parses `axis=level[,axis=level…]` against `axes`.
    pub fn parse(text: &str, axes: &[&'static Axis]) -> Result<Self, ReadingError> {
        let mut reading = Reading::defaults();
        for part in text.split(',').filter(|p| !p.is_empty()) {
            let (a, l) = part.split_once('=').ok_or_else(|| ReadingError::Form(part.to_string()))?;
            let axis = axes.iter().find(|x| x.name == a).ok_or_else(|| ReadingError::Axis {
                axis: a.to_string(),
                expected: axes.iter().map(|x| x.name).collect(),
            })?;
            let level = axis.level(l).ok_or_else(|| ReadingError::Level {
                axis: axis.name,
                level: l.to_string(),
                expected: axis.levels.iter().map(|x| x.name).collect(),
            })?;
            reading = reading.with(axis, level);
        }
        Ok(reading)
    }

    /// The level this reading gives `axis`.
    pub fn level_of(&self, axis: &Axis) -> &'static str {
        self.0.get(axis.name).map_or(axis.default, |(_, l)| *l)
    }

    /// Whether every axis is at its default.
    pub fn is_default(&self) -> bool {
        self.0.is_empty()
    }

    /// `default`, or `axis=level,…` in axis order.
    pub fn label(&self) -> String {
        if self.0.is_empty() {
            "default".into()
        } else {
            self.0.iter().map(|(a, (_, l))| format!("{a}={l}")).collect::<Vec<_>>().join(",")
        }
    }

    /// The non-default choices, in axis order.
    pub fn choices(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.0.iter().map(|(a, (_, l))| (*a, *l))
    }

    /// Whether a chosen axis changes some trials of `experiment` (when none
    /// does, its trials under this reading are its default-reading trials).
    pub fn changes_experiment(&self, experiment: &str) -> bool {
        self.0.values().any(|(axis, _)| axis.experiments.iter().any(|e| e.split(':').next() == Some(experiment)))
    }

    /// The choices of the axes that change the trials of `condition` in
    /// `experiment`: what identifies those trials under this reading (other
    /// axes leave them as they are, so their default-reading records are
    /// reused).
    pub fn restricted_to(&self, experiment: &str, condition: &str) -> Reading {
        Reading(
            self.0.iter().filter(|(_, (axis, _))| axis.changes(experiment, condition)).map(|(k, v)| (*k, *v)).collect(),
        )
    }
}

impl fmt::Display for Reading {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    static TERMINAL: Axis = Axis {
        name: "terminal-potential",
        question: "What is Φ at a terminal state?",
        levels: &[
            Level { name: "literal", meaning: "Φ(s′) as eq. 6.2 writes it", source: "eq. 6.2" },
            Level { name: "zero", meaning: "Φ(terminal) = 0", source: "Ng et al. 1999" },
        ],
        default: "literal",
        why_default: "the thesis's literal text",
        experiments: &["maze"],
    };

    #[test]
    fn readings_parse_label_and_fall_back_to_defaults() {
        let axes = [&TERMINAL];
        assert!(Reading::parse("", &axes).unwrap().is_default());
        let r = Reading::parse("terminal-potential=zero", &axes).unwrap();
        assert_eq!((r.label(), r.level_of(&TERMINAL)), ("terminal-potential=zero".into(), "zero"));
        // The default level is no choice at all.
        assert!(Reading::parse("terminal-potential=literal", &axes).unwrap().is_default());
        assert_eq!(Reading::defaults().level_of(&TERMINAL), "literal");
        assert_eq!(
            Reading::parse("terminal=zero", &axes).unwrap_err().to_string(),
            "unknown reading axis \"terminal\" (expected one of: terminal-potential)"
        );
        assert_eq!(
            Reading::parse("terminal-potential=one", &axes).unwrap_err().to_string(),
            "unknown level \"one\" of reading axis terminal-potential (expected one of: literal, zero)"
        );
        assert!(matches!(Reading::parse("zero", &axes), Err(ReadingError::Form(_))));
        assert_eq!(TERMINAL.alternatives().map(|l| l.name).collect::<Vec<_>>(), vec!["zero"]);
        // Restriction: only the trials an axis changes carry it.
        assert_eq!(r.restricted_to("maze", "sis").label(), "terminal-potential=zero");
        assert!(r.restricted_to("mario", "sis").is_default());
        assert!(r.changes_experiment("maze") && !r.changes_experiment("mario"));
        assert!(!Reading::defaults().changes_experiment("maze"));
        let narrow = Axis { experiments: &["maze:dis"], ..TERMINAL };
        assert!(narrow.changes("maze", "dis-kappa-1") && !narrow.changes("maze", "sis"));
        // An axis of the report alone changes no trial: its level is in the
        // reading, and every trial keeps its default identity and folder.
        static REPORT_ONLY: Axis = Axis { name: "units", experiments: &[], ..TERMINAL };
        let r = Reading::parse("units=zero", &[&REPORT_ONLY]).unwrap();
        assert_eq!(r.level_of(&REPORT_ONLY), "zero");
        assert!(!REPORT_ONLY.changes("maze", "sis") && r.restricted_to("maze", "sis").is_default());
    }
}
