"""Independent reference computations for the tests: Bernstein sums with math.comb in
Fractions (exact), never the binding itself."""

from fractions import Fraction
from math import comb, factorial

import numpy as np
import pytest


def frac_nodes(nodes):
    """The exact values of a D x N array (floats read exactly)."""
    return [[Fraction(x) for x in row] for row in np.asarray(nodes, dtype=object)]


def bernstein_point(nodes, s):
    """B(s) = sum_j C(n, j) (1 - s)^(n - j) s^j v_j, exactly, for D x (n + 1) nodes."""
    rows = frac_nodes(nodes)
    s = Fraction(s)
    n = len(rows[0]) - 1
    return [
        sum(comb(n, j) * (1 - s) ** (n - j) * s**j * row[j] for j in range(n + 1))
        for row in rows
    ]


def bernstein_derivative(nodes, s):
    """B'(s) = n sum_j C(n - 1, j) (1 - s)^(n - 1 - j) s^j (v_(j+1) - v_j), exactly."""
    rows = frac_nodes(nodes)
    s = Fraction(s)
    n = len(rows[0]) - 1
    if n == 0:
        return [Fraction(0) for _ in rows]
    return [
        n
        * sum(
            comb(n - 1, j) * (1 - s) ** (n - 1 - j) * s**j * (row[j + 1] - row[j])
            for j in range(n)
        )
        for row in rows
    ]


def triangle_indices(n):
    """bezier's node order of a degree-n triangle: (i, j) with j the outer loop."""
    return [(i, j) for j in range(n + 1) for i in range(n + 1 - j)]


def triangle_degree(count):
    n = 0
    while (n + 1) * (n + 2) // 2 < count:
        n += 1
    assert (n + 1) * (n + 2) // 2 == count
    return n


def triangle_point(nodes, l1, l2, l3):
    """sum n!/(i! j! k!) l1^k l2^i l3^j v_(i, j), k = n - i - j, exactly (homogeneous)."""
    rows = frac_nodes(nodes)
    n = triangle_degree(len(rows[0]))
    l1, l2, l3 = Fraction(l1), Fraction(l2), Fraction(l3)
    out = []
    for row in rows:
        total = Fraction(0)
        for col, (i, j) in enumerate(triangle_indices(n)):
            k = n - i - j
            coeff = factorial(n) // (factorial(i) * factorial(j) * factorial(k))
            total += coeff * l1**k * l2**i * l3**j * row[col]
        out.append(total)
    return out


def as_floats(v):
    return np.array([float(x) for x in v])


@pytest.fixture
def rng():
    return np.random.default_rng(20261207)


def random_nodes(rng, d, n, scale=1.0):
    """D x (n + 1) float64 nodes with 20-bit coordinates (exact in any exact check)."""
    return np.asfortranarray(np.round(rng.uniform(-scale, scale, (d, n + 1)) * 2**20) / 2**20)
