//! How the library's errors and panics reach Python: every failure is a `blossom.Error`
//! (a `ValueError`) whose message is `PATH: MESSAGE` as the Rust error's `Display`, with the
//! Rust path renamed to the Python argument it came from (`p[2]` of `intersect_curves` is
//! `other.nodes[:, 2]` when `other` was the second curve), and whose attributes `path` and
//! `kind` carry the path and the `ErrorKind` name. A Rust panic (a broken internal invariant,
//! never expected) is caught before it unwinds into Python and raised the same way, with the
//! path `""` and the kind `"Panic"`.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};

pyo3::create_exception!(
    blossom,
    Error,
    PyValueError,
    "Bad input or a refused computation: the message names the argument and field \
     (`path`), `kind` is the library's error kind (`Shape`, `Degree`, `NotFinite`, \
     `TooLarge`, ...), or `Panic` for an internal error."
);

/// One renaming of a Rust path's leading name to the Python argument it came from. When
/// `points` is set, the Rust path indexes points (`p[3]`) and the Python argument is a `D x N`
/// array whose columns are the points, so `[3]` becomes `[:, 3]`.
#[derive(Clone, Copy)]
pub struct Rename {
    pub rust: &'static str,
    pub python: &'static str,
    pub points: bool,
}

/// The Python path of the Rust path `path` under `renames` (the first whose name leads it).
pub fn python_path(path: &str, renames: &[Rename]) -> String {
    for r in renames {
        let Some(rest) = path.strip_prefix(r.rust) else {
            continue;
        };
        if !(rest.is_empty() || rest.starts_with('[') || rest.starts_with('.')) {
            continue;
        }
        if r.points {
            if let Some(index_end) = rest.strip_prefix('[').and_then(|s| s.find(']')) {
                let index = &rest[1..=index_end];
                let after = &rest[index_end + 2..];
                return format!("{}[:, {index}]{after}", r.python);
            }
        }
        return format!("{}{rest}", r.python);
    }
    path.to_string()
}

/// A `blossom.Error` with `path`, `kind` and the message `path: message`.
pub fn error(path: &str, kind: &str, message: &str) -> PyErr {
    let text = if path.is_empty() {
        message.to_string()
    } else {
        format!("{path}: {message}")
    };
    Python::attach(|py| {
        let err = Error::new_err(text);
        let value = err.value(py);
        // Setting two attributes on a fresh exception instance cannot fail.
        let _ = value.setattr("path", path);
        let _ = value.setattr("kind", kind);
        err
    })
}

/// The library's error as a `blossom.Error`, its path renamed.
pub fn from_lib(e: &blossom::Error, renames: &[Rename]) -> PyErr {
    let path = python_path(e.path(), renames);
    error(&path, &format!("{:?}", e.kind()), &e.message)
}

/// A failure of a library call: its error, or a panic's message.
pub enum Failure {
    Lib(blossom::Error),
    Panic(String),
}

impl Failure {
    pub fn into_py(self, renames: &[Rename]) -> PyErr {
        match self {
            Failure::Lib(e) => from_lib(&e, renames),
            Failure::Panic(message) => error(
                "",
                "Panic",
                &format!("internal error (a Rust panic; please report it): {message}"),
            ),
        }
    }
}

/// Runs `f`, catching a panic: the body of every call into the library, so that a panic never
/// unwinds into Python. Needs no GIL, so it also runs inside `Python::detach`.
pub fn catching<T>(f: impl FnOnce() -> Result<T, blossom::Error>) -> Result<T, Failure> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(x)) => Ok(x),
        Ok(Err(e)) => Err(Failure::Lib(e)),
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_string());
            Err(Failure::Panic(message))
        }
    }
}

/// [`catching`] with the GIL held, its failure raised with `renames`.
pub fn call<T>(renames: &[Rename], f: impl FnOnce() -> Result<T, blossom::Error>) -> PyResult<T> {
    catching(f).map_err(|e| e.into_py(renames))
}

/// [`catching`] with the GIL released while `f` runs (long or batch work).
pub fn call_detached<T: Send>(
    py: Python<'_>,
    renames: &[Rename],
    f: impl FnOnce() -> Result<T, blossom::Error> + Send,
) -> PyResult<T> {
    py.detach(|| catching(f)).map_err(|e| e.into_py(renames))
}

/// A `blossom.Error` of kind `kind` on the Python argument `path` (bad input found by the
/// binding itself, before the library is called).
pub fn bad(path: impl AsRef<str>, kind: &str, message: impl AsRef<str>) -> PyErr {
    error(path.as_ref(), kind, message.as_ref())
}

/// The edit distance between two names (insertions, deletions, substitutions of characters).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The name of `names` that `name` most likely misspells, ignoring case ("NonZero" is
/// "nonzero"): the one name it begins ("taylor" for "taylor-shift"), else the name fewest
/// edits away relative to the longer length, when that is at most about half of it.
pub fn nearest_name<'a>(name: &str, names: &[&'a str]) -> Option<&'a str> {
    let lower = name.to_lowercase();
    let prefixed: Vec<&str> = names
        .iter()
        .filter(|n| !lower.is_empty() && n.to_lowercase().starts_with(&lower))
        .copied()
        .collect();
    if let [one] = prefixed.as_slice() {
        return Some(one);
    }
    names
        .iter()
        .map(|n| {
            let longer = n.chars().count().max(name.chars().count()).max(1);
            (edit_distance(&lower, &n.to_lowercase()), longer, *n)
        })
        .filter(|(d, longer, _)| *d <= longer / 2 + 1)
        .min_by(|a, b| (a.0 * b.1).cmp(&(b.0 * a.1)))
        .map(|(_, _, n)| n)
}

/// The value named `name` among `accepted` (name, value) pairs, the argument `path`; an
/// unknown name raises `blossom.Error` (kind `UnknownName`) listing the accepted names and
/// offering the nearest one (`expected "nonzero" or "evenodd", found "odd" (did you mean
/// "evenodd"?)`).
pub fn name_arg<T: Copy>(path: &str, name: &str, accepted: &[(&str, T)]) -> PyResult<T> {
    if let Some((_, value)) = accepted.iter().find(|(n, _)| *n == name) {
        return Ok(*value);
    }
    let quoted: Vec<String> = accepted.iter().map(|(n, _)| format!("{n:?}")).collect();
    let list = match quoted.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
    };
    let names: Vec<&str> = accepted.iter().map(|(n, _)| *n).collect();
    let hint = nearest_name(name, &names)
        .map(|n| format!(" (did you mean {n:?}?)"))
        .unwrap_or_default();
    Err(bad(
        path,
        "UnknownName",
        format!("expected {list}, found {name:?}{hint}"),
    ))
}
