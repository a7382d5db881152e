"""Certified intersections of Bézier curves of high degree (9 to 40), independent of the library.

Writes `cases.json` beside this file: curve pairs of degrees 9 to 40 and single curves of degree
8 to 40 (self-intersections), each with every intersection in [0, 1]^2, each parameter given by
an enclosure [lo, hi] of exact dyadic rationals (width about 2^-100) that holds it.

# Method (shares nothing with the Rust library)

The library isolates with Bernstein subdivision, Descartes' rule on exact Bernstein
coefficients, resultants and a float filter on Bernstein hulls. Here every curve is put in the
power basis exactly (Python fractions), and everything after that is rigorous interval
arithmetic of mpmath (`mpmath.iv`, outward rounding, 200-bit endpoints):

* a *piece* [lo, hi] of a curve carries the Taylor coefficients d_k of each coordinate at its
  centre c (a Taylor shift of the power form in interval arithmetic); over the piece the
  coordinate lies in d_0 + [-B, B] with B = sum_{k>=1} |d_k| r^k (r the half-width), and its
  derivative in d_1 + [-B', B'], B' = sum_{k>=2} k |d_k| r^(k-1);
* two pieces whose boxes are disjoint hold no intersection; a pair of pieces S x T is
  otherwise tested with Krawczyk's operator for F(s, t) = P(s) - Q(t):
  K = m - Y F(m) + (I - Y J(S x T)) (S x T - m), Y an approximate inverse of the midpoint of
  the interval Jacobian J = [P'(S), -Q'(T)]. K inside the interior of S x T proves exactly one
  zero in S x T (and then K is iterated, intersected with the box, down to width 2^-100);
  K disjoint from S x T proves none; else both pieces are halved and the four pairs go back
  on the list;
* one curve with itself: pairs of pieces S before T. A piece with itself, or two pieces that
  touch end to end, hold no pair s < t with P(s) = P(t) when one coordinate's derivative keeps
  one sign over their union (the curve is one-to-one there); otherwise they are halved. Pairs
  that do not touch are tested as above with F(s, t) = P(s) - P(t).

The answer is a **certified count**: [0, 1]^2 (or its part s < t) is covered by boxes each of
which holds no zero or exactly one, proved; a case where some box is still undecided at width
2^-40 (a tangency, a zero on a box edge or on the border of the square) is dropped, and the
generator draws the next one. Points are transversal by construction of the count (a regular
Jacobian), so no case has a tangency or an overlap.

Run: `python3 tests/intersect_corpus/high_degree/truth.py` (sympy not needed; mpmath, and gmpy2
for speed). Deterministic (fixed seeds).
"""

from fractions import Fraction
from math import comb
import json
import os
import random
import sys
import time

from mpmath import iv
from mpmath.libmp import to_rational

iv.prec = 200

MIN_WIDTH = Fraction(1, 2**40)
TARGET_WIDTH = Fraction(1, 2**100)
START_PIECES = 16


def to_iv(q):
    """An exact fraction as an interval (exact when the denominator is a power of two)."""
    q = Fraction(q)
    return iv.mpf(q.numerator) / iv.mpf(q.denominator)


def ends(x):
    """The two end points of an interval as exact fractions."""
    (a, b) = x._mpi_
    pa, qa = to_rational(a)
    pb, qb = to_rational(b)
    return Fraction(pa, qa), Fraction(pb, qb)


def power_form(coefficients):
    """sum b_i C(n, i) t^i (1 - t)^(n - i) = sum a_k t^k, exactly."""
    n = len(coefficients) - 1
    return [
        comb(n, k) * sum((-1) ** (k - i) * comb(k, i) * Fraction(coefficients[i]) for i in range(k + 1))
        for k in range(n + 1)
    ]


class Curve:
    def __init__(self, points):
        self.power = [[to_iv(a) for a in power_form([p[c] for p in points])] for c in range(2)]
        self.pieces = {}

    def piece(self, lo, hi):
        key = (lo, hi)
        if key not in self.pieces:
            self.pieces[key] = Piece(self, lo, hi)
        return self.pieces[key]


class Piece:
    def __init__(self, curve, lo, hi):
        self.curve, self.lo, self.hi = curve, lo, hi
        self.c = (lo + hi) / 2
        self.r = (hi - lo) / 2
        c = to_iv(self.c)
        self.taylor = []
        for a in curve.power:
            d = list(a)
            n = len(d) - 1
            for i in range(n):
                for j in range(n - 1, i - 1, -1):
                    d[j] = d[j] + c * d[j + 1]
            self.taylor.append(d)
        r = to_iv(self.r)
        self.box = [self._value_range(d, r) for d in self.taylor]
        self.slope = [self._slope_range(d, r) for d in self.taylor]

    @staticmethod
    def _value_range(d, r):
        bound = iv.mpf(0)
        power = r
        for k in range(1, len(d)):
            bound += abs(d[k]) * power
            power *= r
        return d[0] + iv.mpf([-bound.b, bound.b])

    @staticmethod
    def _slope_range(d, r):
        if len(d) < 2:
            return iv.mpf(0)
        bound = iv.mpf(0)
        power = r
        for k in range(2, len(d)):
            bound += k * abs(d[k]) * power
            power *= r
        return d[1] + iv.mpf([-bound.b, bound.b])

    def at(self, x):
        """Both coordinates at the interval x (inside the piece), Horner in x - c."""
        h = x - to_iv(self.c)
        out = []
        for d in self.taylor:
            acc = d[-1]
            for k in range(len(d) - 2, -1, -1):
                acc = acc * h + d[k]
            out.append(acc)
        return out

    def derivative(self, x):
        """Both coordinates' derivatives over the interval x (inside the piece)."""
        h = x - to_iv(self.c)
        out = []
        for d in self.taylor:
            n = len(d) - 1
            acc = iv.mpf(n) * d[n]
            for k in range(n - 1, 0, -1):
                acc = acc * h + k * d[k]
            out.append(acc)
        return out

    def halves(self):
        m = self.c
        return self.curve.piece(self.lo, m), self.curve.piece(m, self.hi)


def disjoint(x, y):
    return x.b < y.a or y.b < x.a


def strictly_inside(x, y):
    return y.a < x.a and x.b < y.b


def mid(x):
    return (x.a + x.b) / 2


def krawczyk(A, B, S, T):
    """Krawczyk's operator on S x T for P(s) - Q(t) (A a piece of P holding S, B of Q holding T).
    Returns the new box or None when the Jacobian's midpoint is singular."""
    ms, mt = mid(S), mid(T)
    ps, qt = A.at(ms), B.at(mt)
    f = [ps[0] - qt[0], ps[1] - qt[1]]
    dp, dq = A.derivative(S), B.derivative(T)
    j = [[dp[0], -dq[0]], [dp[1], -dq[1]]]
    jm = [[float(mid(j[r][c]).a) for c in range(2)] for r in range(2)]
    det = jm[0][0] * jm[1][1] - jm[0][1] * jm[1][0]
    if det == 0:
        return None
    y = [[jm[1][1] / det, -jm[0][1] / det], [-jm[1][0] / det, jm[0][0] / det]]
    y = [[iv.mpf(v) for v in row] for row in y]
    dx = [S - ms, T - mt]
    out = []
    m = [ms, mt]
    for r in range(2):
        acc = m[r] - (y[r][0] * f[0] + y[r][1] * f[1])
        for c in range(2):
            e = (1 if r == c else 0) - (y[r][0] * j[0][c] + y[r][1] * j[1][c])
            acc = acc + e * dx[c]
        out.append(acc)
    return out


def width(x):
    lo, hi = ends(x)
    return hi - lo


def narrow(A, B, S, T):
    """Iterates Krawczyk inside a proved box down to the target width."""
    for _ in range(60):
        if width(S) < TARGET_WIDTH and width(T) < TARGET_WIDTH:
            break
        k = krawczyk(A, B, S, T)
        if k is None:
            break
        ns = iv.mpf([max(k[0].a, S.a), min(k[0].b, S.b)])
        nt = iv.mpf([max(k[1].a, T.a), min(k[1].b, T.b)])
        if width(ns) >= width(S) and width(nt) >= width(T):
            break
        S, T = ns, nt
    return S, T


class Undecided(Exception):
    pass


def solve(P, Q, self_mode):
    """Every zero of P(s) - Q(t) in [0, 1]^2 (self_mode: Q is P, zeros with s < t)."""
    step = Fraction(1, START_PIECES)
    ps = [P.piece(i * step, (i + 1) * step) for i in range(START_PIECES)]
    qs = [Q.piece(i * step, (i + 1) * step) for i in range(START_PIECES)]
    if self_mode:
        work = [(ps[i], ps[j]) for i in range(START_PIECES) for j in range(i, START_PIECES)]
    else:
        work = [(a, b) for a in ps for b in qs]
    roots = []
    while work:
        A, B = work.pop()
        if self_mode and (A is B or A.hi == B.lo):
            # One-to-one over the union when a coordinate's derivative keeps its sign.
            if any(not (0 in (A.slope[c] if A is B else iv.mpf([min(A.slope[c].a, B.slope[c].a), max(A.slope[c].b, B.slope[c].b)])))
                   for c in range(2)):
                continue
            if A.r * 2 < MIN_WIDTH:
                raise Undecided(f"diagonal piece [{float(A.lo)}, {float(B.hi)}]")
            if A is B:
                L, R = A.halves()
                work += [(L, L), (R, R), (L, R)]
            else:
                A0, A1 = A.halves()
                B0, B1 = B.halves()
                work += [(A0, B0), (A0, B1), (A1, B0), (A1, B1)]
            continue
        if disjoint(A.box[0], B.box[0]) or disjoint(A.box[1], B.box[1]):
            continue
        S = iv.mpf([to_iv(A.lo).a, to_iv(A.hi).b])
        T = iv.mpf([to_iv(B.lo).a, to_iv(B.hi).b])
        k = krawczyk(A, B, S, T)
        if k is not None:
            if disjoint(k[0], S) or disjoint(k[1], T):
                continue
            if strictly_inside(k[0], S) and strictly_inside(k[1], T):
                roots.append(narrow(A, B, k[0], k[1]))
                continue
        if A.r * 2 < MIN_WIDTH or B.r * 2 < MIN_WIDTH:
            raise Undecided(f"box [{float(A.lo)}, {float(A.hi)}] x [{float(B.lo)}, {float(B.hi)}]")
        A0, A1 = A.halves()
        B0, B1 = B.halves()
        work += [(A0, B0), (A0, B1), (A1, B0), (A1, B1)]
    return roots


def fraction_text(q):
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


GRID = 2**110


def parameter(x):
    lo, hi = ends(x)
    # Outward to multiples of 2^-110: shorter numbers, still an enclosure.
    lo = Fraction(lo.numerator * GRID // lo.denominator, GRID)
    hi = Fraction(-((-hi.numerator * GRID) // hi.denominator), GRID)
    a, b = float(lo), float(hi)  # Fraction -> float rounds correctly (ties to even)
    # The double as its shortest round-trip text: a JSON number would be read back by some
    # parsers (serde_json without `float_roundtrip`) one ulp off.
    return {"lo": fraction_text(lo), "hi": fraction_text(hi), "value": repr(a) if a == b else None}


def number_json(q):
    q = Fraction(q)
    return q.numerator if q.denominator == 1 else fraction_text(q)


def answer(points):
    out = [{"s": parameter(s), "t": parameter(t)} for s, t in points]
    out.sort(key=lambda p: Fraction(p["s"]["lo"]))
    return out


def random_curve(rng, degree, size, denominator=1):
    return [[Fraction(rng.randint(-size, size), denominator) for _ in range(2)] for _ in range(degree + 1)]


# (name, degree of P, degree of Q, coordinate size, denominator)
PAIRS = [
    ("pair-9-9", 9, 9, 20, 1),
    ("pair-9-9-thirds", 9, 9, 20, 3),
    ("pair-10-12", 10, 12, 20, 1),
    ("pair-11-11-sevenths", 11, 11, 30, 7),
    ("pair-12-12", 12, 12, 20, 1),
    ("pair-9-20", 9, 20, 20, 1),
    ("pair-14-14", 14, 14, 50, 1),
    ("pair-16-16", 16, 16, 20, 1),
    ("pair-13-29", 13, 29, 20, 1),
    ("pair-20-20", 20, 20, 20, 1),
    ("pair-24-24", 24, 24, 20, 1),
    ("pair-28-28", 28, 28, 20, 1),
    ("pair-9-40", 9, 40, 20, 1),
    ("pair-32-32", 32, 32, 20, 1),
    ("pair-36-36", 36, 36, 20, 1),
    ("pair-40-40", 40, 40, 20, 1),
]
SELF = [
    ("self-8", 8, 20, 1),
    ("self-9-fifths", 9, 20, 5),
    ("self-10", 10, 20, 1),
    ("self-12", 12, 20, 1),
    ("self-14", 14, 20, 1),
    ("self-16", 16, 20, 1),
    ("self-20", 20, 20, 1),
    ("self-24", 24, 20, 1),
    ("self-28", 28, 20, 1),
    ("self-32", 32, 20, 1),
    ("self-40", 40, 20, 1),
]


# Wiggly graphs (the work-budget family of issue 39): P_i = (i m, y_i), Q_j = (j n, z_j), so
# that x = n m s = n m t and the crossings are the zeros of y(s) - z(s); y is A times the
# Bernstein coefficients of the Chebyshev polynomial T_n(2s - 1), (-1)^(n - i) C(2n, 2i) / C(n, i),
# rounded, plus small integers, z small integers: up to n crossings.
WIGGLY = [("wiggly-16-21", 16, 21), ("wiggly-18-18", 18, 18), ("wiggly-20-17", 20, 17), ("wiggly-21-21", 21, 21)]


def wiggly_pair(rng, n, m):
    a, big_a = rng.randint(1, 4), rng.randint(2, 6)
    p = [[Fraction(i * m), Fraction(round(Fraction(big_a * (-1) ** (n - i) * comb(2 * n, 2 * i), comb(n, i))) + rng.randint(-a, a))]
         for i in range(n + 1)]
    q = [[Fraction(j * n), Fraction(rng.randint(-a, a))] for j in range(m + 1)]
    return p, q


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    cases = []
    for index, (name, n, m, size, den) in enumerate(PAIRS):
        rng = random.Random(1000 + index)
        while True:
            p, q = random_curve(rng, n, size, den), random_curve(rng, m, size, den)
            started = time.time()
            try:
                points = solve(Curve(p), Curve(q), False)
            except Undecided as e:
                print(f"{name}: drawn again ({e})", file=sys.stderr)
                continue
            break
        print(f"{name}: {len(points)} points, {time.time() - started:.1f} s", file=sys.stderr)
        cases.append({"name": name, "kind": "curve-curve",
                      "curves": [[[number_json(c) for c in xy] for xy in curve] for curve in (p, q)],
                      "points": answer(points)})
    for index, (name, n, m) in enumerate(WIGGLY):
        rng = random.Random(3000 + index)
        while True:
            p, q = wiggly_pair(rng, n, m)
            started = time.time()
            try:
                points = solve(Curve(p), Curve(q), False)
            except Undecided as e:
                print(f"{name}: drawn again ({e})", file=sys.stderr)
                continue
            break
        print(f"{name}: {len(points)} points, {time.time() - started:.1f} s", file=sys.stderr)
        cases.append({"name": name, "kind": "curve-curve",
                      "curves": [[[number_json(c) for c in xy] for xy in curve] for curve in (p, q)],
                      "points": answer(points)})
    for index, (name, n, size, den) in enumerate(SELF):
        rng = random.Random(2000 + index)
        while True:
            p = random_curve(rng, n, size, den)
            started = time.time()
            try:
                curve = Curve(p)
                points = solve(curve, curve, True)
            except Undecided as e:
                print(f"{name}: drawn again ({e})", file=sys.stderr)
                continue
            break
        print(f"{name}: {len(points)} points, {time.time() - started:.1f} s", file=sys.stderr)
        cases.append({"name": name, "kind": "self",
                      "curve": [[number_json(c) for c in xy] for xy in p],
                      "points": answer(points)})
    with open(os.path.join(here, "cases.json"), "w") as f:
        json.dump(cases, f, indent=None, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
