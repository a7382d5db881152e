"""Intersections against exact computations in Fractions written here: a line against a
curve reduces to the roots of one polynomial, isolated and bisected in Fractions to decide the
correctly rounded doubles; curve pairs are checked by evaluating both curves exactly."""

import math
from fractions import Fraction

import numpy as np
import pytest

import blossom
from conftest import bernstein_point, frac_nodes, random_nodes


def poly_of_line_and_curve(line, nodes):
    """f(s) = a x(s) + b y(s) + c for the line through line[:, 0], line[:, 1], as a function
    evaluated exactly."""
    (x0, x1), (y0, y1) = frac_nodes(line)
    a, b = y1 - y0, x0 - x1
    c = -(a * x0 + b * y0)

    def f(s):
        x, y = bernstein_point(nodes, s)
        return a * x + b * y + c

    return f


def correctly_rounded_roots(f, approx):
    """For each approximate root, bisect a sign change of f in Fractions down to an interval
    inside one rounding cell, and return the double it rounds to."""
    out = []
    for r in approx:
        lo, hi = Fraction(r) - Fraction(1, 2**30), Fraction(r) + Fraction(1, 2**30)
        flo, fhi = f(lo), f(hi)
        assert flo * fhi < 0, "a simple root near the answer"
        while float(lo) != float(hi) or float(lo) != float((lo + hi) / 2):
            mid = (lo + hi) / 2
            fm = f(mid)
            if fm == 0:
                lo = hi = mid
                break
            if (fm < 0) == (flo < 0):
                lo, flo = mid, fm
            else:
                hi = mid
        out.append(float(lo))
    return out


def count_by_numpy(f, cubic, line):
    """The crossings by numpy: real roots in [0, 1] of the cubic f (power coefficients from
    exact samples), kept when the line's parameter there is in [0, 1]."""
    vander = np.vander(np.arange(4.0), 4)
    coeffs = np.linalg.solve(vander, [float(f(s)) for s in range(4)])
    (x0, x1), (y0, y1) = line
    count = 0
    for r in np.roots(coeffs):
        if abs(r.imag) > 1e-9 or not -1e-9 <= r.real <= 1 + 1e-9:
            continue
        x, y = (float(v) for v in bernstein_point(cubic, r.real))
        t = ((x - x0) * (x1 - x0) + (y - y0) * (y1 - y0)) / ((x1 - x0) ** 2 + (y1 - y0) ** 2)
        assert min(abs(r.real), abs(r.real - 1), abs(t), abs(t - 1)) > 1e-9, "not near an end"
        count += 0 <= t <= 1
    return count


def test_line_against_cubic_is_correctly_rounded(rng):
    checked = 0
    for _ in range(30):
        cubic = random_nodes(rng, 2, 3)
        line = random_nodes(rng, 2, 1)
        a = blossom.Curve(cubic, 3)
        b = blossom.Curve(line, 1)
        st = a.intersect(b)
        assert st.shape[0] == 2
        f = poly_of_line_and_curve(line, cubic)
        assert st.shape[1] == count_by_numpy(f, cubic, line)
        rounded = correctly_rounded_roots(f, st[0]) if st.shape[1] else []
        assert list(st[0]) == rounded
        for s, t in st.T:
            p = bernstein_point(cubic, s)
            q = bernstein_point(line, t)
            assert max(abs(float(u - v)) for u, v in zip(p, q)) < 1e-12
        checked += st.shape[1]
    assert checked > 5


def test_cubic_pairs_meet_where_both_curves_agree(rng):
    found = 0
    for _ in range(40):
        p, q = random_nodes(rng, 2, 3), random_nodes(rng, 2, 3)
        st = blossom.Curve(p, 3).intersect(blossom.Curve(q, 3))
        order = np.lexsort((st[1], st[0]))
        assert np.array_equal(order, np.arange(st.shape[1]))
        for s, t in st.T:
            assert 0.0 <= s <= 1.0 and 0.0 <= t <= 1.0
            gap = [float(u - v) for u, v in zip(bernstein_point(p, s), bernstein_point(q, t))]
            assert max(map(abs, gap)) < 1e-12
        found += st.shape[1]
    assert found > 10


def test_records_are_exact_and_round_to_the_array():
    # The parabola (0,0),(1,2),(2,0) (y = 4s(1-s), x = 2s) meets y = 1/2 where 8s^2 - 8s + 1 = 0.
    p = blossom.Curve(np.array([[0.0, 1.0, 2.0], [0.0, 2.0, 0.0]]), 2)
    q = blossom.Curve(np.array([[0.0, 2.0], [0.5, 0.5]]), 1)
    st = p.intersect(q)
    rec = p.intersections(q)
    assert len(rec.points) == 2 and rec.overlaps == []
    for k, pt in enumerate(rec.points):
        poly = [int(c) for c in pt.s.polynomial]
        # Proportional to 1 - 8 s + 8 s^2.
        assert poly[0] * 8 == poly[2] * 1 and poly[1] == -poly[2]
        lo, hi = pt.s.interval
        assert lo <= hi and pt.s.exact is None
        assert (st[0, k], st[1, k]) == (pt.s.value, pt.t.value)
        assert pt.tangent is False
        exact = (2 - math.sqrt(2)) / 4 if k == 0 else (2 + math.sqrt(2)) / 4
        assert pt.s.value == pytest.approx(exact, abs=1e-16)


def test_tangency_is_answered_and_flagged():
    # y = 4 s (1 - s) touches y = 1 at s = 1/2: bezier's geometric strategy struggles there.
    p = blossom.Curve(np.array([[0.0, 1.0, 2.0], [0.0, 2.0, 0.0]]), 2)
    q = blossom.Curve(np.array([[0.0, 2.0], [1.0, 1.0]]), 1)
    assert p.intersect(q).tolist() == [[0.5], [0.5]]
    rec = p.intersections(q)
    assert rec.points[0].tangent is True and rec.points[0].s.exact == Fraction(1, 2)
    assert rec.points[0].point == (1.0, 1.0)


def test_overlap_is_its_two_end_pairs():
    nodes = np.array([[0.0, 1.0, 3.0, 4.0], [0.0, 2.0, 2.0, 0.0]])
    c = blossom.Curve(nodes, 3)
    part = c.specialize(0.25, 0.75)
    st = c.intersect(part)
    assert st.tolist() == [[0.25, 0.75], [0.0, 1.0]]
    rec = c.intersections(part)
    assert rec.points == [] and len(rec.overlaps) == 1
    o = rec.overlaps[0]
    assert [a.exact for a in o.s] == [Fraction(1, 4), Fraction(3, 4)]
    assert [a.exact for a in o.t] == [0, 1]
    # Running the other way: t decreases.
    back = blossom.Curve(part.nodes[:, ::-1].copy(), 3)
    assert c.intersect(back).tolist() == [[0.25, 0.75], [1.0, 0.0]]


def test_self_intersections_of_bezier_doc_cubic():
    # bezier's documentation example: B((3 - sqrt 5) / 6) = B((3 + sqrt 5) / 6).
    nodes = np.array([[0.0, -1.0, 1.0, -0.75], [2.0, 0.0, 1.0, 1.625]])
    c = blossom.Curve(nodes, 3)
    st = c.self_intersections()
    assert st.shape == (2, 1)
    assert st[0, 0] == (3 - math.sqrt(5)) / 6 or abs(st[0, 0] - (3 - math.sqrt(5)) / 6) <= math.ulp(0.13)
    assert st[0, 0] < st[1, 0]
    rec = c.self_intersection_records()
    poly = [int(x) for x in rec.points[0].s.polynomial]
    assert poly[0] * 9 == poly[2] and poly[1] == -poly[2]  # 1 - 9 s + 9 s^2
    # Both parameters give the same point, exactly within rounding.
    a, b = bernstein_point(nodes, st[0, 0]), bernstein_point(nodes, st[1, 0])
    assert max(abs(float(u - v)) for u, v in zip(a, b)) < 1e-14


def test_no_self_intersection_is_an_empty_2_by_0_array():
    c = blossom.Curve(np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 0.0]]), 2)
    st = c.self_intersections()
    assert st.shape == (2, 0) and st.dtype == np.float64


def test_exact_curves_intersect_exactly():
    p = blossom.Curve([[Fraction(0), Fraction(1)], [Fraction(0), Fraction(1)]], 1)
    q = blossom.Curve([[Fraction(0), Fraction(1)], [Fraction(1, 3), Fraction(0)]], 1)
    rec = p.intersections(q)
    # x = s = t, y: s = 1/3 (1 - t) -> s = 1/4.
    assert rec.points[0].s.exact == Fraction(1, 4) and rec.points[0].t.exact == Fraction(1, 4)
    assert p.intersect(q).tolist() == [[0.25], [0.25]]


def test_zero_parameters_are_positive_zero():
    p = blossom.Curve(np.array([[0.0, 1.0], [0.0, 1.0]]), 1)
    q = blossom.Curve(np.array([[0.0, 1.0], [0.0, -1.0]]), 1)
    st = p.intersect(q)
    assert st.tolist() == [[0.0], [0.0]]
    assert math.copysign(1.0, st[0, 0]) == 1.0 and math.copysign(1.0, st[1, 0]) == 1.0


def test_a_retracing_curve_is_an_overlap_with_itself():
    # x(s) = 4 s (1 - s) on the x axis runs to 1 and back: B(s) = B(1 - s) for every s, so
    # [0, 1/2] is traced again by t = 1 - s (checked here in Fractions).
    nodes = np.array([[0.0, 2.0, 0.0], [0.0, 0.0, 0.0]])
    for s in [Fraction(0), Fraction(1, 7), Fraction(1, 3)]:
        assert bernstein_point(nodes, s) == bernstein_point(nodes, 1 - s)
    c = blossom.Curve(nodes, 2)
    rec = c.self_intersection_records()
    assert rec.points == [] and len(rec.overlaps) == 1
    o = rec.overlaps[0]
    assert [a.exact for a in o.s] == [0, Fraction(1, 2)]
    assert [a.exact for a in o.t] == [1, Fraction(1, 2)]
    # The array: the end pairs with s < t, (1/2, 1/2) being no pair.
    assert c.self_intersections().tolist() == [[0.0], [1.0]]
