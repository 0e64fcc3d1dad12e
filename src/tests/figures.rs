//! The pictures (issue 38): every figure of the papers' examples is
//! well-formed SVG and renders to a non-blank image; a figure for every
//! class of natural intersection and every tangent verdict, with what the
//! class needs drawn; the committed figures of `docs/figures/` are what
//! the code draws now (compared as rendered pixels, within a tolerance).

use crate::cli::examples;
use resvg::tiny_skia::Pixmap;
use std::collections::BTreeSet;
use std::path::Path;

/// The image of SVG text, and the share of its pixels that are not white.
fn render(svg: &str) -> (Pixmap, f64) {
    let png = crate::svg_to_png(svg).expect("renders");
    let pix = Pixmap::decode_png(&png).expect("a PNG");
    let inked = pix
        .pixels()
        .iter()
        .filter(|p| p.red() < 245 || p.green() < 245 || p.blue() < 245)
        .count();
    let share = inked as f64 / pix.pixels().len() as f64;
    (pix, share)
}

/// The share of pixels that differ by more than 64 in a channel.
fn pixel_difference(a: &Pixmap, b: &Pixmap) -> f64 {
    if (a.width(), a.height()) != (b.width(), b.height()) {
        return 1.0;
    }
    let differ = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(p, q)| {
            p.red().abs_diff(q.red()) > 64
                || p.green().abs_diff(q.green()) > 64
                || p.blue().abs_diff(q.blue()) > 64
        })
        .count();
    differ as f64 / a.pixels().len() as f64
}

/// A minimal well-formedness check independent of the renderer: tags
/// open and close in order, attribute values are quoted, no raw `&` or
/// `<` in text.
fn well_formed(svg: &str) -> Result<(), String> {
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let text = &rest[..i];
        if text.contains('>') {
            return Err(format!(
                "a raw '>' in text near {:?}",
                &text[..text.len().min(40)]
            ));
        }
        if let Some(j) = text.find('&')
            && !["&amp;", "&lt;", "&gt;", "&quot;"]
                .iter()
                .any(|e| text[j..].starts_with(e))
        {
            return Err(format!(
                "a raw '&' near {:?}",
                &text[j..text.len().min(j + 20)]
            ));
        }
        let end = rest[i..].find('>').ok_or("an unclosed tag")? + i;
        let tag = &rest[i + 1..end];
        if !tag.matches('"').count().is_multiple_of(2) {
            return Err(format!("unbalanced quotes in <{tag}>"));
        }
        if let Some(name) = tag.strip_prefix('/') {
            let open = stack.pop().ok_or(format!("</{name}> closes nothing"))?;
            if open != name.trim() {
                return Err(format!("<{open}> closed by </{name}>"));
            }
        } else if !tag.ends_with('/') {
            let name = tag.split_whitespace().next().ok_or("an empty tag")?;
            stack.push(name);
        }
        rest = &rest[end + 1..];
    }
    if stack.is_empty() {
        Ok(())
    } else {
        Err(format!("unclosed: {stack:?}"))
    }
}

#[test]
fn every_example_figure_is_well_formed_and_inked() {
    let results = examples::run_all();
    let figures = examples::figures(&results);
    // every example of both papers has one
    let papers = results
        .iter()
        .filter(|e| e.source.starts_with("paper"))
        .count();
    assert_eq!(figures.len(), papers);
    for (name, svg) in &figures {
        well_formed(svg).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (_, inked) = render(svg);
        assert!(inked > 0.03, "{name}: only {inked:.4} of the pixels drawn");
    }
}

#[test]
fn well_formedness_check_rejects_broken_markup() {
    assert!(well_formed("<svg><g></svg>").is_err());
    assert!(well_formed("<svg><text>a & b</text></svg>").is_err());
    assert!(well_formed("<svg><rect x=\"1/></svg>").is_err());
    assert!(well_formed("<svg><text>a &amp; b</text><g/></svg>").is_ok());
}

/// The stroke colours of a figure.
fn strokes(svg: &str) -> BTreeSet<String> {
    svg.split("stroke=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .map(str::to_string)
        .collect()
}

#[test]
fn a_figure_for_every_class_shows_its_components() {
    use crate::natural::result::Class;
    let cases = [
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,0 axis=2,0,0 radius2=1",
            Class::SameSurface,
            &[][..],
        ),
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,0 axis=0,1,0 radius2=1",
            Class::Conics,
            &["#c0392b"][..],
        ),
        (
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cone vertex=2,2,0 axis=0,1,0 tan2=1",
            Class::ConicAndLine,
            &["#c0392b", "#2e8b57"][..],
        ),
        (
            "cylinder point=0,0,0 axis=0,0,1 radius2=1",
            "cylinder point=1,0,0 axis=0,0,1 radius2=1",
            Class::Lines,
            &["#2e8b57"][..],
        ),
        (
            "sphere center=0,4,0 radius2=8",
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            Class::Points,
            &["#7b3fa0"][..],
        ),
        (
            "cylinder point=0,0,0 axis=1,0,0 radius2=1",
            "cylinder point=0,0,5 axis=0,1,0 radius2=1",
            Class::Empty,
            &[][..],
        ),
        (
            "cone vertex=0,0,0 axis=1,0,0 tan2=1",
            "cylinder point=0,0,0 axis=0,0,1 radius2=1",
            Class::Curve,
            &["#1f4e9e"][..],
        ),
    ];
    for (a, b, class, colours) in cases {
        let r = crate::natural::classify(&a.parse().unwrap(), &b.parse().unwrap()).unwrap();
        assert_eq!(r.class(), class, "{a} / {b}");
        let svg = r.svg();
        well_formed(&svg).unwrap();
        assert!(
            svg.contains(&format!("class {}", class.as_str())),
            "{a} / {b}"
        );
        // the axial plane exactly when the axes are not skew
        let skew = r.axes().is_some_and(|x| x.as_str() == "skew");
        assert_eq!(svg.contains("axial plane"), !skew, "{a} / {b}");
        let have = strokes(&svg);
        for c in colours {
            assert!(have.contains(*c), "{a} / {b}: no stroke {c}");
        }
        // a colour of a component the class does not have is absent
        for (c, kinds) in [
            ("#c0392b", "conic"),
            ("#2e8b57", "line"),
            ("#1f4e9e", "curve"),
        ] {
            if !colours.contains(&c) {
                let legend_only = svg.matches(&format!("stroke=\"{c}\"")).count();
                assert_eq!(legend_only, 1, "{a} / {b}: a {kinds} drawn");
            }
        }
    }
}

#[test]
fn a_figure_for_every_verdict() {
    let e = "x^2+y^2+z^2-25";
    for (s, verdict) in [
        ("(x-9)^2/9+y^2/4+z^2/16-1", "separated"),
        ("(x-6)^2/9+y^2/4+z^2/16-1", "intersecting"),
        ("x - 5", "touching"),
    ] {
        let r = crate::tangent::decide_str(e, s).unwrap();
        let svg = r.svg();
        well_formed(&svg).unwrap();
        assert!(svg.contains(&format!("verdict: {verdict}")), "{s}");
        // the witnesses of the certificate are drawn, and the places of
        // both extremes proven
        assert!(svg.contains("witness S"), "{s}");
        assert!(svg.contains("each proven by a Krawczyk box"), "{s}");
        // S = 0 on E is drawn exactly when they meet
        let zero_curve = svg.contains("stroke=\"#111111\" stroke-width=\"2.2\" stroke-linecap");
        assert_eq!(zero_curve, verdict == "intersecting", "{s}");
    }
    // an undecided answer still has a picture that says so
    let none = crate::Budget::unlimited().with_time_limit(Some(std::time::Duration::ZERO));
    let e: crate::Ellipsoid = e.parse().unwrap();
    let s: crate::Polynomial = "x^7 + y^5 - z^3 + x*y*z - 1".parse().unwrap();
    let r = crate::decide_with(&e, &s, &crate::TangentOptions::with_budget(none)).unwrap();
    let svg = r.svg();
    well_formed(&svg).unwrap();
    assert!(svg.contains("verdict: undecided"));
}

#[test]
fn committed_figures_are_what_the_code_draws() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures");
    let figures = examples::figures(&examples::run_all());
    let mut compared = 0;
    for entry in std::fs::read_dir(&dir).expect("docs/figures") {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("svg") {
            continue;
        }
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let committed = std::fs::read_to_string(&path).unwrap();
        let (_, now) = figures
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("{name}.svg is no example's figure"));
        if committed != *now {
            // the same picture up to rounding in the last printed digit
            let (a, _) = render(&committed);
            let (b, _) = render(now);
            let d = pixel_difference(&a, &b);
            assert!(
                d < 0.005,
                "{name}: {:.2}% of the pixels changed; regenerate with \
                 `quadsect examples --figures docs/figures` (README)",
                100.0 * d
            );
        }
        compared += 1;
    }
    assert!(compared >= 3, "docs/figures holds {compared} figures");
}
