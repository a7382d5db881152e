"""blossom.RegionPen (fontTools' pen protocol into a CurvedRegion): each pen call, implied
on-curve points, closed all-off-curve quadratic splines, anchors dropped, components
decomposed through a glyph set, and errors. The areas are checked against Green's theorem
computed here in Fractions (Boole's rule, exact for curves of degree <= 3); fontTools, where
installed, is a peer for the decomposition of long curveTo runs."""

from fractions import Fraction as F

import numpy as np
import pytest

import blossom


def green_area(loops):
    """The signed area enclosed by loops of curves (each a D x (n + 1) array of nodes), n <= 3:
    1/2 * integral of (x y' - y x') dt, by Boole's rule (exact for polynomials of degree <= 5)
    in Fractions."""
    from conftest import bernstein_derivative, bernstein_point

    total = F(0)
    for lp in loops:
        for c in lp:
            nodes = c.nodes if hasattr(c, "nodes") else c
            values = []
            for k in range(5):
                t = F(k, 4)
                (x, y), (dx, dy) = bernstein_point(nodes, t), bernstein_derivative(nodes, t)
                values.append(x * dy - y * dx)
            w = [7, 32, 12, 32, 7]
            total += sum(wi * v for wi, v in zip(w, values)) / 90 / 2
    return total


def region_of(draw, **kwargs):
    pen = blossom.RegionPen(**kwargs)
    draw(pen)
    return pen.region()


def loop_nodes(region):
    """Each loop as a list of node lists [(x, y), ...] per curve."""
    return [[[tuple(p) for p in c.nodes.T.tolist()] for c in lp] for lp in region.loops]


def test_lines_and_close_path():
    def draw(pen):
        pen.moveTo((0, 0))
        pen.lineTo((4, 0))
        pen.lineTo((4, 3))
        pen.closePath()

    r = region_of(draw)
    assert loop_nodes(r) == [[[(0, 0), (4, 0)], [(4, 0), (4, 3)], [(4, 3), (0, 0)]]]
    assert green_area(r.loops) == 6
    lo, hi = r.simplify().area
    assert lo <= 6 <= hi


def test_closing_line_is_not_doubled_and_end_path_closes():
    def draw(pen):
        pen.moveTo((0, 0))
        pen.lineTo((1, 0))
        pen.lineTo((1, 1))
        pen.lineTo((0, 0))
        pen.closePath()
        # An open contour: endPath closes it by a line, as a fill does.
        pen.moveTo((5, 0))
        pen.lineTo((6, 0))
        pen.lineTo((6, 1))
        pen.endPath()

    r = region_of(draw)
    assert [len(lp) for lp in r.loops] == [3, 3]
    assert loop_nodes(r)[1][2] == [(6, 1), (5, 0)]


def test_quadratics_split_at_implied_on_curve_points():
    def draw(pen):
        pen.moveTo((0, 0))
        pen.qCurveTo((1, 2), (3, 2), (5, 1), (6, 0))
        pen.closePath()

    r = region_of(draw)
    assert loop_nodes(r) == [[
        [(0, 0), (1, 2), (2, 2)],
        [(2, 2), (3, 2), (4, 1.5)],
        [(4, 1.5), (5, 1), (6, 0)],
        [(6, 0), (0, 0)],
    ]]
    # Over the top from left to right and back along the bottom: clockwise.
    area = green_area(r.loops)
    assert area == -8
    lo, hi = r.simplify().area
    assert F(lo) <= -area <= F(hi)


def test_all_off_curve_contour():
    # A closed TrueType spline of four off-curve points: on-curve points at the midpoints,
    # starting between the last and the first off-curve point.
    def draw(pen):
        pen.qCurveTo((0, 0), (2, 0), (2, 2), (0, 2), None)
        pen.closePath()

    r = region_of(draw)
    assert loop_nodes(r) == [[
        [(0, 1), (0, 0), (1, 0)],
        [(1, 0), (2, 0), (2, 1)],
        [(2, 1), (2, 2), (1, 2)],
        [(1, 2), (0, 2), (0, 1)],
    ]]
    # Each quadratic cuts a corner of the square [0, 2]^2 off a diamond: the area is
    # 2 (the diamond) + 4 * 1/3 (each parabolic segment is 2/3 of its triangle of area 1/2).
    assert green_area(r.loops) == F(2) + 4 * F(1, 3)
    lo, hi = r.simplify().area
    assert F(lo) <= F(10, 3) <= F(hi)


def test_curve_to_of_every_length():
    def draw(pen):
        pen.moveTo((0, 0))
        pen.curveTo((10, 0))                  # a line
        pen.curveTo((12, 2), (10, 4))         # a quadratic
        pen.curveTo((8, 6), (4, 6), (0, 4))   # a cubic
        pen.closePath()

    r = region_of(draw)
    assert [c.degree for c in r.loops[0]] == [1, 2, 3, 1]
    area = green_area(r.loops)
    lo, hi = r.simplify().area
    assert F(lo) <= area <= F(hi)


def test_super_bezier_as_fonttools_decomposes_it():
    pytest.importorskip("fontTools")
    from fontTools.pens.basePen import decomposeSuperBezierSegment

    offs = [(1, 3), (4, 5), (7, 4), (9, 1), (10, -2)]
    for k in range(2, len(offs) + 1):
        points = offs[:k] + [(12, 0)]

        def draw(pen):
            pen.moveTo((0, 0))
            pen.curveTo(*points)
            pen.closePath()

        r = region_of(draw)
        start = (0, 0)
        want = []
        for p1, p2, p3 in decomposeSuperBezierSegment(points):
            want.append([start, tuple(p1), tuple(p2), tuple(p3)])
            start = tuple(p3)
        assert loop_nodes(r)[0][:-1] == want


def test_anchors_and_empty_contours_are_dropped():
    def draw(pen):
        pen.moveTo((100, 700))     # an anchor
        pen.closePath()
        pen.moveTo((5, 5))
        pen.endPath()
        pen.moveTo((0, 0))
        pen.lineTo((1, 0))
        pen.lineTo((0, 1))
        pen.closePath()

    r = region_of(draw)
    assert r.num_loops == 1
    assert region_of(lambda pen: None).num_loops == 0
    assert region_of(lambda pen: None).simplify().polygons == []


def test_move_to_closes_an_open_contour():
    def draw(pen):
        pen.moveTo((0, 0))
        pen.lineTo((1, 0))
        pen.lineTo((0, 1))
        pen.moveTo((3, 0))
        pen.lineTo((4, 0))
        pen.lineTo((3, 1))

    r = region_of(draw)
    assert [len(lp) for lp in r.loops] == [3, 3]


class Glyph:
    """A minimal drawable glyph: draws its recorded calls (fontTools' RecordingPen form)."""

    def __init__(self, calls):
        self.calls = calls

    def draw(self, pen):
        for name, args in self.calls:
            getattr(pen, name)(*args)


SQUARE = Glyph([("moveTo", ((0, 0),)), ("lineTo", ((1, 0),)), ("lineTo", ((1, 1),)),
                ("lineTo", ((0, 1),)), ("closePath", ())])


def test_components_are_decomposed_through_the_glyph_set():
    glyphs = {
        "square": SQUARE,
        # Two squares, the second scaled by 2 and moved to (1, 0): [1, 3] x [0, 2], touching
        # the first along x = 1.
        "pair": Glyph([("addComponent", ("square", (1, 0, 0, 1, 0, 0))),
                       ("addComponent", ("square", (2, 0, 0, 2, 1, 0)))]),
        # A composite of a composite: the pair scaled by 3 and moved by (10, 20).
        "nested": Glyph([("addComponent", ("pair", (3, 0, 0, 3, 10, 20)))]),
    }
    r = region_of(glyphs["pair"].draw, glyph_set=glyphs)
    assert loop_nodes(r)[1][0] == [(1, 0), (3, 0)]
    assert green_area(r.loops) == 5
    nested = region_of(glyphs["nested"].draw, glyph_set=glyphs)
    assert loop_nodes(nested)[1][0] == [(13, 20), (19, 20)]
    assert green_area(nested.loops) == 45
    lo, hi = nested.simplify().area
    assert lo <= 45 <= hi
    # The transformation is restored after a component: later contours are not moved.
    glyphs["mixed"] = Glyph([("addComponent", ("square", (2, 0, 0, 2, 5, 5)))] + SQUARE.calls)
    mixed = region_of(glyphs["mixed"].draw, glyph_set=glyphs)
    assert loop_nodes(mixed)[1][0] == [(0, 0), (1, 0)]
    # A flipped component (negative determinant) keeps the base glyph's traversal mirrored:
    # the loop runs the other way round, as fontTools' DecomposingPen draws it.
    glyphs["flipped"] = Glyph([("addComponent", ("square", (-1, 0, 0, 1, 0, 0)))])
    assert green_area(region_of(glyphs["flipped"].draw, glyph_set=glyphs).loops) == -1


def test_component_transformation_as_fonttools_transform():
    pytest.importorskip("fontTools")
    from fontTools.misc.transform import Transform

    glyphs = {"square": SQUARE}
    t = Transform().translate(7, 3).scale(0.5, 0.25)

    def draw(pen):
        pen.addComponent("square", t)

    r = region_of(draw, glyph_set=glyphs)
    assert loop_nodes(r)[0][1] == [t.transformPoint((1, 0)), t.transformPoint((1, 1))]


def raises(path, kind, fn, *args, **kwargs):
    with pytest.raises(blossom.Error) as info:
        fn(*args, **kwargs)
    assert (info.value.path, info.value.kind) == (path, kind), str(info.value)
    return info.value


def test_bad_calls_raise_naming_the_argument():
    pen = blossom.RegionPen()
    raises("lineTo", "Shape", pen.lineTo, (1, 1))
    raises("qCurveTo", "Shape", pen.qCurveTo, (1, 1), (2, 2))
    raises("curveTo", "Shape", pen.curveTo, (1, 1), (2, 2), (3, 3))
    raises("moveTo.pt", "Shape", pen.moveTo, (1, 2, 3))
    raises("moveTo.pt", "Shape", pen.moveTo, "xy")
    raises("moveTo.pt[1]", "NotFinite", pen.moveTo, (0.0, float("nan")))
    pen.moveTo((0, 0))
    raises("lineTo.pt[0]", "Invalid", pen.lineTo, ["a", 1])
    raises("qCurveTo.points[1]", "Shape", pen.qCurveTo, (1, 1), 5)
    raises("qCurveTo.points", "Empty", pen.qCurveTo)
    raises("qCurveTo.points", "Empty", pen.qCurveTo, None)
    raises("curveTo.points", "Empty", pen.curveTo)
    e = raises("addComponent", "Invalid", pen.addComponent, "A", (1, 0, 0, 1, 0, 0))
    assert "glyph set" in str(e)
    pen = blossom.RegionPen({"square": SQUARE})
    raises("addComponent.glyphName", "Invalid", pen.addComponent, "B", (1, 0, 0, 1, 0, 0))
    raises("transformation", "Shape", pen.addComponent, "square", (1, 0, 0, 1))
    raises("transformation[4]", "NotFinite", pen.addComponent, "square", (1, 0, 0, 1, float("inf"), 0))
    e = raises("fill_rule", "UnknownName", blossom.RegionPen, None, fill_rule="even-odd")
    assert 'did you mean "evenodd"' in str(e)
    # A loop that does not close exactly cannot arise: the pen closes by a line.
    pen = blossom.RegionPen(fill_rule="evenodd")
    pen.moveTo((0, 0))
    pen.lineTo((1, 0))
    pen.lineTo((0, 1))
    assert pen.region().fill_rule == "evenodd"


def test_fonttools_glyph_through_the_pen_matches_basepen():
    """A TrueType glyph with an all-off-curve contour, drawn by fontTools into the pen and into
    a BasePen that records the decomposition: the same curves."""
    pytest.importorskip("fontTools")
    from fontTools.pens.basePen import BasePen
    from fontTools.pens.ttGlyphPen import TTGlyphPen

    tt = TTGlyphPen(None)
    tt.moveTo((0, 0))
    tt.lineTo((100, 0))
    tt.qCurveTo((150, 50), (100, 100))
    tt.lineTo((0, 100))
    tt.closePath()
    tt.qCurveTo((300, 0), (400, 0), (400, 100), (300, 100), None)
    tt.closePath()
    glyph = tt.glyph()

    class Recording(BasePen):
        def __init__(self):
            super().__init__(None)
            self.loops = []

        def _moveTo(self, pt):
            self.loops.append([])
            self.start = pt

        def _lineTo(self, pt):
            self.loops[-1].append([self._getCurrentPoint(), pt])

        def _qCurveToOne(self, p1, p2):
            self.loops[-1].append([self._getCurrentPoint(), p1, p2])

        def _curveToOne(self, p1, p2, p3):
            self.loops[-1].append([self._getCurrentPoint(), p1, p2, p3])

        def _closePath(self):
            if tuple(self._getCurrentPoint()) != tuple(self.start):
                self.loops[-1].append([self._getCurrentPoint(), self.start])

    rec = Recording()
    glyph.draw(rec, None)
    pen = blossom.RegionPen()
    glyph.draw(pen, None)
    want = [[[tuple(map(float, p)) for p in c] for c in lp] for lp in rec.loops]
    assert loop_nodes(pen.region()) == want
