//! `pdf`: build a report tree's LaTeX into PDFs, the whole replication as
//! one document (`report.tex`: the scorecard, then every chapter) and each
//! chapter alone (`<chapter>/chapter.tex`), and check the result: no LaTeX
//! error, no overfull box wider than 10 pt, and every figure of a chapter
//! included in its PDF and in the whole document.
//!
//! The tree is copied to a build directory first (LaTeX's auxiliary files
//! never land in `reports/`); the PDFs are written to `--out`. It runs
//! `latexmk` when installed, else `pdflatex` until the cross-references
//! settle; without either it says in one line how to install them.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail};

use crate::output::list_files;

/// Settings of `pdf`.
#[derive(Debug, Clone)]
pub struct Options {
    /// The report tree (with `report.tex` at its root).
    pub tree: PathBuf,
    /// Where the PDFs go.
    pub out: PathBuf,
    /// Only the whole document, not each chapter alone.
    pub whole_only: bool,
}

/// The Debian packages the LaTeX needs (named in the README too).
pub const DEBIAN_PACKAGES: &str = "texlive-latex-recommended texlive-fonts-recommended lmodern";

/// Overfull boxes up to this width (points) are tolerated.
const OVERFULL_LIMIT_PT: f64 = 10.0;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Engine {
    Latexmk,
    Pdflatex,
}

fn found(program: &str) -> bool {
    Command::new(program).arg("--version").output().is_ok_and(|o| o.status.success())
}

pub fn run(options: &Options) -> Result<()> {
    let engine = if found("latexmk") {
        Engine::Latexmk
    } else if found("pdflatex") {
        Engine::Pdflatex
    } else {
        bail!("pdflatex not found: install it with `apt-get install {DEBIAN_PACKAGES}` (Debian, Ubuntu) and rerun");
    };
    let tree = &options.tree;
    if !tree.join("report.tex").is_file() {
        bail!(
            "{} is not a report tree: it has no report.tex (render one with `cargo xtask reproduce`)",
            tree.display()
        );
    }
    let build = crate::cli::workspace_root().join("target/rlfd/pdf-build");
    if build.exists() {
        fs::remove_dir_all(&build).with_context(|| format!("cannot clear {}", build.display()))?;
    }
    copy_tree(tree, &build)?;
    fs::create_dir_all(&options.out).with_context(|| format!("cannot create {}", options.out.display()))?;

    // (directory, TeX file, the figures it must include, the PDF's name in --out)
    let chapters = chapter_dirs(&build)?;
    let mut jobs: Vec<(PathBuf, &str, Vec<String>, String)> = Vec::new();
    let mut every_figure = Vec::new();
    for dir in &chapters {
        let slug = dir.file_name().expect("a chapter directory").to_string_lossy().into_owned();
        let figures = figures(dir)?;
        every_figure.extend(figures.iter().map(|f| format!("{slug}/{f}")));
        if !options.whole_only {
            jobs.push((dir.clone(), "chapter.tex", figures, format!("{slug}.pdf")));
        }
    }
    jobs.insert(0, (build.clone(), "report.tex", every_figure, "report.pdf".into()));

    let mut problems = Vec::new();
    for (dir, tex, figures, name) in &jobs {
        let started = std::time::Instant::now();
        compile(engine, dir, tex)?;
        let stem = tex.trim_end_matches(".tex");
        let log = fs::read_to_string(dir.join(format!("{stem}.log")))
            .with_context(|| format!("pdflatex wrote no log for {}", dir.join(tex).display()))?;
        let pdf = dir.join(format!("{stem}.pdf"));
        let pages = pages(&pdf);
        let found = check_log(&log, figures);
        let target = options.out.join(name);
        if pdf.is_file() {
            fs::copy(&pdf, &target).with_context(|| format!("cannot write {}", target.display()))?;
        }
        eprintln!(
            "{}: {} pages, {} figures, {} ({:.1} s)",
            target.display(),
            pages.map_or("?".into(), |p| p.to_string()),
            figures.len(),
            if found.is_empty() {
                "no errors, no overfull box over 10 pt".to_string()
            } else {
                format!("{} problems", found.len())
            },
            started.elapsed().as_secs_f64()
        );
        problems.extend(found.into_iter().map(|p| format!("{}: {p}", dir.join(tex).display())));
    }
    if !problems.is_empty() {
        for p in problems.iter().take(30) {
            eprintln!("{p}");
        }
        bail!("{} LaTeX problems (first: {})", problems.len(), problems[0]);
    }
    Ok(())
}

/// Runs the engine on `tex` in `dir` until its references settle.
fn compile(engine: Engine, dir: &Path, tex: &str) -> Result<()> {
    let run = |program: &str, args: &[&str]| -> Result<()> {
        let out = Command::new(program)
            .args(args)
            .arg(tex)
            .current_dir(dir)
            .output()
            .with_context(|| format!("cannot run {program}"))?;
        // A LaTeX error is reported from the log (with its line), not here.
        let _ = out;
        Ok(())
    };
    match engine {
        Engine::Latexmk => run("latexmk", &["-pdf", "-interaction=nonstopmode", "-halt-on-error", "-silent"]),
        Engine::Pdflatex => {
            let stem = tex.trim_end_matches(".tex");
            for _ in 0..4 {
                run("pdflatex", &["-interaction=nonstopmode", "-halt-on-error"])?;
                let log = fs::read_to_string(dir.join(format!("{stem}.log"))).unwrap_or_default();
                if !log.contains("Rerun") || log.contains("\n! ") {
                    break;
                }
            }
            Ok(())
        }
    }
}

/// The problems a pdflatex log shows: errors, overfull boxes over the
/// limit, and figures of `figures` it did not include.
pub fn check_log(log: &str, figures: &[String]) -> Vec<String> {
    let mut problems = Vec::new();
    let lines: Vec<&str> = log.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        if line.starts_with("! ") {
            let context = lines.get(i + 1).map_or("", |l| l.trim());
            problems.push(format!("LaTeX error: {} {context}", line.trim_start_matches("! ")));
        }
        if let Some(rest) = line.strip_prefix("Overfull \\hbox (")
            && let Some((pt, _)) = rest.split_once("pt too wide)")
            && pt.parse::<f64>().is_ok_and(|w| w > OVERFULL_LIMIT_PT)
        {
            problems.push(line.to_string());
        }
    }
    // pdflatex logs each included graphic as `<figure.pdf>` or `<./figure.pdf>`
    // (with the path it was given), possibly broken across log lines.
    let joined: String = log.lines().collect();
    for f in figures {
        if !joined.contains(&format!("{f}>")) && !joined.contains(&format!("{f},")) {
            problems.push(format!("figure {f} is not in the PDF"));
        }
    }
    problems
}

/// The page count pdfinfo reports, if it is installed.
fn pages(pdf: &Path) -> Option<u32> {
    let out = Command::new("pdfinfo").arg(pdf).output().ok()?;
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .find_map(|l| l.strip_prefix("Pages:").and_then(|n| n.trim().parse().ok()))
}

/// The chapter directories of a tree (those with a `chapter.tex`), sorted.
fn chapter_dirs(tree: &Path) -> Result<Vec<PathBuf>> {
    let mut dirs = Vec::new();
    for e in fs::read_dir(tree).with_context(|| format!("cannot read {}", tree.display()))? {
        let p = e?.path();
        if p.join("chapter.tex").is_file() {
            dirs.push(p);
        }
    }
    dirs.sort();
    Ok(dirs)
}

/// The figure PDFs of a chapter directory (every `.pdf` with an `.svg` beside it).
fn figures(dir: &Path) -> Result<Vec<String>> {
    let mut out = Vec::new();
    for p in list_files(dir)? {
        if p.extension().is_some_and(|e| e == "pdf") && p.with_extension("svg").is_file() {
            out.push(p.file_name().expect("a file").to_string_lossy().into_owned());
        }
    }
    Ok(out)
}

fn copy_tree(from: &Path, to: &Path) -> Result<()> {
    for file in list_files(from)? {
        let rel = file.strip_prefix(from).expect("listed under it");
        let target = to.join(rel);
        fs::create_dir_all(target.parent().expect("a file has a parent"))
            .with_context(|| format!("cannot create {}", target.display()))?;
        fs::copy(&file, &target).with_context(|| format!("cannot copy {}", file.display()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn logs_are_checked() {
        let log = "This is pdfTeX\n<figure_6_1.pdf, id=12, 540.0pt x 330.0pt>\n<use figure_6_1.pdf>\n\
                   Overfull \\hbox (2.2pt too wide) in paragraph at lines 1--2\n\
                   Overfull \\hbox (12.5pt too wide) in alignment at lines 3--4\n\
                   ! Undefined control sequence.\nl.7 \\foo\n";
        let p = check_log(log, &["figure_6_1.pdf".into(), "figure_6_2.pdf".into()]);
        assert_eq!(p.len(), 3, "{p:?}");
        assert!(p[0].contains("12.5pt"), "{p:?}");
        assert!(p[1].starts_with("LaTeX error: Undefined control sequence. l.7"), "{p:?}");
        assert_eq!(p[2], "figure figure_6_2.pdf is not in the PDF");
        assert!(check_log("<./ch6/figure_6_1.pdf>", &["ch6/figure_6_1.pdf".into()]).is_empty());
    }
}
