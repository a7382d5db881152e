"""Every bad argument of every public function and method raises blossom.Error (never
TypeError, OverflowError or a bare ValueError) whose path names the argument: the sweep
calls each with values of wrong types, out-of-range integers, NaN and infinities, one
argument at a time, the others valid."""

from fractions import Fraction

import numpy as np
import pytest

import blossom

LINE = np.array([[0.0, 1.0], [0.0, 1.0]])
CUBIC = np.array([[0.0, 1.0, 2.0, 3.0], [0.0, 2.0, -1.0, 0.5]])
TRI = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
SQUARE = [
    blossom.Curve(np.array([[0.0, 1.0], [0.0, 0.0]]), 1),
    blossom.Curve(np.array([[1.0, 1.0], [0.0, 1.0]]), 1),
    blossom.Curve(np.array([[1.0, 0.0], [1.0, 1.0]]), 1),
    blossom.Curve(np.array([[0.0, 0.0], [1.0, 0.0]]), 1),
]


class Unconvertible:
    """An object no argument accepts."""

    def __repr__(self):
        return "Unconvertible()"


# Bad values by the kind of argument (None is the default of the optional ones, not here).
NOT_A_NUMBER = ["x", [1.0, 2.0], Unconvertible(), b"1", {"a": 1}]
FLOATS = NOT_A_NUMBER + [None, float("nan"), float("inf"), -float("inf"), 10**400]
INTS = ["3", None, 2.5, -1, -(2**70), 2**70, 2**200, Unconvertible(), [1], float("nan")]
STRINGS = [3, b"nonzero", ["nonzero"], Unconvertible()]
ARRAYS = ["abc", None, Unconvertible(), {"a": 1}, [[1.0, 2.0], [3.0]], [[1.0, "x"]], float("nan")]
BOOLS = ["yes", 2, 1.0, Unconvertible()]
CURVES = ["x", None, 3, LINE, Unconvertible()]


class Glyph:
    """A drawable glyph: a triangle."""

    def draw(self, pen):
        pen.moveTo((0.0, 0.0))
        pen.lineTo((1.0, 0.0))
        pen.lineTo((0.0, 1.0))
        pen.closePath()


def opened():
    """A pen with a contour started."""
    pen = blossom.RegionPen()
    pen.moveTo((0.0, 0.0))
    return pen


def region():
    return blossom.CurvedRegion([SQUARE])


def curve():
    return blossom.Curve(CUBIC, 3)


def triangle():
    return blossom.Triangle(TRI, 1)


# (label, function, positional arguments, keyword arguments, {argument: (bad values, the
# path's start)}): each bad value replaces that argument (a keyword when the argument is one).
CASES = [
    ("Curve", blossom.Curve, [CUBIC, 3], {}, {0: (ARRAYS, "nodes"), 1: (INTS, "degree")}),
    ("Curve.from_nodes", blossom.Curve.from_nodes, [CUBIC], {}, {0: (ARRAYS, "nodes")}),
    ("Curve.evaluate", lambda *a: curve().evaluate(*a), [0.5], {}, {0: (FLOATS, "s")}),
    ("Curve.evaluate_multi", lambda *a: curve().evaluate_multi(*a), [[0.5]], {}, {0: (ARRAYS, "s_vals")}),
    ("Curve.evaluate_hodograph", lambda *a: curve().evaluate_hodograph(*a), [0.5], {}, {0: (FLOATS, "s")}),
    ("Curve.specialize", lambda *a: curve().specialize(*a), [0.0, 0.5], {}, {0: (FLOATS, "start"), 1: (FLOATS, "end")}),
    ("Curve.reduce_", lambda **k: curve().reduce_(**k), [], {"method": "least-squares"}, {"method": (STRINGS, "method")}),
    ("Curve.locate", lambda *a: curve().locate(*a), [[0.0, 0.0]], {}, {0: (ARRAYS, "point")}),
    ("Curve.nearest_point", lambda *a: curve().nearest_point(*a), [[0.0, 0.0]], {}, {0: (ARRAYS, "point")}),
    ("Curve.intersect", lambda *a, **k: curve().intersect(*a, **k), [blossom.Curve(LINE, 1)], {"max_work": 1e9},
     {0: (CURVES, "other"), "max_work": (NOT_A_NUMBER + [float("nan"), -1.0, 0.0], "max_work")}),
    ("Curve.self_intersections", lambda **k: curve().self_intersections(**k), [], {"max_work": 1e9},
     {"max_work": (NOT_A_NUMBER + [float("nan"), -1.0], "max_work")}),
    ("Curve.intersections", lambda *a, **k: curve().intersections(*a, **k), [blossom.Curve(LINE, 1)], {"max_work": 1e9},
     {0: (CURVES, "other"), "max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("Curve.self_intersection_records", lambda **k: curve().self_intersection_records(**k), [], {"max_work": 1e9},
     {"max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("Triangle", blossom.Triangle, [TRI, 1], {}, {0: (ARRAYS, "nodes"), 1: (INTS, "degree")}),
    ("Triangle.from_nodes", blossom.Triangle.from_nodes, [TRI], {}, {0: (ARRAYS, "nodes")}),
    ("Triangle.evaluate_barycentric", lambda *a: triangle().evaluate_barycentric(*a), [0.2, 0.3, 0.5], {},
     {0: (FLOATS, "lambda1"), 1: (FLOATS, "lambda2"), 2: (FLOATS, "lambda3")}),
    ("Triangle.evaluate_barycentric_multi", lambda *a: triangle().evaluate_barycentric_multi(*a), [[[0.2, 0.3, 0.5]]], {},
     {0: (ARRAYS, "param_vals")}),
    ("Triangle.evaluate_cartesian", lambda *a: triangle().evaluate_cartesian(*a), [0.2, 0.3], {},
     {0: (FLOATS, "s"), 1: (FLOATS, "t")}),
    ("Triangle.evaluate_cartesian_multi", lambda *a: triangle().evaluate_cartesian_multi(*a), [[[0.2, 0.3]]], {},
     {0: (ARRAYS, "param_vals")}),
    ("Triangle.specialize", lambda *a: triangle().specialize(*a), [[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]], {},
     {0: (ARRAYS, "corners")}),
    ("Triangle.intersect", lambda *a, **k: triangle().intersect(*a, **k), [blossom.Triangle(TRI + 0.1, 1)], {"max_work": 1e10},
     {0: (CURVES + [blossom.Curve(LINE, 1)], "other"), "max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("CurvedPolygon", blossom.CurvedPolygon, list(SQUARE), {},
     {1: (CURVES, "edges[1]")}),
    ("CurvedRegion", blossom.CurvedRegion, [[SQUARE]], {"fill_rule": "nonzero"},
     {0: (["x", None, 3, [3], [[3]], Unconvertible(), [[LINE, "x"]]], "loops"), "fill_rule": (STRINGS, "fill_rule")}),
    ("CurvedRegion.from_triangle", blossom.CurvedRegion.from_triangle, [triangle()], {},
     {0: (CURVES + [blossom.Curve(LINE, 1)], "triangle")}),
    ("CurvedRegion.simplify", lambda **k: region().simplify(**k), [], {"max_work": 1e10},
     {"max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("CurvedRegion.union", lambda *a, **k: region().union(*a, **k), [region()], {"max_work": 1e10},
     {0: (CURVES + [blossom.Curve(LINE, 1)], "other"), "max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("CurvedRegion.winding", lambda *a, **k: region().winding(*a, **k), [[[0.5], [0.5]]], {"max_work": 1e10},
     {0: (ARRAYS, "points"), "max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("BooleanResult.draw", lambda *a, **k: region().simplify().draw(*a, **k), [blossom.RegionPen()], {"clockwise": None},
     {0: ([None, 3, "pen", Unconvertible()], "pen"), "clockwise": (BOOLS, "clockwise")}),
    ("RegionPen", blossom.RegionPen, [], {"fill_rule": "nonzero"}, {"fill_rule": (STRINGS, "fill_rule")}),
    ("RegionPen.moveTo", lambda *a: blossom.RegionPen().moveTo(*a), [(0.0, 0.0)], {},
     {0: (["x", None, Unconvertible(), b"12", {"a": 1}, (float("nan"), 0.0), (0.0, 1, 2), ("x", 0.0)], "moveTo.pt")}),
    ("RegionPen.lineTo", lambda *a: opened().lineTo(*a), [(1.0, 0.0)], {},
     {0: (["x", None, {"a": 1, "b": 2}, (float("inf"), 0.0), (0.0,)], "lineTo.pt")}),
    ("RegionPen.qCurveTo", lambda *a: opened().qCurveTo(*a), [(1.0, 1.0), (2.0, 0.0)], {},
     {0: (["x", 3, {"a": 1, "b": 2}, (float("nan"), 0.0)], "qCurveTo.points[0]")}),
    ("RegionPen.curveTo", lambda *a: opened().curveTo(*a), [(1.0, 1.0), (2.0, 1.0), (3.0, 0.0)], {},
     {1: (["x", None, (0.0, 1, 2)], "curveTo.points[1]")}),
    ("RegionPen.addComponent", lambda *a: blossom.RegionPen({"b": Glyph()}).addComponent(*a), ["b", (1, 0, 0, 1, 0, 0)], {},
     {0: ([3, None, "c", Unconvertible(), ["b"]], "addComponent.glyphName"), 1: (["x", None, 3, (1, 0), Unconvertible(), (1, 0, 0, 1, 0, "x")], "transformation")}),
    ("TensorPatch", blossom.TensorPatch, [np.zeros((2, 2, 2))], {}, {0: (ARRAYS, "nodes")}),
    ("TensorPatch.evaluate", lambda *a: blossom.TensorPatch(np.zeros((2, 2, 2))).evaluate(*a), [0.5, 0.5], {},
     {0: (FLOATS, "s"), 1: (FLOATS, "t")}),
    ("TensorPatch.specialize", lambda *a: blossom.TensorPatch(np.zeros((2, 2, 2))).specialize(*a), [[0.0, 1.0, 0.0, 1.0]], {},
     {0: (ARRAYS + [[0.0, 1.0]], "rect")}),
    ("restrict_power_curve", blossom.restrict_power_curve, [[[0.0, 1.0]], 0.0, 1.0], {"method": "bulk"},
     {0: (ARRAYS, "coefficients"), 1: (FLOATS, "start"), 2: (FLOATS, "end"), "method": (STRINGS, "method")}),
    ("restrict_power_surface", blossom.restrict_power_surface, [np.zeros((1, 2, 2)), [0.0, 1.0, 0.0, 1.0]], {"method": "bulk"},
     {0: (ARRAYS, "coefficients"), 1: (ARRAYS, "rect"), "method": (STRINGS, "method")}),
    ("restrict_power_triangle", blossom.restrict_power_triangle, [np.zeros((1, 3)), [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]], {"method": "bulk"},
     {0: (ARRAYS, "coefficients"), 1: (ARRAYS, "corners"), "method": (STRINGS, "method")}),
    ("restrict_curves", blossom.restrict_curves, [np.zeros((3, 2, 4)), 0.0, 1.0], {"out": None},
     {0: (ARRAYS, "nodes"), 1: (FLOATS, "start"), 2: (FLOATS, "end"), "out": (["x", 3, Unconvertible(), [[[0.0]]]], "out")}),
    ("bezier_zeros", blossom.bezier_zeros, [[1.0, -1.0]], {"max_work": 1e9},
     {0: (ARRAYS, "coefficients"), "max_work": (NOT_A_NUMBER + [-1.0], "max_work")}),
    ("remove_overlaps", blossom.remove_overlaps, [None], {}, {0: ([None, 3, "font", Unconvertible()], "font")}),
]


def sweep():
    for label, fn, args, kwargs, bad in CASES:
        for where, (values, path) in bad.items():
            for value in values:
                yield pytest.param(fn, args, kwargs, where, value, path, id=f"{label}-{where}-{value!r}"[:120])


@pytest.mark.parametrize("fn, args, kwargs, where, value, path", list(sweep()))
def test_bad_argument_is_a_blossom_error_naming_it(fn, args, kwargs, where, value, path):
    args, kwargs = list(args), dict(kwargs)
    if isinstance(where, int):
        args[where] = value
    else:
        kwargs[where] = value
    with pytest.raises(blossom.Error) as info:
        fn(*args, **kwargs)
    assert info.value.path.startswith(path), (info.value.path, str(info.value))
    assert str(info.value).startswith(f"{info.value.path}: ")


def test_every_string_choice_offers_the_nearest_name():
    cases = [
        (lambda v: blossom.CurvedRegion([], fill_rule=v), "fill_rule", "EvenOdd", "evenodd"),
        (lambda v: blossom.RegionPen(fill_rule=v), "fill_rule", "non-zero", "nonzero"),
        (lambda v: curve().reduce_(method=v), "method", "least_squares", "least-squares"),
        (lambda v: curve().reduce_(method=v), "method", "interpolate", "interpolating"),
        (lambda v: blossom.restrict_power_curve([[0.0, 1.0]], 0.0, 1.0, method=v), "method", "taylor", "taylor-shift"),
        (lambda v: blossom.restrict_power_surface(np.zeros((1, 2, 2)), [0, 1, 0, 1], method=v), "method", "Bulk", "bulk"),
        (lambda v: blossom.restrict_power_triangle(np.zeros((1, 3)), [[0, 0], [1, 0], [0, 1]], method=v), "method", "polarization", "polarisation"),
        (lambda v: blossom.RegionPen({"Aring": Glyph()}).addComponent(v, (1, 0, 0, 1, 0, 0)), "addComponent.glyphName", "Arng", "Aring"),
    ]
    for call, path, given, nearest in cases:
        with pytest.raises(blossom.Error) as info:
            call(given)
        assert info.value.path == path
        assert f"did you mean {nearest!r}" in str(info.value).replace('"', "'"), str(info.value)


def test_the_valid_calls_of_the_sweep_succeed():
    for label, fn, args, kwargs, bad in CASES:
        if label == "remove_overlaps":
            continue
        fn(*args, **kwargs)
