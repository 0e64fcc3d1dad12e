//! Ellipsoid–ellipsoid contact from C: one pair, or arrays of pairs, given
//! as `qs_ellipsoid_f64` (the ellipsoid `Σᵢ ((Rᵀ(p − center))ᵢ /
//! semi_axes[i])² ≤ 1`, every double exact).  The answer is exact.

use crate::boundary::{answer_into, check_out, guard, input_error, qs_error, read_ref};
use crate::typed::qs_ellipsoid_f64;
use engine::Error;
use engine::contact::{self, Contact, Pose};
use std::ffi::c_int;

/// The contact of two solid ellipsoids (`QS_CONTACT_…`).
pub type qs_contact = i32;
/// No common point.
pub const QS_CONTACT_SEPARATED: qs_contact = 0;
/// Exactly one common point, interiors disjoint.
pub const QS_CONTACT_TOUCHING: qs_contact = 1;
/// A common interior point.
pub const QS_CONTACT_OVERLAPPING: qs_contact = 2;

fn pose(e: &qs_ellipsoid_f64, name: &str) -> Result<Pose, Error> {
    Pose::new(e.center, e.semi_axes, e.rotation).map_err(|x| x.context(name))
}

/// Whether two solid ellipsoids given in doubles are separated, touching
/// or overlapping, exactly (a floating-point filter, exact arithmetic when
/// it cannot decide).  Writes `*out` and returns 0; 2 for bad input (NaN,
/// infinity, a semi-axis ≤ 0, a singular matrix: `*out` is then
/// `QS_CONTACT_SEPARATED` and `*err` says why), 1 internal.
///
/// # Safety
/// `a`, `b` are NULL or valid; `out` is NULL or writable; `err` is NULL or
/// points to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_ellipsoid_contact_f64(
    a: *const qs_ellipsoid_f64,
    b: *const qs_ellipsoid_f64,
    out: *mut qs_contact,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        answer_into(out, "out", QS_CONTACT_SEPARATED, err, || {
            let (pa, pb) = (
                pose(read_ref(a, "a")?, "in a")?,
                pose(read_ref(b, "b")?, "in b")?,
            );
            Ok((contact::contact(&pa, &pb)? as qs_contact, None))
        })
    }
}

/// The contact of `n` pairs `(a[i], b[i])` into `out[i]` (`QS_CONTACT_…`
/// codes as bytes), on `threads` threads (0: all cores).  Returns 0; 2 when
/// a pair is bad (`*err` names its index; the answers of the other pairs
/// are then unspecified), 1 internal.
///
/// # Safety
/// `a`, `b` point to `n` readable `qs_ellipsoid_f64` (or are NULL with
/// `n = 0`); `out` points to `n` writable bytes; `err` as above.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn qs_ellipsoid_contact_f64_array(
    n: usize,
    a: *const qs_ellipsoid_f64,
    b: *const qs_ellipsoid_f64,
    out: *mut i8,
    threads: usize,
    err: *mut *mut qs_error,
) -> c_int {
    // SAFETY: the caller's contract
    unsafe {
        guard(err, || {
            if n == 0 {
                return Ok(());
            }
            check_out(out, "out")?;
            if a.is_null() || b.is_null() {
                return Err(input_error("a and b must not be NULL when n > 0"));
            }
            let (sa, sb) = (
                std::slice::from_raw_parts(a, n),
                std::slice::from_raw_parts(b, n),
            );
            let flat = |s: &[qs_ellipsoid_f64]| {
                let c: Vec<f64> = s.iter().flat_map(|e| e.center).collect();
                let r: Vec<f64> = s.iter().flat_map(|e| e.semi_axes).collect();
                let m: Vec<f64> = s.iter().flat_map(|e| e.rotation.concat()).collect();
                (c, r, m)
            };
            let ((ca, ra, ma), (cb, rb, mb)) = (flat(sa), flat(sb));
            let mut codes = vec![Contact::Separated; n];
            contact::contact_many(
                contact::Poses {
                    center: &ca,
                    semi_axes: &ra,
                    matrix: &ma,
                },
                contact::Poses {
                    center: &cb,
                    semi_axes: &rb,
                    matrix: &mb,
                },
                &mut codes,
                threads,
            )?;
            let o = std::slice::from_raw_parts_mut(out, n);
            for (x, c) in o.iter_mut().zip(codes) {
                *x = c as i8;
            }
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(x: f64) -> qs_ellipsoid_f64 {
        qs_ellipsoid_f64 {
            center: [x, 0.0, 0.0],
            semi_axes: [1.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        }
    }

    #[test]
    fn one_pair_and_arrays() {
        let mut out: qs_contact = -1;
        let code = unsafe {
            qs_ellipsoid_contact_f64(&sphere(0.0), &sphere(2.0), &mut out, std::ptr::null_mut())
        };
        assert_eq!((code, out), (0, QS_CONTACT_TOUCHING));
        let a = [sphere(0.0), sphere(0.0), sphere(0.0)];
        let b = [sphere(3.0), sphere(2.0), sphere(1.0)];
        let mut o = [9i8; 3];
        let code = unsafe {
            qs_ellipsoid_contact_f64_array(
                3,
                a.as_ptr(),
                b.as_ptr(),
                o.as_mut_ptr(),
                2,
                std::ptr::null_mut(),
            )
        };
        assert_eq!((code, o), (0, [0, 1, 2]));
        let mut bad = sphere(0.0);
        bad.semi_axes[1] = f64::NAN;
        let mut e: *mut qs_error = std::ptr::null_mut();
        let code = unsafe { qs_ellipsoid_contact_f64(&bad, &sphere(2.0), &mut out, &mut e) };
        assert_eq!(code, 2);
        assert!(crate::boundary::tests::take_message(e).contains("semi-axis 1"));
    }
}
