//! JSON written straight into bytes, without a `serde_json::Value` tree.
//!
//! The batch output of a natural pair with components spent about a third
//! of its time building, serializing and freeing `Value`s (an allocation per
//! key, an index map per object).  The answers that matter for throughput
//! are written here directly; scalars (strings, doubles) go through
//! `serde_json`'s own serializer, so the bytes are those `Value` would
//! print (the same escaping, the same shortest round-trip doubles, `null`
//! for a non-finite double).  A `Value`, where the library returns one, is
//! parsed back from these bytes (`serde_json` with `float_roundtrip`, so
//! each double is the one written).

use serde_json::Value;

/// Something that writes itself as one JSON value.
pub(crate) trait Json {
    fn write(&self, out: &mut Vec<u8>);
}

/// A JSON value written by a closure (a nested object or array).
pub(crate) struct W<F: Fn(&mut Vec<u8>)>(pub F);

impl<F: Fn(&mut Vec<u8>)> Json for W<F> {
    fn write(&self, out: &mut Vec<u8>) {
        (self.0)(out)
    }
}

impl<T: Json + ?Sized> Json for &T {
    fn write(&self, out: &mut Vec<u8>) {
        (**self).write(out)
    }
}

impl<T: Json> Json for Option<T> {
    fn write(&self, out: &mut Vec<u8>) {
        match self {
            Some(x) => x.write(out),
            None => out.extend_from_slice(b"null"),
        }
    }
}

/// `[a,b,…]` of the items.
fn write_seq<T: Json>(items: impl Iterator<Item = T>, out: &mut Vec<u8>) {
    out.push(b'[');
    for (i, x) in items.enumerate() {
        if i > 0 {
            out.push(b',');
        }
        x.write(out);
    }
    out.push(b']');
}

impl<T: Json> Json for [T] {
    fn write(&self, out: &mut Vec<u8>) {
        write_seq(self.iter(), out)
    }
}

impl<T: Json> Json for Vec<T> {
    fn write(&self, out: &mut Vec<u8>) {
        self.as_slice().write(out)
    }
}

impl<T: Json, const N: usize> Json for [T; N] {
    fn write(&self, out: &mut Vec<u8>) {
        self.as_slice().write(out)
    }
}

impl<A: Json, B: Json> Json for (A, B) {
    fn write(&self, out: &mut Vec<u8>) {
        out.push(b'[');
        self.0.write(out);
        out.push(b',');
        self.1.write(out);
        out.push(b']');
    }
}

impl Json for () {
    fn write(&self, out: &mut Vec<u8>) {
        out.extend_from_slice(b"null")
    }
}

/// Through `serde_json`'s serializer: its escaping and number formats.
macro_rules! json_via_serde {
    ($($t:ty),*) => {$(
        impl Json for $t {
            fn write(&self, out: &mut Vec<u8>) {
                serde_json::to_writer(&mut *out, self).expect("writing JSON into memory")
            }
        }
    )*};
}

json_via_serde!(str, String, f64, bool, usize, u32, i32);

/// An array of the items an iterator yields (it is cloned to be walked).
pub(crate) fn arr<I>(items: I) -> W<impl Fn(&mut Vec<u8>)>
where
    I: Iterator + Clone,
    I::Item: Json,
{
    W(move |out: &mut Vec<u8>| write_seq(items.clone(), out))
}

/// An object written field by field (when the fields are not one fixed
/// list: shared runs of fields, optional ones): `{` at [`Obj::new`], `}`
/// at [`Obj::end`].
pub(crate) struct Obj<'a> {
    out: &'a mut Vec<u8>,
    first: bool,
}

impl<'a> Obj<'a> {
    pub(crate) fn new(out: &'a mut Vec<u8>) -> Obj<'a> {
        out.push(b'{');
        Obj { out, first: true }
    }

    /// `"key":value` (the key is not escaped: a literal).
    pub(crate) fn field(&mut self, key: &str, value: impl Json) -> &mut Self {
        if !self.first {
            self.out.push(b',');
        }
        self.first = false;
        self.out.push(b'"');
        self.out.extend_from_slice(key.as_bytes());
        self.out.extend_from_slice(b"\":");
        value.write(self.out);
        self
    }

    pub(crate) fn end(self) {
        self.out.push(b'}');
    }
}

/// Writes a JSON object `{"key": value, …}` into `out`, in the order given;
/// each value is anything [`Json`].  Keys are literals (not escaped).
macro_rules! wobj {
    ($out:expr; $($k:literal => $v:expr),* $(,)?) => {{
        let mut _o = $crate::report::json::write::Obj::new($out);
        $(
            _o.field($k, &$v);
        )*
        _o.end();
    }};
}

/// An object value (for a field of another object): `obj_w!{"k" => v, …}`.
macro_rules! obj_w {
    ($($k:literal => $v:expr),* $(,)?) => {
        $crate::report::json::write::W(|o: &mut Vec<u8>| wobj!(o; $($k => $v),*))
    };
}

pub(crate) use {obj_w, wobj};

/// The bytes as a `String` (everything written is UTF-8).
pub(crate) fn into_string(out: Vec<u8>) -> String {
    String::from_utf8(out).expect("JSON written from UTF-8 strings")
}

/// The `Value` of written JSON (the library's `…_json` functions).
pub(crate) fn to_value(out: &[u8]) -> Value {
    serde_json::from_slice(out).expect("JSON written by quadsect parses")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_what_value_prints() {
        let mut out = Vec::new();
        let xs = [1.5f64, -0.0, 1e300, f64::INFINITY, 0.1 + 0.2];
        let notes = ["a \"quoted\" note\n", "ü ∞"];
        wobj!(&mut out;
            "n" => 3usize,
            "s" => "x\\y",
            "xs" => xs,
            "none" => None::<f64>,
            "nested" => obj_w! {"b" => true, "notes" => arr(notes.iter())},
            "pair" => (1i32, "two"),
        );
        let v = serde_json::json!({
            "n": 3, "s": "x\\y", "xs": xs.to_vec(), "none": null,
            "nested": {"b": true, "notes": notes.to_vec()},
            "pair": [1, "two"],
        });
        assert_eq!(into_string(out.clone()), v.to_string());
        assert_eq!(to_value(&out), v);
        // doubles parse back to the very double written
        let y = to_value(&out)["xs"][4].as_f64().unwrap();
        assert_eq!(y.to_bits(), (0.1f64 + 0.2).to_bits());
    }
}
