"""The region layer through Python: Triangle.intersect and CurvedRegion's booleans and winding
numbers, against computations written here in Fractions (convex clipping and the shoelace
formula for straight-edged polygons, an exact crossing-number point-in-polygon test), bezier as
a peer where installed, and bad input."""

from fractions import Fraction as F
import random

import numpy as np
import pytest

import blossom


def shoelace(poly):
    """The signed area of a polygon given as a list of (x, y) Fractions (shoelace)."""
    n = len(poly)
    return sum(poly[k][0] * poly[(k + 1) % n][1] - poly[(k + 1) % n][0] * poly[k][1]
               for k in range(n)) / 2


def clip_convex(subject, clip):
    """Sutherland-Hodgman: the convex polygon `subject` clipped by the counter-clockwise
    convex polygon `clip`, exactly in Fractions."""
    def side(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    out = list(subject)
    for k in range(len(clip)):
        a, b = clip[k], clip[(k + 1) % len(clip)]
        inp, out = out, []
        for j in range(len(inp)):
            p, q = inp[j], inp[(j + 1) % len(inp)]
            sp, sq = side(a, b, p), side(a, b, q)
            if sp >= 0:
                out.append(p)
            if (sp > 0 > sq) or (sp < 0 < sq):
                t = sp / (sp - sq)
                out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
        if not out:
            return []
    return out


def winding_exact(poly, p):
    """The winding number of the closed polygon `poly` around p (off the polygon), by the
    signed crossings of the ray from p along +x, exactly."""
    w = 0
    n = len(poly)
    for k in range(n):
        a, b = poly[k], poly[(k + 1) % n]
        if a[1] <= p[1] < b[1] or b[1] <= p[1] < a[1]:
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > p[0]:
                w += 1 if b[1] > a[1] else -1
    return w


def on_polygon(poly, p):
    n = len(poly)
    for k in range(n):
        a, b = poly[k], poly[(k + 1) % n]
        cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        if cross == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) \
                and min(a[1], b[1]) <= p[1] <= max(a[1], b[1]):
            return True
    return False


def linear_triangle(a, b, c, exact=False):
    """bezier's degree-1 triangle with corners a, b, c (nodes columns a, b, c)."""
    nodes = np.array([[a[0], b[0], c[0]], [a[1], b[1], c[1]]], dtype=object if exact else float)
    return blossom.Triangle(nodes, degree=1)


def polygon_region(poly, exact=True):
    """A CurvedRegion of one straight loop through the points of `poly`."""
    dtype = object if exact else float
    edges = [np.array([[poly[k][0], poly[(k + 1) % len(poly)][0]],
                       [poly[k][1], poly[(k + 1) % len(poly)][1]]], dtype=dtype)
             for k in range(len(poly))]
    return blossom.CurvedRegion([edges])


def random_ccw_triangle(rng):
    while True:
        pts = [(F(rng.randint(0, 40), 8), F(rng.randint(0, 40), 8)) for _ in range(3)]
        a = shoelace(pts)
        if a > 0:
            return pts
        if a < 0:
            return [pts[0], pts[2], pts[1]]


def polygon_area_of(result_list):
    return sum(p.area for p in result_list)


def test_triangle_intersect_matches_exact_clipping():
    rng = random.Random(41)
    nonempty = 0
    for _ in range(40):
        t1, t2 = random_ccw_triangle(rng), random_ccw_triangle(rng)
        exact = clip_convex(t1, t2)
        area = shoelace(exact) if len(exact) >= 3 else F(0)
        got = linear_triangle(*t1, exact=True).intersect(linear_triangle(*t2, exact=True))
        assert abs(F(polygon_area_of(got)) - area) <= F(1, 2**40) * max(area, 1)
        if area > 0:
            nonempty += 1
            assert len(got) == 1
        else:
            assert got == []
    assert nonempty >= 10


def test_triangle_intersect_pieces_are_exact_for_fractions():
    t1 = linear_triangle((0, 0), (4, 0), (0, 4), exact=True)
    t2 = linear_triangle((1, 1), (5, 1), (1, 5), exact=True)
    (poly,) = t1.intersect(t2)
    assert isinstance(poly, blossom.CurvedPolygon)
    corners = {tuple(F(x) for x in e.exact_nodes[:, 0]) for e in poly.edges}
    # The square-cut triangle: (1, 1), (3, 1), (1, 3).
    assert corners == {(F(1), F(1)), (F(3), F(1)), (F(1), F(3))}
    assert poly.area == 2.0


def test_contained_triangle_comes_back_as_itself():
    big = linear_triangle((0, 0), (8, 0), (0, 8))
    small = linear_triangle((1, 1), (2, 1), (1, 2))
    (got,) = big.intersect(small)
    assert isinstance(got, blossom.Triangle)
    assert np.array_equal(got.nodes, small.nodes)
    (got,) = small.intersect(big)
    assert np.array_equal(got.nodes, small.nodes)


def test_touching_triangles_answer_empty_where_bezier_raises():
    # A shared edge (diagonal), and a shared corner only.
    t1 = linear_triangle((0, 0), (2, 0), (0, 2))
    t2 = linear_triangle((2, 2), (0, 2), (2, 0))
    t3 = linear_triangle((2, 0), (3, 0), (2, 1))
    assert t1.intersect(t2) == []
    assert t1.intersect(t3) == []
    # The same triangle: the intersection is itself.
    (same,) = t1.intersect(t1)
    assert np.array_equal(same.nodes, t1.nodes)


def test_curved_triangles_area_within_enclosure_of_pieces():
    # Quadratic triangles bulging outwards; the pieces' exact Green areas (CurvedPolygon.area)
    # must agree with the result's certified enclosure.
    n1 = np.array([[0.0, 1.0, 2.0, 0.1, 1.1, 0.0], [0.0, -0.2, 0.0, 1.0, 1.1, 2.0]])
    n2 = np.array([[0.5, 1.5, 2.5, 0.6, 1.6, 0.5], [0.3, 0.1, 0.3, 1.3, 1.4, 2.3]])
    t1, t2 = blossom.Triangle(n1, 2), blossom.Triangle(n2, 2)
    r1 = blossom.CurvedRegion.from_triangle(t1)
    r2 = blossom.CurvedRegion.from_triangle(t2)
    res = r1.intersection(r2)
    lo, hi = res.area
    assert 0 < lo <= hi
    pieces = t1.intersect(t2)
    assert len(pieces) == len(res.polygons) == 1
    assert abs(pieces[0].area - (lo + hi) / 2) < 1e-12
    # Inclusion-exclusion on the exact enclosures.
    u = r1.union(r2).area
    assert abs((u[0] + lo) - (t1.area + t2.area)) < 1e-12


def test_booleans_of_squares_against_clipping():
    a = [(F(0), F(0)), (F(3), F(0)), (F(3), F(3)), (F(0), F(3))]
    b = [(F(1), F(1)), (F(5), F(1)), (F(5), F(2)), (F(1), F(2))]
    ra, rb = polygon_region(a), polygon_region(b)
    inter = shoelace(clip_convex(a, b))
    want = {
        "intersection": inter,
        "union": shoelace(a) + shoelace(b) - inter,
        "difference": shoelace(a) - inter,
        "xor": shoelace(a) + shoelace(b) - 2 * inter,
    }
    for op, area in want.items():
        res = getattr(ra, op)(rb)
        lo, hi = res.area
        assert F(lo) <= area <= F(hi), op
        total = sum(p.area for p in res.polygons)
        assert abs(F(total) - area) <= F(1, 2**40), op
        for rec in res.edges:
            for region, loop_index, curve, s0, s1 in rec:
                assert region in (0, 1) and loop_index == 0 and 0 <= curve < 4
                assert s0.exact is not None and s1.exact is not None


def test_difference_with_a_hole():
    outer = [(F(0), F(0)), (F(6), F(0)), (F(6), F(6)), (F(0), F(6))]
    inner = [(F(2), F(2)), (F(4), F(2)), (F(4), F(4)), (F(2), F(4))]
    res = polygon_region(outer).difference(polygon_region(inner))
    assert sorted(res.holes) == [False, True]
    assert F(res.area[0]) <= 32 <= F(res.area[1])


def test_winding_against_exact_point_in_polygon():
    rng = random.Random(7)
    # A self-crossing pentagram: winding 2 in the middle, 1 in the tips.
    star = [(F(0), F(10)), (F(-6), F(-8)), (F(9), F(3)), (F(-9), F(3)), (F(6), F(-8))]
    region = polygon_region(star)
    pts = [(F(rng.randint(-100, 100), 10), F(rng.randint(-100, 100), 10)) for _ in range(200)]
    pts += [star[0], (F(0), F(3))]
    arr = np.array([[p[0] for p in pts], [p[1] for p in pts]], dtype=object)
    got = region.winding(arr)
    seen = set()
    for p, w in zip(pts, got):
        if on_polygon(star, p):
            assert w is None
        else:
            assert w == winding_exact(star, p)
            seen.add(w)
    assert {0, 1, 2} <= seen
    # Even-odd: the centre is outside, still winding 2.
    even = blossom.CurvedRegion(region.loops, fill_rule="evenodd")
    assert even.winding(np.array([[0.0], [0.0]])) == [2]
    res = even.intersection(polygon_region([(F(-20), F(-20)), (F(20), F(-20)), (F(20), F(20)),
                                            (F(-20), F(20))]))
    full = region.intersection(polygon_region([(F(-20), F(-20)), (F(20), F(-20)),
                                               (F(20), F(20)), (F(-20), F(20))]))
    assert res.area[1] < full.area[0]


def test_bad_input():
    c = np.array([[0.0, 1.0], [0.0, 0.0]])
    d = np.array([[1.0, 0.0], [1.0, 0.0]])  # starts at (1, 1), not at (1, 0)
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion([[c, d]])
    assert e.value.path.startswith("loops[0][1]")
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion([[np.zeros((3, 2))]])
    assert e.value.path == "loops[0][0]"
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion([[c, np.array([[1.0, 0.0], [0.0, 0.0]])]], fill_rule="odd")
    assert e.value.path == "fill_rule"
    sq = polygon_region([(F(0), F(0)), (F(1), F(0)), (F(1), F(1)), (F(0), F(1))])
    with pytest.raises(blossom.Error) as e:
        sq.winding(np.zeros((3, 2)))
    assert e.value.path == "points"
    with pytest.raises(blossom.Error) as e:
        sq.winding(np.array([[np.nan], [0.0]]))
    assert e.value.path.startswith("points")
    with pytest.raises(blossom.Error) as e:
        sq.union(3)
    assert (e.value.path, e.value.kind) == ("other", "Invalid")
    with pytest.raises(blossom.Error) as e:
        sq.union(sq, max_work=1.0)
    assert e.value.path == "max_work"
    t2 = linear_triangle((0, 0), (1, 0), (0, 1))
    t3 = blossom.Triangle(np.zeros((3, 3)), 1)
    with pytest.raises(blossom.Error) as e:
        t2.intersect(t3)
    assert e.value.path == "other.nodes"
    with pytest.raises(blossom.Error) as e:
        t2.intersect(sq)
    assert (e.value.path, e.value.kind) == ("other", "Invalid")


def test_bezier_peer_triangle_areas():
    bezier = pytest.importorskip("bezier")
    rng = np.random.default_rng(3)
    compared = 0
    for _ in range(30):
        base1 = np.array([[0.0, 1.0, 2.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0, 1.0, 2.0]])
        n1 = base1 + rng.uniform(-0.15, 0.15, (2, 6))
        n2 = base1 + rng.uniform(-0.15, 0.15, (2, 6)) + rng.uniform(0.2, 0.8, (2, 1))
        ours = blossom.CurvedRegion.from_triangle(blossom.Triangle(n1, 2)).intersection(
            blossom.CurvedRegion.from_triangle(blossom.Triangle(n2, 2)))
        try:
            theirs = bezier.Triangle(n1, 2).intersect(bezier.Triangle(n2, 2))
        except Exception:
            continue
        area = sum(p.area for p in theirs)
        lo, hi = ours.area
        assert lo - 1e-9 <= area <= hi + 1e-9
        compared += 1
    assert compared >= 10


def test_repeated_intersections_with_kept_regions_agree():
    # Each triangle keeps its region after the first intersect; later calls (and other
    # partners) must give the same exact answers.
    rng = random.Random(7)
    tris = [linear_triangle(*random_ccw_triangle(rng), exact=True) for _ in range(6)]
    first = {}
    for i, a in enumerate(tris):
        for j, b in enumerate(tris):
            first[i, j] = F(polygon_area_of(a.intersect(b)))
    for (i, j), area in first.items():
        assert F(polygon_area_of(tris[i].intersect(tris[j]))) == area
        # The symmetric operation: the same region (its area summed in another order).
        assert abs(F(polygon_area_of(tris[j].intersect(tris[i]))) - area) <= F(1, 2**40)


def square_loop(x, y, s, exact=True):
    """The counter-clockwise square [x, x + s] x [y, y + s] as a list of corners."""
    return [(F(x), F(y)), (F(x + s), F(y)), (F(x + s), F(y + s)), (F(x), F(y + s))]


def loops_region(polys, fill_rule="nonzero", exact=False):
    """A CurvedRegion of several straight loops (float64 nodes unless exact)."""
    dtype = object if exact else float
    loops = []
    for poly in polys:
        n = len(poly)
        loops.append([np.array([[poly[k][0], poly[(k + 1) % n][0]],
                                [poly[k][1], poly[(k + 1) % n][1]]], dtype=dtype)
                      for k in range(n)])
    return blossom.CurvedRegion(loops, fill_rule=fill_rule)


def polygon_areas(res):
    return sorted(F(p.area) for p in res.polygons)


def test_simplify_merges_overlapping_loops_of_one_region():
    a, b = square_loop(0, 0, 2), square_loop(1, 1, 2)
    for exact in (False, True):
        nonzero = loops_region([a, b], exact=exact).simplify()
        # The union of the squares: 4 + 4 - 1, one loop, every edge from region 0.
        assert len(nonzero.polygons) == 1 and nonzero.holes == [False]
        assert F(nonzero.area[0]) <= 7 <= F(nonzero.area[1])
        assert polygon_areas(nonzero) == [7]
        assert all(rec[0] == 0 for loop in nonzero.edges for rec in loop)
        # Even-odd: the overlap is out; two L-shaped loops of area 3 touching at two corners.
        evenodd = loops_region([a, b], "evenodd", exact=exact).simplify()
        assert F(evenodd.area[0]) <= 6 <= F(evenodd.area[1])
        assert polygon_areas(evenodd) == [3, 3]


def test_simplify_of_a_self_crossing_loop_under_both_rules():
    star = [(F(0), F(10)), (F(-6), F(-8)), (F(9), F(3)), (F(-9), F(3)), (F(6), F(-8))]
    whole = loops_region([star]).simplify()
    tips = loops_region([star], "evenodd").simplify()
    # Against the exact winding numbers: the centre (winding 2) is in under nonzero only;
    # the difference of the two areas is the centre pentagon, one hole-free loop either way.
    centre = whole.area[0] - tips.area[1]
    assert centre > 0
    assert len(whole.polygons) == 1 and not any(whole.holes)
    assert len(tips.polygons) == 5
    # A loop traversed clockwise is the same set: simplify gives the same area.
    backwards = loops_region([star[::-1]]).simplify()
    assert max(backwards.area[0], whole.area[0]) <= min(backwards.area[1], whole.area[1])


def test_simplify_drops_a_loop_that_cancels_and_keeps_a_hole():
    outer, inner = square_loop(0, 0, 6), square_loop(2, 2, 2)
    # The inner loop reversed: a hole under both rules.
    res = loops_region([outer, inner[::-1]]).simplify()
    assert sorted(res.holes) == [False, True]
    assert F(res.area[0]) <= 32 <= F(res.area[1])
    # The inner loop the same way round: winding 2 inside, filled under nonzero.
    res = loops_region([outer, inner]).simplify()
    assert res.holes == [False] and F(res.area[0]) <= 36 <= F(res.area[1])
    # Even-odd: a hole again.
    res = loops_region([outer, inner], "evenodd").simplify()
    assert sorted(res.holes) == [False, True]


def test_empty_regions_everywhere():
    empty = blossom.CurvedRegion([])
    assert empty.num_loops == 0 and empty.loops == [] and empty.fill_rule == "nonzero"
    sq = loops_region([square_loop(0, 0, 2)])
    for res in (empty.simplify(), empty.union(empty), empty.intersection(sq), sq.intersection(empty),
                empty.difference(sq), sq.difference(sq)):
        assert res.polygons == [] and res.holes == [] and res.edges == [] and res.area == (0.0, 0.0)
    for res in (empty.union(sq), sq.union(empty), sq.xor(empty), sq.difference(empty), empty.xor(sq)):
        assert res.area[0] <= 4.0 <= res.area[1] and len(res.polygons) == 1
    # Edges name the operand they come from.
    assert {rec[0] for rec in empty.union(sq).edges[0]} == {1}
    assert empty.winding(np.array([[0.0, 1.0], [0.0, 1.0]])) == [0, 0]
    assert blossom.CurvedRegion([], fill_rule="evenodd").fill_rule == "evenodd"


def test_result_objects_are_built_once_when_read():
    a = loops_region([square_loop(0, 0, 2)])
    b = loops_region([square_loop(1, 1, 2)])
    res = a.union(b)
    assert res.polygons is res.polygons and res.edges is res.edges
    # The pieces and the records agree: each polygon edge is the recorded input piece.
    for poly, records in zip(res.polygons, res.edges):
        assert poly.num_sides == len(records)
        for edge, (region, loop_index, curve, s0, s1) in zip(poly.edges, records):
            source = (a if region == 0 else b).loops[loop_index][curve]
            assert np.array_equal(edge.nodes[:, 0], source.evaluate(s0.value)[:, 0])
            assert np.array_equal(edge.nodes[:, -1], source.evaluate(s1.value)[:, 0])
    # A result outlives its operands (it shares their curves).
    del a, b
    assert F(res.area[0]) <= 7 <= F(res.area[1]) and len(res.polygons) == 1


def test_fill_rule_names_and_simplify_work_limit():
    sq = [[np.array([[0.0, 1.0], [0.0, 0.0]]), np.array([[1.0, 0.0], [0.0, 0.0]])]]
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion(sq, fill_rule="odd")
    assert e.value.path == "fill_rule" and e.value.kind == "UnknownName"
    assert 'did you mean "evenodd"' in str(e.value)
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion(sq, fill_rule="NonZero")
    assert 'did you mean "nonzero"' in str(e.value)
    with pytest.raises(blossom.Error) as e:
        blossom.CurvedRegion(sq, fill_rule="winding-number-rule")
    assert "did you mean" not in str(e.value) and '"nonzero" or "evenodd"' in str(e.value)
    with pytest.raises(blossom.Error) as e:
        loops_region([square_loop(0, 0, 2)]).simplify(max_work=1.0)
    assert e.value.path == "max_work" and e.value.kind == "TooLarge"
    with pytest.raises(blossom.Error) as e:
        loops_region([square_loop(0, 0, 2)]).simplify(max_work=-1.0)
    assert e.value.path == "max_work"
