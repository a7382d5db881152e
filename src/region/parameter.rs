//! The parameters of result edges: exact numbers, made exact only when asked.
//!
//! A parameter is either known exactly from the start (a curve's end 0 or 1, or a number the
//! exact pipeline found) or a *certified crossing*: the float filter
//! ([`certified_crossings_f64`](crate::certified_crossings_f64)) proved that the two curves
//! cross exactly once in a box of doubles, and gave the correctly rounded double of each
//! parameter. Both facts are proofs, so the answer is certified without the exact number; the
//! exact [`AlgebraicReal`] (resultant, square-free part, isolating interval) is computed from
//! the two curves on the first call to [`Parameter::algebraic`], then kept. A boolean of regions
//! with a few dozen crossings therefore costs float work only, unless its caller asks for the
//! exact numbers.

use crate::error::{Error, ErrorKind, Result};
use crate::intersect::algebraic::{exact_f64, AlgebraicReal};
use crate::intersect::curves::{intersect_curves_f64, Intersections};
use crate::num::ring::Rational;
use crate::num::small::SmallRational;
use crate::region::arrangement::CurveId;
use crate::region::input::Doubles;
use crate::region::straight::Straight;
use std::cmp::Ordering;
use std::fmt;
use std::sync::{Arc, OnceLock};

/// One exact parameter of a result edge (see [`Edge`](super::Edge)).
///
/// [`to_f64`](Parameter::to_f64) and [`enclosure`](Parameter::enclosure) are free: the double
/// nearest to the exact parameter (ties to even) and doubles around it, both certified.
/// [`algebraic`](Parameter::algebraic) gives the exact algebraic number; for a crossing found by the
/// float filter it is computed on the first call (exact intersection of the two curves, a
/// fraction of a millisecond for cubics) and kept.
///
/// ```
/// use blossom::region::{boolean, BooleanOp, FillRule, Region};
/// use blossom::Bezier;
/// let square = |x: f64, y: f64| -> Result<Region, blossom::Error> {
///     let c = [[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]];
///     let sides = (0..4).map(|i| Bezier::new(vec![c[i], c[(i + 1) % 4]]));
///     Region::from_f64(vec![sides.collect::<Result<_, _>>()?], FillRule::NonZero)
/// };
/// let r = boolean(&square(0.0, 0.0)?, &square(1.0, 1.0)?, BooleanOp::Intersection)?;
/// for e in &r.loops[0].edges {
///     let [lo, hi] = e.from.enclosure();
///     assert!(lo <= e.from.to_f64() && e.from.to_f64() <= hi);
///     // The exact number rounds to the same double.
///     assert_eq!(e.from.algebraic()?.to_f64(), e.from.to_f64());
/// }
/// # Ok::<(), blossom::Error>(())
/// ```
#[derive(Clone)]
pub struct Parameter {
    /// The nearest double, except for a straight quadratic's parameter (a double in the
    /// enclosure; see [`Parameter::to_f64`]).
    nearest: f64,
    enclosure: [f64; 2],
    /// Boxed: most parameters never make their exact number, and a small `Parameter` is
    /// cheap to sort and copy.
    exact: OnceLock<Box<AlgebraicReal>>,
    source: Source,
}

/// What makes the exact number when it is not known yet.
#[derive(Clone)]
enum Source {
    /// Known from the start.
    Known,
    /// A curve's end: 0 (`false`) or 1 (`true`).
    End(bool),
    /// A crossing proved by the float filter.
    Crossing(Crossing),
    /// An exact rational found in fixed-width arithmetic (the contacts of segments with
    /// integer or dyadic ends): compared without big integers.
    Small(SmallRational),
    /// The parameter t = φ⁻¹(u) of a straight quadratic whose chord parameter u was found in
    /// fixed width (module `straight`): compared by u; its certified nearest double (kept
    /// here) and its exact number made on demand.
    Straight(SmallRational, Straight, OnceLock<f64>),
}

/// Where a crossing parameter comes from: the pair, which side, and both enclosures (which
/// pick the crossing among the pair's exact intersections).
#[derive(Clone)]
struct Crossing {
    all: Arc<Crossings>,
    /// The index of the pair in `all`.
    pair: usize,
    /// 0: the parameter on the pair's first curve, 1: on the second.
    side: usize,
    s: [f64; 2],
    t: [f64; 2],
}

/// The curves of the two regions of one boolean (shared, not copied), the pairs of curves
/// that cross, and each pair's exact intersections once computed.
pub(crate) struct Crossings {
    doubles: [Arc<Doubles>; 2],
    pairs: Vec<[CurveId; 2]>,
    exact: Vec<OnceLock<std::result::Result<Intersections, Error>>>,
}

impl Crossings {
    pub(crate) fn new(doubles: [Arc<Doubles>; 2], pairs: Vec<[CurveId; 2]>) -> Arc<Crossings> {
        let exact = pairs.iter().map(|_| OnceLock::new()).collect();
        Arc::new(Crossings {
            doubles,
            pairs,
            exact,
        })
    }

    fn points(&self, id: CurveId) -> &[[f64; 2]] {
        &self.doubles[id.region][id.loop_index][id.curve]
    }

    /// The exact intersections of pair k, computed once.
    fn exact(&self, k: usize) -> &std::result::Result<Intersections, Error> {
        let [p, q] = self.pairs[k];
        self.exact[k].get_or_init(|| intersect_curves_f64(self.points(p), self.points(q)))
    }
}

/// Whether the exact number `x` lies in the closed interval of doubles `[lo, hi]`.
fn inside(x: &AlgebraicReal, [lo, hi]: [f64; 2]) -> bool {
    x.cmp_rational(&exact_f64(lo)) != Ordering::Less
        && x.cmp_rational(&exact_f64(hi)) != Ordering::Greater
}

impl Parameter {
    /// An exact number.
    pub(crate) fn known(x: AlgebraicReal) -> Parameter {
        // The correctly rounded double, and the doubles on either side of it (the exact
        // number is within half an ulp of it), or the double itself when the number is one:
        // one rounding instead of three.
        let nearest = x.to_f64();
        let enclosure = match x.exact() {
            Some(r) if nearest.is_finite() && &exact_f64(nearest) == r => [nearest, nearest],
            _ => [nearest.next_down(), nearest.next_up()],
        };
        Parameter {
            nearest,
            enclosure,
            exact: OnceLock::from(Box::new(x)),
            source: Source::Known,
        }
    }

    /// A curve's end, 0 or 1 (its exact number made on demand, to spare the allocations).
    pub(crate) fn end(one: bool) -> Parameter {
        let x = f64::from(u8::from(one));
        Parameter {
            nearest: x,
            enclosure: [x, x],
            exact: OnceLock::new(),
            source: Source::End(one),
        }
    }

    /// An exact rational found in fixed-width arithmetic (its big form made on demand).
    pub(crate) fn small(x: SmallRational) -> Parameter {
        let (nearest, enclosure) = x.to_f64_enclosure();
        Parameter {
            nearest,
            enclosure,
            exact: OnceLock::new(),
            source: Source::Small(x),
        }
    }

    /// The parameter t = φ⁻¹(u) of a straight quadratic of kind `kind` at the chord
    /// parameter u (module `straight`), its double certified now, its exact number made on
    /// demand.
    pub(crate) fn straight(u: SmallRational, kind: Straight) -> Parameter {
        let (approx, enclosure) = kind.enclosure(u);
        Parameter {
            nearest: approx,
            enclosure,
            exact: OnceLock::new(),
            source: Source::Straight(u, kind, OnceLock::new()),
        }
    }

    /// The parameter of a point of a chord (a segment, or a straight quadratic's chord when
    /// `kind` is one) at the chord parameter u.
    pub(crate) fn on_chord(u: SmallRational, kind: Option<Straight>) -> Parameter {
        match kind {
            Some(kind) => Parameter::straight(u, kind),
            None => Parameter::small(u),
        }
    }

    /// The chord parameter u of the point, as a fixed-width rational when known without exact
    /// work: a curve's end (0 or 1), a number found in fixed width on a segment, or the u of a
    /// straight quadratic's parameter.
    pub(crate) fn chord_coordinate(&self) -> Option<SmallRational> {
        match self.source {
            Source::End(one) => Some(SmallRational::integer(i64::from(one))),
            Source::Small(x) | Source::Straight(x, ..) => Some(x),
            _ => None,
        }
    }

    /// The parameter on side `side` (0: first curve, 1: second) of the crossing of pair
    /// `pair` of `all` proved in the box `s` x `t`, with `nearest` its correctly rounded
    /// double.
    pub(crate) fn crossing(
        all: Arc<Crossings>,
        pair: usize,
        side: usize,
        s: [f64; 2],
        t: [f64; 2],
        nearest: f64,
    ) -> Parameter {
        Parameter {
            nearest,
            enclosure: if side == 0 { s } else { t },
            exact: OnceLock::new(),
            source: Source::Crossing(Crossing {
                all,
                pair,
                side,
                s,
                t,
            }),
        }
    }

    /// The double nearest to the exact parameter (ties to even), certified.
    pub fn to_f64(&self) -> f64 {
        match &self.source {
            Source::Straight(u, kind, nearest) => *nearest.get_or_init(|| kind.nearest(*u).0),
            _ => self.nearest,
        }
    }

    /// A double inside [`enclosure`](Parameter::enclosure) (the nearest one, except for a
    /// straight quadratic's parameter, whose nearest double is certified only on demand):
    /// what the float stages compute with, the enclosure's width as the bound.
    pub(crate) fn approx(&self) -> f64 {
        self.nearest
    }

    /// Doubles `[lo, hi]` with lo <= the exact parameter <= hi (a few ulps apart for a
    /// crossing; the two doubles around it, or the double itself, for a known number).
    pub fn enclosure(&self) -> [f64; 2] {
        self.enclosure
    }

    /// Whether the parameter is known to be the end 0 or 1 of its curve without exact work
    /// (`Some(false)` for 0, `Some(true)` for 1); crossings proved by the filter lie strictly
    /// inside (0, 1), so they answer `None`.
    pub fn curve_end(&self) -> Option<bool> {
        match self.source {
            Source::End(one) => return Some(one),
            Source::Small(x) | Source::Straight(x, ..) if x == SmallRational::ZERO => {
                return Some(false)
            }
            Source::Small(x) | Source::Straight(x, ..) if x == SmallRational::ONE => {
                return Some(true)
            }
            Source::Small(_) | Source::Straight(..) => return None,
            _ => {}
        }
        let x = self.exact.get()?.exact()?;
        if x == &Rational::from_integer(0.into()) {
            Some(false)
        } else if x == &Rational::from_integer(1.into()) {
            Some(true)
        } else {
            None
        }
    }

    /// The exact parameter: computed on the first call for a crossing proved by the float
    /// filter, from the exact intersections of its two curves, then kept.
    ///
    /// # Errors
    /// Those of [`intersect_curves`](crate::intersect_curves) on the two curves (none for
    /// curves the filter decided, whose degrees are within the region limit), and an
    /// `Invalid` error if no exact intersection lies in the certified box (a bug).
    pub fn algebraic(&self) -> Result<&AlgebraicReal> {
        if let Some(x) = self.exact.get() {
            return Ok(x);
        }
        let c = match &self.source {
            Source::Crossing(c) => c,
            Source::End(one) => {
                let x = Rational::from_integer(i64::from(*one).into());
                return Ok(self
                    .exact
                    .get_or_init(|| Box::new(AlgebraicReal::from_rational(x))));
            }
            Source::Small(x) => {
                return Ok(self
                    .exact
                    .get_or_init(|| Box::new(AlgebraicReal::from_rational(x.to_rational()))));
            }
            Source::Straight(u, kind, _) => {
                return Ok(self.exact.get_or_init(|| Box::new(kind.root(*u))));
            }
            Source::Known => unreachable!("a known parameter has its exact number"),
        };
        let found = c
            .all
            .exact(c.pair)
            .as_ref()
            .map_err(Clone::clone)?
            .points
            .iter()
            .find(|x| inside(&x.s, c.s) && inside(&x.t, c.t))
            .ok_or_else(|| {
                Error::of(
                    ErrorKind::Invalid,
                    "parameter",
                    "internal: no exact intersection lies in the certified box",
                )
            })?;
        let x = if c.side == 0 { &found.s } else { &found.t };
        Ok(self.exact.get_or_init(|| Box::new(x.clone())))
    }

    /// The exact order of two parameters (of one curve): their enclosures first, exact
    /// numbers only where those meet.
    ///
    /// # Errors
    /// Those of [`Parameter::algebraic`].
    pub fn compare(&self, other: &Parameter) -> Result<Ordering> {
        if self.same_source(other) {
            return Ok(Ordering::Equal);
        }
        if self.enclosure[1] < other.enclosure[0] {
            return Ok(Ordering::Less);
        }
        if other.enclosure[1] < self.enclosure[0] {
            return Ok(Ordering::Greater);
        }
        // Fixed-width numbers of one kind (φ is increasing, so u orders a straight
        // quadratic's parameters; its ends are u = 0 and 1).
        let straight = |p: &Parameter| match p.source {
            Source::Straight(_, kind, _) => Some(kind),
            _ => None,
        };
        let comparable = match (straight(self), straight(other)) {
            (Some(a), Some(b)) => a == b,
            (Some(_), None) => matches!(other.source, Source::End(_)),
            (None, Some(_)) => matches!(self.source, Source::End(_)),
            (None, None) => true,
        };
        if let (true, Some(a), Some(b)) = (
            comparable,
            self.chord_coordinate(),
            other.chord_coordinate(),
        ) {
            return Ok(a.cmp(&b));
        }
        Ok(self.algebraic()?.compare(other.algebraic()?))
    }
}

impl Parameter {
    /// Whether the two are the same number by construction: the same end of a curve, or the
    /// same side of the same certified crossing (no exact work).
    fn same_source(&self, other: &Parameter) -> bool {
        match (&self.source, &other.source) {
            (Source::End(a), Source::End(b)) => a == b,
            (Source::Crossing(a), Source::Crossing(b)) => {
                Arc::ptr_eq(&a.all, &b.all)
                    && a.pair == b.pair
                    && a.side == b.side
                    && a.s == b.s
                    && a.t == b.t
            }
            _ => false,
        }
    }
}

impl From<AlgebraicReal> for Parameter {
    fn from(x: AlgebraicReal) -> Parameter {
        Parameter::known(x)
    }
}

impl fmt::Debug for Parameter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.exact.get(), &self.source) {
            (Some(x), _) => write!(f, "{x}"),
            (None, Source::End(one)) => write!(f, "{}", u8::from(*one)),
            (None, Source::Small(x)) if x.denom() == 1 => write!(f, "{}", x.numer()),
            (None, Source::Small(x)) => write!(f, "{}/{}", x.numer(), x.denom()),
            (None, Source::Straight(u, kind, _)) => write!(
                f,
                "{:?} (φ⁻¹({}/{}) of a straight quadratic, {kind:?})",
                self.nearest,
                u.numer(),
                u.denom()
            ),
            (None, _) => write!(
                f,
                "{:?} (crossing in [{:?}, {:?}])",
                self.nearest, self.enclosure[0], self.enclosure[1]
            ),
        }
    }
}

impl fmt::Display for Parameter {
    /// The exact number when known (`1/2`, or the root with its polynomial), else the
    /// correctly rounded double with its certified enclosure.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}
