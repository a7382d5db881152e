"""Every kind of bad input raises blossom.Error (a ValueError) naming the argument and field;
a Rust panic is an exception, not an abort."""

from fractions import Fraction

import numpy as np
import pytest

import blossom

LINE = np.array([[0.0, 1.0], [0.0, 1.0]])


def raises(path, kind, fn, *args, **kwargs):
    with pytest.raises(blossom.Error) as info:
        fn(*args, **kwargs)
    assert isinstance(info.value, ValueError)
    assert info.value.path == path and info.value.kind == kind, (info.value.path, info.value.kind, str(info.value))
    assert str(info.value).startswith(f"{path}: ") or path == ""
    return info.value


def test_nodes_shape_and_values():
    raises("nodes", "Shape", blossom.Curve, [0.0, 1.0], 1)
    raises("nodes", "Shape", blossom.Curve, np.zeros((2, 2, 2)), 1)
    raises("nodes", "Empty", blossom.Curve, np.zeros((2, 0)), 0)
    raises("degree", "Degree", blossom.Curve, LINE, 2)
    raises("nodes[1, 0]", "NotFinite", blossom.Curve, np.array([[0.0, 1.0], [np.nan, 1.0]]), 1)
    raises("nodes[0, 1]", "NotFinite", blossom.Curve, [[0.0, float("inf")], [0.0, 1.0]], 1)
    raises("nodes", "Invalid", blossom.Curve, np.array([[0, 2**60 + 1], [0, 1]]), 1)
    raises("nodes", "Invalid", blossom.Curve, [["a", "b"], ["c", "d"]], 1)
    raises("nodes[0, 1]", "Invalid", blossom.Curve, np.array([[0.0, "x"], [0.0, 1.0]], dtype=object), 1)
    raises("nodes[0, 1]", "Invalid", blossom.Curve, np.array([[Fraction(0), True], [0.0, 1.0]], dtype=object), 1)
    raises("nodes[1, 1]", "Invalid", blossom.Curve, np.array([[0.0, 1.0], [0.0, 2**70 + 1]], dtype=object), 1)
    if np.dtype(np.longdouble).itemsize > 8:
        raises("nodes[0, 0]", "Invalid", blossom.Curve, np.array([[np.longdouble(1), 1.0], [0.0, 1.0]], dtype=object), 1)
    raises("degree", "Degree", blossom.Triangle, np.zeros((2, 4)), 1)
    raises("nodes", "Shape", blossom.Triangle.from_nodes, np.zeros((2, 4)))
    raises("nodes", "Shape", blossom.TensorPatch, np.zeros((2, 3)))


def test_parameters():
    c = blossom.Curve(LINE, 1)
    raises("s", "NotFinite", c.evaluate, float("nan"))
    raises("s", "Invalid", c.evaluate, "half")
    raises("s_vals", "Shape", c.evaluate_multi, np.zeros((2, 2)))
    raises("s_vals[1]", "NotFinite", c.evaluate_multi, [0.0, float("inf")])
    raises("end", "NotFinite", c.specialize, 0.0, float("inf"))
    raises("point", "Dimension", c.locate, np.zeros((3, 1)))
    raises("point", "Dimension", c.nearest_point, [1.0])
    raises("method", "UnknownName", c.reduce_, method="pseudo-inverse")
    raises("self", "Degree", blossom.Curve(np.array([[1.0], [2.0]]), 0).reduce_)


def test_dimensions_an_operation_does_not_take():
    c3 = blossom.Curve(np.zeros((3, 2)) + [[0.0, 1.0]], 1)
    c2 = blossom.Curve(LINE, 1)
    raises("self.nodes", "Dimension", c3.intersect, c2)
    raises("other.nodes", "Dimension", c2.intersect, c3)
    raises("self.nodes", "Dimension", c3.self_intersections)
    raises("self.nodes", "Dimension", c3.intersections, c2)
    raises("other", "Invalid", c2.intersect, "not a curve")
    t3 = blossom.Triangle(np.zeros((3, 3)), 1)
    raises("self.nodes", "Dimension", getattr, t3, "area")
    raises("self.nodes", "Dimension", getattr, t3, "is_valid")


def test_triangle_parameters():
    t = blossom.Triangle(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 1)
    raises("lambda1 + lambda2 + lambda3", "Domain", t.evaluate_barycentric, 0.5, 0.5, 0.5)
    raises("lambda1, lambda2, lambda3", "Domain", t.evaluate_barycentric, 1.5, -0.5, 0.0)
    raises("s, t", "Domain", t.evaluate_cartesian, 0.75, 0.5)
    raises("param_vals", "Shape", t.evaluate_cartesian_multi, np.zeros((4, 3)))
    raises("param_vals", "Shape", t.evaluate_barycentric_multi, np.zeros((4, 2)))
    raises("corners", "Shape", t.specialize, np.zeros((2, 2)))
    raises("lambda2", "NotFinite", t.evaluate_barycentric, 0.0, float("nan"), 1.0)


def test_curved_polygon():
    a = blossom.Curve(np.array([[0.0, 1.0], [0.0, 0.0]]), 1)
    b = blossom.Curve(np.array([[1.0, 0.0], [0.0, 1.0]]), 1)
    raises("edges[1]", "Invalid", blossom.CurvedPolygon, a, b)  # b ends at (0, 1), a starts at (0, 0)
    raises("edges", "Shape", blossom.CurvedPolygon, a)
    raises("edges[1]", "Invalid", blossom.CurvedPolygon, a, "b")


def test_power_and_batch_arguments():
    raises("method", "UnknownName", blossom.restrict_power_curve, [[0.0, 1.0]], 0.0, 1.0, method="magic")
    raises("coefficients", "Shape", blossom.restrict_power_curve, [0.0, 1.0], 0.0, 1.0)
    raises("rect", "Shape", blossom.restrict_power_surface, np.zeros((1, 2, 2)), [0.0, 1.0])
    raises("coefficients", "Shape", blossom.restrict_power_triangle, np.zeros((1, 4)), np.zeros((3, 2)))
    raises("coefficients", "TooLarge", blossom.restrict_power_curve, np.zeros((1, 2000)), 0.0, 1.0)
    raises("nodes", "Shape", blossom.restrict_curves, np.zeros((2, 4)), 0.0, 1.0)
    raises("nodes[1, 0, 2]", "NotFinite", blossom.restrict_curves, np.array([[[0.0, 0, 0]], [[0, 0, np.nan]]]), 0.0, 1.0)
    raises("start", "NotFinite", blossom.restrict_curves, np.zeros((1, 2, 4)), float("nan"), 1.0)
    raises("nodes", "Invalid", blossom.restrict_curves, [[[Fraction(1), Fraction(2)]]], 0.0, 1.0)
    raises("coefficients", "Empty", blossom.bezier_zeros, [])
    nodes = np.zeros((3, 2, 4))
    raises("out", "Shape", blossom.restrict_curves, nodes, 0.0, 1.0, out=np.zeros((3, 2, 5)))
    raises("out", "Shape", blossom.restrict_curves, nodes, 0.0, 1.0, out=np.zeros((3, 4, 2)).transpose(0, 2, 1))
    raises("out", "Invalid", blossom.restrict_curves, nodes, 0.0, 1.0, out=np.zeros((3, 2, 4), dtype=np.float32))
    raises("out", "Invalid", blossom.restrict_curves, nodes, 0.0, 1.0, out=nodes)


def test_work_over_the_limit_is_refused_before_computing():
    rng = np.random.default_rng(1)
    p = blossom.Curve(rng.uniform(-1, 1, (2, 30)), 29)
    q = blossom.Curve(rng.uniform(-1, 1, (2, 30)), 29)
    raises("max_work", "TooLarge", p.intersect, q, max_work=1e6)
    raises("max_work", "TooLarge", p.self_intersections, max_work=1e6)
    raises("max_work", "TooLarge", blossom.bezier_zeros, rng.uniform(-1, 1, 40), max_work=1e3)
    raises("max_work", "Domain", p.intersect, q, max_work=-1.0)
    raises("max_work", "Domain", blossom.bezier_zeros, [1.0, -1.0], max_work=float("nan"))


def test_degrees_types_and_flags():
    # The issue-47 case: a negative degree was an OverflowError.
    raises("degree", "Degree", blossom.Curve, LINE, -1)
    raises("degree", "TooLarge", blossom.Curve, LINE, 2**70)
    raises("degree", "Invalid", blossom.Curve, LINE, "1")
    raises("degree", "Invalid", blossom.Curve, LINE, 1.0)
    raises("degree", "Invalid", blossom.Curve, LINE, True)
    assert blossom.Curve(LINE, np.int64(1)).degree == 1
    raises("degree", "Degree", blossom.Triangle, np.zeros((2, 3)), -2)
    raises("method", "Invalid", blossom.Curve(LINE, 1).reduce_, 3)
    raises("fill_rule", "Invalid", blossom.CurvedRegion, [], fill_rule=0)
    raises("start", "Invalid", blossom.restrict_curves, np.zeros((1, 2, 4)), "0", 1.0)
    raises("end", "NotFinite", blossom.restrict_curves, np.zeros((1, 2, 4)), 0.0, 10**400)
    raises("max_work", "Invalid", blossom.bezier_zeros, [1.0, -1.0], max_work="a lot")
    t = blossom.Triangle(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 1)
    raises("verify", "Invalid", t.evaluate_cartesian, 0.2, 0.2, verify="no")
    raises("triangle", "Invalid", blossom.CurvedRegion.from_triangle, LINE)
    raises("other", "Invalid", blossom.Curve(LINE, 1).intersections, None)
    # Arguments taken for bezier's signature only accept anything, as bezier's do.
    assert blossom.Curve(LINE, 1, copy=0, verify="yes").degree == 1
    # None is the default of the optional string arguments.
    assert blossom.Curve(LINE, 1).reduce_(method=None).degree == 0


def test_a_rust_panic_is_an_exception():
    err = raises("", "Panic", blossom._panic_for_tests)
    assert "deliberate panic" in str(err)
