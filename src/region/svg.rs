//! SVG path data in: the commands M, L, H, V, Q, T, C, S, Z (absolute and relative) read into
//! the loops of a [`Region`], every number exactly; and the subpaths of a path being drawn
//! (`Subpaths`), shared with kurbo's `BezPath` (feature `kurbo`).

use super::input::{FillRule, Region};
use crate::error::{Error, ErrorKind, Result};
use crate::num::parse::parse_rational;
use crate::num::ring::{Rational, Ring};
use crate::shape::array::Bezier;

/// The loops of a path being drawn in absolute coordinates, as SVG fills it: a subpath ends at
/// a close or at the next move; when it does not end where it started it is closed by a line;
/// one whose segments all stay at one point (none moving anywhere) is dropped. After a close
/// the current point is the closed subpath's start, where the next segment starts a new
/// subpath.
pub(crate) struct Subpaths<T: Ring> {
    loops: Vec<Vec<Bezier<T, 2>>>,
    segments: Vec<Bezier<T, 2>>,
    start: [T; 2],
    current: [T; 2],
}

/// The curve through `points` (at least two: a start and the control points after it).
fn curve<T: Ring>(points: Vec<[T; 2]>) -> Bezier<T, 2> {
    Bezier::new(points).expect("a segment has a start and at least one more point")
}

impl<T: Ring> Subpaths<T> {
    /// No subpath yet; the current point is the origin.
    pub(crate) fn new() -> Self {
        let origin = [T::zero(), T::zero()];
        Subpaths {
            loops: Vec::new(),
            segments: Vec::new(),
            start: origin.clone(),
            current: origin,
        }
    }

    /// The current point: where the last segment ended (the origin before any).
    pub(crate) fn current(&self) -> &[T; 2] {
        &self.current
    }

    /// Ends the subpath and starts one at `p`.
    pub(crate) fn move_to(&mut self, p: [T; 2]) {
        self.close();
        self.start = p.clone();
        self.current = p;
    }

    /// A segment from the current point through `controls` (its control points after the
    /// first, at least one), which then ends at the last of them.
    pub(crate) fn segment(&mut self, controls: Vec<[T; 2]>) {
        let mut points = Vec::with_capacity(controls.len() + 1);
        points.push(self.current.clone());
        points.extend(controls);
        self.current = points[points.len() - 1].clone();
        self.segments.push(curve(points));
    }

    /// Ends the subpath: kept as a loop (closed by a line when it does not end at its start)
    /// unless no segment moves; the current point goes back to its start.
    pub(crate) fn close(&mut self) {
        let mut segments = std::mem::take(&mut self.segments);
        let moves = segments
            .iter()
            .any(|s| s.points().iter().any(|p| p != &s.points()[0]));
        if moves {
            if self.current != self.start {
                segments.push(curve(vec![self.current.clone(), self.start.clone()]));
            }
            self.loops.push(segments);
        }
        self.current = self.start.clone();
    }

    /// The kept loops, the last subpath ended.
    pub(crate) fn finish(mut self) -> Vec<Vec<Bezier<T, 2>>> {
        self.close();
        self.loops
    }
}

/// The commands of SVG path data that this reader draws (arcs are refused).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Command {
    Move,
    Line,
    Horizontal,
    Vertical,
    Quadratic,
    SmoothQuadratic,
    Cubic,
    SmoothCubic,
    Close,
}

impl Command {
    /// The command of a letter and whether it is relative (lower case).
    fn of(letter: char) -> Option<(Command, bool)> {
        let command = match letter.to_ascii_uppercase() {
            'M' => Command::Move,
            'L' => Command::Line,
            'H' => Command::Horizontal,
            'V' => Command::Vertical,
            'Q' => Command::Quadratic,
            'T' => Command::SmoothQuadratic,
            'C' => Command::Cubic,
            'S' => Command::SmoothCubic,
            'Z' => Command::Close,
            _ => return None,
        };
        Some((command, letter.is_ascii_lowercase()))
    }

    /// How many numbers one segment of the command takes.
    fn arity(self) -> usize {
        match self {
            Command::Close => 0,
            Command::Horizontal | Command::Vertical => 1,
            Command::Move | Command::Line | Command::SmoothQuadratic => 2,
            Command::Quadratic | Command::SmoothCubic => 4,
            Command::Cubic => 6,
        }
    }
}

/// The control point the next T or S reflects: the last of a Q or T, the second of a C or S.
enum Reflect {
    None,
    Quadratic([Rational; 2]),
    Cubic([Rational; 2]),
}

/// The error at byte offset `at` of the path data: an empty field (the caller names the
/// string), the message `at N: ...`.
fn error_at(kind: ErrorKind, at: usize, message: impl std::fmt::Display) -> Error {
    Error::of(kind, "", format!("at {at}: {message}"))
}

/// A cursor over path data.
struct Reader<'a> {
    text: &'a str,
    at: usize,
}

impl Reader<'_> {
    fn peek(&self) -> Option<char> {
        self.text[self.at..].chars().next()
    }

    /// What stands at the cursor, for a message: `'X'` or `the end of the data`.
    fn found(&self) -> String {
        match self.peek() {
            Some(c) => format!("{c:?}"),
            None => "the end of the data".to_string(),
        }
    }

    /// Skips SVG's white space (space, tab, line feed, form feed, carriage return).
    fn skip_spaces(&mut self) {
        let rest = &self.text[self.at..];
        let trimmed = rest.trim_start_matches([' ', '\t', '\n', '\x0C', '\r']);
        self.at += rest.len() - trimmed.len();
    }

    /// Skips white space with at most one comma in it; whether there was a comma.
    fn skip_separator(&mut self) -> bool {
        self.skip_spaces();
        let comma = self.peek() == Some(',');
        if comma {
            self.at += 1;
            self.skip_spaces();
        }
        comma
    }

    /// Whether a number may start at the cursor (a sign, a digit or a point).
    fn at_number(&self) -> bool {
        matches!(self.peek(), Some('0'..='9' | '.' | '+' | '-'))
    }

    /// The end of the longest SVG number starting at the cursor, if one does:
    /// `[sign] (digits ["." digits*] | "." digits) [("e" | "E") [sign] digits]`, so that
    /// `-.5.5` is `-.5` then `.5`, `1-2` is `1` then `-2`, and an `e` not followed by an
    /// exponent is not part of the number.
    fn number_end(&self) -> Option<usize> {
        let bytes = self.text.as_bytes();
        let digits = |mut i: usize| {
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            i
        };
        let mut i = self.at;
        if matches!(bytes.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        let int_end = digits(i);
        let mut end = int_end;
        if bytes.get(int_end) == Some(&b'.') {
            let frac_end = digits(int_end + 1);
            if int_end > i || frac_end > int_end + 1 {
                end = frac_end;
            }
        }
        if end == int_end && int_end == i {
            return None;
        }
        if matches!(bytes.get(end), Some(b'e' | b'E')) {
            let mut j = end + 1;
            if matches!(bytes.get(j), Some(b'+' | b'-')) {
                j += 1;
            }
            let exponent_end = digits(j);
            if exponent_end > j {
                end = exponent_end;
            }
        }
        Some(end)
    }

    /// The number at the cursor (after white space), read by `number`; `letter` and `arity`
    /// name the command in the message of a missing number.
    fn number<F: FnMut(&str) -> Result<Rational>>(
        &mut self,
        number: &mut F,
        letter: char,
        arity: usize,
    ) -> Result<Rational> {
        self.skip_spaces();
        let at = self.at;
        let Some(end) = self.number_end() else {
            return Err(error_at(
                ErrorKind::Invalid,
                at,
                format!(
                    "expected a number ('{letter}' takes {arity} per segment), found {}",
                    self.found()
                ),
            ));
        };
        self.at = end;
        number(&self.text[at..end])
            .map_err(|e| Error::of(e.kind, e.field, format!("at {at}: {}", e.message)))
    }

    /// The command at the cursor (its letter, the command, whether relative), or the error
    /// of what stands there instead; `first` for the start of the data, which must be a move.
    fn command(&self, first: bool) -> Result<(char, Command, bool)> {
        let at = self.at;
        let c = self.peek().unwrap_or(' ');
        let known = Command::of(c);
        match known {
            Some((Command::Move, relative)) => return Ok((c, Command::Move, relative)),
            Some((command, relative)) if !first => return Ok((c, command, relative)),
            _ => {}
        }
        Err(if c == 'A' || c == 'a' {
            error_at(
                ErrorKind::Invalid,
                at,
                "arcs (A) are not polynomial curves; convert them to cubics",
            )
        } else if c.is_alphabetic() && known.is_none() {
            error_at(ErrorKind::UnknownName, at, format!("unknown command {c:?}"))
        } else if first {
            error_at(
                ErrorKind::Invalid,
                at,
                format!("path data must start with M or m, found {c:?}"),
            )
        } else {
            error_at(
                ErrorKind::Invalid,
                at,
                format!("expected a command letter, found {c:?}"),
            )
        })
    }

    /// After the numbers of one segment: whether another segment of the same command
    /// follows (implicit repeat), past the separator.
    fn repeats(&mut self, letter: char, arity: usize) -> Result<bool> {
        let comma = self.skip_separator();
        if self.at_number() {
            return Ok(true);
        }
        if comma {
            return Err(error_at(
                ErrorKind::Invalid,
                self.at,
                format!(
                    "expected a number after ',' ('{letter}' takes {arity} per segment), found {}",
                    self.found()
                ),
            ));
        }
        Ok(false)
    }
}

/// 2 c - p: the reflection of `p` about `c`, exactly.
fn reflect(c: &[Rational; 2], p: &[Rational; 2]) -> [Rational; 2] {
    [&c[0] + &c[0] - &p[0], &c[1] + &c[1] - &p[1]]
}

/// Draws one segment of `command` with its numbers `v` into `paths`; `reflect` holds the
/// control point a following T or S reflects.
fn draw(
    paths: &mut Subpaths<Rational>,
    reflection: &mut Reflect,
    command: Command,
    relative: bool,
    v: &[Rational],
) {
    let current = paths.current().clone();
    let point = |x: &Rational, y: &Rational| {
        if relative {
            [&current[0] + x, &current[1] + y]
        } else {
            [x.clone(), y.clone()]
        }
    };
    let coordinate = |x: &Rational, axis: usize| {
        if relative {
            &current[axis] + x
        } else {
            x.clone()
        }
    };
    let mut next = Reflect::None;
    match command {
        Command::Move => paths.move_to(point(&v[0], &v[1])),
        Command::Line => paths.segment(vec![point(&v[0], &v[1])]),
        Command::Horizontal => paths.segment(vec![[coordinate(&v[0], 0), current[1].clone()]]),
        Command::Vertical => paths.segment(vec![[current[0].clone(), coordinate(&v[0], 1)]]),
        Command::Quadratic | Command::SmoothQuadratic => {
            let (control, end) = if command == Command::Quadratic {
                (point(&v[0], &v[1]), point(&v[2], &v[3]))
            } else if let Reflect::Quadratic(previous) = reflection {
                (reflect(&current, previous), point(&v[0], &v[1]))
            } else {
                (current.clone(), point(&v[0], &v[1]))
            };
            next = Reflect::Quadratic(control.clone());
            paths.segment(vec![control, end]);
        }
        Command::Cubic | Command::SmoothCubic => {
            let (first, rest) = if command == Command::Cubic {
                (point(&v[0], &v[1]), &v[2..])
            } else if let Reflect::Cubic(previous) = reflection {
                (reflect(&current, previous), v)
            } else {
                (current.clone(), v)
            };
            let second = point(&rest[0], &rest[1]);
            next = Reflect::Cubic(second.clone());
            paths.segment(vec![first, second, point(&rest[2], &rest[3])]);
        }
        Command::Close => paths.close(),
    }
    *reflection = next;
}

/// The loops of SVG path data `d`, each number's text read by `number`: subpath l is loop l
/// of the answer (for [`Region::new`]), its segments curves 0, 1, ... in order (a line for
/// L, H, V and for the closing line, a quadratic for Q, T, a cubic for C, S), as SVG draws
/// them:
///
/// * commands M, L, H, V, Q, T, C, S, Z, upper case absolute, lower case relative to the
///   current point (added exactly); the numbers of one more segment after a command's repeat
///   it (after M or m they are L or l);
/// * numbers in SVG's syntax (`1e3`, `.5`, `-.5.5` is two numbers, `1-2` is two numbers),
///   separated by white space and at most one comma; `number` gets each number's text
///   ([`parse_rational`] reads it exactly; [`parse_f64`](crate::parse_f64) then
///   `Rational::from_float` as the nearest double, relative coordinates then added exactly);
/// * T reflects the control point of a preceding Q or T, S the second control point of a
///   preceding C or S, about the current point, exactly; after any other command the
///   reflected point is the current point (so T after L is a quadratic whose control point is
///   its start);
/// * after Z the current point is the closed subpath's start, and a drawing command there
///   starts a new subpath;
/// * a subpath that does not end where it started is closed by a line (with Z or without), a
///   subpath none of whose segments moves (`M 1 2`, `M 1 2 Z`, `M 1 2 L 1 2`) is dropped,
///   and data without a kept subpath (or empty) gives no loops.
///
/// ```
/// use blossom::region::parse_svg_path;
/// use blossom::{parse_rational, Rational};
/// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// let loops = parse_svg_path("M 0 0 h 1 q .5 1 0 1 Z", parse_rational)?;
/// assert_eq!(loops.len(), 1);
/// let curves = &loops[0];
/// // The line, the quadratic, then the line closing the subpath.
/// assert_eq!(curves.len(), 3);
/// assert_eq!(curves[1].points(), &[[q(1, 1), q(0, 1)], [q(3, 2), q(1, 1)], [q(1, 1), q(1, 1)]]);
/// assert_eq!(curves[2].points(), &[[q(1, 1), q(1, 1)], [q(0, 1), q(0, 1)]]);
/// # Ok::<(), blossom::Error>(())
/// ```
///
/// # Errors
/// The field is empty, for the caller to name the string (the CLI writes
/// `regions[0].path: at 17: ...`); the message starts with `at N: `, N the 0-based byte offset
/// in `d` of the offending character:
/// * [`ErrorKind::Invalid`] for an arc: `at N: arcs (A) are not polynomial curves; convert
///   them to cubics`;
/// * [`ErrorKind::UnknownName`] for any other letter that is not a command:
///   `at N: unknown command 'X'`;
/// * [`ErrorKind::Invalid`] for data that does not start with M or m, a missing number
///   (`at N: expected a number ('L' takes 2 per segment), found 'Z'`), a comma not followed
///   by a number, or a number where a command letter must stand (after Z);
/// * the error of `number` for a number's text (its kind and field, the message prefixed with
///   `at N: `).
pub fn parse_svg_path<F: FnMut(&str) -> Result<Rational>>(
    d: &str,
    mut number: F,
) -> Result<Vec<Vec<Bezier<Rational, 2>>>> {
    let mut reader = Reader { text: d, at: 0 };
    let mut paths = Subpaths::new();
    let mut reflection = Reflect::None;
    let mut first = true;
    reader.skip_spaces();
    while reader.peek().is_some() {
        let (letter, mut command, relative) = reader.command(first)?;
        first = false;
        reader.at += letter.len_utf8();
        let arity = command.arity();
        if arity == 0 {
            draw(&mut paths, &mut reflection, command, relative, &[]);
            reader.skip_spaces();
            continue;
        }
        loop {
            let mut values = Vec::with_capacity(arity);
            for k in 0..arity {
                if k > 0 {
                    reader.skip_separator();
                }
                values.push(reader.number(&mut number, letter, arity)?);
            }
            draw(&mut paths, &mut reflection, command, relative, &values);
            if command == Command::Move {
                command = Command::Line;
            }
            if !reader.repeats(letter, arity)? {
                break;
            }
        }
    }
    Ok(paths.finish())
}

impl Region {
    /// The region of SVG path data `d` under `fill`, every number read exactly
    /// ([`parse_rational`]): [`parse_svg_path`] then [`Region::new`]. Loop l is the l-th kept
    /// subpath, curve c its c-th segment, the closing line last.
    ///
    /// ```
    /// use blossom::region::{FillRule, Position, Region};
    /// use blossom::Rational;
    /// let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    /// // A 2 x 2 square with a quadratic bulge on top; 0.1 is read as 1/10 exactly.
    /// let r = Region::from_svg_path("M0,0 2,0 2,2 Q1,3 0,2z", FillRule::NonZero)?;
    /// assert_eq!(r.loops()[0].len(), 4);
    /// assert_eq!(r.contains(&[q(1, 1), q(9, 4)]), Position::Inside);
    /// assert_eq!(r.contains(&[q(1, 1), q(5, 2)]), Position::Boundary);
    /// assert_eq!(r.contains(&[q(1, 1), q(1, 10)]), Position::Inside);
    /// let e = Region::from_svg_path("M 0 0 A 1 1 0 0 1 2 0", FillRule::NonZero).unwrap_err();
    /// assert_eq!(e.to_string(), "at 6: arcs (A) are not polynomial curves; convert them to cubics");
    /// # Ok::<(), blossom::Error>(())
    /// ```
    ///
    /// # Errors
    /// Those of [`parse_svg_path`] (with an empty field: the caller names the string).
    pub fn from_svg_path(d: &str, fill: FillRule) -> Result<Region> {
        Region::new(parse_svg_path(d, parse_rational)?, fill)
    }
}

#[cfg(test)]
mod tests {
    use super::parse_svg_path;
    use crate::error::{ErrorKind, Result};
    use crate::intersect::algebraic::exact_f64;
    use crate::num::parse::{parse_f64, parse_rational};
    use crate::num::ring::Rational;
    use crate::region::{FillRule, Position, Region};
    use crate::shape::array::Bezier;

    /// A rational from a decimal text (the test's own notation for expected points).
    fn r(text: &str) -> Rational {
        parse_rational(text).unwrap()
    }

    /// Expected curves: each a list of points `"x y"`.
    fn curves(expected: &[&[&str]]) -> Vec<Bezier<Rational, 2>> {
        expected
            .iter()
            .map(|points| {
                let points = points
                    .iter()
                    .map(|p| {
                        let (x, y) = p.split_once(' ').unwrap();
                        [r(x), r(y)]
                    })
                    .collect();
                Bezier::new(points).unwrap()
            })
            .collect()
    }

    fn parse(d: &str) -> Vec<Vec<Bezier<Rational, 2>>> {
        parse_svg_path(d, parse_rational).unwrap_or_else(|e| panic!("{d}: {e}"))
    }

    /// The message of the error of `d`, with its kind and an empty field.
    fn error(d: &str) -> (ErrorKind, String) {
        let e = parse_svg_path(d, parse_rational).unwrap_err();
        assert_eq!(e.field, "", "{d}");
        (e.kind, e.message)
    }

    #[test]
    fn every_command_absolute_and_relative() {
        // M L H V Q T C S Z, each form; the last segment ends at the start (no closing line).
        let absolute = "M 1 2 L 3 2 H 5 V 4 Q 6 5 5 6 T 3 6 C 2 7 1 7 1 6 S 0 3 1 2 Z";
        let relative = "m 1 2 l 2 0 h 2 v 2 q 1 1 0 2 t -2 0 c -1 1 -2 1 -2 0 s -1 -3 0 -4 z";
        let want = curves(&[
            &["1 2", "3 2"],
            &["3 2", "5 2"],
            &["5 2", "5 4"],
            &["5 4", "6 5", "5 6"],
            // T reflects Q's control point (6, 5) about (5, 6): (4, 7).
            &["5 6", "4 7", "3 6"],
            &["3 6", "2 7", "1 7", "1 6"],
            // S reflects C's second control point (1, 7) about (1, 6): (1, 5).
            &["1 6", "1 5", "0 3", "1 2"],
        ]);
        assert_eq!(parse(absolute), vec![want.clone()]);
        assert_eq!(parse(relative), vec![want]);
    }

    #[test]
    fn reflections_follow_svg() {
        // T after T reflects the reflected point; T after L uses the current point.
        let got = parse("M 0 0 Q 1 1 2 0 T 4 0 T 6 0 L 6 -3 T 0 -3");
        let want = curves(&[
            &["0 0", "1 1", "2 0"],
            &["2 0", "3 -1", "4 0"],
            &["4 0", "5 1", "6 0"],
            &["6 0", "6 -3"],
            &["6 -3", "6 -3", "0 -3"],
            &["0 -3", "0 0"],
        ]);
        assert_eq!(got, vec![want]);
        // S after S reflects the second control point of the S; S after Q (not a C) and
        // after M use the current point; T after C uses the current point.
        let got = parse("M 0 0 S 1 1 2 0 S 3 -2 4 0 Q 5 1 6 0 S 7 -1 8 0 T 9 1 L 0 1");
        let want = curves(&[
            &["0 0", "0 0", "1 1", "2 0"],
            &["2 0", "3 -1", "3 -2", "4 0"],
            &["4 0", "5 1", "6 0"],
            &["6 0", "6 0", "7 -1", "8 0"],
            &["8 0", "8 0", "9 1"],
            &["9 1", "0 1"],
            &["0 1", "0 0"],
        ]);
        assert_eq!(got, vec![want]);
        // Relative T and S reflect the same way.
        let got = parse("m 0 0 q 1 1 2 0 t 2 0 c 1 1 2 1 2 0 s 2 -1 2 0 z");
        let want = curves(&[
            &["0 0", "1 1", "2 0"],
            &["2 0", "3 -1", "4 0"],
            &["4 0", "5 1", "6 1", "6 0"],
            &["6 0", "6 -1", "8 -1", "8 0"],
            &["8 0", "0 0"],
        ]);
        assert_eq!(got, vec![want]);
        // A reflection does not cross a subpath: M and Z reset it.
        let got = parse("M 0 0 Q 1 1 2 0 Z T 0 -2 L 0 0 M 5 5 C 6 6 7 6 8 5 M 0 0 S 1 1 2 0");
        assert_eq!(got[1][0], curves(&[&["0 0", "0 0", "0 -2"]])[0]);
        assert_eq!(got[3][0], curves(&[&["0 0", "0 0", "1 1", "2 0"]])[0]);
    }

    #[test]
    fn implicit_repeats_separators_and_numbers() {
        let square = vec![curves(&[
            &["0 0", "2 0"],
            &["2 0", "2 2"],
            &["2 2", "0 2"],
            &["0 2", "0 0"],
        ])];
        for d in [
            "M 0 0 L 2 0 L 2 2 L 0 2 Z",
            "M0,0 2,0 2,2 0,2z",
            "M0 0L2 0 2 2 0 2",
            "m 0 0 2 0 0 2 -2 0 z",
            "M 0 , 0 H 2 V 2 H 0 V 0 Z",
            "\t\n M0\r\n0h2v2h-2\x0Cz  ",
            "M0,0h+2v2.h-2e0v-.2e1Z",
        ] {
            let got = parse(d);
            assert_eq!(got, square, "{d}");
        }
        // Implicit repeats of H and V.
        let got = parse("M0 0 h1 1 v1 1 H0");
        let want = curves(&[
            &["0 0", "1 0"],
            &["1 0", "2 0"],
            &["2 0", "2 1"],
            &["2 1", "2 2"],
            &["2 2", "0 2"],
            &["0 2", "0 0"],
        ]);
        assert_eq!(got, vec![want]);
        // Number boundaries: "-.5.5" is -.5 then .5, "1-2" is 1 then -2, "1e1.5" is 10
        // then .5, "3e" is not an exponent (e is then a command letter).
        let got = parse("M-.5.5L1-2 1e1.5 2E-1+3");
        let want = curves(&[
            &["-0.5 0.5", "1 -2"],
            &["1 -2", "10 0.5"],
            &["10 0.5", "0.2 3"],
            &["0.2 3", "-0.5 0.5"],
        ]);
        assert_eq!(got, vec![want]);
        let (kind, message) = error("M 3e 1 L 2 2");
        assert_eq!(
            (kind, message.as_str()),
            (
                ErrorKind::Invalid,
                "at 3: expected a number ('M' takes 2 per segment), found 'e'"
            )
        );
        // Numbers are read exactly: 0.1 + 0.2 is 3/10, not the sum of doubles.
        let got = parse("M 0.1 0 l 0.2 0 l 0 1");
        assert_eq!(got[0][0].points()[1][0], r("0.3"));
        // As doubles, then added exactly.
        let doubles =
            parse_svg_path("M 0.1 0 l 0.2 0 l 0 1", |t| parse_f64(t).map(exact_f64)).unwrap();
        let sum = exact_f64(0.1) + exact_f64(0.2);
        assert_eq!(doubles[0][0].points()[1][0], sum);
        assert_ne!(sum, exact_f64(0.1 + 0.2));
    }

    #[test]
    fn subpaths_closing_dropping_and_starting_after_z() {
        // After Z a relative command starts at the closed subpath's start.
        let got = parse("M 1 1 L 3 1 L 1 3 Z l 0 -1 l -1 1 z");
        assert_eq!(got.len(), 2);
        assert_eq!(
            got[1],
            curves(&[&["1 1", "1 0"], &["1 0", "0 1"], &["0 1", "1 1"]])
        );
        // After Z, m is relative to the start too.
        let got = parse("M 1 1 h 1 v 1 z m 2 0 h 1 v 1 z");
        assert_eq!(got[1][0], curves(&[&["3 1", "4 1"]])[0]);
        // Unclosed subpaths are closed by a line, before M and at the end.
        let got = parse("M 0 0 L 1 0 L 0 1 M 5 5 Q 6 6 5 7");
        assert_eq!(got[0].len(), 3);
        assert_eq!(got[0][2], curves(&[&["0 1", "0 0"]])[0]);
        assert_eq!(got[1][1], curves(&[&["5 7", "5 5"]])[0]);
        // A subpath ending at its start gets no closing line; one going out and back is kept.
        assert_eq!(parse("M 0 0 L 1 0 L 0 0 Z")[0].len(), 2);
        assert_eq!(parse("M 0 0 Q 1 1 0 0")[0].len(), 1);
        // Zero-length subpaths are dropped, zero-length segments in kept ones kept.
        for d in [
            "",
            "  \n",
            "M 1 2",
            "M 1 2 Z",
            "m 1 2 z z",
            "M 1 2 L 1 2 Z",
            "M 1 2 C 1 2 1 2 1 2",
        ] {
            assert!(parse(d).is_empty(), "{d:?}");
        }
        let got = parse("M 9 9 M 0 0 L 0 0 L 1 0 L 0 1 Z M 4 4 Z");
        assert_eq!(got.len(), 1);
        assert_eq!(got[0].len(), 4);
        assert_eq!(got[0][0], curves(&[&["0 0", "0 0"]])[0]);
        // The empty path is the empty region.
        assert!(Region::from_svg_path("M 1 1", FillRule::EvenOdd)
            .unwrap()
            .loops()
            .is_empty());
    }

    #[test]
    fn regions_of_path_data() {
        // Two nested squares, the inner one the same way round: evenodd makes it a hole.
        let d = "M0 0H4V4H0Z M1 1h2v2h-2z";
        let half = [r("1/2"), r("1/2")];
        let middle = [r("2"), r("2")];
        let even = Region::from_svg_path(d, FillRule::EvenOdd).unwrap();
        let nonzero = Region::from_svg_path(d, FillRule::NonZero).unwrap();
        assert_eq!(even.fill(), FillRule::EvenOdd);
        assert_eq!(even.contains(&half), Position::Inside);
        assert_eq!(even.contains(&middle), Position::Outside);
        assert_eq!(nonzero.contains(&middle), Position::Inside);
        assert_eq!(nonzero.winding(&middle), crate::region::Winding::Number(2));
    }

    #[test]
    fn errors_name_the_offset() {
        let cases: [(&str, ErrorKind, &str); 13] = [
            (
                "M 0 0 L 1 0 A 1 1 0 0 1 0 0",
                ErrorKind::Invalid,
                "at 12: arcs (A) are not polynomial curves; convert them to cubics",
            ),
            (
                "M0 0a1 1 0 0 1 2 2",
                ErrorKind::Invalid,
                "at 4: arcs (A) are not polynomial curves; convert them to cubics",
            ),
            (
                "M 0 0 X 1",
                ErrorKind::UnknownName,
                "at 6: unknown command 'X'",
            ),
            (
                "M 0 0 L 1 1 é",
                ErrorKind::UnknownName,
                "at 12: unknown command 'é'",
            ),
            ("B 1 2", ErrorKind::UnknownName, "at 0: unknown command 'B'"),
            (
                "  L 1 2",
                ErrorKind::Invalid,
                "at 2: path data must start with M or m, found 'L'",
            ),
            (
                "1 2",
                ErrorKind::Invalid,
                "at 0: path data must start with M or m, found '1'",
            ),
            (
                "M 0",
                ErrorKind::Invalid,
                "at 3: expected a number ('M' takes 2 per segment), found the end of the data",
            ),
            (
                "M 0 0 c 1 1 2 Z",
                ErrorKind::Invalid,
                "at 14: expected a number ('c' takes 6 per segment), found 'Z'",
            ),
            (
                "M,0 0",
                ErrorKind::Invalid,
                "at 1: expected a number ('M' takes 2 per segment), found ','",
            ),
            (
                "M 0 0 L 1 1, Z",
                ErrorKind::Invalid,
                "at 13: expected a number after ',' ('L' takes 2 per segment), found 'Z'",
            ),
            (
                "M 0 0 L 1 1,, 2 2",
                ErrorKind::Invalid,
                "at 12: expected a number after ',' ('L' takes 2 per segment), found ','",
            ),
            (
                "M 0 0 H 1 V 1 Z 3",
                ErrorKind::Invalid,
                "at 16: expected a command letter, found '3'",
            ),
        ];
        for (d, kind, message) in cases {
            assert_eq!(error(d), (kind, message.to_string()), "{d}");
        }
        // The reader's own errors pass through with the offset.
        let (kind, message) = error("M 0 0 L 1e999999 0");
        assert_eq!(kind, ErrorKind::TooLarge);
        assert!(message.starts_with("at 8: the exponent"), "{message}");
        let e = parse_svg_path("M 0 0 L 1 x", |t: &str| -> Result<Rational> {
            parse_rational(t)
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "at 10: expected a number ('L' takes 2 per segment), found 'x'"
        );
        let e = parse_svg_path("M 0 0 L 7 1", |t: &str| {
            if t == "7" {
                Err(crate::Error::of(ErrorKind::Domain, "", "seven"))
            } else {
                parse_rational(t)
            }
        })
        .unwrap_err();
        assert_eq!(
            (e.kind, e.message.as_str()),
            (ErrorKind::Domain, "at 8: seven")
        );
    }
}
