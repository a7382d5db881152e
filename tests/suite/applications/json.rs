//! JSON values for this crate's snapshots, printed the way `insta::assert_json_snapshot!`
//! prints them (two-space indentation, one item a line), with the keys of an object in the
//! order they are written.
//!
//! Not `serde_json::json!`: the library's dev-dependency `serde_json` is built without the
//! feature `preserve_order`, and its objects would sort their keys (and so change the
//! snapshots) unless another package of the build turns the feature on.

use std::fmt::Write;

/// A JSON value made of strings, arrays and objects (all this crate's snapshots need).
pub enum Json {
    String(String),
    Array(Vec<Json>),
    Object(Vec<(&'static str, Json)>),
}

impl Json {
    /// The string of `x`'s `Display`.
    pub fn string(x: impl std::fmt::Display) -> Json {
        Json::String(x.to_string())
    }

    /// An array of the strings of `items`.
    pub fn strings<T: std::fmt::Display>(items: &[T]) -> Json {
        Json::array(items.iter().map(Json::string))
    }

    pub fn array(items: impl IntoIterator<Item = Json>) -> Json {
        Json::Array(items.into_iter().collect())
    }

    /// An object with `fields` in this order.
    pub fn object<const N: usize>(fields: [(&'static str, Json); N]) -> Json {
        Json::Object(fields.into())
    }

    /// The value as insta prints a JSON snapshot.
    pub fn pretty(&self) -> String {
        let mut out = String::new();
        self.write(&mut out, 0);
        out
    }

    fn write(&self, out: &mut String, depth: usize) {
        match self {
            Json::String(s) => write_string(out, s),
            Json::Array(items) => {
                write_container(out, depth, ('[', ']'), items, |out, item| {
                    item.write(out, depth + 1)
                });
            }
            Json::Object(fields) => {
                write_container(out, depth, ('{', '}'), fields, |out, (key, value)| {
                    write_string(out, key);
                    out.push_str(": ");
                    value.write(out, depth + 1);
                });
            }
        }
    }
}

fn write_container<I>(
    out: &mut String,
    depth: usize,
    (open, close): (char, char),
    items: &[I],
    mut write_item: impl FnMut(&mut String, &I),
) {
    out.push(open);
    for (k, item) in items.iter().enumerate() {
        out.push_str(if k == 0 { "\n" } else { ",\n" });
        out.push_str(&"  ".repeat(depth + 1));
        write_item(out, item);
    }
    if !items.is_empty() {
        out.push('\n');
        out.push_str(&"  ".repeat(depth));
    }
    out.push(close);
}

fn write_string(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            c if u32::from(c) < 0x20 => write!(out, "\\u{:04x}", u32::from(c)).unwrap(),
            c => out.push(c),
        }
    }
    out.push('"');
}
