"""Fonts: BooleanResult.draw into fontTools pens (round trips through RecordingPen and
RegionPen, implied on-curve points, contour direction), to_region and svg, and
blossom.remove_overlaps on small TTFonts built with fontTools' FontBuilder (glyf and CFF),
checked against blossom's certified area enclosures and against the glyphs' structure.
Skipped when fontTools is not installed (blossom itself never imports it)."""

import subprocess
import sys
from fractions import Fraction as F

import numpy as np
import pytest

import blossom

fontTools = pytest.importorskip("fontTools")
from fontTools.fontBuilder import FontBuilder  # noqa: E402
from fontTools.pens.recordingPen import RecordingPen  # noqa: E402
from fontTools.pens.t2CharStringPen import T2CharStringPen  # noqa: E402
from fontTools.pens.ttGlyphPen import TTGlyphPen  # noqa: E402
from fontTools.ttLib import TTFont  # noqa: E402
from fontTools.ttLib.tables import ttProgram  # noqa: E402


def draw_calls(calls, pen):
    for name, args in calls:
        getattr(pen, name)(*args)


def region_of(calls, glyph_set=None):
    pen = blossom.RegionPen(glyph_set)
    draw_calls(calls, pen)
    return pen.region()


def rect(x0, y0, x1, y1, clockwise=True):
    """A rectangle contour (clockwise, TrueType's outer direction, by default)."""
    pts = [(x0, y0), (x0, y1), (x1, y1), (x1, y0)]
    if not clockwise:
        pts = pts[::-1]
    return [("moveTo", (pts[0],))] + [("lineTo", (p,)) for p in pts[1:]] + [("closePath", ())]


def blob(cx, cy, r):
    """A closed TrueType spline of 8 off-curve points (no on-curve point), clockwise."""
    offs = [(cx - r, cy), (cx - r, cy + r), (cx, cy + r), (cx + r, cy + r),
            (cx + r, cy), (cx + r, cy - r), (cx, cy - r), (cx - r, cy - r)]
    return [("qCurveTo", tuple(offs) + (None,)), ("closePath", ())]


def signed_area(calls):
    """The signed area of a RecordingPen drawing, through blossom's exact CurvedPolygon.area of
    each contour (every contour read back by a RegionPen, one at a time)."""
    total = 0.0
    contour = []
    for name, args in calls:
        contour.append((name, args))
        if name in ("closePath", "endPath"):
            r = region_of(contour)
            for lp in r.loops:
                total += blossom.CurvedPolygon(*lp).area
            contour = []
    return total


def contained(area, enclosure):
    lo, hi = enclosure
    return F(lo) <= F(area) <= F(hi)


def test_import_does_not_import_fonttools():
    code = "import sys, blossom; assert 'fontTools' not in sys.modules, 'imported'"
    subprocess.run([sys.executable, "-c", code], check=True)


def test_draw_round_trip_through_a_recording_pen():
    # Two overlapping rectangles and an all-off-curve blob crossing them, TrueType style.
    glyph = rect(0, 0, 400, 300) + rect(200, 100, 600, 500) + blob(500, 150, 120)
    region = region_of(glyph)
    res = region.simplify()
    rec = RecordingPen()
    res.draw(rec)
    back = region_of(rec.value)
    again = back.simplify()
    # The drawing is the result's geometry itself: the same area enclosure up to its width,
    # and simplifying what was drawn changes nothing (it draws the same calls).
    (lo, hi), (lo2, hi2) = res.area, again.area
    assert max(lo, lo2) <= min(hi, hi2)
    assert again._draws_input()
    rec2 = RecordingPen()
    again.draw(rec2)
    assert rec2.value == rec.value
    # TrueType direction kept: the outer contour clockwise (negative signed area).
    assert signed_area(rec.value) < 0
    assert abs(-signed_area(rec.value) - (lo + hi) / 2) <= 1e-6 * hi
    # One contour: the three shapes merged.
    assert sum(1 for name, _ in rec.value if name == "closePath") == 1


def test_draw_keeps_implied_points_and_kinds_of_pieces():
    # The blob alone: a contour without on-curve points comes back as one.
    rec = RecordingPen()
    region_of(blob(0, 0, 100)).simplify().draw(rec)
    assert rec.value[0][0] == "qCurveTo" and rec.value[0][1][-1] is None
    assert len(rec.value[0][1]) == 9 and rec.value[1] == ("closePath", ())
    assert set(rec.value[0][1][:-1]) == {p for p in blob(0, 0, 100)[0][1] if p is not None}
    # A rectangle with a cubic side and a run of quadratics whose middle on-curve point is
    # not the midpoint of its neighbours: lineTo, curveTo, a qCurveTo ending there, another.
    glyph = [
        ("moveTo", ((0, 0),)),
        ("lineTo", ((0, 100),)),
        ("curveTo", ((30, 150), (70, 150), (100, 100))),
        ("qCurveTo", ((120, 80), (130, 60), (140, 0))),   # (125, 70): implied
        ("qCurveTo", ((100, -40), (50, -10))),            # (140, 0) is not implied
        ("closePath", ()),
    ]
    rec = RecordingPen()
    region_of(glyph).simplify().draw(rec)
    names = [n for n, _ in rec.value]
    assert names.count("curveTo") == 1 and names.count("moveTo") == 1
    q = [args for n, args in rec.value if n == "qCurveTo"]
    # The run through (125, 70) stays one call with two off-curve points.
    assert ((120.0, 80.0), (130.0, 60.0), (140.0, 0.0)) in q
    # The input's starting point is kept, and its direction (clockwise).
    assert rec.value[0] == ("moveTo", ((0.0, 0.0),))
    assert rec.value[1] == ("lineTo", ((0.0, 100.0),))


def test_draw_direction_detected_or_given():
    cw = rect(0, 0, 10, 10) + rect(5, 5, 15, 15)
    ccw = rect(0, 0, 10, 10, clockwise=False) + rect(5, 5, 15, 15, clockwise=False)
    for calls, sign in ((cw, -1), (ccw, 1)):
        res = region_of(calls).simplify()
        for clockwise, want in ((None, sign), (True, -1), (False, 1)):
            rec = RecordingPen()
            res.draw(rec, clockwise=clockwise)
            assert signed_area(rec.value) == want * 175
    # A hole runs the other way from its outer contour.
    ring = rect(0, 0, 10, 10) + rect(3, 3, 7, 7, clockwise=False)
    rec = RecordingPen()
    region_of(ring).simplify().draw(rec)
    areas = []
    contour = []
    for name, args in rec.value:
        contour.append((name, args))
        if name == "closePath":
            areas.append(signed_area(contour))
            contour = []
    assert sorted(areas) == [-100, 16]


def test_draw_refuses_pieces_of_high_degree():
    quartic = np.array([[0.0, 1.0, 2.0, 3.0, 4.0], [0.0, 2.0, -2.0, 2.0, 0.0]])
    back = np.array([[4.0, 0.0], [0.0, 0.0]])
    res = blossom.CurvedRegion([[quartic, back]]).simplify()
    assert res.svg is None
    with pytest.raises(blossom.Error) as e:
        res.draw(RecordingPen())
    assert e.value.kind == "Degree" and e.value.path.startswith("geometry[")


def test_to_region_chains_booleans_and_svg():
    a = region_of(rect(0, 0, 2, 2, clockwise=False))
    b = region_of(rect(1, 1, 3, 3, clockwise=False))
    c = region_of(rect(1, 0, 3, 2, clockwise=False))
    union = a.union(b)
    # (A ∪ B) - C = the unit squares [0, 1] x [0, 2] and [1, 3] x [2, 3]: area 2 + 2.
    chained = union.to_region().difference(c)
    assert contained(4, chained.area)
    assert union.to_region().fill_rule == "nonzero"
    # The result's geometry is exact here: the L-shaped union of two squares.
    pieces = union.geometry
    assert len(pieces) == 1 and all(p.degree == 1 for p in pieces[0])
    for k, p in enumerate(pieces[0]):
        assert np.array_equal(p.nodes[:, 0], pieces[0][k - 1].nodes[:, -1])
    svg = union.svg
    assert svg.startswith("M ") and svg.endswith(" Z") and svg.count("L") == 8
    assert blossom.CurvedRegion([]).simplify().svg == ""
    assert blossom.CurvedRegion([]).simplify().to_region().num_loops == 0


def build_glyf_font(glyphs, hinted=()):
    """A TrueType font of `glyphs` {name: calls}; components as ("addComponent", ...)."""
    names = [".notdef"] + sorted(glyphs)
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(names)
    fb.setupCharacterMap({})
    built = {".notdef": TTGlyphPen(None).glyph()}
    for name in sorted(glyphs):
        pen = TTGlyphPen(glyphs)
        draw_calls(glyphs[name], pen)
        built[name] = pen.glyph()
        if name in hinted:
            built[name].program = ttProgram.Program()
            built[name].program.fromBytecode(b"\xb0\x01")  # PUSHB[0] 1
    fb.setupGlyf(built)
    glyf = fb.font["glyf"]
    metrics = {}
    for name in names:
        g = glyf[name]
        g.recalcBounds(glyf)
        metrics[name] = (1000, getattr(g, "xMin", 0))
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupOS2()
    fb.setupPost()
    fb.setupNameTable({"familyName": "Test", "styleName": "Regular"})
    return fb.font


def contours(font, name):
    rec = RecordingPen()
    font.getGlyphSet()[name].draw(rec)
    return sum(1 for n, _ in rec.value if n == "closePath")


def certified_area(font, name):
    gs = font.getGlyphSet()
    pen = blossom.RegionPen(gs)
    gs[name].draw(pen)
    return pen.region().simplify().area


def test_remove_overlaps_on_a_truetype_font():
    glyphs = {
        # Overlapping rectangles with integer intersections: one contour after.
        "A": rect(0, 0, 400, 300) + rect(200, 100, 600, 500),
        # No overlap, hinted: kept as it is.
        "B": rect(50, 0, 150, 700) + rect(250, 0, 350, 700),
        # A composite whose components overlap: decomposed, one contour.
        "C": [("addComponent", ("bar", (1, 0, 0, 1, 0, 0))),
              ("addComponent", ("bar", (0, 1, -1, 0, 450, -300)))],
        # A composite whose components are apart: kept as a composite.
        "D": [("addComponent", ("bar", (1, 0, 0, 1, 0, 0))),
              ("addComponent", ("bar", (1, 0, 0, 1, 0, 400)))],
        "bar": rect(100, 0, 800, 100),
        # An all-off-curve contour overlapping a rectangle.
        "E": blob(300, 300, 200) + rect(300, 250, 900, 350),
    }
    font = build_glyf_font(glyphs, hinted=("B", "A"))
    before = {name: certified_area(font, name) for name in glyphs}
    modified = blossom.remove_overlaps(font)
    assert modified == {"A", "C", "E"}
    glyf = font["glyf"]
    assert contours(font, "A") == 1 and contours(font, "C") == 1 and contours(font, "E") == 1
    assert not glyf["C"].isComposite() and glyf["D"].isComposite()
    # Exact integer intersections: the rewritten glyphs keep their certified areas.
    assert contained(120000 + 160000 - 40000, certified_area(font, "A"))
    assert contained(2 * 70000 - 10000, certified_area(font, "C"))
    for name in "ABCD":
        lo, hi = certified_area(font, name)
        assert max(lo, before[name][0]) <= min(hi, before[name][1]), name
    # E's intersections are irrational: coordinates rounded to integers by TTGlyphPen move
    # the area by at most the perimeter times half a unit.
    (lo, hi), (lo0, hi0) = certified_area(font, "E"), before["E"]
    assert abs(lo - lo0) < 0.5 * 4000
    # TrueType direction kept (clockwise outer contours) and hmtx lsb = xMin.
    rec = RecordingPen()
    font.getGlyphSet()["A"].draw(rec)
    assert signed_area(rec.value) < 0
    for name in "ACE":
        assert font["hmtx"][name][1] == glyf[name].xMin
    # Hinting dropped everywhere by default, kept on unchanged glyphs when asked.
    assert not glyf["B"].program.getBytecode()
    font = build_glyf_font(glyphs, hinted=("B", "A"))
    blossom.remove_overlaps(font, glyph_names=["A", "B"], remove_hinting=False)
    assert font["glyf"]["B"].program.getBytecode() == b"\xb0\x01"
    assert contours(font, "A") == 1 and font["glyf"]["C"].isComposite()


def test_remove_overlaps_on_a_cff_font():
    def charstring(calls, width=500):
        pen = T2CharStringPen(width, None)
        draw_calls(calls, pen)
        return pen.getCharString()

    # CFF outer contours run counter-clockwise.
    glyphs = {
        ".notdef": [],
        "A": rect(0, 0, 400, 300, clockwise=False) + rect(200, 100, 600, 500, clockwise=False),
        "B": rect(0, 0, 100, 100, clockwise=False),
        # A cubic circle-ish contour overlapping a rectangle.
        "O": [("moveTo", ((0, 200),)),
              ("curveTo", ((0, 90), (90, 0), (200, 0))),
              ("curveTo", ((310, 0), (400, 90), (400, 200))),
              ("curveTo", ((400, 310), (310, 400), (200, 400))),
              ("curveTo", ((90, 400), (0, 310), (0, 200))),
              ("closePath", ())] + rect(150, -50, 250, 450, clockwise=False),
    }
    fb = FontBuilder(1000, isTTF=False)
    fb.setupGlyphOrder(list(glyphs))
    fb.setupCharacterMap({})
    fb.setupCFF("Test-Regular", {"FullName": "Test"}, {n: charstring(c) for n, c in glyphs.items()}, {})
    fb.setupHorizontalMetrics({n: (500, 0) for n in glyphs})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupOS2()
    fb.setupPost()
    fb.setupNameTable({"familyName": "Test", "styleName": "Regular"})
    font = fb.font
    before = {n: certified_area(font, n) for n in ("A", "B", "O")}
    assert blossom.remove_overlaps(font) == {"A", "O"}
    assert contours(font, "A") == 1 and contours(font, "O") == 1 and contours(font, "B") == 1
    assert contained(120000 + 160000 - 40000, certified_area(font, "A"))
    rec = RecordingPen()
    font.getGlyphSet()["A"].draw(rec)
    assert signed_area(rec.value) > 0
    assert all(n in ("moveTo", "lineTo", "curveTo", "closePath") for n, _ in rec.value)
    (lo, hi), (lo0, hi0) = certified_area(font, "O"), before["O"]
    assert abs(lo - lo0) < 0.5 * 2000
    # The font still compiles and reads back.
    import io
    data = io.BytesIO()
    font.save(data)
    data.seek(0)
    assert contours(TTFont(data), "A") == 1


def test_remove_overlaps_errors():
    font = build_glyf_font({"A": rect(0, 0, 400, 300) + rect(200, 100, 600, 500)})
    with pytest.raises(blossom.Error) as e:
        blossom.remove_overlaps(font, max_work=1.0)
    assert e.value.path == "glyphs['A'].max_work" and e.value.kind == "TooLarge"
    # The glyph was left untouched by the refused call (nothing half-written).
    assert contours(font, "A") == 2
    for kwargs, path in [
        ({"glyph_names": 3}, "glyph_names"),
        ({"glyph_names": "A"}, "glyph_names"),
        ({"glyph_names": ["A", "Z"]}, "glyph_names[1]"),
        ({"glyph_names": [None]}, "glyph_names[0]"),
        ({"max_work": "x"}, "max_work"),
        ({"max_work": -1.0}, "max_work"),
        ({"glyph_names": [], "max_work": float("nan")}, "max_work"),
    ]:
        with pytest.raises(blossom.Error) as e:
            blossom.remove_overlaps(font, **kwargs)
        assert e.value.path == path, kwargs
    assert contours(font, "A") == 2
    with pytest.raises(blossom.Error) as e:
        blossom.remove_overlaps(font, glyph_names=["a"])
    assert "did you mean 'A'" in str(e.value)
    del font["glyf"]
    with pytest.raises(NotImplementedError):
        blossom.remove_overlaps(font)
    with pytest.raises(blossom.Error) as e:
        blossom.remove_overlaps({"glyf": None})
    assert e.value.path == "font"
    res = region_of(rect(0, 0, 1, 1)).simplify()
    with pytest.raises(blossom.Error) as e:
        res.draw(object())
    assert e.value.path == "pen" and "moveTo" in str(e.value)
