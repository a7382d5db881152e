"""Exact truth for `blossom intersect`, computed with sympy and Python's `fractions` only.

Nothing here shares the method of the Rust implementation (Bernstein subdivision, Descartes'
rule, the engine): the zeros of a univariate polynomial come from sympy's square-free
factorisation, its factorisation into irreducibles over Q and its real-root isolation (checked
against a Sturm count); the intersections of two curves from the resultant and the first
subresultant in Q[s][t], with every pairing verified exactly in Q[s]/(g(s)); correctly rounded
doubles from exact bisection of an isolating interval (exact sign evaluation of the minimal
polynomial) until both ends round to the same double (Python's int/int division, which is
correctly rounded, ties to even).

An algebraic number is `Alg(m, lo, hi)`: `m` the primitive irreducible integer polynomial
(ascending coefficients, positive leading one) and [lo, hi] an interval holding exactly one
real root of `m` (lo == hi for a rational number, whose `m` is linear).
"""

from fractions import Fraction
from functools import cmp_to_key
import struct

import sympy as sp
from sympy import Poly, QQ, ZZ

S, T, X = sp.symbols("s t x")


# ---------------------------------------------------------------------------------------------
# Numbers


def fr(q):
    """A sympy rational (or int, or Fraction) as a Fraction."""
    if isinstance(q, Fraction):
        return q
    if isinstance(q, int):
        return Fraction(q)
    q = sp.Rational(q)
    return Fraction(int(q.p), int(q.q))


def fmt(q):
    """The spec's exact number string: "p/q" in lowest terms with q > 1, or "p"."""
    q = fr(q)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def bits(v):
    return "%016x" % struct.unpack("<Q", struct.pack("<d", v))[0]


def rnd(q):
    """The double nearest to the rational q, ties to even (Python's int / int is correctly rounded)."""
    q = fr(q)
    return q.numerator / q.denominator


def sgn(v):
    return (v > 0) - (v < 0)


def horner(coeffs, x):
    """Sum coeffs[i] x^i, exactly."""
    acc = Fraction(0)
    for c in reversed(coeffs):
        acc = acc * x + c
    return acc


def interval_horner(coeffs, lo, hi):
    """An enclosure [a, b] of {sum coeffs[i] x^i : lo <= x <= hi}, exact interval arithmetic."""
    a = b = Fraction(0)
    for c in reversed(coeffs):
        prods = (a * lo, a * hi, b * lo, b * hi)
        a, b = min(prods) + c, max(prods) + c
    return a, b


# ---------------------------------------------------------------------------------------------
# Real algebraic numbers


def primitive_int(poly):
    """A nonzero univariate sympy Poly as a tuple of ints (ascending), primitive, leading > 0."""
    _, p = poly.clear_denoms(convert=True)
    cs = [int(c) for c in reversed(p.all_coeffs())]
    g = 0
    for c in cs:
        g = sp.igcd(g, c)
    cs = [c // g for c in cs]
    if cs[-1] < 0:
        cs = [-c for c in cs]
    return tuple(cs)


class Alg:
    __slots__ = ("m", "lo", "hi", "slo", "idx")

    def __init__(self, m, lo, hi, idx=0):
        self.m = tuple(m)
        self.idx = idx  # which real root of m, counted from the least
        self.lo = fr(lo)
        self.hi = fr(hi)
        if len(self.m) == 2:
            q = Fraction(-self.m[0], self.m[1])
            self.lo = self.hi = q
            self.slo = 0
        else:
            self.slo = sgn(horner(self.m, self.lo))
            assert self.slo != 0 and self.slo == -sgn(horner(self.m, self.hi)), "not isolating"

    @classmethod
    def rat(cls, q):
        q = fr(q)
        return cls((-q.numerator, q.denominator), q, q)

    def copy(self):
        a = Alg.__new__(Alg)
        a.m, a.lo, a.hi, a.slo, a.idx = self.m, self.lo, self.hi, self.slo, self.idx
        return a

    @property
    def rational(self):
        return len(self.m) == 2

    def bisect(self):
        assert not self.rational
        mid = (self.lo + self.hi) / 2
        v = sgn(horner(self.m, mid))
        assert v != 0  # an irreducible polynomial of degree >= 2 has no rational root
        if v == self.slo:
            self.lo = mid
        else:
            self.hi = mid

    def to_double(self):
        if self.rational:
            return rnd(self.lo)
        while rnd(self.lo) != rnd(self.hi):
            self.bisect()
        return rnd(self.lo)

    def approx(self):
        return float((self.lo + self.hi) / 2)

    def param_json(self):
        v = self.to_double()
        return {
            "value": v,
            "bits": bits(v),
            "exact": fmt(self.lo) if self.rational else None,
            "minpoly": [str(c) for c in self.m],
            "enclosure": [fmt(self.lo), fmt(self.hi)],
        }

    def __repr__(self):
        return f"Alg({self.approx():.17g}, deg {len(self.m) - 1})"


def alg_cmp(a, b):
    """-1, 0, 1 as a <, =, > b, decided exactly."""
    if a.rational and b.rational:
        return sgn(a.lo - b.lo)
    if a.m == b.m:
        # Both come from the one isolation of m's real roots (irreducible_real_roots).
        return sgn(a.idx - b.idx)
    # Different numbers (equal numbers have the same minimal polynomial): separate them.
    while True:
        if a.hi < b.lo:
            return -1
        if b.hi < a.lo:
            return 1
        if not a.rational and (b.rational or a.hi - a.lo >= b.hi - b.lo):
            a.bisect()
        else:
            b.bisect()


def cmp_q(a, q):
    return alg_cmp(a, Alg.rat(q))


def in_unit(a):
    return cmp_q(a, 0) >= 0 and cmp_q(a, 1) <= 0


_real_roots_cache = {}


def irreducible_real_roots(m):
    """The real roots of an irreducible primitive integer polynomial m, increasing."""
    if m in _real_roots_cache:
        return [a.copy() for a in _real_roots_cache[m]]
    if len(m) == 2:
        out = [Alg(m, 0, 0)]
    else:
        p = Poly(list(reversed(m)), X, domain=ZZ)
        out = [Alg(m, lo, hi, i) for i, ((lo, hi), k) in enumerate(p.intervals())]
        assert len(out) == p.count_roots()
    _real_roots_cache[m] = out
    return [a.copy() for a in out]


def unit_roots(f):
    """The distinct zeros in [0, 1] of a nonzero univariate Poly f over Q, increasing, with
    their multiplicities: sympy's square-free factorisation, each square-free part factored
    into irreducibles, each irreducible's real roots isolated; cross-checked with a Sturm
    count of the square-free part on [0, 1]."""
    assert not f.is_zero
    if f.degree() <= 0:
        return []
    out = []
    _, parts = f.sqf_list()
    for fk, k in parts:
        _, irr = fk.factor_list()
        for g, e in irr:
            assert e == 1
            for a in irreducible_real_roots(primitive_int(g)):
                if in_unit(a):
                    out.append((a, k))
    assert f.sqf_part().count_roots(0, 1) == len(out)
    out.sort(key=cmp_to_key(lambda u, v: alg_cmp(u[0], v[0])))
    return out


# ---------------------------------------------------------------------------------------------
# Bézier polynomials


def bernstein_power(ctrl):
    """Power coefficients (ascending, Fractions) of sum ctrl[i] C(n,i) x^i (1-x)^(n-i)."""
    n = len(ctrl) - 1
    from math import comb

    a = [Fraction(0)] * (n + 1)
    for i, b in enumerate(ctrl):
        b = fr(b)
        if b == 0:
            continue
        for k in range(i, n + 1):
            a[k] += b * comb(n, i) * comb(n - i, k - i) * (-1) ** (k - i)
    return a


def upoly(coeffs, var):
    return Poly(list(reversed([sp.Rational(c.numerator, c.denominator) for c in coeffs])), var, domain=QQ)


def bezier_expr(ctrl, var):
    return upoly(bernstein_power(ctrl), var).as_expr()


def power_to_bernstein(a):
    """Bernstein coefficients over [0, 1] of the power coefficients a (ascending)."""
    from math import comb

    n = len(a) - 1
    return [sum(Fraction(comb(i, k), comb(n, k)) * fr(a[k]) for k in range(i + 1)) for i in range(n + 1)]


def de_casteljau_restrict(ctrl, a, b):
    """Control points of the curve restricted to [a, b] (exact, by two de Casteljau splits)."""
    a, b = fr(a), fr(b)

    def split(pts, u):  # (left on [0,u], right on [u,1])
        left, right, row = [], [], [list(p) for p in pts]
        while row:
            left.append(row[0])
            right.append(row[-1])
            row = [[(1 - u) * p + u * q for p, q in zip(row[i], row[i + 1])] for i in range(len(row) - 1)]
        return left, right[::-1]

    pts = [[fr(c) for c in p] for p in ctrl]
    if b != 1:
        pts, _ = split(pts, b)
    if a != 0:
        _, pts = split(pts, a / b)
    return [tuple(p) for p in pts]


def elevate(ctrl):
    n = len(ctrl) - 1
    out = [tuple(map(fr, ctrl[0]))]
    for i in range(1, n + 1):
        w = Fraction(i, n + 1)
        out.append(tuple(w * fr(p) + (1 - w) * fr(q) for p, q in zip(ctrl[i - 1], ctrl[i])))
    out.append(tuple(map(fr, ctrl[n])))
    return out


# ---------------------------------------------------------------------------------------------
# Zeros of a Bézier function


def roots_truth(coeffs):
    f = upoly(bernstein_power(coeffs), T)
    if f.is_zero:
        return {"identically_zero": True, "roots": []}
    return {
        "identically_zero": False,
        "roots": [{"t": a.param_json(), "multiplicity": k} for a, k in unit_roots(f)],
    }


# ---------------------------------------------------------------------------------------------
# Arithmetic in Q[u]/(g(u))


def upoly_of(expr, var):
    return Poly(expr, var, domain=QQ)


def coeff_list(P, main, other):
    """P (expr or Poly in main, other) as the list of its coefficients in `main`, ascending,
    each a Poly in `other` over Q."""
    P = Poly(P, main, other, domain=QQ)
    d = P.degree(main)
    cs = [Poly(0, other, domain=QQ) for _ in range(max(d, 0) + 1)]
    for (i, j), c in P.terms():
        cs[i] += Poly(c * other**j, other, domain=QQ)
    return cs


class Hard(Exception):
    """The pairing at an algebraic parameter is not one-to-one: try the other variable."""


def mod_gcd(A, B, g):
    """gcd in (Q[u]/(g))[v] of A and B (coefficient lists of Polys in u), monic; g
    irreducible, so Q[u]/(g) is a field (Euclid's algorithm, inverses modulo g)."""

    def red(cs):
        cs = [c.rem(g) for c in cs]
        while cs and cs[-1].is_zero:
            cs.pop()
        return cs

    a, b = red(A), red(B)
    while b:
        inv = b[-1].invert(g)
        while len(a) >= len(b):
            f = (a[-1] * inv).rem(g)
            shift = len(a) - len(b)
            for i, c in enumerate(b):
                a[i + shift] = (a[i + shift] - f * c).rem(g)
            a = red(a)
            if not a:
                break
        a, b = b, a
    if not a:
        raise Hard("both vanish")
    inv = a[-1].invert(g)
    return [(c * inv).rem(g) for c in a]


def eval_at_rel(P, main, other, N, D, g):
    """D(u)^k P(u, N(u)/D(u)) mod g(u), k the degree of P in `main`: zero exactly when P
    vanishes at (a, N(a)/D(a)) for the roots a of g (D(a) != 0). P is an expression in both
    variables; the homogeneous Horner scheme needs no inverse modulo g."""
    cs = coeff_list(P, main, other)
    acc = Poly(0, other, domain=QQ)
    dpow = Poly(1, other, domain=QQ)
    for c in reversed(cs):
        acc = (acc * N + c * dpow).rem(g)
        dpow = (dpow * D).rem(g)
    return acc


def interval_quotient(n, d):
    assert d[0] > 0 or d[1] < 0
    qs = [x / y for x in n for y in d]
    return min(qs), max(qs)


def alg_of_value(N, D, a, candidates=()):
    """The algebraic number N(a)/D(a) for Polys N, D over Q in one variable and an Alg a with
    D(a) != 0, exactly. It is a real root of one of `candidates` (irreducible integer
    polynomials, pairwise distinct, so without common roots) when given, else of the
    irreducible factor of Res_u(g(u), D(u) x - N(u)), g the minimal polynomial of a; the root
    is the only one whose isolating interval meets an exact interval enclosure of N/D on a's
    isolating interval, refined until just one does."""
    var = N.gens[0]
    if a.rational:
        q = sp.Rational(a.lo.numerator, a.lo.denominator)
        return Alg.rat(fr(N.eval(q)) / fr(D.eval(q)))
    g = Poly(list(reversed(a.m)), var, domain=QQ)
    N, D = N.rem(g), D.rem(g)
    assert not D.is_zero
    if D.degree() <= 0 and N.degree() <= 0:
        return Alg.rat((fr(N.LC()) if not N.is_zero else Fraction(0)) / fr(D.LC()))
    if candidates:
        cands = [c for m in candidates for c in irreducible_real_roots(m)]
    else:
        M = Poly(g.as_expr(), var, X).resultant(Poly(D.as_expr() * X - N.as_expr(), var, X))
        M = Poly(M.as_expr() if hasattr(M, "as_expr") else M, X, domain=QQ)
        _, facs = M.factor_list()
        ms = {primitive_int(f) for f, e in facs if f.degree() > 0}
        assert len(ms) == 1, "the resultant is a power of one irreducible"
        cands = irreducible_real_roots(ms.pop())
    nc = [fr(c) for c in reversed(N.all_coeffs())]
    dc = [fr(c) for c in reversed(D.all_coeffs())]
    a = a.copy()
    while True:
        dlo, dhi = interval_horner(dc, a.lo, a.hi)
        if dlo <= 0 <= dhi:
            a.bisect()
            continue
        lo, hi = interval_quotient(interval_horner(nc, a.lo, a.hi), (dlo, dhi))
        hits = [c for c in cands if not (c.hi < lo or hi < c.lo)]
        if len(hits) == 1:
            return hits[0]
        assert hits, "the value is a real root of a candidate"
        a.bisect()
        for c in hits:
            if not c.rational:
                c.bisect()


def coordinate_json(q, a):
    """The double nearest to q(a) (q a Poly in one variable, a an Alg), with the exact value
    when it is rational."""
    var = q.gens[0]
    if a.rational:
        v = fr(q.eval(sp.Rational(a.lo.numerator, a.lo.denominator)))
        return {"value": rnd(v), "bits": bits(rnd(v)), "exact": fmt(v)}
    g = Poly(list(reversed(a.m)), var, domain=QQ)
    r = q.rem(g)
    if r.degree() <= 0:
        v = fr(r.LC()) if not r.is_zero else Fraction(0)
        return {"value": rnd(v), "bits": bits(rnd(v)), "exact": fmt(v)}
    # Irrational (1, a, ..., a^(d-1) are independent over Q): never on a rounding boundary.
    rc = [fr(c) for c in reversed(r.all_coeffs())]
    a = a.copy()
    while True:
        lo, hi = interval_horner(rc, a.lo, a.hi)
        if rnd(lo) == rnd(hi):
            return {"value": rnd(lo), "bits": bits(rnd(lo)), "exact": None}
        a.bisect()


# ---------------------------------------------------------------------------------------------
# Two polynomial equations A(s, t) = B(s, t) = 0 without a common factor


class Sol:
    """A common zero (s, t) in [0, 1]^2, with how t is tied to s exactly:
    rel = None when s is rational (t is any Alg); ("frac", g, N, D) with t = N(s)/D(s),
    g = s.m (D(s) != 0); or ("conj", g, m): the common zeros over Q(s) are all the roots of
    m = t.m (an integer polynomial), every root of g paired with every root of m."""

    __slots__ = ("s", "t", "rel", "swapped")

    def __init__(self, s, t, rel, swapped=False):
        self.s, self.t, self.rel, self.swapped = s, t, rel, swapped

    def zero_at(self, E):
        """Whether the expression E(s, t) vanishes at this point, exactly."""
        u, v = (T, S) if self.swapped else (S, T)  # u carries the base parameter
        a, b = (self.t, self.s) if self.swapped else (self.s, self.t)
        if self.rel is None:  # a rational
            e = Poly(sp.sympify(E).subs(u, sp.Rational(a.lo.numerator, a.lo.denominator)), v, domain=QQ)
            if b.rational:
                return e.is_zero or fr(e.eval(sp.Rational(b.lo.numerator, b.lo.denominator))) == 0
            return e.rem(Poly(list(reversed(b.m)), v, domain=QQ)).is_zero
        if self.rel[0] == "frac":
            _, g, N, D = self.rel
            return eval_at_rel(E, v, u, N, D, g).is_zero
        # "conj": every root of m is a partner of every root of g; E vanishes at them all,
        # at none, or the point is not decided here.
        _, g, m = self.rel
        ec = coeff_list(E, v, u)
        if all(c.rem(g).is_zero for c in ec):
            return True
        mc = [Poly(c, u, domain=QQ) for c in m]
        k = len(mod_gcd(ec, mc, g)) - 1
        if k == 0:
            return False
        if k == len(m) - 1:
            return True
        raise Hard("a condition holds at some conjugate partners only")


_res_cache = {}


def resultant_factors(A, B, v, u):
    """The distinct irreducible factors (primitive integer tuples) of Res_v(A, B), a
    polynomial in u; [] when it is a nonzero constant."""
    key = (sp.srepr(A), sp.srepr(B), str(v))
    if key not in _res_cache:
        R = Poly(A, v, u, domain=QQ).resultant(Poly(B, v, u, domain=QQ))
        R = Poly(R.as_expr() if hasattr(R, "as_expr") else R, u, domain=QQ)
        assert not R.is_zero, "coprime polynomials have a nonzero resultant"
        _res_cache[key] = [] if R.degree() <= 0 else [primitive_int(f) for f, _e in R.factor_list()[1]]
    return _res_cache[key]


def solve_system(A, B, u=S, v=T):
    """Every common zero (u, v) in [0, 1]^2 of coprime A, B (expressions in u, v)."""
    Ap, Bp = Poly(A, v, u, domain=QQ), Poly(B, v, u, domain=QQ)
    if Ap.is_zero or Bp.is_zero:
        other = Bp if Ap.is_zero else Ap
        assert other.is_ground and not other.is_zero, "coprime"
        return []
    if Ap.is_ground or Bp.is_ground:
        return []
    R = resultant_factors(A, B, v, u)
    if not R:
        return []
    # The partner of a common zero is a root of Res_u(A, B): its irreducible factors are the
    # candidates for the partner's minimal polynomial.
    partners = resultant_factors(A, B, u, v)
    prs = Ap.subresultants(Bp)
    S1 = [p for p in prs if p.degree(v) == 1]
    Acs, Bcs = coeff_list(A, v, u), coeff_list(B, v, u)
    out = []
    for m in R:
        roots = [a for a in irreducible_real_roots(m) if in_unit(a)]
        if not roots:
            continue
        if len(m) == 2:
            a = roots[0]
            ar = sp.Rational(a.lo.numerator, a.lo.denominator)
            ea = Poly(sp.sympify(A).subs(u, ar), v, domain=QQ)
            eb = Poly(sp.sympify(B).subs(u, ar), v, domain=QQ)
            H = ea.gcd(eb)
            assert not H.is_zero
            for b, _k in unit_roots(H):
                out.append(Sol(a, b, None))
            continue
        g = Poly(list(reversed(m)), u, domain=QQ)
        rel = None
        lead_ok = not Acs[-1].rem(g).is_zero or not Bcs[-1].rem(g).is_zero
        if S1 and lead_ok:
            # The first subresultant c1(u) v + c0(u): where the resultant vanishes and c1 does
            # not, the common root is v = -c0/c1.
            c = coeff_list(S1[-1].as_expr(), v, u)
            if not c[1].rem(g).is_zero:
                rel = ("frac", g, -c[0], c[1])
        if rel is None:
            H = mod_gcd(Acs, Bcs, g)
            if len(H) == 2:
                rel = ("frac", g, (-H[0]).rem(g), Poly(1, u, domain=QQ))
            else:
                # Several partners over Q(a): the candidates' common factor with H decides.
                for mp in partners:
                    Dg = mod_gcd(H, [Poly(c, u, domain=QQ) for c in mp], g)
                    k = len(Dg) - 1
                    if k == 0:
                        continue
                    if k == 1:
                        out += paired(A, B, u, v, g, ("frac", g, (-Dg[0]).rem(g), Poly(1, u, domain=QQ)), roots, partners)
                    elif k == len(mp) - 1:
                        for a in roots:
                            for b in irreducible_real_roots(mp):
                                if in_unit(b):
                                    out.append(Sol(a, b, ("conj", g, mp)))
                    else:
                        raise Hard(f"{k} of the {len(mp) - 1} roots of a partner polynomial pair with one parameter")
                continue
        out += paired(A, B, u, v, g, rel, roots, partners)
    return out


def paired(A, B, u, v, g, rel, roots, partners):
    """The common zeros (a, N(a)/D(a)) for the roots a of g in [0, 1], the relation verified
    exactly first: A(u, N/D) = B(u, N/D) = 0 in Q[u]/(g)."""
    _, _, N, D = rel
    assert eval_at_rel(A, v, u, N, D, g).is_zero and eval_at_rel(B, v, u, N, D, g).is_zero
    out = []
    for a in roots:
        b = alg_of_value(N, D, a, partners)
        if in_unit(b):
            out.append(Sol(a, b, rel))
    return out


def same_points(xs, ys):
    if len(xs) != len(ys):
        return False
    return all(any(alg_cmp(x.s, y.s) == 0 and alg_cmp(x.t, y.t) == 0 for y in ys) for x in xs)


def solve_both_ways(A, B):
    """The common zeros, found by eliminating t and, independently, by eliminating s; when both
    succeed they must agree (this also catches a parameter paired with two partners)."""
    try:
        one = solve_system(A, B, S, T)
    except Hard:
        one = None
    try:
        two = [Sol(x.t, x.s, x.rel, swapped=True) for x in solve_system(A, B, T, S)]
    except Hard:
        two = None
    if one is None and two is None:
        raise Hard("both eliminations")
    if one is not None and two is not None:
        assert same_points(one, two), "the two eliminations disagree"
    return one if one is not None else two


# ---------------------------------------------------------------------------------------------
# Curve-curve and self


def clip_linear(f, selfmode):
    """The stretch of the line f(s, t) = 0 (f of degree one in each variable) inside the
    unit square (and s <= t for a curve with itself): None, a single point, or (s0, s1)."""
    fp = Poly(f, S, T, domain=QQ)
    a = fr(fp.coeff_monomial(S))
    b = fr(fp.coeff_monomial(T))
    c = fr(fp.coeff_monomial(1))
    if a == 0 or b == 0 or fp.total_degree() != 1:
        raise ValueError(f"common factor {f} is not a reparametrisation")

    def tof(sv):
        return -(a * sv + c) / b

    lo, hi = Fraction(0), Fraction(1)
    # 0 <= t(s) <= 1 with t(s) = k s + d
    k, d = -a / b, -c / b
    for bound_lo, bound_hi in [(Fraction(0), Fraction(1))]:
        # k s + d >= 0 and k s + d <= 1
        e1, e2 = (bound_lo - d) / k, (bound_hi - d) / k
        lo, hi = max(lo, min(e1, e2)), min(hi, max(e1, e2))
    if selfmode:
        # s <= k s + d ; the relation of a curve with itself reverses the parameter (k < 0)
        if k >= 0:
            raise ValueError("a polynomial curve cannot repeat itself with the same orientation")
        hi = min(hi, d / (1 - k))
    if lo > hi:
        return None
    if lo == hi:
        return ("point", lo, tof(lo))
    return ("stretch", lo, hi, tof(lo), tof(hi))


def curve_truth(P, Q=None, constructed=()):
    """The answer of `curve-curve` (Q given) or `self` (Q None) for control points P, Q (pairs
    of rationals). `constructed` lists overlaps that do not follow from a linear common
    factor: (s0, s1, rel) with t = rel(s) on [s0, s1], each verified exactly."""
    selfmode = Q is None
    _res_cache.clear()
    Px, Py = bezier_expr([p[0] for p in P], S), bezier_expr([p[1] for p in P], S)
    Pxt, Pyt = Px.subs(S, T), Py.subs(S, T)
    if selfmode:
        Qx, Qy = Pxt, Pyt
        F1 = sp.div(Poly(Px - Qx, S, T, domain=QQ), Poly(S - T, S, T, domain=QQ))
        F2 = sp.div(Poly(Py - Qy, S, T, domain=QQ), Poly(S - T, S, T, domain=QQ))
        assert F1[1].is_zero and F2[1].is_zero
        F1, F2 = F1[0], F2[0]
    else:
        Qx, Qy = bezier_expr([q[0] for q in Q], T), bezier_expr([q[1] for q in Q], T)
        F1, F2 = Poly(Px - Qx, S, T, domain=QQ), Poly(Py - Qy, S, T, domain=QQ)
    G = F1.gcd(F2)
    overlaps, extra = [], []
    if G.total_degree() > 0:
        used = set()
        for f, _e in G.factor_list()[1]:
            if f.degree(S) == 1 and f.degree(T) == 1 and f.total_degree() == 1:
                r = clip_linear(f.as_expr(), selfmode)
                if r is None:
                    continue
                if r[0] == "point":
                    extra.append((r[1], r[2]))
                else:
                    overlaps.append(r[1:])
                continue
            hit = False
            for i, (s0, s1, rel) in enumerate(constructed):
                if Poly(f.as_expr().subs(T, rel), S, domain=QQ).is_zero:
                    hit = True
                    used.add(i)
                    overlaps.append(verify_constructed(Px, Py, Qx, Qy, s0, s1, rel))
            if not hit:
                raise ValueError(f"common factor {f.as_expr()} has no constructed overlap")
        assert used == set(range(len(constructed))), "every constructed overlap is a common factor"
        A, B = F1.exquo(G), F2.exquo(G)
    else:
        assert not constructed
        A, B = F1, F2
    sols = solve_both_ways(A.as_expr(), B.as_expr())
    for s0, t0 in extra:
        sols.append(Sol(Alg.rat(s0), Alg.rat(t0), None))

    def covered(x):
        for s0, s1, t0, t1 in overlaps:
            if cmp_q(x.s, s0) >= 0 and cmp_q(x.s, s1) <= 0:
                return True
            tl, th = min(t0, t1), max(t0, t1)
            if cmp_q(x.t, tl) >= 0 and cmp_q(x.t, th) <= 0:
                return True
        return False

    keep = []
    for x in sols:
        if covered(x):
            continue
        if selfmode and alg_cmp(x.s, x.t) >= 0:
            continue
        if any(alg_cmp(x.s, y.s) == 0 and alg_cmp(x.t, y.t) == 0 for y in keep):
            continue
        keep.append(x)
    keep.sort(key=cmp_to_key(lambda x, y: alg_cmp(x.s, y.s) or alg_cmp(x.t, y.t)))
    dPx, dPy = sp.diff(Px, S), sp.diff(Py, S)
    dQx, dQy = sp.diff(Qx, T), sp.diff(Qy, T)
    cross = sp.expand(dPx * dQy - dPy * dQx)
    points = []
    for x in keep:
        sp_ = x.s
        # Exact check that P(s) = Q(t) at the pair, and the tangency decided exactly.
        assert x.zero_at(Px - Qx) and x.zero_at(Py - Qy)
        points.append(
            {
                "s": x.s.param_json(),
                "t": x.t.param_json(),
                "tangent": bool(x.zero_at(cross)),
                "point": [coordinate_json(upoly_of(Px, S), sp_), coordinate_json(upoly_of(Py, S), sp_)],
            }
        )
    ov = []
    for s0, s1, t0, t1 in sorted(overlaps):
        ov.append({"s": [Alg.rat(s0).param_json(), Alg.rat(s1).param_json()],
                   "t": [Alg.rat(t0).param_json(), Alg.rat(t1).param_json()]})
    return {"points": points, "overlaps": ov}


def verify_constructed(Px, Py, Qx, Qy, s0, s1, rel):
    """A constructed overlap t = rel(s) on [s0, s1], checked exactly: P(s) = Q(rel(s)) as
    polynomials, rel monotone on (s0, s1), each end maximal (a parameter at 0 or 1, or rel
    turning back there)."""
    s0, s1 = fr(s0), fr(s1)
    assert s0 < s1
    assert sp.expand(Px - Qx.subs(T, rel)) == 0 and sp.expand(Py - Qy.subs(T, rel)) == 0
    r = Poly(rel, S, domain=QQ)
    dr = r.diff(S)
    q0, q1 = sp.Rational(s0.numerator, s0.denominator), sp.Rational(s1.numerator, s1.denominator)
    inner = dr.count_roots(q0, q1) - (dr.eval(q0) == 0) - (dr.eval(q1) == 0)
    assert inner == 0, "monotone"
    t0, t1 = fr(r.eval(q0)), fr(r.eval(q1))
    for sv, tv, qv in ((s0, t0, q0), (s1, t1, q1)):
        assert sv in (0, 1) or tv in (0, 1) or dr.eval(qv) == 0, "maximal"
    assert 0 <= min(t0, t1) and max(t0, t1) <= 1
    return (s0, s1, t0, t1)
