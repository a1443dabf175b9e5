//! The crate's error type. Rendering fails only on content that cannot make a
//! valid report (a table whose rows do not match its columns, a file name
//! that would escape the chapter's directory, a claim id the thesis does not
//! have, a figure with nothing to draw), never on IO, which is the caller's.

/// Everything that can go wrong while turning report content into files.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A path into `thesis-numbers.toml` that does not exist or holds another type.
    #[error("published value `{path}`: {reason}")]
    Published { path: String, reason: String },
    /// A claim id that `claims.md` does not list.
    #[error("claim `{0}` is not in claims.md")]
    UnknownClaim(String),
    /// Two chapters (or one chapter twice) supplied a verdict for one claim.
    #[error("claim `{0}` has a verdict from more than one place")]
    DuplicateClaim(String),
    /// A chapter's data file (deviations, evidence) that does not parse, or
    /// an entry or placeholder in it that is missing or wrong.
    #[error("{file}: {entry}: {reason}")]
    DataFile { file: String, entry: String, reason: String },
    /// A table whose shape or content cannot be rendered.
    #[error("table `{table}`: {reason}")]
    Table { table: String, reason: String },
    /// A figure that cannot be drawn (no data, a bad range, mismatched lengths).
    #[error("figure `{figure}`: {reason}")]
    Figure { figure: String, reason: String },
    /// The drawing backend failed (plotters' error, as text).
    #[error("drawing `{figure}` failed: {reason}")]
    Drawing { figure: String, reason: String },
    /// A slug or file name that is empty, has a separator, `..` or a character
    /// outside `[A-Za-z0-9._-]`, or an extension the block does not allow.
    #[error("file name `{name}`: {reason}")]
    FileName { name: String, reason: String },
    /// Two blocks of one chapter would write the same file.
    #[error("two blocks would write `{0}`")]
    DuplicateFile(String),
    /// An SVG handed to a chapter that does not carry the chapter's provenance line.
    #[error("figure `{file}` does not start with this chapter's provenance comment")]
    Provenance { file: String },
    /// A template failed to render (a bug in this crate's templates or context).
    #[error("template `{name}`: {source}")]
    Template {
        name: String,
        #[source]
        source: minijinja::Error,
    },
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
