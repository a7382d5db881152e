//! Reading a job with serde: the job types derive `Deserialize`, and [`read`] runs them over the
//! parsed document through [`Reader`], a thin `Deserializer` over `serde_json::Value` that
//! knows the path of every value, so that each error names its field
//! (`coefficients[2]: expected 3 coordinates, found 2`, `regions[1].loops[0][2][1][0]: ...`).
//!
//! The reader keeps the contract's order of checks: the fields of an object are checked for
//! unknown names before any value is read (the nearest accepted name in the message: `did you
//! mean "control_points"?`), then read in the order the type declares them, a missing one
//! refused when it is reached (`interval: missing field`); arrays element by element. The
//! leaves are this module's types: [`Num`] reads one number by the contract's rules for the
//! arithmetic `T` ([`Reading`]: integers and fractions and decimals as strings exactly, JSON
//! numbers with a fraction part only under `f64`), and the containers check counts and
//! dimensions as they go ([`Numbers`], [`Point`], [`Points`], [`Rows`]).

use crate::names::{did_you_mean, listed, quoted, unknown_field};
use crate::number::{f64_from_json, format_rational, json_type, rational_from_json, JsonNumber};
use blossom::{BoundedF64, Error, ErrorKind, Rational};
use serde::de::{self, DeserializeOwned, DeserializeSeed, IntoDeserializer, Visitor};
use serde::{Deserialize, Deserializer};
use serde_json::{Map, Value};
use std::fmt;
use std::marker::PhantomData;

/// Reads a `D` from `value`, the whole job (errors at its top level name `input`).
pub fn read<D: DeserializeOwned>(value: &Value) -> Result<D, Error> {
    read_at(value, "")
}

/// Reads a `D` from `value`, which sits at `path` in the job.
pub fn read_at<D: DeserializeOwned>(value: &Value, path: &str) -> Result<D, Error> {
    D::deserialize(Reader::at(Some(value), path.to_string())).map_err(ReadError::finish)
}

/// A job object read without its `"kind"` (named first among the accepted fields).
pub fn read_job<D: DeserializeOwned>(job: &Map<String, Value>) -> Result<D, Error> {
    let reader = Reader {
        value: None,
        object: Some(job),
        path: String::new(),
    };
    D::deserialize(reader).map_err(ReadError::finish)
}

/// The fields of the struct `D` reads (its serde field names, in order).
pub fn fields_of<D: DeserializeOwned>() -> &'static [&'static str] {
    /// A deserializer that only asks which fields a struct has.
    struct Fields;
    #[derive(Debug)]
    struct Found(&'static [&'static str]);
    impl fmt::Display for Found {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("fields")
        }
    }
    impl std::error::Error for Found {}
    impl de::Error for Found {
        fn custom<M: fmt::Display>(_: M) -> Self {
            Found(&[])
        }
    }
    impl<'de> Deserializer<'de> for Fields {
        type Error = Found;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Found> {
            Err(Found(&[]))
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Found> {
            Err(Found(fields))
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes
            byte_buf option unit unit_struct newtype_struct seq tuple tuple_struct map enum
            identifier ignored_any
        }
    }
    match D::deserialize(Fields) {
        Ok(_) => &[],
        Err(Found(fields)) => fields,
    }
}

/// An error of reading: a library [`Error`] whose field is completed by the reader that
/// returns it (`relative` under its own path) on the way out.
#[derive(Debug)]
pub struct ReadError {
    error: Error,
    placed: bool,
}

impl ReadError {
    /// An error at `relative` (`""`, `[2]` or `name`) below the value being read.
    pub fn below(relative: impl Into<String>, kind: ErrorKind, message: impl Into<String>) -> Self {
        ReadError {
            error: Error::of(kind, relative, message),
            placed: false,
        }
    }

    /// A library error whose field is relative to the value being read (a region's
    /// `loops[0][2]`).
    pub fn from_library(error: Error) -> Self {
        ReadError {
            error,
            placed: false,
        }
    }

    fn at(mut self, path: &str) -> Self {
        if !self.placed {
            self.error.field = joined(path, &self.error.field);
            self.placed = true;
        }
        self
    }

    fn finish(self) -> Error {
        let mut error = self.error;
        if error.field.is_empty() {
            error.field = String::from("input");
        }
        error
    }
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.error.fmt(f)
    }
}

impl std::error::Error for ReadError {}

impl de::Error for ReadError {
    fn custom<M: fmt::Display>(message: M) -> Self {
        let text = message.to_string();
        match text
            .strip_prefix(RELATIVE)
            .and_then(|t| t.split_once(RELATIVE))
        {
            Some((field, message)) => ReadError::below(field, ErrorKind::Invalid, message),
            None => ReadError::below("", ErrorKind::Invalid, text),
        }
    }
}

/// Marks the field of an error raised through serde's `Error::custom` below the value being
/// read ([`below`]).
const RELATIVE: &str = "\u{0}";

/// The library error `error`, whose field is relative to the value being read (a region's
/// `loops[0][2]`, a triangle's `nodes`), as the error of any deserializer: the reader puts it
/// under the value's path.
pub fn below<E: de::Error>(error: &Error) -> E {
    E::custom(format!(
        "{RELATIVE}{}{RELATIVE}{}",
        error.field, error.message
    ))
}

/// `path` and `name` joined: `name` at the top, `path.name` for a field, `path[2]` for an index.
pub fn joined(path: &str, name: &str) -> String {
    match (path, name) {
        ("", name) => name.to_string(),
        (path, "") => path.to_string(),
        (path, name) if name.starts_with('[') => format!("{path}{name}"),
        (path, name) => format!("{path}.{name}"),
    }
}

/// The `Deserializer` of one value of the job at `path` (`value` `None`: a field that is
/// absent, which reads as `None` where optional and is missing elsewhere; `object` set: the
/// job object, whose `"kind"` is read already).
pub struct Reader<'a> {
    value: Option<&'a Value>,
    object: Option<&'a Map<String, Value>>,
    path: String,
}

impl<'a> Reader<'a> {
    fn at(value: Option<&'a Value>, path: String) -> Self {
        Reader {
            value,
            object: None,
            path,
        }
    }

    /// The refusal of a value of the wrong type: `expected EXPECTED, found an array`.
    fn wrong_type(&self, expected: &dyn fmt::Display) -> ReadError {
        let found = self.value.map_or("nothing", json_type);
        ReadError::below(
            "",
            ErrorKind::Invalid,
            format!("expected {expected}, found {found}"),
        )
        .at(&self.path)
    }

    /// The object being read, or the refusal of what is there instead.
    fn object<'v, V: Visitor<'v>>(&self, visitor: &V) -> Result<&'a Map<String, Value>, ReadError> {
        match (self.object, self.value) {
            (Some(map), _) | (None, Some(Value::Object(map))) => Ok(map),
            (None, None) => Err(self.missing()),
            (None, Some(_)) => Err(self.wrong_type(&Expecting(visitor))),
        }
    }

    fn missing(&self) -> ReadError {
        ReadError::below("", ErrorKind::Invalid, "missing field").at(&self.path)
    }
}

/// What a visitor expects, for messages.
struct Expecting<'v, V>(&'v V);

impl<'de, V: Visitor<'de>> fmt::Display for Expecting<'_, V> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.expecting(f)
    }
}

impl<'de> Deserializer<'de> for Reader<'de> {
    type Error = ReadError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        let path = self.path.clone();
        let result = match self.value {
            None if self.object.is_some() => return self.deserialize_map(visitor),
            None => return Err(self.missing()),
            Some(Value::Array(items)) => visitor.visit_seq(Elements {
                items: items.iter().enumerate(),
                path: &path,
            }),
            Some(Value::Object(_)) => return self.deserialize_map(visitor),
            // Numbers keep their spelling (`arbitrary_precision`): serde_json presents them.
            Some(leaf) => leaf
                .deserialize_any(visitor)
                .map_err(|e| ReadError::below("", ErrorKind::Invalid, e.to_string())),
        };
        result.map_err(|e| e.at(&path))
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        match self.value {
            None | Some(Value::Null) if self.object.is_none() => visitor.visit_none(),
            _ => visitor.visit_some(self),
        }
    }

    fn deserialize_seq<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        match self.value {
            Some(Value::Array(_)) => self.deserialize_any(visitor),
            None if self.object.is_none() => Err(self.missing()),
            _ => Err(self.wrong_type(&Expecting(&visitor))),
        }
    }

    fn deserialize_map<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, ReadError> {
        let map = self.object(&visitor)?;
        let entries: Vec<(&str, Option<&Value>)> = map
            .iter()
            .filter(|(k, _)| self.object.is_none() || k.as_str() != "kind")
            .map(|(k, v)| (k.as_str(), Some(v)))
            .collect();
        visitor
            .visit_map(Fields::new(entries, &self.path))
            .map_err(|e| e.at(&self.path))
    }

    /// An object: its fields are checked for unknown names first, then read in the order of
    /// `fields`, an absent one read as absent.
    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, ReadError> {
        let map = self.object(&visitor)?;
        let top = self.object.is_some();
        let mut accepted: Vec<&str> = Vec::with_capacity(fields.len() + 1);
        if top {
            accepted.push("kind");
        }
        accepted.extend_from_slice(fields);
        if let Some(name) = map.keys().find(|k| !accepted.contains(&k.as_str())) {
            return Err(ReadError::below(
                name.clone(),
                ErrorKind::Invalid,
                unknown_field(name, &accepted),
            )
            .at(&self.path));
        }
        let entries = fields.iter().map(|f| (*f, map.get(*f))).collect();
        visitor
            .visit_map(Fields::new(entries, &self.path))
            .map_err(|e| e.at(&self.path))
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, ReadError> {
        visitor.visit_newtype_struct(self)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        unit unit_struct tuple tuple_struct enum identifier ignored_any
    }
}

/// The elements of an array, each read at `path[i]`.
struct Elements<'a, 'p> {
    items: std::iter::Enumerate<std::slice::Iter<'a, Value>>,
    path: &'p str,
}

impl<'de> de::SeqAccess<'de> for Elements<'de, '_> {
    type Error = ReadError;

    fn next_element_seed<S: DeserializeSeed<'de>>(
        &mut self,
        seed: S,
    ) -> Result<Option<S::Value>, ReadError> {
        match self.items.next() {
            None => Ok(None),
            Some((i, item)) => {
                let path = format!("{}[{i}]", self.path);
                seed.deserialize(Reader::at(Some(item), path.clone()))
                    .map(Some)
                    .map_err(|e| e.at(&path))
            }
        }
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.items.len())
    }
}

/// The fields of an object, each read at `path.name` (`None`: absent).
struct Fields<'a, 'p> {
    entries: std::vec::IntoIter<(&'a str, Option<&'a Value>)>,
    current: Option<(&'a str, Option<&'a Value>)>,
    path: &'p str,
}

impl<'a, 'p> Fields<'a, 'p> {
    fn new(entries: Vec<(&'a str, Option<&'a Value>)>, path: &'p str) -> Self {
        Fields {
            entries: entries.into_iter(),
            current: None,
            path,
        }
    }
}

impl<'de> de::MapAccess<'de> for Fields<'de, '_> {
    type Error = ReadError;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, ReadError> {
        self.current = self.entries.next();
        match self.current {
            None => Ok(None),
            Some((name, _)) => seed
                .deserialize(name.into_deserializer())
                .map(Some)
                .map_err(|e: de::value::Error| de::Error::custom(e))
                .map_err(|e: ReadError| e.at(&joined(self.path, name))),
        }
    }

    fn next_value_seed<S: DeserializeSeed<'de>>(&mut self, seed: S) -> Result<S::Value, ReadError> {
        let (name, value) = self.current.take().expect("a key before its value");
        let path = joined(self.path, name);
        seed.deserialize(Reader::at(value, path.clone()))
            .map_err(|e| e.at(&path))
    }
}

// ------------------------------------------------------------------------------------------
// Numbers.

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
pub struct Written<T>(pub Rational, PhantomData<T>);

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
            let spelling = match value {
                Value::Number(n) => Value::String(n.to_string()),
                other => other.clone(),
            };
            match rational_from_json(&spelling) {
                _ if double == 0.0 => Rational::default(),
                Ok(q) => q,
                Err(_) => Rational::from_float(double).unwrap_or_default(),
            }
        };
        Ok(Written(exact, PhantomData))
    }

    fn exact(&self) -> Rational {
        self.0.clone()
    }
}

/// One number of a job, read by [`Reading`].
#[derive(Clone, Debug)]
pub struct Num<T>(pub T);

impl<'de, T: Reading> Deserialize<'de> for Num<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let value = Value::deserialize(d)?;
        T::read(&value).map(Num).map_err(de::Error::custom)
    }
}

/// Exactly `N` numbers (an interval, a rectangle, barycentric coordinates).
#[derive(Clone, Debug)]
pub struct Numbers<T, const N: usize>(pub [T; N]);

impl<'de, T: Reading, const N: usize> Deserialize<'de> for Numbers<T, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let expected = format!("an array of {N} numbers");
        let items = counted::<D, Num<T>>(d, Count::Exactly(N, "numbers"), expected)?;
        let numbers: Vec<T> = items.into_iter().map(|n| n.0).collect();
        Ok(Numbers(
            numbers.try_into().unwrap_or_else(|_| unreachable!()),
        ))
    }
}

/// The three corners of a triangle, each `D` numbers: points of the plane (`D` = 2) or
/// barycentric coordinates (`D` = 3).
#[derive(Clone, Debug)]
pub struct Corners<T, const D: usize>(pub [[T; D]; 3]);

impl<'de, T: Reading, const D: usize> Deserialize<'de> for Corners<T, D> {
    fn deserialize<D2: Deserializer<'de>>(d: D2) -> Result<Self, D2::Error> {
        let corners: Vec<Corner<T, D>> =
            counted(d, Count::Exactly(3, "corners"), "an array of 3 corners")?;
        let corners: Vec<[T; D]> = corners.into_iter().map(|c| c.0).collect();
        Ok(Corners(
            corners.try_into().unwrap_or_else(|_| unreachable!()),
        ))
    }
}

/// One corner of [`Corners`].
struct Corner<T, const D: usize>([T; D]);

impl<'de, T: Reading, const D: usize> Deserialize<'de> for Corner<T, D> {
    fn deserialize<D2: Deserializer<'de>>(d: D2) -> Result<Self, D2::Error> {
        let (noun, what) = match D {
            2 => ("coordinates", "a corner (an array of 2 numbers)"),
            _ => (
                "barycentric coordinates",
                "a corner (an array of 3 barycentric coordinates)",
            ),
        };
        let items: Vec<Num<T>> = counted(d, Count::Exactly(D, noun), what)?;
        let numbers: Vec<T> = items.into_iter().map(|n| n.0).collect();
        Ok(Corner(
            numbers.try_into().unwrap_or_else(|_| unreachable!()),
        ))
    }
}

/// How many elements an array must have, and what they are called in messages.
#[derive(Clone, Copy)]
pub enum Count {
    /// Exactly this many.
    Exactly(usize, &'static str),
    /// At least one.
    NotEmpty(&'static str),
    /// Any number.
    Any,
}

/// The elements of an array, each read as `E`, their count checked before they are read.
pub fn counted<'de, D: Deserializer<'de>, E: Deserialize<'de>>(
    d: D,
    count: Count,
    expected: impl Into<String>,
) -> Result<Vec<E>, D::Error> {
    struct Items<E>(Count, String, PhantomData<E>);
    impl<'de, E: Deserialize<'de>> Visitor<'de> for Items<E> {
        type Value = Vec<E>;
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str(&self.1)
        }
        fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<E>, A::Error> {
            let found = seq.size_hint().unwrap_or(0);
            match self.0 {
                Count::Exactly(n, what) if found != n => {
                    return Err(de::Error::custom(format!(
                        "expected {n} {what}, found {found}"
                    )))
                }
                Count::NotEmpty(what) if found == 0 => {
                    return Err(de::Error::custom(format!(
                        "expected at least one {what}, found none"
                    )))
                }
                _ => {}
            }
            let mut out = Vec::with_capacity(found);
            while let Some(item) = seq.next_element()? {
                out.push(item);
            }
            Ok(out)
        }
    }
    d.deserialize_seq(Items(count, expected.into(), PhantomData))
}

/// "1 coordinate", "3 coordinates".
pub fn coordinates(d: usize) -> String {
    if d == 1 {
        String::from("1 coordinate")
    } else {
        format!("{d} coordinates")
    }
}

/// A point of any dimension D >= 1.
#[derive(Clone, Debug)]
pub struct Point<T>(pub blossom::Point<T>);

impl<'de, T: Reading> Deserialize<'de> for Point<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let xs: Vec<Num<T>> = counted(
            d,
            Count::NotEmpty("coordinate"),
            "a point (an array of numbers)",
        )?;
        Ok(Point(xs.into_iter().map(|x| x.0).collect()))
    }
}

/// Refuses the first point (at `[k]` below the value read, `at(k)`) whose dimension is not
/// that of the first.
fn same_dimension<'a, T: 'a, E: de::Error>(
    points: impl Iterator<Item = (String, &'a blossom::Point<T>)>,
) -> Result<(), E> {
    let mut dim = None;
    for (at, p) in points {
        match dim {
            Some(d) if d != p.len() => {
                let message = format!("expected {}, found {}", coordinates(d), p.len());
                return Err(below(&Error::new(at, message)));
            }
            _ => dim = Some(p.len()),
        }
    }
    Ok(())
}

/// A non-empty list of points of one dimension (the coefficients of a curve, control points).
#[derive(Clone, Debug)]
pub struct Points<T>(pub Vec<blossom::Point<T>>);

impl<'de, T: Reading> Deserialize<'de> for Points<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let points: Vec<Point<T>> = counted(d, Count::NotEmpty("point"), "an array of points")?;
        let points: Vec<_> = points.into_iter().map(|p| p.0).collect();
        same_dimension(
            points
                .iter()
                .enumerate()
                .map(|(k, p)| (format!("[{k}]"), p)),
        )?;
        Ok(Points(points))
    }
}

/// Rows of points, all of one dimension (a grid or a triangular array, whose shape the job
/// checks with [`rectangular`] or [`triangular`]).
#[derive(Clone, Debug)]
pub struct Rows<T>(pub Vec<Vec<blossom::Point<T>>>);

/// A row of [`Rows`].
struct Row<T>(Vec<blossom::Point<T>>);

impl<'de, T: Reading> Deserialize<'de> for Row<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let points: Vec<Point<T>> = counted(d, Count::Any, "a row of points (an array)")?;
        Ok(Row(points.into_iter().map(|p| p.0).collect()))
    }
}

impl<'de, T: Reading> Deserialize<'de> for Rows<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let rows: Vec<Row<T>> = counted(d, Count::Any, "an array of rows of points")?;
        let rows: Vec<_> = rows.into_iter().map(|r| r.0).collect();
        same_dimension(rows.iter().enumerate().flat_map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(move |(j, p)| (format!("[{i}][{j}]"), p))
        }))?;
        Ok(Rows(rows))
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

/// Rows of numbers (the grid of a rational surface's denominator).
#[derive(Clone, Debug)]
pub struct NumberRows<T>(pub Vec<Vec<T>>);

impl<'de, T: Reading> Deserialize<'de> for NumberRows<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let rows: Vec<NumberRow<T>> = counted(d, Count::Any, "an array of rows of numbers")?;
        Ok(NumberRows(rows.into_iter().map(|r| r.0).collect()))
    }
}

/// A row of numbers.
struct NumberRow<T>(Vec<T>);

impl<'de, T: Reading> Deserialize<'de> for NumberRow<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let items: Vec<Num<T>> =
            counted(d, Count::NotEmpty("number"), "a row of numbers (an array)")?;
        Ok(NumberRow(items.into_iter().map(|n| n.0).collect()))
    }
}

/// A list of numbers, possibly empty.
#[derive(Clone, Debug)]
pub struct NumberList<T>(pub Vec<T>);

impl<'de, T: Reading> Deserialize<'de> for NumberList<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let items: Vec<Num<T>> = counted(d, Count::Any, "an array of numbers")?;
        Ok(NumberList(items.into_iter().map(|n| n.0).collect()))
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
        let value = Value::deserialize(d)?;
        let text = match &value {
            Value::Number(n) => n.to_string(),
            Value::String(s) => s.trim().to_string(),
            other => {
                return Err(de::Error::custom(format!(
                    "expected a non-negative integer, found {}",
                    json_type(other)
                )))
            }
        };
        if text.is_empty() || !text.bytes().all(|b| b.is_ascii_digit()) {
            return Err(de::Error::custom(format!(
                "expected a non-negative integer, found {text:?}"
            )));
        }
        match text.parse::<usize>() {
            Ok(d) if d <= MAX_DEGREE => Ok(Degree(d)),
            _ => Err(de::Error::custom(format!(
                "expected a degree of at most {MAX_DEGREE}, found {text}"
            ))),
        }
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
        let names: Vec<&str> = E::NAMES.iter().map(|(n, _)| *n).collect();
        match Value::deserialize(d)? {
            Value::String(name) => E::NAMES
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, e)| Name(*e))
                .ok_or_else(|| {
                    de::Error::custom(format!(
                        "unknown {} {}{} (expected {})",
                        E::WHAT,
                        quoted(&name),
                        did_you_mean(&name, &names),
                        listed(&names)
                    ))
                }),
            other => Err(de::Error::custom(format!(
                "expected a string ({}), found {}",
                listed(&names),
                json_type(&other)
            ))),
        }
    }
}

/// An exact number as the contract writes it, for messages (`1/2`).
pub fn shown(q: &Rational) -> String {
    format_rational(q).unwrap_or_else(|_| q.to_string())
}
