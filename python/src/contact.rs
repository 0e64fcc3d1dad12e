//! Ellipsoid contact in bulk: the arrays arrive as the bytes of
//! contiguous float64 arrays (the Python half makes them with
//! `numpy.ascontiguousarray(..., dtype=float64).tobytes()`; the limited
//! API of abi3-py39 has no buffer protocol) and the answer leaves as the
//! bytes of an int8 array (0 separated, 1 touching, 2 overlapping).  The
//! engine runs with the GIL released, on `threads` threads.

use crate::guard;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use quadsect::contact::{self, Contact, Poses};
use quadsect::{Error, ErrorKind};

/// Native-endian doubles of a byte string whose length is a multiple of 8:
/// the bytes themselves when they are 8-aligned (CPython's bytes objects
/// are), a copy otherwise.
fn doubles<'a>(b: &'a [u8], what: &str) -> Result<std::borrow::Cow<'a, [f64]>, Error> {
    if !b.len().is_multiple_of(8) {
        return Err(Error::new(
            ErrorKind::Input,
            format!("{what}: {} bytes is not a whole number of doubles", b.len()),
        ));
    }
    // SAFETY: every bit pattern is a valid f64; align_to leaves unaligned
    // ends apart, and then the bytes are copied instead
    let (pre, mid, post) = unsafe { b.align_to::<f64>() };
    Ok(if pre.is_empty() && post.is_empty() {
        std::borrow::Cow::Borrowed(mid)
    } else {
        std::borrow::Cow::Owned(
            b.chunks_exact(8)
                .map(|c| f64::from_ne_bytes(c.try_into().unwrap()))
                .collect(),
        )
    })
}

/// ellipsoid_contact_bytes(ca, ra, ma, cb, rb, mb, threads) -> bytes
///
/// The codes of n pairs from the float64 bytes of arrays of shapes (n, 3),
/// (n, 3), (n, 3, 3) for each side.
#[pyfunction]
#[pyo3(signature = (ca, ra, ma, cb, rb, mb, threads = 0))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn ellipsoid_contact_bytes<'py>(
    py: Python<'py>,
    ca: &[u8],
    ra: &[u8],
    ma: &[u8],
    cb: &[u8],
    rb: &[u8],
    mb: &[u8],
    threads: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let codes = guard::run(py, || {
        let (ca, ra, ma) = (doubles(ca, "ca")?, doubles(ra, "ra")?, doubles(ma, "Ra")?);
        let (cb, rb, mb) = (doubles(cb, "cb")?, doubles(rb, "rb")?, doubles(mb, "Rb")?);
        let n = ca.len() / 3;
        let mut out = vec![Contact::Separated; n];
        contact::contact_many(
            Poses {
                center: &ca,
                semi_axes: &ra,
                matrix: &ma,
            },
            Poses {
                center: &cb,
                semi_axes: &rb,
                matrix: &mb,
            },
            &mut out,
            threads,
        )?;
        Ok(out.into_iter().map(|c| c as u8).collect::<Vec<u8>>())
    })?;
    Ok(PyBytes::new(py, &codes))
}
