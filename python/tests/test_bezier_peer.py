"""Python bezier as a peer (skipped where it is not installed): the same names, argument
orders and shapes give the same answers, up to rounding, on inputs bezier handles."""

import numpy as np
import pytest

import blossom
from conftest import random_nodes

bezier = pytest.importorskip("bezier")


def pair(nodes, degree=None):
    degree = nodes.shape[1] - 1 if degree is None else degree
    return blossom.Curve(nodes, degree), bezier.Curve(nodes, degree)


def test_curve_methods_agree(rng):
    for n in [1, 2, 3, 5]:
        nodes = random_nodes(rng, 2, n)
        ours, theirs = pair(nodes)
        s = np.linspace(0, 1, 17)
        assert np.allclose(ours.evaluate_multi(s), theirs.evaluate_multi(s), atol=1e-14)
        assert np.allclose(ours.evaluate(0.3), theirs.evaluate(0.3), atol=1e-14)
        assert np.allclose(ours.evaluate_hodograph(0.7), theirs.evaluate_hodograph(0.7), atol=1e-13)
        for a, b in zip(ours.subdivide(), theirs.subdivide()):
            assert np.allclose(a.nodes, b.nodes, atol=1e-15)
        assert np.allclose(ours.specialize(-0.25, 0.6).nodes, theirs.specialize(-0.25, 0.6).nodes, atol=1e-14)
        assert np.allclose(ours.elevate().nodes, theirs.elevate().nodes, atol=1e-15)
        if n <= 3:  # bezier reduces degrees 1 to 4 only
            assert np.allclose(ours.elevate().reduce_().nodes, theirs.elevate().reduce_().nodes, atol=1e-14)
        assert ours.length == pytest.approx(theirs.length, rel=1e-10)
        assert ours.locate(theirs.evaluate(0.4)) == pytest.approx(theirs.locate(theirs.evaluate(0.4)), abs=1e-9)
        assert (ours.degree, ours.dimension) == (theirs.degree, theirs.dimension)
        assert repr(ours) == repr(theirs)


def test_intersections_agree_on_random_cubics(rng):
    compared = 0
    for _ in range(50):
        p, q = random_nodes(rng, 2, 3), random_nodes(rng, 2, 3)
        ours = blossom.Curve(p, 3).intersect(blossom.Curve(q, 3))
        try:
            theirs = bezier.Curve(p, 3).intersect(bezier.Curve(q, 3))
        except Exception:  # bezier raises on some inputs; ours answers (tested elsewhere)
            continue
        theirs = theirs[:, np.lexsort((theirs[1], theirs[0]))]
        assert ours.shape == theirs.shape
        assert np.allclose(ours, theirs, atol=1e-10)
        compared += 1
    assert compared > 40


def test_self_intersections_agree_with_bezier_doc_example():
    nodes = np.asfortranarray([[0.0, -1.0, 1.0, -0.75], [2.0, 0.0, 1.0, 1.625]])
    ours, theirs = pair(nodes)
    assert np.allclose(ours.self_intersections(), np.sort(theirs.self_intersections(), axis=0), atol=1e-12)


def test_triangles_agree(rng):
    for n in [1, 2, 3]:
        count = (n + 1) * (n + 2) // 2
        nodes = np.asfortranarray(rng.uniform(-1, 1, (2, count)))
        nodes[:, 0], nodes[:, n], nodes[:, -1] = [0, 0], [1, 0], [0, 1]
        ours, theirs = blossom.Triangle(nodes, n), bezier.Triangle(nodes, n)
        params = np.asfortranarray(rng.dirichlet([1, 1, 1], 10))
        assert np.allclose(ours.evaluate_barycentric_multi(params), theirs.evaluate_barycentric_multi(params), atol=1e-14)
        assert np.allclose(ours.evaluate_cartesian_multi(params[:, 1:]), theirs.evaluate_cartesian_multi(np.asfortranarray(params[:, 1:])), atol=1e-14)
        for a, b in zip(ours.subdivide(), theirs.subdivide()):
            assert np.allclose(a.nodes, b.nodes, atol=1e-15)
        for a, b in zip(ours.edges, theirs.edges):
            assert np.allclose(a.nodes, b.nodes, atol=0)
        assert np.allclose(ours.elevate().nodes, theirs.elevate().nodes, atol=1e-15)
        assert ours.area == pytest.approx(theirs.area, rel=1e-12, abs=1e-15)
        try:
            valid = theirs.is_valid
        except ValueError:  # bezier's subdivision did not conclude
            continue
        assert ours.is_valid == valid


def test_curved_polygon_area_agrees():
    edges = [
        np.asfortranarray([[0.0, 1.0, 2.0], [0.0, -1.0, 0.0]]),
        np.asfortranarray([[2.0, 1.0, 0.0], [0.0, 1.5, 0.0]]),
    ]
    ours = blossom.CurvedPolygon(*[blossom.Curve.from_nodes(e) for e in edges])
    theirs = bezier.CurvedPolygon(*[bezier.Curve.from_nodes(e) for e in edges])
    assert ours.num_sides == theirs.num_sides
    assert ours.area == pytest.approx(theirs.area, rel=1e-14)
