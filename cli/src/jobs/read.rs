//! Reading a job with serde: the objects of a job (the job itself, a region, a triangle, a
//! `bezier-triangle` entry, a `bspline` piece) derive `Deserialize`, and [`read_job`] runs them
//! over the parsed document through [`Reader`], a thin `Deserializer` over `serde_json::Value`
//! that knows the path of every field; everything else (numbers, points, grids, lists, degrees
//! and names: the leaves) is read from its JSON value by plain functions ([`leaf`], [`items`]),
//! so that each error names its field (`coefficients[2]: expected 3 coordinates, found 2`,
//! `regions[1].loops[0][2][1][0]: ...`).
//!
//! The reader keeps the contract's order of checks: the fields of an object are checked for
//! unknown names before any value is read (the nearest accepted name in the message: `did you
//! mean "control_points"?`), then read in the order the type declares them, a missing one
//! refused when it is reached (`interval: missing field`); arrays element by element, their
//! count checked before their elements are read. [`number`] reads one number by the contract's
//! rules for the arithmetic `T` ([`Reading`]: integers and fractions and decimals as strings
//! exactly, JSON numbers with a fraction part only under `f64`), and the containers check
//! counts and dimensions as they go ([`Numbers`], [`Points`], [`Rows`]).

use crate::names::{listed, lookup, unknown_field};
use crate::number::{f64_from_json, json_type, rational_from_json, JsonNumber};
use blossom::{BoundedF64, Error, Rational};
use serde::de::{self, DeserializeOwned, DeserializeSeed, IntoDeserializer, Visitor};
use serde::{Deserialize, Deserializer};
use serde_json::{Map, Value};
use std::cell::Cell;
use std::fmt;
use std::marker::PhantomData;

/// Reads the job object `job` (its `"kind"` read already, and accepted among its fields) as a
/// `D`; errors at its top level name `input`.
pub fn read_job<D: DeserializeOwned>(job: &Map<String, Value>) -> Result<D, Error> {
    let reader = Reader {
        value: None,
        job: Some(job),
    };
    D::deserialize(reader).map_err(|ReadError(e)| match e.field.is_empty() {
        true => Error::of(e.kind, "input", e.message),
        false => e,
    })
}

/// Reads an object of a job (a region, an entry) from `value` on its own: its errors name
/// fields relative to it.
pub fn object<D: DeserializeOwned>(value: &Value) -> Result<D, Error> {
    let reader = Reader {
        value: Some(value),
        job: None,
    };
    D::deserialize(reader).map_err(|ReadError(e)| e)
}

/// The fields of the struct `D` reads (its serde field names, in order).
pub fn fields_of<D: DeserializeOwned>() -> &'static [&'static str] {
    /// A deserializer that only asks which fields a struct has.
    struct Fields<'c>(&'c Cell<&'static [&'static str]>);
    impl<'de> Deserializer<'de> for Fields<'_> {
        type Error = de::value::Error;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Self::Error> {
            Err(de::Error::custom("not a struct"))
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Self::Error> {
            self.0.set(fields);
            Err(de::Error::custom("only its fields"))
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes
            byte_buf option unit unit_struct newtype_struct seq tuple tuple_struct map enum
            identifier ignored_any
        }
    }
    let fields = Cell::new(&[][..]);
    let _ = D::deserialize(Fields(&fields));
    fields.get()
}

/// An error of reading: a library [`Error`] whose field is relative to the value being read;
/// the reader of each object above puts it under the field's name on the way out.
#[derive(Debug)]
pub struct ReadError(Error);

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl std::error::Error for ReadError {}

impl de::Error for ReadError {
    /// An error at the value being read, or below it with its relative field (marked by
    /// [`below`]).
    fn custom<M: fmt::Display>(message: M) -> Self {
        let text = message.to_string();
        let (field, message) = text
            .strip_prefix(RELATIVE)
            .and_then(|t| t.split_once(RELATIVE))
            .unwrap_or(("", &text));
        ReadError(Error::new(field, message))
    }
}

/// Marks the field of an error raised through serde's `Error::custom` below the value being
/// read ([`below`]).
const RELATIVE: &str = "\u{0}";

/// The library error `error`, whose field is relative to the value being read (a region's
/// `loops[0][2]`, a point's `[1]`), as the error of any deserializer.
pub fn below<E: de::Error>(error: &Error) -> E {
    E::custom(format!(
        "{RELATIVE}{}{RELATIVE}{}",
        error.field, error.message
    ))
}

/// `error` re-addressed under `path` (`[2]`, `regions`): a field named relative to a value
/// put under the value's own path (`regions` and `[1].loops[0]` make `regions[1].loops[0]`).
pub fn under(path: &str, error: Error) -> Error {
    let field = match (path, error.field.as_str()) {
        ("", name) => name.to_string(),
        (path, "") => path.to_string(),
        (path, name) if name.starts_with('[') => format!("{path}{name}"),
        (path, name) => format!("{path}.{name}"),
    };
    Error::of(error.kind, field, error.message)
}

/// The `Deserializer` of one value of a job: `value` `None` is a field that is absent (read as
/// `None` where optional, missing elsewhere), `job` the job object itself, whose `"kind"` is
/// read already. Objects are read by the types that derive `Deserialize`, their fields checked
/// first and then read in their declared order (`Fields`); every other value is handed whole
/// to the leaf that reads it (by serde_json's own deserializer: numbers keep their spelling,
/// `arbitrary_precision`).
pub struct Reader<'a> {
    value: Option<&'a Value>,
    job: Option<&'a Map<String, Value>>,
}

impl<'a> Reader<'a> {
    /// The object of this reader, its fields checked for unknown names, and its `fields` in
    /// their declared order (the work of `deserialize_struct` apart from the visitor, so that it
    /// is compiled once).
    fn fields(
        &self,
        fields: &'static [&'static str],
        expecting: &dyn fmt::Display,
    ) -> Result<Fields<'a>, ReadError> {
        let refusal = |field: &str, message: String| ReadError(Error::new(field, message));
        let map = match (self.job, self.value) {
            (Some(map), _) | (None, Some(Value::Object(map))) => map,
            (None, None) => return Err(refusal("", "missing field".into())),
            (None, Some(other)) => {
                let found = json_type(other);
                return Err(refusal("", format!("expected {expecting}, found {found}")));
            }
        };
        let top = self.job.map(|_| "kind");
        let accepted: Vec<&str> = top.into_iter().chain(fields.iter().copied()).collect();
        if let Some(name) = map.keys().find(|k| !accepted.contains(&k.as_str())) {
            return Err(refusal(name, unknown_field(name, &accepted)));
        }
        let entries: Vec<_> = fields.iter().map(|f| (*f, map.get(*f))).collect();
        Ok(Fields(entries.into_iter(), ("", None)))
    }
}

impl<'de> Deserializer<'de> for Reader<'de> {
    type Error = ReadError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        let Some(value) = self.value else {
            return Err(ReadError(Error::new("", "missing field")));
        };
        value.deserialize_any(visitor).map_err(de::Error::custom)
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        match self.value {
            None | Some(Value::Null) if self.job.is_none() => visitor.visit_none(),
            _ => visitor.visit_some(self),
        }
    }

    /// An object: its fields are checked for unknown names first, then read in the order of
    /// `fields`, an absent one read as absent.
    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, ReadError> {
        let fields = self.fields(fields, &Expecting(&visitor))?;
        visitor.visit_map(fields)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier ignored_any
    }
}

/// What a visitor expects, for messages.
struct Expecting<'v, V>(&'v V);

impl<'de, V: Visitor<'de>> fmt::Display for Expecting<'_, V> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.expecting(f)
    }
}

/// The fields of an object in their declared order (`None`: absent) and the current one, each
/// read's error put under the field's name.
struct Fields<'a>(
    std::vec::IntoIter<(&'static str, Option<&'a Value>)>,
    (&'static str, Option<&'a Value>),
);

impl<'de> de::MapAccess<'de> for Fields<'de> {
    type Error = ReadError;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, ReadError> {
        let Some(entry) = self.0.next() else {
            return Ok(None);
        };
        self.1 = entry;
        seed.deserialize(entry.0.into_deserializer()).map(Some)
    }

    fn next_value_seed<S: DeserializeSeed<'de>>(&mut self, seed: S) -> Result<S::Value, ReadError> {
        let (name, value) = self.1;
        let reader = Reader { value, job: None };
        seed.deserialize(reader)
            .map_err(|ReadError(e)| ReadError(under(name, e)))
    }
}

// ------------------------------------------------------------------------------------------
// Leaves: read from their JSON value by plain functions, their errors relative to the value.

/// Reads a leaf of a job from its JSON value by `read`, whose errors name fields relative to
/// the value (`[2][0]`); the reader puts them under the value's path.
pub fn leaf<'de, D: Deserializer<'de>, X>(
    d: D,
    read: impl FnOnce(&Value) -> Result<X, Error>,
) -> Result<X, D::Error> {
    read(&Value::deserialize(d)?).map_err(|e| below(&e))
}

/// The elements of the array `value`, each read by `item` under its index, after `count` has
/// accepted their number; `expected` says what `value` must be (`an array of points`).
pub fn items<X>(
    value: &Value,
    expected: &str,
    count: impl Fn(usize) -> Result<(), String>,
    item: impl Fn(&Value) -> Result<X, Error>,
) -> Result<Vec<X>, Error> {
    let items = array(value, expected, &count)?;
    let mut out = Vec::with_capacity(items.len());
    for (k, x) in items.iter().enumerate() {
        match item(x) {
            Ok(x) => out.push(x),
            Err(e) => return Err(under(&format!("[{k}]"), e)),
        }
    }
    Ok(out)
}

/// The elements of `value` once `count` has accepted their number, or the refusal (the work
/// of [`items`] apart from reading the elements, compiled once).
fn array<'v>(
    value: &'v Value,
    expected: &str,
    count: &dyn Fn(usize) -> Result<(), String>,
) -> Result<&'v [Value], Error> {
    let Value::Array(items) = value else {
        let message = format!("expected {expected}, found {}", json_type(value));
        return Err(Error::new("", message));
    };
    count(items.len()).map_err(|message| Error::new("", message))?;
    Ok(items)
}

/// A list of values that read themselves (objects of a job, points), any number of them.
#[derive(Clone, Debug)]
pub struct List<E>(pub Vec<E>);

impl<'de, E: DeserializeOwned> Deserialize<'de> for List<E> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| items(v, "a sequence", any, object)).map(List)
    }
}

/// Exactly two objects of a job (`curves`, `regions`, `triangles`).
#[derive(Clone, Debug)]
pub struct Two<S>(pub [S; 2]);

impl<'de, S: DeserializeOwned + Plural> Deserialize<'de> for Two<S> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let expected = format!("an array of two {}", S::PLURAL);
        let two = leaf(d, |v| items(v, &expected, exactly(2, S::PLURAL), object))?;
        Ok(Two(two.try_into().unwrap_or_else(|_| unreachable!())))
    }
}

/// The name of several objects, for messages.
pub trait Plural {
    /// `curves`, `regions`, `triangles`.
    const PLURAL: &'static str;
}

/// The count of exactly `n` elements (`expected 3 corners, found 2`).
pub fn exactly(n: usize, what: &'static str) -> impl Fn(usize) -> Result<(), String> {
    move |found| match found == n {
        true => Ok(()),
        false => Err(format!("expected {n} {what}, found {found}")),
    }
}

/// The count of at least one element (`expected at least one point, found none`).
pub fn not_empty(what: &'static str) -> impl Fn(usize) -> Result<(), String> {
    move |found| match found {
        0 => Err(format!("expected at least one {what}, found none")),
        _ => Ok(()),
    }
}

/// Any count.
pub fn any(_: usize) -> Result<(), String> {
    Ok(())
}

/// A number type a job is read into: the arithmetic's rules for one JSON value (the messages of
/// [`crate::number`]), and its exact value for the jobs that decide exactly.
pub trait Reading: Sized + Clone {
    /// Whether the numbers are read as written (`--arithmetic exact`).
    const EXACT: bool;

    /// Whether only the job's shape is read, not its numbers ([`Text`]).
    const SHAPE_ONLY: bool = false;

    /// Reads one number (a JSON number or string).
    fn read(value: &Value) -> Result<Self, String>;

    /// The exact value of the number read.
    fn exact(&self) -> Rational;
}

impl Reading for Rational {
    const EXACT: bool = true;

    fn read(value: &Value) -> Result<Self, String> {
        rational_from_json(value)
    }

    fn exact(&self) -> Rational {
        self.clone()
    }
}

impl Reading for BoundedF64 {
    const EXACT: bool = false;

    fn read(value: &Value) -> Result<Self, String> {
        <BoundedF64 as JsonNumber>::from_json(value)
    }

    fn exact(&self) -> Rational {
        Rational::from_float(self.value()).unwrap_or_default()
    }
}

/// A number of a job as written, not yet read (the first reading of `blossom restrict`, which
/// checks the job's shape before the budget): its JSON value.
#[derive(Clone, Debug)]
pub struct Text(pub Value);

impl Reading for Text {
    const EXACT: bool = true;
    const SHAPE_ONLY: bool = true;

    fn read(value: &Value) -> Result<Self, String> {
        match value {
            Value::Number(_) | Value::String(_) => Ok(Text(value.clone())),
            other => rational_from_json(other).map(|_| Text(Value::Null)),
        }
    }

    fn exact(&self) -> Rational {
        rational_from_json(&self.0).unwrap_or_default()
    }
}

/// A number of a job that decides exactly (`bspline`, the rational jobs): under exact
/// arithmetic as written; under `f64` read as a double first (so that the errors of `f64` input
/// are those of every other job), then taken as written (a JSON number `0.1` as 1/10), except
/// that a number whose double is zero is zero and one that exact reading refuses (an exponent
/// beyond its limit) is its double's exact value.
#[derive(Clone, Debug)]
pub struct Written<T>(pub Rational, PhantomData<T>, String);

impl<T> Written<T> {
    /// The number as written in the job (`0.1`, `1/3`), for messages.
    pub fn spelling(&self) -> &str {
        &self.2
    }
}

impl<T: Reading> Reading for Written<T> {
    const EXACT: bool = <T as Reading>::EXACT;

    fn read(value: &Value) -> Result<Self, String> {
        let exact = if T::SHAPE_ONLY {
            T::read(value)?;
            Rational::default()
        } else if <T as Reading>::EXACT {
            T::read(value)?.exact()
        } else {
            let double = f64_from_json(value)?;
            match rational_from_json(&Value::String(spelling(value))) {
                _ if double == 0.0 => Rational::default(),
                Ok(q) => q,
                Err(_) => Rational::from_float(double).unwrap_or_default(),
            }
        };
        Ok(Written(exact, PhantomData, spelling(value)))
    }

    fn exact(&self) -> Rational {
        self.0.clone()
    }
}

/// A number as written in the job (`0.1`, `"1/3"` as `1/3`), for messages.
pub fn spelling(value: &Value) -> String {
    match value {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// One number of a job, read by [`Reading`].
pub fn number<T: Reading>(value: &Value) -> Result<T, Error> {
    T::read(value).map_err(|message| Error::new("", message))
}

/// `N` numbers, called `what` in a refusal of their count.
pub fn numbers<T: Reading, const N: usize>(
    value: &Value,
    expected: &str,
    what: &'static str,
) -> Result<[T; N], Error> {
    let numbers = items(value, expected, exactly(N, what), number)?;
    Ok(numbers.try_into().unwrap_or_else(|_| unreachable!()))
}

/// Exactly `N` numbers (an interval, a rectangle).
#[derive(Clone, Debug)]
pub struct Numbers<T, const N: usize>(pub [T; N]);

impl<'de, T: Reading, const N: usize> Deserialize<'de> for Numbers<T, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| {
            numbers(v, &format!("an array of {N} numbers"), "numbers").map(Numbers)
        })
    }
}

/// The three corners of a triangle, each `D` numbers: points of the plane (`D` = 2) or
/// barycentric coordinates (`D` = 3).
#[derive(Clone, Debug)]
pub struct Corners<T, const D: usize>(pub [[T; D]; 3]);

impl<'de, T: Reading, const D: usize> Deserialize<'de> for Corners<T, D> {
    fn deserialize<D2: Deserializer<'de>>(d: D2) -> Result<Self, D2::Error> {
        let (what, expected) = match D {
            2 => ("coordinates", "a corner (an array of 2 numbers)"),
            _ => (
                "barycentric coordinates",
                "a corner (an array of 3 barycentric coordinates)",
            ),
        };
        let corner = |c: &Value| numbers(c, expected, what);
        leaf(d, |v| {
            let corners = items(v, "an array of 3 corners", exactly(3, "corners"), corner)?;
            Ok(Corners(
                corners.try_into().unwrap_or_else(|_| unreachable!()),
            ))
        })
    }
}

/// "1 coordinate", "3 coordinates".
pub fn coordinates(d: usize) -> String {
    format!("{d} coordinate{}", if d == 1 { "" } else { "s" })
}

/// A point of any dimension D >= 1.
pub fn point<T: Reading>(value: &Value) -> Result<blossom::Point<T>, Error> {
    let expected = "a point (an array of numbers)";
    items(value, expected, not_empty("coordinate"), number)
}

/// Refuses the first point (at `[k]` below the value read, `at(k)`) whose dimension is not
/// that of the first.
fn same_dimension<'a, T: 'a>(
    points: impl Iterator<Item = (String, &'a blossom::Point<T>)>,
) -> Result<(), Error> {
    let mut dim = None;
    for (at, p) in points {
        match dim {
            Some(d) if d != p.len() => {
                let message = format!("expected {}, found {}", coordinates(d), p.len());
                return Err(Error::new(at, message));
            }
            _ => dim = Some(p.len()),
        }
    }
    Ok(())
}

/// A point of a job, its own field (the point of a `bezier-triangle` entry).
#[derive(Clone, Debug)]
pub struct Point<T>(pub blossom::Point<T>);

impl<'de, T: Reading> Deserialize<'de> for Point<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, point).map(Point)
    }
}

/// A non-empty list of points of one dimension (the coefficients of a curve, control points).
#[derive(Clone, Debug)]
pub struct Points<T>(pub Vec<blossom::Point<T>>);

impl<'de, T: Reading> Deserialize<'de> for Points<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| {
            let points = items(v, "an array of points", not_empty("point"), point)?;
            same_dimension(
                points
                    .iter()
                    .enumerate()
                    .map(|(k, p)| (format!("[{k}]"), p)),
            )?;
            Ok(Points(points))
        })
    }
}

impl<T> Points<T> {
    /// The degree n of the curve of these points (their number minus one) and their dimension,
    /// for estimates.
    pub fn sizes(&self) -> (f64, f64) {
        let d = self.0.first().map_or(1, Vec::len).max(1);
        ((self.0.len() as f64 - 1.0).max(0.0), d as f64)
    }
}

/// Rows of points, all of one dimension (a grid or a triangular array, whose shape the job
/// checks with [`rectangular`] or [`triangular`]).
#[derive(Clone, Debug)]
pub struct Rows<T>(pub Vec<Vec<blossom::Point<T>>>);

impl<'de, T: Reading> Deserialize<'de> for Rows<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let row = |r: &Value| items(r, "a row of points (an array)", any, point);
        leaf(d, |v| {
            let rows = items(v, "an array of rows of points", any, row)?;
            same_dimension(rows.iter().enumerate().flat_map(|(i, row)| {
                let at = move |(j, p)| (format!("[{i}][{j}]"), p);
                row.iter().enumerate().map(at)
            }))?;
            Ok(Rows(rows))
        })
    }
}

impl<T> Rows<T> {
    /// The number of rows, that of the first row's points and their dimension (1 without
    /// them), for estimates.
    pub fn sizes(&self) -> (f64, f64, f64) {
        let first = self.0.first();
        let d = first.and_then(|row| row.first()).map_or(1, Vec::len).max(1);
        let columns = first.map_or(0, Vec::len);
        (self.0.len() as f64, columns as f64, d as f64)
    }
}

/// Refuses `rows` (at `path`) unless it is a non-empty rectangular grid.
pub fn rectangular<X>(rows: &[Vec<X>], path: &str, what: &str) -> Result<(), Error> {
    let Some(first) = rows.first() else {
        return Err(Error::new(path, "expected at least one row, found none"));
    };
    for (i, row) in rows.iter().enumerate() {
        if row.is_empty() || row.len() != first.len() {
            let message = if row.is_empty() && i == 0 {
                format!("expected at least one {what}, found none")
            } else {
                format!(
                    "expected {} {what}s (the grid must be rectangular), found {}",
                    first.len(),
                    row.len()
                )
            };
            return Err(Error::new(format!("{path}[{i}]"), message));
        }
    }
    Ok(())
}

/// Refuses `rows` (at `path`) unless it is the triangular array of total degree `big_n`: N + 1
/// rows, row i holding N + 1 - i entries.
pub fn triangular<X>(rows: &[Vec<X>], path: &str, big_n: usize, what: &str) -> Result<(), Error> {
    if rows.len() != big_n + 1 {
        return Err(Error::new(
            path,
            format!(
                "expected {} rows (a triangular array of total degree {big_n}), found {}",
                big_n + 1,
                rows.len()
            ),
        ));
    }
    for (i, row) in rows.iter().enumerate() {
        if row.len() != big_n + 1 - i {
            return Err(Error::new(
                format!("{path}[{i}]"),
                format!(
                    "expected {} {what}s (row {i} of a triangular array of total degree {big_n} \
                     holds N + 1 - i), found {}",
                    big_n + 1 - i,
                    row.len()
                ),
            ));
        }
    }
    Ok(())
}

/// Rows of numbers (the grid of a rational surface's denominator), each row non-empty.
#[derive(Clone, Debug)]
pub struct NumberRows<T>(pub Vec<Vec<T>>);

impl<'de, T: Reading> Deserialize<'de> for NumberRows<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let expected = "a row of numbers (an array)";
        let row = |r: &Value| items(r, expected, not_empty("number"), number);
        leaf(d, |v| items(v, "an array of rows of numbers", any, row)).map(NumberRows)
    }
}

/// A list of numbers, possibly empty.
#[derive(Clone, Debug)]
pub struct NumberList<T>(pub Vec<T>);

impl<'de, T: Reading> Deserialize<'de> for NumberList<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, |v| items(v, "an array of numbers", any, number)).map(NumberList)
    }
}

// ------------------------------------------------------------------------------------------
// Degrees and names.

/// The largest degree a job may name (`degree`, `to_degree`, `total_degree`, `order`, the
/// indices of a `bezier-triangle` entry).
pub const MAX_DEGREE: usize = 200;

/// A degree: a non-negative JSON integer or a string of digits, at most [`MAX_DEGREE`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Degree(pub usize);

impl<'de> Deserialize<'de> for Degree {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        leaf(d, degree).map(Degree)
    }
}

/// A degree (see [`Degree`]).
pub fn degree(value: &Value) -> Result<usize, Error> {
    let text = match value {
        Value::Number(n) => n.to_string(),
        Value::String(s) => s.trim().to_string(),
        other => {
            let found = json_type(other);
            return Err(Error::new(
                "",
                format!("expected a non-negative integer, found {found}"),
            ));
        }
    };
    if text.is_empty() || !text.bytes().all(|b| b.is_ascii_digit()) {
        let message = format!("expected a non-negative integer, found {text:?}");
        return Err(Error::new("", message));
    }
    match text.parse::<usize>() {
        Ok(d) if d <= MAX_DEGREE => Ok(d),
        _ => Err(Error::new(
            "",
            format!("expected a degree of at most {MAX_DEGREE}, found {text}"),
        )),
    }
}

/// A value named by a string from a fixed list (an `op`, a fill rule).
pub trait Named: Sized + Copy + 'static {
    /// What the name names, for messages (`op`, `fill rule`).
    const WHAT: &'static str;
    /// The accepted names and their values, the default first.
    const NAMES: &'static [(&'static str, Self)];
}

/// A [`Named`] value read from its name.
#[derive(Clone, Copy, Debug)]
pub struct Name<E>(pub E);

impl<'de, E: Named> Deserialize<'de> for Name<E> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let read = |value: &Value| match value {
            Value::String(name) => lookup(E::WHAT, name, E::NAMES).map(Name),
            other => {
                let names: Vec<&str> = E::NAMES.iter().map(|(n, _)| *n).collect();
                let (names, found) = (listed(&names), json_type(other));
                Err(format!("expected a string ({names}), found {found}"))
            }
        };
        leaf(d, |value| {
            read(value).map_err(|message| Error::new("", message))
        })
    }
}
