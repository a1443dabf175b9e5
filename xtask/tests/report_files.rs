//! What the committed quick-scale report (`golden/`) ships, checked as a
//! reader would meet it: every page is valid HTML5 (no parse error, unique
//! ids), every link and image resolves inside the tree, the prose names no
//! file that is neither in the report nor in the repository and no process
//! language, and every CSV reads with a default CSV reader (one header row,
//! no comment line, one field per header column), the Maze demonstrations
//! round trip through the project's own reader.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use html5ever::tendril::TendrilSink;
use markup5ever_rcdom::{Handle, NodeData, RcDom};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            files(&p, out);
        } else {
            out.push(p);
        }
    }
}

fn golden_files(ext: &str) -> Vec<PathBuf> {
    let mut all = Vec::new();
    files(&root().join("golden"), &mut all);
    all.retain(|p| p.extension().is_some_and(|e| e == ext));
    all.sort();
    assert!(!all.is_empty(), "golden/ has no .{ext} file");
    all
}

/// Parse errors, ids, link targets and text of one page.
struct Page {
    errors: Vec<String>,
    ids: Vec<String>,
    links: Vec<String>,
    text: String,
}

fn parse(html: &str) -> Page {
    let opts = html5ever::ParseOpts {
        tokenizer: html5ever::tokenizer::TokenizerOpts { exact_errors: true, ..Default::default() },
        tree_builder: html5ever::tree_builder::TreeBuilderOpts { exact_errors: true, ..Default::default() },
    };
    let dom = html5ever::parse_document(RcDom::default(), opts).one(html);
    let mut page = Page {
        errors: dom.errors.borrow().iter().map(|e| e.to_string()).collect(),
        ids: Vec::new(),
        links: Vec::new(),
        text: String::new(),
    };
    walk(&dom.document, &mut page, false);
    page
}

fn walk(node: &Handle, page: &mut Page, in_code: bool) {
    let mut code = in_code;
    match &node.data {
        NodeData::Element { name, attrs, .. } => {
            let tag = name.local.as_ref();
            if matches!(tag, "code" | "style") {
                code = true;
            }
            for a in attrs.borrow().iter() {
                match a.name.local.as_ref() {
                    "id" => page.ids.push(a.value.to_string()),
                    "href" | "src" => page.links.push(a.value.to_string()),
                    _ => {}
                }
            }
        }
        NodeData::Text { contents } if !code => {
            page.text.push_str(&contents.borrow());
            page.text.push(' ');
        }
        _ => {}
    }
    for child in node.children.borrow().iter() {
        walk(child, page, code);
    }
}

/// Files the report links to that are written per run and kept out of golden/.
const PER_RUN: [&str; 1] = ["run.json"];

/// Prose in chapter 5's report that the chapter's own rework replaces
/// (its report belongs to that work); every other page must be clean.
const KNOWN_CHAPTER_5: [&str; 3] = ["domains.md", "algorithms.md", "Allowed by the issue"];

#[test]
fn pages_are_valid_html5_with_unique_ids_and_resolving_links() {
    let mut checked = 0;
    for path in golden_files("html") {
        let html = fs::read_to_string(&path).unwrap();
        let page = parse(&html);
        let name = path.strip_prefix(root()).unwrap().display().to_string();
        assert!(page.errors.is_empty(), "{name}: HTML parse errors: {:?}", page.errors);
        let mut seen = BTreeSet::new();
        for id in &page.ids {
            assert!(seen.insert(id), "{name}: id `{id}` appears twice");
        }
        let dir = path.parent().unwrap();
        for link in &page.links {
            if link.starts_with("http://") || link.starts_with("https://") {
                continue;
            }
            let (file, anchor) = link.split_once('#').unwrap_or((link, ""));
            let target = if file.is_empty() { path.clone() } else { dir.join(file) };
            if PER_RUN.iter().any(|p| file.ends_with(p)) {
                continue;
            }
            assert!(target.is_file(), "{name}: link `{link}` points to no file");
            if !anchor.is_empty() && target.extension().is_some_and(|e| e == "html") {
                let ids =
                    if file.is_empty() { page.ids.clone() } else { parse(&fs::read_to_string(&target).unwrap()).ids };
                assert!(ids.iter().any(|i| i == anchor), "{name}: link `{link}` names no id of its page");
            }
        }
        checked += 1;
    }
    assert_eq!(checked, 5, "the index and four chapter pages");
}

#[test]
fn prose_names_only_files_that_exist_and_no_process() {
    let mut repo_names = BTreeSet::new();
    let mut all = Vec::new();
    for dir in ["crates", "domains", "chapters", "xtask", "golden"] {
        files(&root().join(dir), &mut all);
    }
    for p in &all {
        repo_names.insert(p.file_name().unwrap().to_string_lossy().into_owned());
    }
    for f in ["README.md", "ARCHITECTURE.md", "Cargo.toml"] {
        repo_names.insert(f.into());
    }
    let process = ["the issue", "issue #", "TODO", "FIXME", "the lead", "helper", "the review"];
    for path in golden_files("html") {
        let page = parse(&fs::read_to_string(&path).unwrap());
        let name = path.strip_prefix(root()).unwrap().display().to_string();
        let chapter_5 = name.contains("ch5-");
        for word in page.text.split(|c: char| c.is_whitespace() || "(),;:\"'“”".contains(c)) {
            let word = word.trim_end_matches('.');
            let Some((stem, ext)) = word.rsplit_once('.') else { continue };
            if stem.is_empty() || !["md", "csv", "svg", "pdf", "rs", "toml", "json", "txt", "tex"].contains(&ext) {
                continue;
            }
            if chapter_5 && KNOWN_CHAPTER_5.contains(&word) {
                continue;
            }
            let file = word.rsplit('/').next().unwrap();
            assert!(
                repo_names.contains(file) || PER_RUN.contains(&file),
                "{name}: the text names `{word}`, which is in neither the report nor the repository"
            );
        }
        for phrase in process {
            let found = page.text.contains(phrase);
            let known = chapter_5 && KNOWN_CHAPTER_5.iter().any(|k| k.contains(phrase));
            assert!(!found || known, "{name}: process language `{phrase}` in the text");
        }
    }
}

#[test]
fn every_csv_reads_with_default_options() {
    let mut checked = 0;
    for path in golden_files("csv") {
        let name = path.strip_prefix(root()).unwrap().display().to_string();
        let bytes = fs::read(&path).unwrap();
        assert!(!bytes.starts_with(b"#"), "{name}: starts with a comment line");
        // The csv crate's defaults are pandas' and R's: comma, double quotes, a header row.
        let mut r = csv::Reader::from_reader(bytes.as_slice());
        let header = r.headers().unwrap().clone();
        assert!(header.iter().all(|h| !h.is_empty() && h.trim() == h), "{name}: header {header:?}");
        let mut rows = 0;
        for record in r.records() {
            let record = record.unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(record.len(), header.len(), "{name}: row {rows}");
            for field in record.iter() {
                let lower = field.to_ascii_lowercase();
                assert!(!["nan", "-nan"].contains(&lower.as_str()), "{name}: a NaN field (write it empty)");
            }
            rows += 1;
        }
        assert!(rows > 0, "{name}: no rows");
        checked += 1;
    }
    assert!(checked >= 60, "{checked} CSV files");
}

#[test]
fn the_maze_demonstrations_round_trip_through_our_reader() {
    use ch6_irl_shaping::DemonstrationSource;
    use ch6_irl_shaping::maze::experiment::demonstrations;
    let shipped = root().join("golden/ch6-irl-shaping/maze_demonstrations.csv");
    // The shipped file is the default layout's (the report ships no other).
    let layout = ch6_irl_shaping::maze::layout::LayoutId::default();
    let read = demonstrations(20160501, &DemonstrationSource::File(shipped), layout).unwrap_or_else(|e| panic!("{e}"));
    let made = demonstrations(20160501, &DemonstrationSource::Synthetic, layout).unwrap();
    assert_eq!(read.set, made.set, "the shipped demonstrations are the ones the run made, bit for bit");
}

/// Every committed report says which analysis plan decided it, and that is
/// the committed plan: the index and every chapter page of `golden/` and
/// `reports/` name it, and a page naming another digest fails (its verdicts
/// were decided under a plan that is not the committed one).
#[test]
fn committed_reports_were_decided_by_the_committed_plan() {
    let current = rlfd_report::plan::analysis_plan().line();
    let digest = rlfd_report::plan::analysis_plan().digest.clone();
    for tree in ["golden", "reports"] {
        let mut pages = Vec::new();
        files(&root().join(tree), &mut pages);
        pages.retain(|p| p.extension().is_some_and(|e| e == "html" || e == "json" || e == "tex"));
        assert!(!pages.is_empty(), "{tree}/ has pages");
        for page in pages {
            let text = fs::read_to_string(&page).unwrap();
            for named in text.split("(sha256 ").skip(1) {
                let named: String = named.chars().take_while(char::is_ascii_hexdigit).collect();
                assert_eq!(named, digest, "{} was decided by another plan than `{current}`", page.display());
            }
            if page.file_name().is_some_and(|n| n == "index.html") {
                assert!(text.contains(&current), "{} does not name `{current}`", page.display());
            }
        }
    }
}
