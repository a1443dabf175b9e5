//! The one font of every figure: DejaVu Sans, shipped by the `dejavu` crate.
//! Figures name it first in their font stack ([`FONT_STACK`]), text is
//! measured with its advance widths ([`text_width`]) so legends and labels
//! are laid out for the face that draws them, and the PDF versions embed it
//! ([`svg_to_pdf`]), so no system font is looked up and the bytes are the
//! same on every machine.

use std::sync::{Arc, OnceLock};

use svg2pdf::usvg;

use crate::{Error, Result};

/// The `font-family` of every text element: DejaVu Sans where it is
/// installed (and always in the PDF), then faces of similar width.
pub const FONT_STACK: &str = "DejaVu Sans, Verdana, Bitstream Vera Sans, sans-serif";

/// DejaVu Sans Regular, as TrueType bytes.
pub(crate) fn font_bytes() -> &'static [u8] {
    dejavu::sans::regular()
}

/// The parsed font and its units per em.
struct Metrics {
    units_per_em: f64,
    face: ttf_parser::Face<'static>,
}

fn metrics() -> &'static Metrics {
    static METRICS: OnceLock<Metrics> = OnceLock::new();
    METRICS.get_or_init(|| {
        let face = ttf_parser::Face::parse(font_bytes(), 0).expect("the dejavu crate ships a valid TrueType font");
        Metrics { units_per_em: f64::from(face.units_per_em()), face }
    })
}

/// The width in pixels of `text` set in DejaVu Sans at `px` pixels, rounded
/// up (kerning ignored, as SVG viewers mostly do at these sizes); a
/// character the font lacks counts as one em.
pub fn text_width(text: &str, px: i32) -> i32 {
    let m = metrics();
    let units: f64 = text
        .chars()
        .map(|c| m.face.glyph_index(c).and_then(|g| m.face.glyph_hor_advance(g)).map_or(m.units_per_em, f64::from))
        .sum();
    (units * f64::from(px) / m.units_per_em).ceil() as i32
}

/// The usvg options every conversion uses: only DejaVu Sans in the font
/// database, standing in for every generic family.
fn options() -> &'static usvg::Options<'static> {
    static OPTIONS: OnceLock<usvg::Options<'static>> = OnceLock::new();
    OPTIONS.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(font_bytes().to_vec());
        for set in [
            usvg::fontdb::Database::set_sans_serif_family,
            usvg::fontdb::Database::set_serif_family,
            usvg::fontdb::Database::set_monospace_family,
        ] {
            set(&mut db, "DejaVu Sans");
        }
        usvg::Options { font_family: "DejaVu Sans".into(), fontdb: Arc::new(db), ..usvg::Options::default() }
    })
}

/// An SVG figure as a one-page PDF of the figure's size (1 px = 0.75 pt, so
/// a 720 px wide figure is 540 pt, 19 cm), its text embedded as text in a
/// subset of DejaVu Sans. Deterministic: the same SVG gives the same bytes.
pub fn svg_to_pdf(svg: &str, figure: &str) -> Result<Vec<u8>> {
    let bad = |reason: String| Error::Figure { figure: figure.to_owned(), reason };
    let tree = usvg::Tree::from_str(svg, options()).map_err(|e| bad(format!("the SVG does not parse: {e}")))?;
    let page = svg2pdf::PageOptions { dpi: 96.0 };
    let pdf = svg2pdf::to_pdf(&tree, svg2pdf::ConversionOptions::default(), page)
        .map_err(|e| bad(format!("PDF conversion failed: {e}")))?;
    Ok(canonical_resources(pdf))
}

/// svg2pdf writes each resource dictionary's entries in a hash map's order,
/// which differs from process to process. This puts them in byte order: the
/// entries are whole lines of one dictionary, so sorting them keeps every
/// object's length and offset (the cross-reference table stays right), and
/// the same SVG gives the same bytes in every run.
fn canonical_resources(pdf: Vec<u8>) -> Vec<u8> {
    const KINDS: [&[u8]; 6] =
        [b"/XObject <<", b"/ExtGState <<", b"/Font <<", b"/ColorSpace <<", b"/Pattern <<", b"/Shading <<"];
    // Line spans [start, end) without the newline.
    let mut lines = Vec::new();
    let mut start = 0;
    for (i, &b) in pdf.iter().enumerate() {
        if b == b'\n' {
            lines.push((start, i));
            start = i + 1;
        }
    }
    lines.push((start, pdf.len()));
    let mut out = pdf.clone();
    let mut in_stream = false;
    let mut k = 0;
    while k < lines.len() {
        let line = &pdf[lines[k].0..lines[k].1];
        if in_stream {
            in_stream = !line.starts_with(b"endstream");
            k += 1;
            continue;
        }
        if line == b"stream" {
            in_stream = true;
            k += 1;
            continue;
        }
        let trimmed = line.trim_ascii_start();
        if KINDS.contains(&trimmed) {
            let indent = line.len() - trimmed.len();
            let close: Vec<u8> = [&vec![b' '; indent][..], b">>"].concat();
            let first = k + 1;
            let mut last = first;
            while last < lines.len() && pdf[lines[last].0..lines[last].1] != close[..] {
                last += 1;
            }
            let mut entries: Vec<&[u8]> = lines[first..last].iter().map(|&(a, b)| &pdf[a..b]).collect();
            if last < lines.len() && entries.iter().all(|e| !e.ends_with(b"<<")) {
                entries.sort();
                let mut at = lines[first].0;
                for e in entries {
                    out[at..at + e.len()].copy_from_slice(e);
                    out[at + e.len()] = b'\n';
                    at += e.len() + 1;
                }
            }
            k = last;
            continue;
        }
        k += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widths_follow_the_font() {
        // DejaVu Sans: "i" is narrow, "W" wide; 12 px text.
        assert!(text_width("iiii", 12) < text_width("WWWW", 12));
        assert_eq!(text_width("", 12), 0);
        // "M" is 1,767 of 2,048 units wide in DejaVu Sans: 10.35 px at 12 px.
        assert_eq!(text_width("M", 12), 11);
        assert_eq!(text_width("MMMMMMMMMM", 12), 104);
    }

    #[test]
    fn a_figure_converts_deterministically_with_its_text() {
        let svg = format!(
            "<svg width=\"200\" height=\"100\" viewBox=\"0 0 200 100\" xmlns=\"http://www.w3.org/2000/svg\">\n\
             <rect x=\"10\" y=\"10\" width=\"50\" height=\"30\" fill=\"#0072B2\"/>\n\
             <text x=\"20\" y=\"80\" font-family=\"{FONT_STACK}\" font-size=\"12\">Reward −1,234 ×10⁴</text>\n</svg>\n"
        );
        let a = svg_to_pdf(&svg, "t").unwrap();
        assert_eq!(a, svg_to_pdf(&svg, "t").unwrap());
        assert!(a.starts_with(b"%PDF-"));
        let text = String::from_utf8_lossy(&a);
        assert!(text.contains("DejaVuSans"), "the font is embedded");
        assert!(text.contains("/MediaBox [0 0 150 75]"), "200 x 100 px at 96 dpi");
        assert!(svg_to_pdf("<svg", "t").is_err());
        // Resource entries come out in byte order, lengths kept.
        let messy =
            b"x\n  /XObject <<\n    /xo2 12 0 R\n    /xo0 9 0 R\n  >>\nstream\n  /Font <<\n b\n a\n  >>\nendstream\n"
                .to_vec();
        let clean = canonical_resources(messy.clone());
        assert_eq!(clean.len(), messy.len());
        assert_eq!(
            String::from_utf8(clean).unwrap(),
            "x\n  /XObject <<\n    /xo0 9 0 R\n    /xo2 12 0 R\n  >>\nstream\n  /Font <<\n b\n a\n  >>\nendstream\n"
        );
    }
}
