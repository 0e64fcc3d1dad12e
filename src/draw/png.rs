//! PNG from the pictures' SVG text (feature `png`): resvg and tiny-skia,
//! pure Rust; labels in the system's fonts (a machine without fonts gets
//! the strokes without the text).

use crate::error::{Error, ErrorKind};
use resvg::usvg::{self, fontdb};
use std::sync::{Arc, OnceLock};

/// The system's fonts, loaded once per process.
fn fonts() -> Arc<fontdb::Database> {
    static FONTS: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = fontdb::Database::new();
            db.load_system_fonts();
            Arc::new(db)
        })
        .clone()
}

/// Renders SVG text (as [`NaturalReport::svg`](crate::NaturalReport::svg)
/// and [`TangentReport::svg`](crate::TangentReport::svg) make it) to the
/// bytes of a PNG image at its own size (feature `png`).
///
/// ```
/// let r = quadsect::tangent::decide_str("x^2+y^2+z^2-25", "(x-6)^2/9+y^2/4+z^2/16-1").unwrap();
/// let png = quadsect::svg_to_png(&r.svg()).unwrap();
/// assert_eq!(&png[1..4], b"PNG");
/// ```
///
/// # Errors
/// `input` when the text is not SVG.
pub fn svg_to_png(svg: &str) -> Result<Vec<u8>, Error> {
    let options = usvg::Options {
        fontdb: fonts(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|e| Error::new(ErrorKind::Input, format!("not SVG: {e}")))?;
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| Error::new(ErrorKind::Input, "an empty picture"))?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| Error::internal(format!("PNG encoding: {e}")))
}
