"""Power-form restrictions, TensorPatch, the batch and zeros, against exact evaluations of the
power form and of Bernstein sums in Fractions, and numpy."""

from fractions import Fraction
from math import comb

import numpy as np
import pytest

import blossom
from conftest import bernstein_point, triangle_point

METHODS = ["bulk", "taylor-shift", "closed-form", "definition", "pyramid", "polarisation"]


def power_value(coeffs, u):
    return [sum(c * u**i for i, c in enumerate(row)) for row in coeffs]


@pytest.mark.parametrize("method", METHODS)
def test_power_curve_restriction_is_exact_for_fractions(method):
    coeffs = [[Fraction(1), Fraction(-2, 3), Fraction(5, 7), Fraction(1, 2)], [Fraction(0), Fraction(3), Fraction(-1), Fraction(2, 5)]]
    a, b = Fraction(-1, 3), Fraction(5, 4)
    c = blossom.restrict_power_curve(coeffs, a, b, method=method)
    assert c.exact and c.degree == 3
    nodes = c.exact_nodes
    for u in [Fraction(0), Fraction(1, 7), Fraction(1, 2), Fraction(1)]:
        assert bernstein_point(nodes, u) == power_value(coeffs, a + u * (b - a))


@pytest.mark.parametrize("method", METHODS)
def test_power_curve_restriction_in_float64(method, rng):
    coeffs = rng.uniform(-1, 1, (2, 6))
    c = blossom.restrict_power_curve(coeffs, 0.25, 0.75, method=method)
    for u in [0.0, 0.3, 1.0]:
        exact = power_value([[Fraction(x) for x in row] for row in coeffs], Fraction(0.25) + Fraction(u) / 2)
        assert np.allclose(c.evaluate(u)[:, 0], [float(e) for e in exact], atol=1e-12)


def tensor_value(nodes, s, t):
    d, rows, cols = len(nodes), len(nodes[0]), len(nodes[0][0])
    n, m = rows - 1, cols - 1
    return [
        sum(comb(n, i) * (1 - s) ** (n - i) * s**i * comb(m, j) * (1 - t) ** (m - j) * t**j * nodes[x][i][j] for i in range(rows) for j in range(cols))
        for x in range(d)
    ]


def test_power_surface_restriction_is_exact():
    coeffs = [[[Fraction(i + 2 * j + 1, 3) for j in range(3)] for i in range(2)]]
    rect = [Fraction(1, 4), Fraction(3, 4), Fraction(-1, 2), Fraction(1)]
    for method in METHODS:
        patch = blossom.restrict_power_surface(coeffs, rect, method=method)
        assert patch.exact and patch.degree == (1, 2) and patch.dimension == 1
        nodes = patch.nodes.tolist()
        for s, t in [(Fraction(0), Fraction(0)), (Fraction(1, 3), Fraction(2, 5))]:
            u, v = rect[0] + s * (rect[1] - rect[0]), rect[2] + t * (rect[3] - rect[2])
            expect = sum(coeffs[0][i][j] * u**i * v**j for i in range(2) for j in range(3))
            assert tensor_value(nodes, s, t) == [expect]
            assert patch.evaluate(s, t)[:, 0].tolist() == [expect]


def test_tensor_patch_specialize_and_evaluate(rng):
    nodes = rng.uniform(-1, 1, (2, 3, 4))
    p = blossom.TensorPatch(nodes)
    assert p.degree == (2, 3) and np.array_equal(p.nodes, nodes)
    exact = [[[Fraction(v) for v in row] for row in plane] for plane in nodes]
    sub = p.specialize([0.25, 0.5, 0.0, 0.5])
    for s, t in [(0.0, 0.0), (0.5, 0.25), (1.0, 1.0)]:
        want = tensor_value(exact, Fraction(0.25) + Fraction(s) / 4, Fraction(t) / 2)
        assert np.allclose(sub.evaluate(s, t)[:, 0], [float(w) for w in want], atol=1e-14)
        assert np.allclose(p.evaluate(s, t)[:, 0], [float(w) for w in tensor_value(exact, Fraction(s), Fraction(t))], atol=1e-14)


def test_power_triangle_restriction_is_exact():
    # p(s, t) = 1 + 2 s - t + s t + 3 t^2 (N = 2), columns in Triangle order (i, j), j outer.
    order = [(i, j) for j in range(3) for i in range(3 - j)]
    c = {(0, 0): 1, (1, 0): 2, (0, 1): -1, (1, 1): 1, (0, 2): 3}
    coeffs = [[Fraction(c.get(ij, 0)) for ij in order]]
    corners = [[Fraction(1, 4), Fraction(0)], [Fraction(1), Fraction(1, 2)], [Fraction(0), Fraction(1)]]
    for method in METHODS:
        tri = blossom.restrict_power_triangle(coeffs, corners, method=method)
        assert tri.exact and tri.degree == 2
        for u, v in [(Fraction(0), Fraction(0)), (Fraction(1, 3), Fraction(1, 5)), (Fraction(0), Fraction(1))]:
            s = corners[0][0] + u * (corners[1][0] - corners[0][0]) + v * (corners[2][0] - corners[0][0])
            t = corners[0][1] + u * (corners[1][1] - corners[0][1]) + v * (corners[2][1] - corners[0][1])
            want = sum(k * s**i * t**j for (i, j), k in c.items())
            assert triangle_point(tri.exact_nodes, 1 - u - v, u, v) == [want]


def de_casteljau_specialize(nodes, a, b):
    """Numpy reference: the nodes of B over [a, b], by blossoming B(a^(n-j), b^j)."""
    n = nodes.shape[-1] - 1
    out = np.empty_like(nodes)
    for j in range(n + 1):
        level = nodes.copy()
        args = [a] * (n - j) + [b] * j
        for arg in args:
            level = (1 - arg) * level[..., :-1] + arg * level[..., 1:]
        out[..., j] = level[..., 0]
    return out


def test_batch_restriction_matches_specialize_bit_for_bit(rng):
    nodes = rng.uniform(-1, 1, (1000, 2, 4))
    out = blossom.restrict_curves(nodes, 0.25, 0.75)
    assert out.shape == nodes.shape and out.dtype == np.float64
    for k in [0, 1, 517, 999]:
        one = blossom.Curve(nodes[k], 3).specialize(0.25, 0.75).nodes
        assert np.array_equal(out[k], one)
    assert np.allclose(out, de_casteljau_specialize(nodes, 0.25, 0.75), atol=1e-15)
    # Any memory order and any degree.
    fortran = np.asfortranarray(rng.uniform(-1, 1, (7, 3, 12)))
    assert np.allclose(blossom.restrict_curves(fortran, -0.5, 0.5), de_casteljau_specialize(fortran, -0.5, 0.5), atol=1e-13)


def test_bezier_zeros_with_multiplicities(rng):
    z = blossom.bezier_zeros([1.0, -1.0, 1.0])  # (1 - 2t)^2
    assert [(x.t.exact, x.multiplicity) for x in z.zeros] == [(Fraction(1, 2), 2)]
    z = blossom.bezier_zeros([Fraction(1), Fraction(-2), Fraction(1)])  # 1 - 6t + 6t^2
    roots = sorted(np.roots([6, -6, 1]))
    assert [x.t.value for x in z.zeros] == pytest.approx(roots, abs=1e-16)
    assert [int(c) for c in z.zeros[0].t.polynomial] in ([1, -6, 6], [-1, 6, -6])
    assert blossom.bezier_zeros([0.0, 0.0]).identically_zero
    for _ in range(20):
        b = np.round(rng.uniform(-1, 1, 6) * 2**10) / 2**10
        n = 5
        power = [sum(comb(n, k) * comb(k, j) * (-1) ** (k - j) * b[j] for j in range(k + 1)) for k in range(n + 1)]
        ref = [r.real for r in np.roots(power[::-1]) if abs(r.imag) < 1e-9 and 1e-7 < r.real < 1 - 1e-7]
        got = blossom.bezier_zeros(b)
        assert [z.t.value for z in got.zeros] == pytest.approx(sorted(ref), abs=1e-7)
