#!/usr/bin/env python3
"""Writes tests/intersect_corpus/cases.json: jobs of `blossom intersect` with their exact
answers computed independently in truth.py (sympy + fractions). Deterministic (fixed seed).

    python3 tests/intersect_corpus/generate.py            # writes cases.json, prints a summary

Each case: {"name", "family", "arithmetic": "exact"|"f64", "job", "expected"}. Under "exact" the
job's numbers are exact strings (or JSON integers); under "f64" they are JSON numbers (doubles,
printed by Python's shortest round-trip repr) and the truth is the exact answer for those
doubles. See README.md for the form of "expected".
"""

import json
import os
import random
import sys
import time
from collections import Counter
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from truth import (  # noqa: E402
    S,
    bernstein_power,
    curve_truth,
    de_casteljau_restrict,
    elevate,
    fmt,
    power_to_bernstein,
    roots_truth,
)

random.seed(20240526)
CASES = []


# ---------------------------------------------------------------------------------------------
# Writing numbers of a job


def num_exact(q, style):
    """An exact input number: a string "p/q" (style "frac"), a JSON integer when integral
    (style "int"), or a finite decimal string when the denominator allows (style "dec")."""
    q = F(q)
    if style == "int" and q.denominator == 1:
        return q.numerator
    if style == "dec":
        d = q.denominator
        k2 = k5 = 0
        while d % 2 == 0:
            d //= 2
            k2 += 1
        while d % 5 == 0:
            d //= 5
            k5 += 1
        if d == 1:
            k = max(k2, k5)
            n = q.numerator * 10**k // q.denominator
            sign = "-" if n < 0 else ""
            digits = str(abs(n)).rjust(k + 1, "0")
            return sign + (digits[:-k] + "." + digits[-k:] if k else digits)
    return fmt(q)


def pts_exact(P, style):
    return [[num_exact(c, style) for c in p] for p in P]


_last = [time.time()]


def add(family, name, arithmetic, job, expected):
    now = time.time()
    if os.environ.get("CORPUS_PROGRESS"):
        print(f"{now - _last[0]:8.2f} s  {name}", file=sys.stderr, flush=True)
    _last[0] = now
    CASES.append({"name": name, "family": family, "arithmetic": arithmetic, "job": job, "expected": expected})


def add_roots(family, name, coeffs, arithmetic="exact", style="frac"):
    if arithmetic == "f64":
        job_pts = [float(c) for c in coeffs]
        truth = roots_truth([F(c) for c in job_pts])
    else:
        job_pts = [num_exact(c, style) for c in coeffs]
        truth = roots_truth([F(c) for c in coeffs])
    add(family, name, arithmetic, {"kind": "roots", "control_points": job_pts}, truth)


def as_f64_points(P):
    return [[float(c) for c in p] for p in P]


def add_cc(family, name, P, Q, arithmetic="exact", style="frac", constructed=()):
    if arithmetic == "f64":
        Pj, Qj = as_f64_points(P), as_f64_points(Q)
        Pt, Qt = [tuple(F(c) for c in p) for p in Pj], [tuple(F(c) for c in p) for p in Qj]
    else:
        Pj, Qj = pts_exact(P, style), pts_exact(Q, style)
        Pt, Qt = P, Q
    truth = curve_truth(Pt, Qt, constructed)
    add(family, name, arithmetic, {"kind": "curve-curve", "curves": [Pj, Qj]}, {"kind": "curve-curve", **truth})


def add_self(family, name, P, arithmetic="exact", style="frac"):
    if arithmetic == "f64":
        Pj = as_f64_points(P)
        Pt = [tuple(F(c) for c in p) for p in Pj]
    else:
        Pj, Pt = pts_exact(P, style), P
    truth = curve_truth(Pt, None)
    add(family, name, arithmetic, {"kind": "self", "curve": Pj}, {"kind": "self", **truth})


def rand_int_pts(n, lo=-10, hi=10):
    return [(F(random.randint(lo, hi)), F(random.randint(lo, hi))) for _ in range(n + 1)]


def rand_rat_pts(n, den=16, span=16):
    return [(F(random.randint(-span, span), random.randint(1, den)), F(random.randint(-span, span), random.randint(1, den))) for _ in range(n + 1)]


def rand_f64_pts(n, scale=1.0):
    return [(F(random.random() * scale), F(random.random() * scale)) for _ in range(n + 1)]


def rand_dyadic_pts(n, bitsz=10):
    return [(F(random.randint(0, 2**bitsz), 2**bitsz), F(random.randint(0, 2**bitsz), 2**bitsz)) for _ in range(n + 1)]


def poly_mul(a, b):
    out = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def from_roots(roots, lead=1):
    p = [F(lead)]
    for r in roots:
        p = poly_mul(p, [-F(r), F(1)])
    return p


# ---------------------------------------------------------------------------------------------
# roots


def family_roots():
    fam = "roots"
    for i in range(40):
        n = random.randint(1, 20)
        add_roots(fam + "/random-int", f"roots-int-{i}-deg{n}", [random.randint(-10, 10) for _ in range(n + 1)], style=random.choice(["frac", "int"]))
    for i in range(15):
        n = random.randint(1, 12)
        add_roots(fam + "/random-rational", f"roots-rat-{i}-deg{n}", [F(random.randint(-50, 50), random.randint(1, 30)) for _ in range(n + 1)])
    for i in range(20):
        n = random.randint(1, 12)
        add_roots(fam + "/random-f64", f"roots-f64-{i}-deg{n}", [F(random.uniform(-1, 1)) for _ in range(n + 1)], arithmetic="f64")
    for i in range(5):
        n = random.randint(2, 8)
        add_roots(fam + "/random-f64", f"roots-f64-dyadic-{i}-deg{n}", [F(random.randint(-64, 64), 64) for _ in range(n + 1)], arithmetic="f64")
    # Constructed rational roots (some outside [0, 1]).
    for i in range(12):
        k = random.randint(1, 6)
        rts = [F(random.randint(-3, 12), random.randint(1, 10)) for _ in range(k)]
        add_roots(fam + "/rational-roots", f"roots-rational-{i}", power_to_bernstein(from_roots(rts, random.choice([1, -2, F(3, 7)]))), style=random.choice(["frac", "dec"]))
    # Quadratic surds: t^2 - t + c and (t - a)^2 - d.
    for i, (a, d) in enumerate([(F(1, 2), F(1, 8)), (F(1, 3), F(1, 50)), (F(2, 3), F(2, 9)), (F(1, 2), F(1, 4) - F(1, 10**6)), (F(0), F(1, 2)), (F(1, 10), F(3, 100)), (F(9, 10), F(1, 1000)), (F(1, 2), F(1, 3))]):
        add_roots(fam + "/surds", f"roots-surd-{i}", power_to_bernstein([a * a - d, -2 * a, F(1)]))
    add_roots(fam + "/surds", "roots-surd-cubic-2", power_to_bernstein([F(-1, 4), 0, 0, F(1)]))
    add_roots(fam + "/surds", "roots-surd-times-rational", power_to_bernstein(poly_mul([F(-1, 2), 0, F(1)], from_roots([F(1, 3)]))))
    # Roots at the ends.
    for i, (a, b, mid) in enumerate([(1, 0, []), (0, 1, []), (1, 1, []), (2, 1, [F(1, 2)]), (1, 3, [F(2, 5)]), (3, 2, []), (1, 1, [F(1, 3), F(3, 4)]), (4, 4, [])]):
        p = from_roots([F(0)] * a + [F(1)] * b + mid)
        add_roots(fam + "/ends", f"roots-ends-{i}", power_to_bernstein(p))
    add_roots(fam + "/ends", "roots-ends-linear-0", [0, 1], style="int")
    add_roots(fam + "/ends", "roots-ends-linear-1", [-1, 0], style="int")
    add_roots(fam + "/ends", "roots-ends-f64", [0.0, 0.5, -0.25, 0.0], arithmetic="f64")
    # High multiplicity.
    for i, rts in enumerate([
        [F(1, 3)] * 5 + [F(1, 2)],
        [F(1, 2)] * 7,
        [F(1, 4)] * 3 + [F(3, 4)] * 4,
        [F(0)] * 2 + [F(1, 3)] * 3 + [F(1)] * 2,
        [F(2, 7)] * 10,
        [F(1, 2)] * 2 + [F(1, 2) + F(1, 10**12)],
        [F(1, 5)] * 4 + [F(6, 5)] * 3,
    ]):
        add_roots(fam + "/multiplicity", f"roots-mult-{i}", power_to_bernstein(from_roots(rts)))
    surd_sq = poly_mul([F(-1, 2), 0, F(1)], [F(-1, 2), 0, F(1)])
    add_roots(fam + "/multiplicity", "roots-mult-surd-squared", power_to_bernstein(poly_mul(surd_sq, from_roots([F(1, 7)] * 3))))
    # Clustered roots.
    for i, rts in enumerate([
        [F(1, 2), F(1, 2) + F(1, 10**12)],
        [F(1, 2) - F(1, 10**12), F(1, 2) + F(1, 10**12)],
        [F(1, 3), F(1, 3) + F(1, 10**15), F(1, 3) + F(2, 10**15)],
        [F(0), F(1, 10**12)],
        [F(1) - F(1, 10**12), F(1)],
        [F(1, 2), F(1, 2) + F(1, 2**60)],
    ]):
        add_roots(fam + "/clustered", f"roots-cluster-{i}", power_to_bernstein(from_roots(rts)))
    # Irrational pair 1/2 +- 1e-12: t^2 - t + 1/4 - 1e-24 ... times 2 so 2e-24 is not a square.
    add_roots(fam + "/clustered", "roots-cluster-surd", power_to_bernstein([F(1, 4) - F(2, 10**24), F(-1), F(1)]))
    # Correct rounding: ties to even and the smallest doubles.
    for i, r in enumerate([
        F(1, 2) + F(1, 2**54),  # tie between 0.5 and its successor: to 0.5 (even)
        F(1, 2) + F(3, 2**54),  # tie: to 0.5 + 2^-52 (even)
        F(1) - F(1, 2**54),  # tie between 1 - 2^-53 and 1: to 1
        F(1, 2**1075),  # tie between 0 and the least subnormal: to 0
        F(3, 2**1075),  # tie: to 2^-1073 (even)
        F(1, 3),
        F(1, 10),
        F(1, 10**300),
        F(2, 3) + F(1, 2**80),
    ]):
        add_roots(fam + "/rounding", f"roots-round-{i}", [-r, 1 - r])
    add_roots(fam + "/rounding", "roots-round-cubic-ties", power_to_bernstein(from_roots([F(1, 2) + F(1, 2**54), F(1, 2) + F(3, 2**54), F(1, 4) + F(1, 2**56)])))
    # Identically zero, no roots, lower true degree.
    for n in (1, 3, 20):
        add_roots(fam + "/zero", f"roots-zero-deg{n}", [0] * (n + 1), style="int")
    add_roots(fam + "/zero", "roots-zero-f64", [0.0, -0.0, 0.0], arithmetic="f64")
    for i, c in enumerate([[1, 2, 3], [5, -1, 5], [1, 1, 1, 1, 1, 1, 1], [-3, -1, F(-1, 100)], [F(1, 10**12), -F(1, 10**12), F(1, 10**12)], [1, -2, F(1001, 1000)]]):
        add_roots(fam + "/none", f"roots-none-{i}", c)
    add_roots(fam + "/none", "roots-none-constant", [7, 7, 7, 7], style="int")
    add_roots(fam + "/multiplicity", "roots-wilkinson-20", power_to_bernstein(from_roots([F(i, 21) for i in range(1, 21)])))
    add_roots(fam + "/multiplicity", "roots-wilkinson-19-with-ends", power_to_bernstein(from_roots([F(i, 18) for i in range(0, 19)])))
    add_roots(fam + "/lower-degree", "roots-elevated-linear", [F(-1, 3) + F(i, 5) for i in range(6)])
    add_roots(fam + "/lower-degree", "roots-elevated-quadratic", power_to_bernstein([F(3, 16), F(-1), F(1), 0, 0, 0]))


# ---------------------------------------------------------------------------------------------
# curve-curve


def translate(P, d):
    return [(p[0] + d[0], p[1] + d[1]) for p in P]


def point_at(P, u):
    return de_casteljau_restrict(P, 0, u)[-1] if u != 0 else tuple(P[0])


def deriv_at(P, u):
    n = len(P) - 1
    D = [(n * (P[i + 1][0] - P[i][0]), n * (P[i + 1][1] - P[i][1])) for i in range(n)]
    if n == 1:
        return D[0]
    return point_at(D, u)


def family_cc():
    fam = "curve-curve"
    for i in range(40):
        add_cc(fam + "/random-cubic-exact", f"cc-cubic-int-{i}", rand_int_pts(3), rand_int_pts(3), style=random.choice(["frac", "int"]))
    for i in range(10):
        add_cc(fam + "/random-cubic-exact", f"cc-cubic-rat-{i}", rand_rat_pts(3), rand_rat_pts(3), style=random.choice(["frac", "dec"]))
    for i in range(25):
        add_cc(fam + "/random-cubic-f64", f"cc-cubic-f64-{i}", rand_f64_pts(3), rand_f64_pts(3), arithmetic="f64")
    for i in range(10):
        add_cc(fam + "/random-cubic-f64", f"cc-cubic-f64-dyadic-{i}", rand_dyadic_pts(3), rand_dyadic_pts(3), arithmetic="f64")
    for i in range(15):
        n, m = random.randint(1, 4), random.randint(1, 4)
        add_cc(fam + "/random-mixed", f"cc-mixed-{i}-deg{n}-{m}", rand_int_pts(n), rand_int_pts(m))
    for i in range(12):
        add_cc(fam + "/line-cubic", f"cc-line-cubic-{i}", rand_int_pts(1), rand_int_pts(3))
    for i in range(4):
        add_cc(fam + "/line-cubic", f"cc-line-cubic-f64-{i}", rand_f64_pts(1), rand_f64_pts(3), arithmetic="f64")
    # Transversal crossings at chosen rational parameters.
    for i in range(15):
        P, Q = rand_int_pts(random.randint(1, 4)), rand_int_pts(random.randint(1, 4))
        s0, t0 = F(random.randint(0, 12), 12), F(random.randint(0, 10), 10)
        a, b = point_at(P, s0), point_at(Q, t0)
        add_cc(fam + "/rational-crossing", f"cc-rational-cross-{i}", P, translate(Q, (a[0] - b[0], a[1] - b[1])))
    # Tangent contacts.
    par = [(F(0), F(0)), (F(1, 2), F(-1)), (F(1), F(0))]
    add_cc(fam + "/tangent", "cc-tangent-parabola-line", par, [(F(0), F(-1, 2)), (F(1), F(-1, 2))])
    add_cc(fam + "/tangent", "cc-tangent-parabola-line-reversed", par, [(F(2), F(-1, 2)), (F(-1), F(-1, 2))])
    add_cc(fam + "/tangent", "cc-tangent-two-parabolas", [(0, 0), (1, 1), (2, 0)], [(0, 1), (1, 0), (2, 1)], style="int")
    add_cc(fam + "/tangent", "cc-tangent-parabolas-inside", [(0, 0), (1, 2), (2, 0)], [(F(1, 2), F(1, 2)), (1, F(3, 2)), (F(3, 2), F(1, 2))])
    add_cc(fam + "/tangent", "cc-line-through-cubic-zeros", [(0, 0), (F(1, 3), 1), (F(2, 3), -1), (1, 0)], [(0, 0), (1, 0)])
    # y = 4 (x - 1/2)^3 against y = 0: an inflection tangency (contact of order three).
    infl = list(zip(power_to_bernstein([0, 1, 0, 0]), power_to_bernstein([F(-1, 2), 3, -6, 4])))
    add_cc(fam + "/tangent", "cc-tangent-inflection", infl, [(-1, 0), (2, 0)])
    # Tangent at irrational parameters: y = x^2 with x = (s^2 + s)/2 touches the line
    # y = x/2 - 1/16 at x = 1/4, where s = (sqrt(3) - 1)/2; the line written as a quadratic
    # with x = (t^2 + 2t)/3 meets it there at t = sqrt(7)/2 - 1.
    xs = [0, F(1, 2), F(1, 2), 0, 0]
    par4 = list(zip(power_to_bernstein(xs), power_to_bernstein([0, 0, F(1, 4), F(1, 2), F(1, 4)])))
    line1 = [(0, F(-1, 16)), (1, F(7, 16))]
    xq = [0, F(2, 3), F(1, 3)]
    line2 = list(zip(power_to_bernstein(xq), power_to_bernstein([F(-1, 16), F(1, 3), F(1, 6)])))
    add_cc(fam + "/tangent", "cc-tangent-irrational-s", par4, line1)
    add_cc(fam + "/tangent", "cc-tangent-irrational-both", par4, line2)
    add_cc(fam + "/tangent", "cc-tangent-irrational-both-swapped", line2, par4)
    add_cc(fam + "/tangent", "cc-tangent-inflection-line-through", [(0, -1), (F(1, 3), 2), (F(2, 3), -2), (1, 1)], [(-1, 0), (2, 0)])
    cusp = [(0, 0), (1, 0), (1, 1), (0, -1)]
    add_cc(fam + "/tangent", "cc-cusp-line", cusp, [(F(3, 4), -2), (F(3, 4), 2)], style="int")
    add_cc(fam + "/tangent", "cc-cusp-line-oblique", cusp, [(F(0), F(-1, 8)), (F(3, 2), F(5, 8))])
    for i in range(8):
        P = rand_int_pts(3)
        s0 = F(random.randint(1, 9), 10)
        a, d = point_at(P, s0), deriv_at(P, s0)
        if d == (0, 0):
            continue
        Q = [(a[0] - d[0] / 3, a[1] - d[1] / 3), (a[0] + d[0] / 2, a[1] + d[1] / 2)]
        add_cc(fam + "/tangent", f"cc-tangent-line-at-{i}", P, Q)
    # y = x^2 against the line y = 2x - 1 written as a quadratic: tangent at both ends s = t = 1.
    add_cc(fam + "/tangent", "cc-tangent-quadratic-pair", [(0, 0), (F(1, 2), 0), (1, 1)], [(0, -1), (F(1, 2), 0), (1, 1)])
    add_cc(fam + "/tangent", "cc-tangent-f64-parabola-line", [(0.0, 0.0), (0.5, -1.0), (1.0, 0.0)], [(0.0, -0.5), (1.0, -0.5)], arithmetic="f64")
    # End points.
    for i in range(6):
        P, Q = rand_int_pts(3), rand_int_pts(random.randint(1, 3))
        Q = translate(Q, (P[-1][0] - Q[0][0], P[-1][1] - Q[0][1]))
        add_cc(fam + "/end-points", f"cc-shared-end-{i}", P, Q)
    for i in range(6):
        P, Q = rand_int_pts(3), rand_int_pts(random.randint(1, 3))
        s0 = F(random.randint(1, 7), 8)
        a = point_at(P, s0)
        end = random.choice([0, -1])
        Q = translate(Q, (a[0] - Q[end][0], a[1] - Q[end][1]))
        add_cc(fam + "/end-points", f"cc-end-on-interior-{i}", P, Q)
    add_cc(fam + "/end-points", "cc-end-to-end-line", [(0, 0), (1, 1)], [(1, 1), (2, 0)], style="int")
    add_cc(fam + "/end-points", "cc-end-to-end-tangent", [(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)], style="int")
    add_cc(fam + "/end-points", "cc-both-ends-shared", [(0, 0), (1, 2), (2, 0)], [(0, 0), (1, -2), (2, 0)], style="int")
    add_cc(fam + "/end-points", "cc-end-points-f64", [(0.1, 0.2), (0.7, 0.9), (0.3, 0.4), (0.8, 0.1)], [(0.8, 0.1), (0.5, 0.5), (0.2, 0.9)], arithmetic="f64")
    # Near misses at distance 1e-12.
    eps = F(1, 10**12)
    add_cc(fam + "/near-miss", "cc-near-miss-parabola-above", par, [(F(0), F(-1, 2) - eps), (F(1), F(-1, 2) - eps)])
    add_cc(fam + "/near-miss", "cc-near-crossing-parabola", par, [(F(0), F(-1, 2) + eps), (F(1), F(-1, 2) + eps)])
    add_cc(fam + "/near-miss", "cc-near-miss-end", [(0, 0), (1, 1)], [(1 + eps, 1), (2, 0)])
    add_cc(fam + "/near-miss", "cc-near-miss-two-parabolas", [(0, 0), (1, 1), (2, 0)], [(0, 1 + eps), (1, eps), (2, 1 + eps)])
    add_cc(fam + "/near-miss", "cc-near-miss-parallel-lines", [(0, 0), (1, 1)], [(0, eps), (1, 1 + eps)])
    add_cc(fam + "/near-miss", "cc-near-miss-f64", [(0.0, 0.0), (0.5, -1.0), (1.0, 0.0)], [(0.0, -0.5 - 1e-12), (1.0, -0.5 - 1e-12)], arithmetic="f64")
    add_cc(fam + "/near-miss", "cc-near-cross-f64", [(0.0, 0.0), (0.5, -1.0), (1.0, 0.0)], [(0.0, -0.5 + 1e-12), (1.0, -0.5 + 1e-12)], arithmetic="f64")
    # Overlaps.
    loop = [(F(0), F(0)), (F(3), F(3)), (F(-2), F(3)), (F(1), F(0))]
    R = rand_int_pts(3)
    add_cc(fam + "/overlap", "cc-overlap-same", R, R)
    add_cc(fam + "/overlap", "cc-overlap-reversed", R, R[::-1])
    add_cc(fam + "/overlap", "cc-overlap-sub-segment", R, de_casteljau_restrict(R, F(1, 3), F(3, 4)))
    add_cc(fam + "/overlap", "cc-overlap-sub-segment-reversed", de_casteljau_restrict(R, F(1, 5), F(2, 3))[::-1], R)
    add_cc(fam + "/overlap", "cc-overlap-elevated", R, elevate(R))
    add_cc(fam + "/overlap", "cc-overlap-elevated-twice-reversed", elevate(elevate(R))[::-1], R)
    add_cc(fam + "/overlap", "cc-overlap-partial", de_casteljau_restrict(R, 0, F(2, 3)), de_casteljau_restrict(R, F(1, 3), 1))
    add_cc(fam + "/overlap", "cc-overlap-loop-same", loop, loop)
    add_cc(fam + "/overlap", "cc-overlap-loop-partial-with-crossing", de_casteljau_restrict(loop, 0, F(7, 10)), de_casteljau_restrict(loop, F(3, 10), 1))
    add_cc(fam + "/overlap", "cc-overlap-loop-partial-reversed", de_casteljau_restrict(loop, 0, F(7, 10)), de_casteljau_restrict(loop, F(3, 10), 1)[::-1])
    add_cc(fam + "/overlap", "cc-overlap-collinear-partial", [(0, 0), (2, 0)], [(1, 0), (3, 0)], style="int")
    add_cc(fam + "/overlap", "cc-overlap-collinear-diagonal-reversed", [(0, 0), (3, 3)], [(5, 5), (1, 1)], style="int")
    add_cc(fam + "/overlap", "cc-overlap-collinear-contained", [(0, 0), (4, 2)], [(1, F(1, 2)), (3, F(3, 2))])
    add_cc(fam + "/overlap", "cc-overlap-collinear-elevated", [(0, 0), (1, 1), (2, 2)], [(1, 1), (3, 3)], style="int")
    add_cc(fam + "/overlap", "cc-collinear-disjoint", [(0, 0), (1, 0)], [(2, 0), (3, 0)], style="int")
    add_cc(fam + "/overlap", "cc-collinear-touching", [(0, 0), (1, 0)], [(1, 0), (2, 0)], style="int")
    add_cc(fam + "/overlap", "cc-overlap-f64-same", [(0.1, 0.2), (0.7, 0.9), (0.3, 0.4), (0.8, 0.1)], [(0.1, 0.2), (0.7, 0.9), (0.3, 0.4), (0.8, 0.1)], arithmetic="f64")
    add_cc(fam + "/overlap", "cc-overlap-f64-reversed", [(0.1, 0.2), (0.7, 0.9), (0.3, 0.4), (0.8, 0.1)], [(0.8, 0.1), (0.3, 0.4), (0.7, 0.9), (0.1, 0.2)], arithmetic="f64")
    add_cc(fam + "/overlap", "cc-overlap-f64-collinear", [(0.0, 0.0), (0.75, 0.5)], [(0.375, 0.25), (1.5, 1.0)], arithmetic="f64")
    # Retracing (constructed): P(s) = L(4s(1-s)) runs along the segment L and back.
    L = [(F(0), F(0)), (F(2), F(1))]
    u = 4 * S * (1 - S)
    Pret = [(F(0), F(0)), (F(4), F(2)), (F(0), F(0))]  # quadratic with control points L0, L0 + 2(L1 - L0), L0
    add_cc(fam + "/overlap", "cc-overlap-retrace-constructed", Pret, L, constructed=[(F(0), F(1, 2), u), (F(1, 2), F(1), u)])
    # Higher degree.
    for i, n in enumerate([5, 6, 7, 8]):
        add_cc(fam + "/high-degree", f"cc-degree-{n}-{n}", rand_int_pts(n, -5, 5), rand_int_pts(n, -5, 5))
    add_cc(fam + "/high-degree", "cc-degree-8-3", rand_int_pts(8, -5, 5), rand_int_pts(3, -5, 5))
    add_cc(fam + "/high-degree", "cc-degree-6-f64-dyadic", rand_dyadic_pts(6, 6), rand_dyadic_pts(6, 6), arithmetic="f64")


# ---------------------------------------------------------------------------------------------
# self


def family_self():
    fam = "self"
    for i in range(30):
        add_self(fam + "/random-cubic-exact", f"self-cubic-int-{i}", rand_int_pts(3), style=random.choice(["frac", "int"]))
    for i in range(12):
        add_self(fam + "/random-cubic-f64", f"self-cubic-f64-{i}", rand_f64_pts(3), arithmetic="f64")
    for i, P in enumerate([
        [(0, 0), (3, 3), (-2, 3), (1, 0)],
        [(0, 0), (2, 2), (-1, 2), (1, 0)],
        [(0, 0), (F(5, 2), 1), (F(-3, 2), 1), (1, 0)],
        [(0, 0), (10, 10), (-9, 10), (1, 0)],
        [(1, 0), (-2, 3), (3, 3), (0, 0)],
        [(0, 0), (3, 1), (-1, 3), (0, 1)],
    ]):
        add_self(fam + "/loop", f"self-loop-{i}", P)
    add_self(fam + "/loop", "self-loop-f64", [(0.0, 0.0), (3.0, 3.0), (-2.0, 3.0), (1.0, 0.0)], arithmetic="f64")
    add_self(fam + "/loop", "self-loop-f64-inexact", [(0.1, 0.0), (3.3, 3.1), (-2.2, 2.9), (1.0, 0.3)], arithmetic="f64")
    for i, P in enumerate([
        [(0, 0), (1, 2), (2, -1), (0, 0)],
        [(0, 0), (3, 3), (-3, 3), (0, 0)],
        [(1, 1), (5, 0), (-2, 4), (3, 7), (1, 1)],
        [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)],
        [(0, 0), (4, 4), (-3, 4), (1, 0), (0, 0)],
    ]):
        add_self(fam + "/closed", f"self-closed-{i}", P)
    add_self(fam + "/cusp", "self-cusp-brief-example", [(0, 0), (1, 1), (0, 1), (1, 0)], style="int")
    add_self(fam + "/cusp", "self-cusp", [(0, 0), (1, 0), (1, 1), (0, -1)], style="int")
    add_self(fam + "/cusp", "self-cusp-f64", [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, -1.0)], arithmetic="f64")
    for i, P in enumerate([[(0, 0), (1, 1), (2, 0), (3, 1)], [(0, 0), (1, 0), (2, 1), (2, 2)], [(0, 0), (1, 1)], [(0, 0), (1, 2), (3, 0)]]):
        add_self(fam + "/simple", f"self-simple-{i}", P)
    # Retracing: the quadratic with P0 = P2 runs out and back; a quartic L(u(s)).
    add_self(fam + "/retrace", "self-retrace-quadratic", [(0, 0), (1, 1), (0, 0)], style="int")
    add_self(fam + "/retrace", "self-retrace-quadratic-f64", [(0.25, 0.5), (1.5, 0.75), (0.25, 0.5)], arithmetic="f64")
    Rq = [(F(0), F(0)), (F(1), F(2)), (F(3), F(0))]
    # R(4s(1-s)) as a quartic: compose in power form, back to Bernstein.
    import sympy as sp
    from truth import bezier_expr

    comp = []
    for k in range(2):
        e = sp.Poly(sp.expand(bezier_expr([p[k] for p in Rq], S).subs(S, 4 * S * (1 - S))), S)
        a = [F(int(c.p), int(c.q)) for c in reversed(e.all_coeffs())]
        a += [F(0)] * (5 - len(a))
        comp.append(power_to_bernstein(a))
    add_self(fam + "/retrace", "self-retrace-quartic", list(zip(comp[0], comp[1])))
    for i, n in enumerate([4, 5, 5, 6, 6, 7]):
        add_self(fam + "/higher-degree", f"self-degree-{n}-{i}", rand_int_pts(n, -6, 6))

# ---------------------------------------------------------------------------------------------
# Families added after the first 426 cases (each reseeds, so the cases above are unchanged):
# extreme f64 scales, rounding ties, structured cases rounded to doubles, degree 4-5 contacts.


def padd(a, b):
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else F(0)) + (b[i] if i < len(b) else F(0)) for i in range(n)]


def pscale(a, c):
    return [x * c for x in a]


def ppow(a, k):
    out = [F(1)]
    for _ in range(k):
        out = poly_mul(out, a)
    return out


def compose(p, q):
    """p(q(x)), ascending coefficients."""
    out = [F(0)]
    for c in reversed(p):
        out = padd(poly_mul(out, q), [c])
    return out


def curve_power(P):
    return [bernstein_power([F(p[0]) for p in P]), bernstein_power([F(p[1]) for p in P])]


def curve_from_power(cx, cy):
    n = max(len(cx), len(cy)) - 1
    while n > 1 and all(c == 0 for c in cx[n:] + cy[n:]):
        n -= 1
    pad = lambda p: (list(p) + [F(0)] * (n + 1))[: n + 1]  # noqa: E731
    assert all(c == 0 for c in cx[n + 1:] + cy[n + 1:])
    return list(zip(power_to_bernstein(pad(cx)), power_to_bernstein(pad(cy))))


def is_double(q):
    q = F(q)
    try:
        return F(float(q)) == q
    except OverflowError:
        return False


def rand_pts_kind(n, kind, span):
    if kind == "int":
        return [(F(random.randint(-span, span)), F(random.randint(-span, span))) for _ in range(n + 1)]
    if kind == "dyadic":
        d = 2 ** random.randint(1, 5)
        return [(F(random.randint(-span * d, span * d), d), F(random.randint(-span * d, span * d), d)) for _ in range(n + 1)]
    d = random.randint(2, 12)
    return [(F(random.randint(-span * d, span * d), random.randint(1, d)), F(random.randint(-span * d, span * d), random.randint(1, d))) for _ in range(n + 1)]


def rand_param(ends=0.25, den=None):
    r = random.random()
    if r < ends / 2:
        return F(0)
    if r < ends:
        return F(1)
    den = den or random.choice([2, 3, 4, 5, 7, 8, 10, 16, 12])
    return F(random.randint(1, den - 1), den)


def tangent_pair(P, s0, t0, variant, k):
    """A curve Q through P(s0) at t = t0, tangent to P there: "quad" is
    P(s0) + c (t - t0) P'(s0) + (t - t0)^2 w, "comp" is P(s0 + c (t - t0)) + (t - t0)^k w (contact
    of order k)."""
    d, a = deriv_at(P, s0), point_at(P, s0)
    c = F(random.choice([1, -1, 2, -2, 3]), random.choice([1, 2, 3]))
    w = (F(random.randint(-4, 4)), F(random.randint(-4, 4)))
    if w == (0, 0):
        w = (F(1), F(-2))
    lin = [-t0, F(1)]
    if variant == "quad":
        cx = padd([a[0]], padd(pscale(lin, c * d[0]), pscale(ppow(lin, k), w[0])))
        cy = padd([a[1]], padd(pscale(lin, c * d[1]), pscale(ppow(lin, k), w[1])))
    else:
        px, py = curve_power(P)
        arg = padd([s0], pscale(lin, c))
        cx = padd(compose(px, arg), pscale(ppow(lin, k), w[0]))
        cy = padd(compose(py, arg), pscale(ppow(lin, k), w[1]))
    return curve_from_power(cx, cy)


def attempt(fn, *args, **kw):
    """Adds a case unless the truth declines it (ValueError: a nonlinear common factor that is
    not constructed); deterministic, so the same cases are dropped on every run."""
    try:
        fn(*args, **kw)
        return True
    except ValueError:
        return False


def scaled(P, k, off=(0, 0)):
    return [(F(p[0]) * F(2) ** k + off[0], F(p[1]) * F(2) ** k + off[1]) for p in P]


def family_f64_scaled():
    """f64 jobs scaled by 2^k (k = +-300, +-600, -1000: products of coordinates over- or
    underflow) or shifted by 2^20..2^40 (the shifted coordinates are rounded to doubles; the
    truth is for the doubles of the job)."""
    random.seed(20261206)
    fam = "f64-scaled"
    ks = [300, -300, 600, -600, -1000]
    for i, k in enumerate(ks):
        P, Q = rand_f64_pts(3), rand_f64_pts(random.choice([2, 3]))
        P, Q = scaled(P, k), scaled(Q, k)
        assert all(is_double(c) for p in P + Q for c in p)
        attempt(add_cc, fam + "/curve-curve", f"scaled-cc-random-{i}-2^{k}", P, Q, arithmetic="f64")
    par = [(F(0), F(0)), (F(1, 2), F(-1)), (F(1), F(0))]
    line = [(F(0), F(-1, 2)), (F(1), F(-1, 2))]
    for k in (300, -1000):
        attempt(add_cc, fam + "/curve-curve", f"scaled-cc-tangent-parabola-line-2^{k}", scaled(par, k), scaled(line, k), arithmetic="f64")
    for k in (-600, 600):
        loop = [(0.1, 0.0), (3.3, 3.1), (-2.2, 2.9), (1.0, 0.3)]
        attempt(add_self, fam + "/self", f"scaled-self-loop-2^{k}", scaled([(F(x), F(y)) for x, y in loop], k), arithmetic="f64")
    for k in (-1000, 300):
        n = random.randint(3, 6)
        add_roots(fam + "/roots", f"scaled-roots-random-deg{n}-2^{k}", [F(random.uniform(-1, 1)) * F(2) ** k for _ in range(n + 1)], arithmetic="f64")
    dbl = power_to_bernstein(from_roots([F(1, 4), F(1, 4), F(5, 8)], 3))
    for k in (-600, 600):
        add_roots(fam + "/roots", f"scaled-roots-double-root-2^{k}", [c * F(2) ** k for c in dbl], arithmetic="f64")
    for i in range(3):
        e1, e2 = random.randint(20, 40), random.randint(20, 40)
        off = (F(random.choice([1, -1]) * 2**e1), F(2**e2))
        P, Q = rand_f64_pts(3), rand_f64_pts(3)
        attempt(add_cc, fam + "/shifted", f"shifted-cc-random-{i}-2^{e1}-2^{e2}", scaled(P, 0, off), scaled(Q, 0, off), arithmetic="f64")
    attempt(add_cc, fam + "/shifted", "shifted-cc-tangent-parabola-line-2^40", scaled(par, 0, (F(2**40), F(-(2**40)))), scaled(line, 0, (F(2**40), F(-(2**40)))), arithmetic="f64")
    attempt(add_self, fam + "/shifted", "shifted-self-loop-2^33", scaled([(F(0), F(0)), (F(3), F(3)), (F(-2), F(3)), (F(1), F(0))], 0, (F(2**33), F(2**33))), arithmetic="f64")
    attempt(add_self, fam + "/shifted", "shifted-self-loop-inexact-2^21", scaled([(F(0.1), F(0.0)), (F(3.3), F(3.1)), (F(-2.2), F(2.9)), (F(1.0), F(0.3))], 0, (F(-(2**21)), F(2**21))), arithmetic="f64")


def family_ties():
    """Parameters at exact rounding ties (ties to even) and a hair away from them (rational and
    irrational), as roots with multiplicity, crossings and a tangent (exact arithmetic)."""
    random.seed(20261207)
    fam = "ties"
    ties = [F(1, 2) + F(1, 2**54), F(1, 2) + F(3, 2**54), 1 - F(1, 2**54), F(1, 4) + F(1, 2**56), F(3, 4) + F(5, 2**55), F(1, 2**60) * 3]
    near = [F(1, 2) + F(1, 2**54) + F(1, 2**200), F(1, 2) + F(1, 2**54) - F(1, 2**200), F(1, 4) + F(1, 2**56) - F(1, 3 * 2**110)]
    for i, r in enumerate(ties + near):
        k = random.randint(1, 3)
        add_roots(fam + "/roots", f"ties-roots-{i}-k{k}", power_to_bernstein(from_roots([r] * k + [F(random.randint(0, 4), 4)])))
    # (t - m)^2 - 2 eps^2: two irrational roots m +- sqrt(2) eps astride the tie m.
    for i, (m, e) in enumerate([(ties[0], 120), (ties[1], 200), (ties[3], 70)]):
        add_roots(fam + "/roots", f"ties-roots-surds-astride-{i}-2^-{e}", power_to_bernstein([m * m - 2 * F(1, 2**e) ** 2, -2 * m, F(1)]))
    for i in range(6):
        s0, t0 = random.choice(ties + near), random.choice(ties + [F(1, 3)])
        P = rand_pts_kind(random.choice([1, 2, 3]), "int", 5)
        Q = rand_pts_kind(random.choice([1, 2]), "int", 5)
        a, b = point_at(P, s0), point_at(Q, t0)
        attempt(add_cc, fam + "/curve-curve", f"ties-cc-cross-{i}", P, translate(Q, (a[0] - b[0], a[1] - b[1])))
    made = 0
    while made < 2:
        P = rand_pts_kind(2, "int", 5)
        s0, t0 = random.choice(ties), random.choice(ties)
        if deriv_at(P, s0) == (0, 0):
            continue
        if attempt(add_cc, fam + "/curve-curve", f"ties-cc-tangent-{made}", P, tangent_pair(P, s0, t0, "quad", 2)):
            made += 1


def family_f64_rounded():
    """Structured exact configurations (multiple roots, tangencies, overlaps, loops) whose
    rational data is rounded to doubles: a near-degenerate perturbation, solved for the doubles."""
    random.seed(20261208)
    fam = "f64-rounded"
    for i in range(4):
        r = [F(random.randint(1, 11), 12)] * random.randint(2, 5) + [F(random.randint(0, 12), 12) for _ in range(random.randint(0, 2))]
        add_roots(fam + "/roots", f"rounded-roots-mult-{i}", power_to_bernstein(from_roots(r)), arithmetic="f64")
    made = 0
    while made < 4:
        n = random.choice([2, 3, 3])
        P = rand_pts_kind(n, "rat", 3)
        s0, t0 = rand_param(0.2), rand_param(0.2)
        if deriv_at(P, s0) == (0, 0):
            continue
        Q = tangent_pair(P, s0, t0, random.choice(["quad", "comp"]), 2)
        if len(Q) > 5:
            continue
        if attempt(add_cc, fam + "/tangent", f"rounded-cc-tangent-{made}", P, Q, arithmetic="f64"):
            made += 1
    for i in range(4):
        P = rand_pts_kind(random.choice([2, 3]), "rat", 3)
        a, b = F(random.randint(0, 4), 10), F(random.randint(6, 10), 10)
        Q = de_casteljau_restrict(P, a, b) if i % 3 else elevate(P)
        if i % 2:
            Q = Q[::-1]
        attempt(add_cc, fam + "/overlap", f"rounded-cc-overlap-{i}", P, Q, arithmetic="f64")
    for i in range(4):
        P = rand_pts_kind(3, "rat", 3)
        if i % 2:
            P[-1] = P[0]
        else:
            P[2] = (P[0][0] + F(1, 3), P[0][1] - F(1, 7))
        attempt(add_self, fam + "/self", f"rounded-self-{i}", P, arithmetic="f64")


def family_heavy():
    """Degree 4-5 pairs with a contact of order 2-5 (every third shifted off by 1e-9..1e-14
    along the normal); dyadic ones also under f64."""
    random.seed(20261209)
    fam = "heavy"
    made = 0
    while made < 10:
        n = random.choice([4, 5])
        kind = random.choice(["int", "dyadic"])
        P = rand_pts_kind(n, kind, 6)
        s0, t0 = rand_param(0.3), rand_param(0.3)
        if deriv_at(P, s0) == (0, 0):
            continue
        k = random.randint(2, 5)
        Q = tangent_pair(P, s0, t0, "comp", k)
        if len(Q) - 1 > 5:
            continue
        if made % 3 == 2:
            d = deriv_at(P, s0)
            eps = F(1, 10 ** random.randint(9, 14))
            Q = translate(Q, (-eps * d[1], eps * d[0]))
        name = f"heavy-cc-{made}-k{k}-deg{len(P) - 1}-{len(Q) - 1}"
        if not attempt(add_cc, fam + "/contact", name, P, Q, style=random.choice(["frac", "int"])):
            continue
        if all(is_double(c) for p in P + Q for c in p):
            attempt(add_cc, fam + "/contact", name + "-f64", P, Q, arithmetic="f64")
        made += 1


def main():
    t0 = time.time()
    family_roots()
    t1 = time.time()
    family_cc()
    t2 = time.time()
    family_self()
    t3 = time.time()
    family_f64_scaled()
    family_ties()
    family_f64_rounded()
    family_heavy()
    t4 = time.time()
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases.json")
    with open(out, "w") as f:
        json.dump({"generator": "tests/intersect_corpus/generate.py", "cases": CASES}, f, separators=(",", ":"))
        f.write("\n")
    fams = Counter(c["family"] for c in CASES)
    print(f"{len(CASES)} cases, {os.path.getsize(out)} bytes, {t4 - t0:.1f} s (roots {t1 - t0:.1f} s, curve-curve {t2 - t1:.1f} s, self {t3 - t2:.1f} s, added families {t4 - t3:.1f} s)")
    for k in sorted(fams):
        print(f"  {k:40s} {fams[k]}")
    npts = sum(len(c["expected"].get("points", c["expected"].get("roots", []))) for c in CASES)
    nov = sum(len(c["expected"].get("overlaps", [])) for c in CASES)
    ntan = sum(sum(p["tangent"] for p in c["expected"].get("points", [])) for c in CASES)
    nirr = sum(
        sum(1 for p in c["expected"].get("points", []) for k in ("s", "t") if p[k]["exact"] is None)
        + sum(1 for r in c["expected"].get("roots", []) if r["t"]["exact"] is None)
        for c in CASES
    )
    print(f"  points/roots {npts}, of which tangent {ntan}; irrational parameters {nirr}; overlaps {nov}")
    names = [c["name"] for c in CASES]
    assert len(names) == len(set(names)), "unique names"


if __name__ == "__main__":
    main()
