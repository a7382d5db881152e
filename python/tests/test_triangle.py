"""Triangle and CurvedPolygon against the exact trinomial sum (conftest), exact Green's
theorem written here, and bezier's documented conventions."""

from fractions import Fraction

import numpy as np
import pytest

import blossom
from conftest import as_floats, random_nodes, triangle_point

QUADRATIC = np.asfortranarray(
    [[0.0, 0.5, 1.0, 0.125, 0.375, 0.25], [0.0, 0.0, 0.25, 0.5, 0.375, 1.0]]
)


def test_properties_and_from_nodes():
    t = blossom.Triangle(QUADRATIC, 2)
    assert (t.degree, t.dimension, t.exact) == (2, 2, False)
    assert np.array_equal(t.nodes, QUADRATIC)
    assert blossom.Triangle.from_nodes(QUADRATIC).degree == 2
    assert repr(t) == "<Triangle (degree=2, dimension=2)>"


def test_evaluations_match_the_trinomial_sum(rng):
    for n in [1, 2, 3, 5]:
        count = (n + 1) * (n + 2) // 2
        nodes = np.asfortranarray(np.round(rng.uniform(-1, 1, (3, count)) * 2**20) / 2**20)
        t = blossom.Triangle(nodes, n)
        params = rng.dirichlet([1, 1, 1], 20)
        multi = t.evaluate_barycentric_multi(params)
        cart = t.evaluate_cartesian_multi(params[:, 1:])
        for k, (l1, l2, l3) in enumerate(params):
            exact = as_floats(triangle_point(nodes, l1, l2, l3))
            one = t.evaluate_barycentric(l1, l2, l3)
            assert one.shape == (3, 1)
            assert np.allclose(one[:, 0], exact, atol=1e-14)
            assert np.allclose(multi[:, k], exact, atol=1e-14)
            # Cartesian (s, t) = (lambda2, lambda3); lambda1 = 1 - s - t is rounded.
            assert np.allclose(cart[:, k], as_floats(triangle_point(nodes, 1 - Fraction(l2) - Fraction(l3), l2, l3)), atol=1e-14)
            assert np.allclose(t.evaluate_cartesian(l2, l3)[:, 0], cart[:, k], atol=0)


def test_homogeneous_evaluation_without_verify():
    t = blossom.Triangle(QUADRATIC, 2)
    got = t.evaluate_barycentric(0.5, 1.0, 1.5, verify=False)[:, 0]
    assert np.allclose(got, as_floats(triangle_point(QUADRATIC, 0.5, 1.0, 1.5)), atol=1e-14)


def test_exact_triangle_answers_in_fractions():
    nodes = [[Fraction(k, 7) for k in range(6)], [Fraction(k * k, 5) for k in range(6)]]
    t = blossom.Triangle(nodes, 2)
    assert t.exact
    l = (Fraction(1, 3), Fraction(1, 5), Fraction(7, 15))
    assert t.evaluate_barycentric(*l)[:, 0].tolist() == triangle_point(nodes, *l)
    assert t.evaluate_cartesian(l[1], l[2])[:, 0].tolist() == triangle_point(nodes, *l)


def test_subdivide_follows_bezier_order(rng):
    nodes = random_nodes(rng, 2, 5)  # 6 nodes: a quadratic triangle
    t = blossom.Triangle(nodes, 2)
    parts = t.subdivide()
    # Each part maps (0,0), (1,0), (0,1) to these (s, t), as bezier documents.
    corners = [
        [(0, 0), (0.5, 0), (0, 0.5)],
        [(0.5, 0.5), (0, 0.5), (0.5, 0)],
        [(0.5, 0), (1, 0), (0.5, 0.5)],
        [(0, 0.5), (0.5, 0.5), (0, 1)],
    ]
    for part, c in zip(parts, corners):
        (a, b, d) = [np.array(p, dtype=float) for p in c]
        for u, v in [(0.0, 0.0), (0.2, 0.3), (1.0, 0.0), (0.0, 1.0)]:
            s, tt = a + u * (b - a) + v * (d - a)
            exact = as_floats(triangle_point(nodes, 1 - Fraction(s) - Fraction(tt), s, tt))
            assert np.allclose(part.evaluate_cartesian(u, v)[:, 0], exact, atol=1e-14)


def test_specialize_maps_the_reference_triangle():
    nodes = [[Fraction(k, 3) for k in range(6)], [Fraction(k * k - 2, 5) for k in range(6)]]
    t = blossom.Triangle(nodes, 2)
    corners = [[Fraction(1, 4), Fraction(1, 8)], [Fraction(1, 2), Fraction(1, 4)], [Fraction(0), Fraction(3, 4)]]
    sub = t.specialize(corners)
    assert sub.exact
    (a, b, d) = [(Fraction(x), Fraction(y)) for x, y in corners]
    u, v = Fraction(1, 3), Fraction(1, 6)
    s = a[0] + u * (b[0] - a[0]) + v * (d[0] - a[0])
    tt = a[1] + u * (b[1] - a[1]) + v * (d[1] - a[1])
    assert sub.evaluate_cartesian(u, v)[:, 0].tolist() == triangle_point(nodes, 1 - s - tt, s, tt)


def test_elevate_keeps_the_surface(rng):
    t = blossom.Triangle(QUADRATIC, 2)
    e = t.elevate()
    assert e.degree == 3
    for l in [(1, 0, 0), (0.2, 0.3, 0.5), (0, 0, 1)]:
        assert np.allclose(e.evaluate_barycentric(*l)[:, 0], as_floats(triangle_point(QUADRATIC, *l)), atol=1e-15)


def test_edges_run_around_the_boundary():
    t = blossom.Triangle(QUADRATIC, 2)
    e1, e2, e3 = t.edges
    for u in [0.0, 0.3, 1.0]:
        assert np.allclose(e1.evaluate(u)[:, 0], as_floats(triangle_point(QUADRATIC, 1 - u, u, 0)))
        assert np.allclose(e2.evaluate(u)[:, 0], as_floats(triangle_point(QUADRATIC, 0, 1 - u, u)))
        assert np.allclose(e3.evaluate(u)[:, 0], as_floats(triangle_point(QUADRATIC, u, 0, 1 - u)))


def green_area(edge_nodes_list):
    """(1/2) sum of int (x y' - y x') over the edges, by the power form in Fractions."""
    from math import comb

    total = Fraction(0)
    for nodes in edge_nodes_list:
        xs, ys = [[Fraction(v) for v in row] for row in np.asarray(nodes, dtype=object)]
        n = len(xs) - 1
        # Power coefficients a_k = sum_j C(n, k) C(k, j) (-1)^(k-j) v_j.
        def power(v):
            return [sum(comb(n, k) * comb(k, j) * (-1) ** (k - j) * v[j] for j in range(k + 1)) for k in range(n + 1)]

        a, b = power(xs), power(ys)
        for i in range(n + 1):
            for j in range(n + 1):
                if i + j > 0:
                    total += a[i] * b[j] * Fraction(j - i, i + j)
    return total / 2


def test_area_is_exact_green(rng):
    t = blossom.Triangle(QUADRATIC, 2)
    exact = green_area([e.exact_nodes for e in t.edges])
    assert t.area == float(exact)
    linear = blossom.Triangle(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 1)
    assert linear.area == 0.5
    clockwise = blossom.Triangle(np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]]), 1)
    assert clockwise.area == -0.5


def test_is_valid_decides_the_jacobian_sign():
    assert blossom.Triangle(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 1).is_valid
    # Collinear corners: invalid.
    assert not blossom.Triangle(np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 2.0]]), 1).is_valid
    # Clockwise: J < 0, invalid (bezier's definition: positive Jacobian).
    assert not blossom.Triangle(np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]]), 1).is_valid
    assert blossom.Triangle(QUADRATIC, 2).is_valid
    # bezier's documented invalid quadratic: its Jacobian (central differences of the exact
    # sum, an independent witness) takes both signs.
    folded = np.array([[1.0, 0.0, 1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0, 0.0, 1.0]])
    h = Fraction(1, 10**6)

    def jac(s, t):
        def p(s, t):
            return triangle_point(folded, 1 - s - t, s, t)

        xs = [(a - b) / (2 * h) for a, b in zip(p(s + h, t), p(s - h, t))]
        xt = [(a - b) / (2 * h) for a, b in zip(p(s, t + h), p(s, t - h))]
        return xs[0] * xt[1] - xs[1] * xt[0]

    signs = {jac(Fraction(s), Fraction(t)) > 0 for s, t in [(0.1, 0.1), (0.05, 0.3), (0.5, 0.3)]}
    assert signs == {True, False}
    assert not blossom.Triangle(folded, 2).is_valid
    # Degree 4 (bezier raises UnsupportedDegree there): an elevated valid triangle is valid.
    assert blossom.Triangle(QUADRATIC, 2).elevate().elevate().is_valid


def test_triangle_intersect_with_itself_is_itself():
    # bezier raises on coincident triangles; the regularized intersection is the triangle.
    t = blossom.Triangle(QUADRATIC, 2)
    (got,) = t.intersect(t)
    assert isinstance(got, blossom.Triangle)
    assert np.array_equal(got.nodes, t.nodes)


def test_curved_polygon_area_and_sides():
    square = [
        blossom.Curve(np.array([[0.0, 1.0], [0.0, 0.0]]), 1),
        blossom.Curve(np.array([[1.0, 1.0], [0.0, 1.0]]), 1),
        blossom.Curve(np.array([[1.0, 0.0], [1.0, 1.0]]), 1),
        blossom.Curve(np.array([[0.0, 0.0], [1.0, 0.0]]), 1),
    ]
    poly = blossom.CurvedPolygon(*square)
    assert poly.num_sides == 4 and poly.area == 1.0
    assert len(poly.edges) == 4
    # A lens: a parabola arc and a segment, area 2/3 * base * height.
    arc = blossom.Curve(np.array([[0.0, 1.0, 2.0], [0.0, -2.0, 0.0]]), 2)
    back = blossom.Curve(np.array([[2.0, 0.0], [0.0, 0.0]]), 1)
    lens = blossom.CurvedPolygon(arc, back)
    assert lens.area == float(green_area([arc.exact_nodes, back.exact_nodes]))
    assert lens.area == pytest.approx(2 / 3 * 2 * 1)
    assert blossom.CurvedPolygon(arc, back, metadata=((0, 0.0, 1.0),)).metadata == ((0, 0.0, 1.0),)
