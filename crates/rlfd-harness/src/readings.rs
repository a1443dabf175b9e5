//! Readings: the thesis's open choices, declared as data with typed values.
//!
//! Where the thesis leaves a choice open (a tile width, the size of the IRL
//! reward, the terminal potential, how a policy is scored), a chapter
//! declares an [`Axis<T>`]: its name, its levels, each with the value it
//! sets (a `T`: a number, an enum), what it means and the sentence of the
//! thesis or the cited paper behind it, and the default with its reason (the
//! rule: the thesis's literal text, then the cited original paper or
//! software, then a value fixed before any run). A [`Reading`] picks one
//! level per axis; the empty reading is every axis at its default.
//!
//! A chapter reads a level's value with [`Reading::value`] and sets it in
//! the trials' parameters; the harness computes each trial's identity from
//! those parameters, so a reading changes exactly the trials whose
//! parameters it changes, and their seed stays the same (common random
//! numbers across readings: a difference between readings is the
//! reading's, not the stream's). An unknown axis or level is an error
//! naming the valid ones; nothing falls back to a default.

use std::collections::BTreeMap;
use std::fmt;

use thiserror::Error;

/// One level of an axis, and the value it sets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Level<T: 'static> {
    /// Its name on the command line and in reports (`[a-z0-9.-]+`).
    pub name: &'static str,
    /// The value it sets.
    pub value: T,
    /// What the level means, in one sentence.
    pub meaning: &'static str,
    /// The sentence of the thesis or the paper behind it (quoted), or why
    /// it is a plausible alternative.
    pub source: &'static str,
}

/// An open choice of the thesis whose levels set values of type `T`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis<T: 'static> {
    /// Its name (`[a-z0-9-]+`), e.g. `terminal-potential`.
    pub name: &'static str,
    /// The choice, as a question.
    pub question: &'static str,
    /// Its levels, the default among them.
    pub levels: &'static [Level<T>],
    /// The default level's name.
    pub default: &'static str,
    /// Why that level is the default, by the rule for defaults.
    pub why_default: &'static str,
    /// Whether the axis changes no trial, only what the chapter's report
    /// computes from them (a robustness run at its levels reuses every
    /// trial and recomputes the verdicts).
    pub report_only: bool,
}

/// What every axis says of itself, whatever the type of its values: what
/// the command line, the robustness run and the reports need.
pub trait AnyAxis: Sync + fmt::Debug {
    /// Its name.
    fn name(&self) -> &'static str;
    /// The choice, as a question.
    fn question(&self) -> &'static str;
    /// Its levels' names, in declared order.
    fn level_names(&self) -> Vec<&'static str>;
    /// Each level's (name, meaning, source), in declared order.
    fn level_texts(&self) -> Vec<(&'static str, &'static str, &'static str)>;
    /// The default level's name.
    fn default_level(&self) -> &'static str;
    /// Why it is the default.
    fn why_default(&self) -> &'static str;
    /// Whether it changes no trial.
    fn report_only(&self) -> bool;

    /// The levels other than the default, in declared order.
    fn alternatives(&self) -> Vec<&'static str> {
        let default = self.default_level();
        self.level_names().into_iter().filter(|l| *l != default).collect()
    }

    /// Whether the declaration is sound: a well-formed name, at least two
    /// levels with distinct well-formed names, the default among them.
    fn check(&self) -> Result<(), String> {
        let ok = |s: &str, dot: bool| {
            !s.is_empty()
                && s.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-' || (dot && c == '.'))
        };
        let names = self.level_names();
        if !ok(self.name(), false) {
            return Err(format!("axis name {:?} is not [a-z0-9-]+", self.name()));
        }
        if names.len() < 2 {
            return Err(format!("axis {} has fewer than two levels", self.name()));
        }
        if let Some(bad) = names.iter().find(|n| !ok(n, true)) {
            return Err(format!("axis {}: level name {bad:?} is not [a-z0-9.-]+", self.name()));
        }
        let mut sorted = names.clone();
        sorted.sort_unstable();
        sorted.dedup();
        if sorted.len() != names.len() {
            return Err(format!("axis {} names a level twice", self.name()));
        }
        if !names.contains(&self.default_level()) {
            return Err(format!(
                "axis {}: its default {:?} is not one of its levels",
                self.name(),
                self.default_level()
            ));
        }
        Ok(())
    }
}

impl<T: Sync + fmt::Debug> AnyAxis for Axis<T> {
    fn name(&self) -> &'static str {
        self.name
    }
    fn question(&self) -> &'static str {
        self.question
    }
    fn level_names(&self) -> Vec<&'static str> {
        self.levels.iter().map(|l| l.name).collect()
    }
    fn level_texts(&self) -> Vec<(&'static str, &'static str, &'static str)> {
        self.levels.iter().map(|l| (l.name, l.meaning, l.source)).collect()
    }
    fn default_level(&self) -> &'static str {
        self.default
    }
    fn why_default(&self) -> &'static str {
        self.why_default
    }
    fn report_only(&self) -> bool {
        self.report_only
    }
}

impl<T> Axis<T> {
    /// The level called `name`.
    pub fn level(&self, name: &str) -> Option<&'static Level<T>> {
        self.levels.iter().find(|l| l.name == name)
    }

    /// The default level.
    pub fn default_level(&self) -> &'static Level<T> {
        self.level(self.default).unwrap_or_else(|| panic!("axis {}: its default is one of its levels", self.name))
    }
}

/// A choice of levels: the axes not named are at their defaults.
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord)]
pub struct Reading(BTreeMap<&'static str, &'static str>);

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

    /// This reading with `axis` at its level `level` (the default level
    /// removes the choice).
    ///
    /// # Panics
    /// When `level` is not one of `axis`'s levels: callers pass levels they
    /// took from the axis (the command line goes through [`Reading::parse`]).
    pub fn with(mut self, axis: &dyn AnyAxis, level: &str) -> Self {
        let level = axis
            .level_names()
            .into_iter()
            .find(|l| *l == level)
            .unwrap_or_else(|| panic!("{level:?} is a level of axis {}", axis.name()));
        if level == axis.default_level() {
            self.0.remove(axis.name());
        } else {
            self.0.insert(axis.name(), level);
        }
        self
    }

    /// Parses `axis=level[,axis=level…]` against `axes`.
    pub fn parse(text: &str, axes: &[&'static dyn AnyAxis]) -> Result<Self, ReadingError> {
        let mut reading = Reading::defaults();
        for part in text.split(',').filter(|p| !p.is_empty()) {
            let (a, l) = part.split_once('=').ok_or_else(|| ReadingError::Form(part.to_string()))?;
            let axis = axes.iter().find(|x| x.name() == a).ok_or_else(|| ReadingError::Axis {
                axis: a.to_string(),
                expected: axes.iter().map(|x| x.name()).collect(),
            })?;
            if !axis.level_names().contains(&l) {
                return Err(ReadingError::Level {
                    axis: axis.name(),
                    level: l.to_string(),
                    expected: axis.level_names(),
                });
            }
            reading = reading.with(*axis, l);
        }
        Ok(reading)
    }

    /// The name of the level this reading gives `axis`.
    pub fn level_of(&self, axis: &dyn AnyAxis) -> &'static str {
        self.0.get(axis.name()).copied().unwrap_or(axis.default_level())
    }

    /// The level this reading gives `axis`.
    pub fn level<T>(&self, axis: &'static Axis<T>) -> &'static Level<T> {
        match self.0.get(axis.name) {
            Some(name) => axis
                .level(name)
                .unwrap_or_else(|| panic!("a reading holds only levels of its axes ({name:?} of {})", axis.name)),
            None => axis.default_level(),
        }
    }

    /// The value this reading gives `axis`.
    pub fn value<T>(&self, axis: &'static Axis<T>) -> &'static T {
        &self.level(axis).value
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
            self.0.iter().map(|(a, l)| format!("{a}={l}")).collect::<Vec<_>>().join(",")
        }
    }

    /// The non-default choices, in axis order.
    pub fn choices(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.0.iter().map(|(a, l)| (*a, *l))
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

    #[derive(Clone, Copy, Debug, PartialEq)]
    enum Terminal {
        Literal,
        Zero,
    }

    static TERMINAL: Axis<Terminal> = Axis {
        name: "terminal-potential",
        question: "What is Φ at a terminal state?",
        levels: &[
            Level {
                name: "literal",
                value: Terminal::Literal,
                meaning: "Φ(s′) as eq. 6.2 writes it",
                source: "eq. 6.2",
            },
            Level { name: "zero", value: Terminal::Zero, meaning: "Φ(terminal) = 0", source: "Ng et al. 1999" },
        ],
        default: "literal",
        why_default: "the thesis's literal text",
        report_only: false,
    };

    static SCALE: Axis<f64> = Axis {
        name: "irl-scale",
        question: "How large is R_IRL?",
        levels: &[
            Level { name: "1", value: 1.0, meaning: "unit", source: "fixed before any run" },
            Level { name: "0.1", value: 0.1, meaning: "a tenth", source: "an alternative" },
        ],
        default: "1",
        why_default: "fixed before any run",
        report_only: false,
    };

    #[test]
    fn readings_parse_to_typed_values_and_refuse_unknown_names() {
        let axes: [&'static dyn AnyAxis; 2] = [&TERMINAL, &SCALE];
        for a in axes {
            a.check().unwrap();
        }
        let d = Reading::parse("", &axes).unwrap();
        assert!(d.is_default());
        assert_eq!((*d.value(&TERMINAL), *d.value(&SCALE)), (Terminal::Literal, 1.0));
        let r = Reading::parse("terminal-potential=zero,irl-scale=0.1", &axes).unwrap();
        assert_eq!(r.label(), "irl-scale=0.1,terminal-potential=zero");
        assert_eq!((*r.value(&TERMINAL), *r.value(&SCALE)), (Terminal::Zero, 0.1));
        assert_eq!(r.level_of(&TERMINAL), "zero");
        // The default level is no choice at all.
        assert!(Reading::parse("terminal-potential=literal", &axes).unwrap().is_default());
        assert_eq!(
            Reading::parse("terminal=zero", &axes).unwrap_err().to_string(),
            "unknown reading axis \"terminal\" (expected one of: terminal-potential, irl-scale)"
        );
        // A misspelt level is refused, naming the valid ones (no fallback to the default).
        assert_eq!(
            Reading::parse("irl-scale=0.2", &axes).unwrap_err().to_string(),
            "unknown level \"0.2\" of reading axis irl-scale (expected one of: 1, 0.1)"
        );
        assert!(matches!(Reading::parse("zero", &axes), Err(ReadingError::Form(_))));
        assert_eq!(TERMINAL.alternatives(), vec!["zero"]);
    }

    #[test]
    fn a_malformed_axis_is_found() {
        static BAD: Axis<u8> = Axis {
            name: "x",
            question: "?",
            levels: &[
                Level { name: "a", value: 0, meaning: "", source: "" },
                Level { name: "b", value: 1, meaning: "", source: "" },
            ],
            default: "c",
            why_default: "",
            report_only: false,
        };
        assert_eq!(BAD.check().unwrap_err(), "axis x: its default \"c\" is not one of its levels");
    }
}
