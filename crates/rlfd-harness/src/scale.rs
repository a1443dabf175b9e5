//! The two sizes of every experiment.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// How big an experiment runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Scale {
    /// Every code path, table and figure in seconds: what the golden files hold.
    Quick,
    /// The thesis's trial counts and lengths.
    Paper,
}

impl Scale {
    /// `quick` or `paper`.
    pub fn as_str(self) -> &'static str {
        match self {
            Scale::Quick => "quick",
            Scale::Paper => "paper",
        }
    }
}

impl fmt::Display for Scale {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Scale {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "quick" => Ok(Scale::Quick),
            "paper" => Ok(Scale::Paper),
            other => Err(format!("unknown scale \"{other}\" (expected quick or paper)")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_prints() {
        assert_eq!("quick".parse::<Scale>(), Ok(Scale::Quick));
        assert_eq!(Scale::Paper.to_string(), "paper");
        assert_eq!("big".parse::<Scale>().unwrap_err(), "unknown scale \"big\" (expected quick or paper)");
    }
}
