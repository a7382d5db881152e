"""Curve against exact Bernstein sums (conftest), numpy quadrature, and exact Fractions."""

import math
from fractions import Fraction

import numpy as np
import pytest

import blossom
from conftest import (
    as_floats,
    bernstein_derivative,
    bernstein_point,
    frac_nodes,
    random_nodes,
)


def close_to_exact(answer, exact, ulps=4):
    """Each float within `ulps` units in the last place of the exact value."""
    for a, e in zip(np.ravel(answer), exact):
        tol = ulps * math.ulp(max(abs(float(e)), 1e-300)) + 1e-300
        assert abs(a - float(e)) <= max(tol, 4 * np.finfo(float).eps * 4), (a, e)


def test_properties_and_nodes(rng):
    nodes = random_nodes(rng, 3, 4)
    c = blossom.Curve(nodes, 4)
    assert (c.degree, c.dimension, c.exact) == (4, 3, False)
    assert c.nodes.shape == (3, 5) and c.nodes.dtype == np.float64
    assert np.array_equal(c.nodes, nodes)
    assert c.nodes.flags.f_contiguous
    assert [[Fraction(x) for x in row] for row in nodes] == c.exact_nodes.tolist()
    same = blossom.Curve.from_nodes(nodes.tolist())
    assert np.array_equal(same.nodes, nodes) and same.degree == 4
    assert np.array_equal(c.copy().nodes, nodes)
    assert repr(c) == "<Curve (degree=4, dimension=3)>"


def test_integer_nodes_convert_losslessly():
    c = blossom.Curve(np.array([[0, 1, 2], [0, 3, 0]]), 2)
    assert c.nodes.dtype == np.float64 and c.nodes[1, 1] == 3.0


def test_numpy_scalars_in_object_arrays_are_read_exactly():
    nodes = np.array([[np.float32(0.1), Fraction(1, 3)], [np.int64(2), np.float64(0.25)]], dtype=object)
    c = blossom.Curve(nodes, 1)
    assert c.exact
    assert c.exact_nodes.tolist() == [[Fraction(float(np.float32(0.1))), Fraction(1, 3)], [2, Fraction(1, 4)]]


def test_evaluate_and_multi_match_the_bernstein_sum(rng):
    for d, n in [(1, 0), (2, 1), (2, 3), (3, 7), (2, 12)]:
        nodes = random_nodes(rng, d, n)
        c = blossom.Curve(nodes, n)
        s_vals = rng.uniform(-0.25, 1.25, 50)
        multi = c.evaluate_multi(s_vals)
        assert multi.shape == (d, 50)
        for k, s in enumerate(s_vals):
            exact = bernstein_point(nodes, s)
            one = c.evaluate(s)
            assert one.shape == (d, 1)
            # evaluate is de Casteljau's; evaluate_multi is too up to degree 4 and outside
            # [0, 1], and the O(n) method above (the same values within its error bound).
            if n <= 4 or not 0 <= s <= 1:
                assert np.array_equal(one[:, 0], multi[:, k])
            scale = np.abs(nodes).max() * 2**n * 8
            for got in (one[:, 0], multi[:, k]):
                assert np.all(np.abs(got - as_floats(exact)) <= scale * np.finfo(float).eps)


def test_evaluate_multi_error_within_twice_de_casteljau(rng):
    # Degrees 5..20 (the O(n) method): the largest error against the exact value over random
    # curves and parameters in [0, 1], at most twice that of de Casteljau's algorithm
    # (`evaluate`, bit for bit the library's de Casteljau), per degree.
    for n in range(5, 21):
        worst_multi = worst_dc = 0.0
        for lo, hi in [(-1.0, 1.0), (10.0, 11.0)]:
            nodes = np.asfortranarray(rng.uniform(lo, hi, (1, n + 1)))
            c = blossom.Curve(nodes, n)
            s_vals = rng.uniform(0.0, 1.0, 40)
            multi = c.evaluate_multi(s_vals)[0]
            for s, got in zip(s_vals, multi):
                exact = bernstein_point(nodes, s)[0]
                worst_multi = max(worst_multi, abs(float(Fraction(got) - exact)))
                worst_dc = max(worst_dc, abs(float(Fraction(c.evaluate(s)[0, 0]) - exact)))
        assert worst_multi <= 2 * worst_dc, (n, worst_multi, worst_dc)


def test_evaluate_multi_ends_and_layouts():
    nodes = np.asfortranarray([[10.0 + j / 7 for j in range(9)], [-(j**2) / 3 - 1e-3 for j in range(9)]])
    c = blossom.Curve(nodes, 8)
    s = np.array([0.0, 1.0, -0.5, 1.5, 0.5, 0.25])
    multi = c.evaluate_multi(s)
    assert multi.tolist()[0][:2] == [nodes[0, 0], nodes[0, -1]]
    assert multi.tolist()[1][:2] == [nodes[1, 0], nodes[1, -1]]
    for k in (2, 3):
        assert np.array_equal(multi[:, k], c.evaluate(s[k])[:, 0])
    # Strided, list and integer inputs give the same answer as a contiguous array.
    wide = np.zeros(12)
    wide[::2] = s
    assert np.array_equal(c.evaluate_multi(wide[::2]), multi)
    assert np.array_equal(c.evaluate_multi(s.tolist()), multi)
    assert np.array_equal(c.evaluate_multi(np.array([0, 1])), multi[:, :2])
    assert c.evaluate_multi(np.zeros(0)).shape == (2, 0)


def test_hodograph_matches_the_derivative_sum(rng):
    nodes = random_nodes(rng, 2, 5)
    c = blossom.Curve(nodes, 5)
    for s in [0.0, 0.3, 0.5, 1.0]:
        exact = bernstein_derivative(nodes, s)
        h = c.evaluate_hodograph(s)
        assert h.shape == (2, 1)
        assert np.allclose(h[:, 0], as_floats(exact), rtol=1e-13, atol=1e-13)


def test_exact_curve_answers_in_fractions():
    nodes = [[Fraction(0), Fraction(1, 3), Fraction(1)], [Fraction(0), Fraction(1), Fraction(0)]]
    c = blossom.Curve(nodes, 2)
    assert c.exact
    s = Fraction(2, 7)
    assert c.evaluate(s)[:, 0].tolist() == bernstein_point(nodes, s)
    multi = c.evaluate_multi([Fraction(1, 5), Fraction(3, 4)])
    assert multi[:, 1].tolist() == bernstein_point(nodes, Fraction(3, 4))
    left, right = c.subdivide()
    assert left.exact and right.exact
    # The left half at u is B(u / 2), exactly.
    u = Fraction(5, 9)
    assert left.evaluate(u)[:, 0].tolist() == bernstein_point(nodes, u / 2)
    assert right.evaluate(u)[:, 0].tolist() == bernstein_point(nodes, (1 + u) / 2)
    sp = c.specialize(Fraction(1, 3), Fraction(2, 3))
    assert sp.evaluate(u)[:, 0].tolist() == bernstein_point(nodes, Fraction(1, 3) + u / 3)
    # The float view of an exact curve is the nearest doubles.
    assert c.nodes[0, 1] == float(Fraction(1, 3))


def test_subdivide_and_specialize_trace_the_same_points(rng):
    nodes = random_nodes(rng, 2, 4)
    c = blossom.Curve(nodes, 4)
    left, right = c.subdivide()
    a, b = -0.5, 0.75
    sp = c.specialize(a, b)
    for u in [0.0, 0.25, 0.6, 1.0]:
        assert np.allclose(left.evaluate(u)[:, 0], as_floats(bernstein_point(nodes, u / 2)), atol=1e-14)
        assert np.allclose(right.evaluate(u)[:, 0], as_floats(bernstein_point(nodes, (1 + u) / 2)), atol=1e-14)
        assert np.allclose(sp.evaluate(u)[:, 0], as_floats(bernstein_point(nodes, a + u * (b - a))), atol=1e-13)


def test_elevate_is_exact_then_correctly_rounded(rng):
    nodes = random_nodes(rng, 2, 3)
    e = blossom.Curve(nodes, 3).elevate()
    assert e.degree == 4
    v = frac_nodes(nodes)
    n = 3
    # w_j = j/(n+1) v_(j-1) + (1 - j/(n+1)) v_j, exactly, then rounded.
    for x in range(2):
        for j in range(n + 2):
            w = Fraction(0)
            if j > 0:
                w += Fraction(j, n + 1) * v[x][j - 1]
            if j <= n:
                w += (1 - Fraction(j, n + 1)) * v[x][j]
            assert e.nodes[x, j] == float(w)


def test_reduce_undoes_elevate_exactly(rng):
    nodes = random_nodes(rng, 2, 3)
    c = blossom.Curve(nodes, 3)
    for method in ["least-squares", "least-squares-endpoints", "interpolating"]:
        r = c.elevate().reduce_(method=method)
        assert r.degree == 3 and np.array_equal(r.nodes, nodes)


def test_reduce_least_squares_is_the_l2_projection():
    # A cubic that is not a quadratic: its L2 projection on quadratics leaves an error
    # orthogonal to every quadratic (checked by exact integration with Fractions).
    nodes = [[Fraction(0), Fraction(1), Fraction(-1), Fraction(2)]]
    r = blossom.Curve(nodes, 3).reduce_()
    assert r.exact and r.degree == 2
    w = r.exact_nodes[0].tolist()
    v = nodes[0]

    def inner(f, g, deg_f, deg_g):
        # int_0^1 B_i^p B_j^q = C(p,i) C(q,j) / ((p+q+1) C(p+q, i+j))
        return sum(
            f[i] * g[j] * Fraction(math.comb(deg_f, i) * math.comb(deg_g, j), (deg_f + deg_g + 1) * math.comb(deg_f + deg_g, i + j))
            for i in range(deg_f + 1)
            for j in range(deg_g + 1)
        )

    for k in range(3):
        basis = [Fraction(int(i == k)) for i in range(3)]
        assert inner(v, basis, 3, 2) == inner(w, basis, 2, 2)


def test_length_matches_numpy_quadrature(rng):
    nodes = random_nodes(rng, 2, 3)
    c = blossom.Curve(nodes, 3)
    x, w = np.polynomial.legendre.leggauss(40)
    total = 0.0
    edges = np.linspace(0, 1, 65)
    for a, b in zip(edges[:-1], edges[1:]):
        s = (a + b) / 2 + (b - a) / 2 * x
        speed = [np.linalg.norm(as_floats(bernstein_derivative(nodes, si))) for si in s]
        total += (b - a) / 2 * np.dot(w, speed)
    assert abs(c.length - total) <= 1e-12 * total
    line = blossom.Curve(np.array([[0.0, 3.0], [0.0, 4.0]]), 1)
    assert line.length == pytest.approx(5.0, rel=1e-15)


def test_locate_finds_parameters_of_points_on_the_curve(rng):
    nodes = random_nodes(rng, 2, 3)
    c = blossom.Curve(nodes, 3)
    for s in [0.0, 0.3, 0.75, 1.0]:
        p = c.evaluate(s)
        assert c.locate(p) == pytest.approx(s, abs=1e-9)
    assert c.locate(np.array([[10.0], [10.0]])) is None
    exact = blossom.Curve([[Fraction(0), Fraction(1), Fraction(2)], [Fraction(0), Fraction(2), Fraction(0)]], 2)
    assert exact.locate(np.array([[Fraction(1)], [Fraction(1)]], dtype=object)) == 0.5
    # Exactly off the curve by 2^-60: not on it for exact input.
    assert exact.locate(np.array([[Fraction(1)], [Fraction(1) + Fraction(1, 2**60)]], dtype=object)) is None


def test_negative_zero_is_never_answered():
    c = blossom.Curve(np.array([[-0.0, -0.0], [0.0, 1.0]]), 1)
    v = c.evaluate(0.0)
    assert math.copysign(1.0, v[0, 0]) == 1.0
    assert math.copysign(1.0, c.nodes[0, 0]) == 1.0


def test_bounding_box_contains_samples_and_is_tight(rng):
    nodes = random_nodes(rng, 3, 5)
    c = blossom.Curve(nodes, 5)
    box = c.bounding_box()
    assert box.shape == (3, 2)
    samples = np.array([as_floats(bernstein_point(nodes, s)) for s in np.linspace(0, 1, 2001)]).T
    assert np.all(box[:, 0] <= samples.min(axis=1)) and np.all(samples.max(axis=1) <= box[:, 1])
    assert np.all(samples.min(axis=1) - box[:, 0] < 1e-5)
    assert np.all(box[:, 1] - samples.max(axis=1) < 1e-5)


def test_extremes_are_exact_for_a_parabola():
    # y(s) = 2 s (1 - s) * 2 = 4 s - 4 s^2 for nodes y = (0, 2, 0): max 1 at s = 1/2.
    c = blossom.Curve([[Fraction(0), Fraction(1), Fraction(2)], [Fraction(0), Fraction(2), Fraction(0)]], 2)
    e = c.extremes()
    assert e.max[1].value.exact == 1 and [a.exact for a in e.max[1].at] == [Fraction(1, 2)]
    assert e.min[1].value.exact == 0 and [a.exact for a in e.min[1].at] == [0, 1]


def test_nearest_point_against_sampling_and_exactly(rng):
    nodes = random_nodes(rng, 2, 3)
    c = blossom.Curve(nodes, 3)
    q = np.array([0.1, -0.2])
    near = c.nearest_point(q)
    s_grid = np.linspace(0, 1, 20001)
    d2 = [np.sum((as_floats(bernstein_point(nodes, s)) - q) ** 2) for s in s_grid[::50]]
    best = s_grid[::50][int(np.argmin(d2))]
    assert abs(near.at[0].value - best) < 0.01
    assert near.squared_distance.value <= min(d2) + 1e-15
    # Exactly: the point (1, 1) is at squared distance 1 from the segment (0, 0)-(2, 0),
    # reached at s = 1/2.
    seg = blossom.Curve([[Fraction(0), Fraction(2)], [Fraction(0), Fraction(0)]], 1)
    n2 = seg.nearest_point([Fraction(1), Fraction(1)])
    assert n2.squared_distance.exact == 1 and n2.at[0].exact == Fraction(1, 2)
    assert [p.exact for p in n2.points[0]] == [1, 0]
