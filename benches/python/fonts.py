"""Overlap removal on real fonts: blossom against skia-pathops (the call fontTools'
removeOverlaps makes), on the same outlines, interleaved in one process.

    pip install ./python numpy fonttools skia-pathops      # in a virtual environment
    python benches/python/fonts.py [--dir /usr/share/fonts/truetype/dejavu]
        [--faces DejaVuSans.ttf,DejaVuSans-Bold.ttf,...] [--tasks remove,shifted,words]
        [--limit N] [--shift 20] [--copies 4] [--squeeze 0.75] [--words "..."] [--json FILE]

Every glyph of every face (the glyph order, components decomposed) is recorded once with
fontTools' DecomposingRecordingPen and replayed into both tools, so both read the same numbers:
skia-pathops through `pathops.Path().getPen()` (as fontTools' removeOverlaps builds its path),
blossom through `blossom.RegionPen()` (fill rule nonzero, TrueType's). Glyphs without contours
(space, anchors only) are skipped. The tasks, each answered by both tools under the nonzero
rule:

  * remove: overlap removal of one glyph. Skia: `pathops.simplify(path,
    clockwise=path.clockwise)` (removeOverlaps' call); blossom: `region.simplify()`. Timed on
    outlines already built ("op"), and from the glyph ("draw+op": the pen, the glyph drawn
    into it, the region or path made, then the operation: what removeOverlaps pays per glyph).
  * shifted: the union of the glyph and `copies - 1` copies of it shifted by `shift`,
    2 * shift, ... units in x: the outlines of all copies in one path / one region (drawn
    through fontTools' TransformPen), then simplify: the nonzero fill of all their contours
    together, which is the union of the copies' own fills for outlines whose winding numbers
    are 0 or 1.
  * words: each word of a word list laid out with the face's advance widths times `squeeze`
    (rounded to integer units, so that consecutive letters overlap), all letters in one path /
    one region, then simplify.

Each call is timed alone (time.perf_counter around it; the tools alternate glyph by glyph, so
both see the same load). A raised exception counts as an error (skia-pathops raises
PathOpsError on some outlines; fontTools then retries with rounded coordinates, which is not
done here). Every blossom answer is checked well-formed: its area enclosure lo <= hi, lo >= 0,
hi - lo <= 2^-40 B (B the area of the box of the input points), its loops non-empty, their
pieces (`BooleanResult.geometry`) of degree <= 3, each piece starting bit for bit where the
previous ends and each loop closing exactly, each loop's signed area (Green's theorem on the
pieces, in doubles) of the sign its `hole` flag says, and the sum of the loops' areas within
the enclosure up to the rounding of that sum. Skia's area (`Path.area`, computed on its float32
answer) is compared with blossom's enclosure: the count of answers outside it by more than
1e-9 B is printed.

Printed: per face and over all faces, per task and tool, the total and the median time per call,
the 99th percentile and the maximum, the errors, and blossom's malformed answers.
"""

import argparse
import json
import math
import os
import statistics
import sys
import time

import blossom

try:
    import pathops
except ImportError:
    sys.exit("skia-pathops is not installed: pip install skia-pathops")
from fontTools.pens.recordingPen import DecomposingRecordingPen
from fontTools.pens.transformPen import TransformPen
from fontTools.ttLib import TTFont

FACES = [
    "DejaVuSans.ttf",
    "DejaVuSans-Bold.ttf",
    "DejaVuSerif.ttf",
    "DejaVuSerif-Bold.ttf",
    "DejaVuSansMono.ttf",
    "DejaVuSansMono-Bold.ttf",
]

WORDS = (
    "blossom overlap Typography WAVE minimum glyphs Bézier quartz jumping fox Wolfgang "
    "AVATAR kerning Hamburgefonstiv offline ffi affluent 1234567890 Zürich Ωμέγα Жизнь "
    "certified outlines @#&%$ sphinx"
)


def record(glyph_set, name):
    """The glyph's outline with components decomposed, as (method, args) calls."""
    pen = DecomposingRecordingPen(glyph_set)
    glyph_set[name].draw(pen)
    return pen.value


def replay(calls, pen, dx=0):
    if dx:
        pen = TransformPen(pen, (1, 0, 0, 1, dx, 0))
    for method, args in calls:
        getattr(pen, method)(*args)


def has_contours(calls):
    """Whether the outline draws anything beyond single points (anchors)."""
    return any(m in ("lineTo", "curveTo", "qCurveTo") for m, _ in calls)


def skia_path(pieces):
    """A pathops.Path of the outlines `pieces` [(calls, dx), ...]."""
    path = pathops.Path()
    pen = path.getPen()
    for calls, dx in pieces:
        replay(calls, pen, dx)
    return path


def blossom_region(pieces):
    pen = blossom.RegionPen()
    for calls, dx in pieces:
        replay(calls, pen, dx)
    return pen.region()


def skia_simplify(path):
    return pathops.simplify(path, clockwise=path.clockwise)


def box_area(pieces_box):
    (x0, y0), (x1, y1) = pieces_box
    return max(x1 - x0, 0.0) * max(y1 - y0, 0.0)


def input_box(region):
    xs, ys = [], []
    for lp in region.loops:
        for c in lp:
            n = c.nodes
            xs.extend(n[0])
            ys.extend(n[1])
    if not xs:
        return (0.0, 0.0), (0.0, 0.0)
    return (min(xs), min(ys)), (max(xs), max(ys))


def signed_area(pieces):
    """Green's theorem on a loop of pieces (2 x (n + 1) node arrays, n <= 3), in doubles:
    1/2 * integral of (x y' - y x'), by Simpson on quadratics and Boole on cubics (exact
    polynomials up to the rounding of doubles)."""
    total = 0.0
    for nodes in pieces:
        n = nodes.shape[1] - 1
        xs, ys = nodes[0], nodes[1]
        if n == 1:
            total += 0.5 * (xs[0] * ys[1] - xs[1] * ys[0])
            continue
        w = [7, 32, 12, 32, 7]
        acc = 0.0
        for k in range(5):
            t = k / 4
            # de Casteljau for the point, the hodograph for the derivative
            px, py = casteljau(xs, t), casteljau(ys, t)
            dx = n * casteljau([xs[j + 1] - xs[j] for j in range(n)], t)
            dy = n * casteljau([ys[j + 1] - ys[j] for j in range(n)], t)
            acc += w[k] * (px * dy - py * dx)
        total += acc / 90 / 2
    return total


def casteljau(values, t):
    v = list(values)
    for r in range(1, len(v)):
        for j in range(len(v) - r):
            v[j] = v[j] + t * (v[j + 1] - v[j])
    return v[0]


def malformed(result, region):
    """Why a blossom answer is not well-formed, or None (see the module docs)."""
    lo, hi = result.area
    b = box_area(input_box(region))
    if not (0.0 <= lo <= hi):
        return f"area enclosure {lo}, {hi}"
    if hi - lo > b * 2.0**-40 * (1 + 1e-12):
        return f"area enclosure {lo}, {hi} wider than 2^-40 B"
    geometry = result.geometry
    holes = result.holes
    if len(geometry) != len(holes):
        return "loops and holes differ in number"
    total = 0.0
    for lp, hole in zip(geometry, holes):
        if not lp:
            return "an empty loop"
        nodes = [c.nodes for c in lp]
        for k, c in enumerate(nodes):
            if c.shape[1] - 1 > 3:
                return f"a piece of degree {c.shape[1] - 1}"
            previous = nodes[k - 1]
            if not (previous[:, -1] == c[:, 0]).all():
                return "a piece does not start where the previous one ends"
        a = signed_area(nodes)
        if (a < 0) != hole:
            return f"a loop of signed area {a} with hole={hole}"
        total += a
    slack = 1e-9 * max(b, 1.0)
    if not (lo - slack <= total <= hi + slack):
        return f"the loops' areas sum to {total}, outside [{lo}, {hi}]"
    return None


def timed(fn):
    start = time.perf_counter()
    try:
        out = fn()
    except (pathops.PathOpsError, blossom.Error) as e:
        return time.perf_counter() - start, e
    return time.perf_counter() - start, out


class Tally:
    def __init__(self):
        self.times, self.errors, self.malformed, self.skia_off = [], 0, 0, 0
        self.examples = []

    def add(self, seconds, failed):
        if failed:
            self.errors += 1
        else:
            self.times.append(seconds)

    def row(self, label):
        t = sorted(self.times)
        if not t:
            return f"{label:<34} {'-':>10} {'-':>10} {'-':>10} {'-':>10} {self.errors:>6}"
        p99 = t[min(len(t) - 1, int(math.ceil(0.99 * len(t))) - 1)]
        return (f"{label:<34} {sum(t):10.3f} {1e6 * statistics.median(t):10.1f} "
                f"{1e6 * p99:10.1f} {1e6 * t[-1]:10.1f} {self.errors:>6}")


def compare(task, key, skia_tally, ours_tally, pieces, face_name):
    """One task on one input: both tools, timed; the checks on blossom's answer."""
    path = skia_path(pieces)
    region = blossom_region(pieces)
    t, skia_out = timed(lambda: skia_simplify(path))
    skia_tally.add(t, isinstance(skia_out, Exception))
    t, ours = timed(lambda: region.simplify())
    failed = isinstance(ours, Exception)
    ours_tally.add(t, failed)
    if failed:
        ours_tally.examples.append(f"{face_name} {key}: {ours}")
        return
    why = malformed(ours, region)
    if why:
        ours_tally.malformed += 1
        ours_tally.examples.append(f"{face_name} {key}: malformed: {why}")
    if not isinstance(skia_out, Exception):
        lo, hi = ours.area
        b = box_area(input_box(region))
        a = skia_out.area
        if a < lo - 1e-9 * b or a > hi + 1e-9 * b:
            ours_tally.skia_off += 1


def from_glyph(glyph_set, name, skia_tally, ours_tally):
    """remove, draw+op: the pen, the glyph drawn, the path or region made, then simplify."""
    def skia():
        path = pathops.Path()
        glyph_set[name].draw(path.getPen(glyphSet=glyph_set))
        return skia_simplify(path)

    def ours():
        pen = blossom.RegionPen(glyph_set)
        glyph_set[name].draw(pen)
        return pen.region().simplify()

    t, out = timed(skia)
    skia_tally.add(t, isinstance(out, Exception))
    t, out = timed(ours)
    ours_tally.add(t, isinstance(out, Exception))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--dir", default="/usr/share/fonts/truetype/dejavu")
    parser.add_argument("--faces", default=",".join(FACES))
    parser.add_argument("--tasks", default="remove,shifted,words")
    parser.add_argument("--limit", type=int, default=0, help="glyphs per face (0: all)")
    parser.add_argument("--shift", type=float, default=20)
    parser.add_argument("--copies", type=int, default=4)
    parser.add_argument("--squeeze", type=float, default=0.75)
    parser.add_argument("--words", default=WORDS)
    parser.add_argument("--json", help="write the per-call times here")
    args = parser.parse_args()
    tasks = args.tasks.split(",")
    labels = {
        "remove": "remove overlaps, op",
        "remove_draw": "remove overlaps, draw+op",
        "shifted": f"union of {args.copies} copies shifted {args.shift:g}",
        "words": f"words, advances x {args.squeeze:g}",
    }
    order = [k for k in ("remove", "remove_draw", "shifted", "words")
             if k.split("_")[0] in tasks]
    overall = {(k, tool): Tally() for k in order for tool in ("skia", "blossom")}
    per_face = {}
    print(f"blossom {blossom.__version__}, skia-pathops {pathops.__version__}, "
          f"python {sys.version.split()[0]}", flush=True)
    for face in args.faces.split(","):
        font = TTFont(os.path.join(args.dir, face))
        glyph_set = font.getGlyphSet()
        names = font.getGlyphOrder()
        if args.limit:
            names = names[: args.limit]
        tallies = {(k, tool): Tally() for k in order for tool in ("skia", "blossom")}
        outlines = {}
        for name in names:
            calls = record(glyph_set, name)
            if has_contours(calls):
                outlines[name] = calls
        start = time.perf_counter()
        for name, calls in outlines.items():
            if "remove" in tasks:
                compare("remove", name, tallies["remove", "skia"], tallies["remove", "blossom"],
                        [(calls, 0)], face)
                from_glyph(glyph_set, name, tallies["remove_draw", "skia"],
                           tallies["remove_draw", "blossom"])
            if "shifted" in tasks:
                pieces = [(calls, k * args.shift) for k in range(args.copies)]
                compare("shifted", name, tallies["shifted", "skia"],
                        tallies["shifted", "blossom"], pieces, face)
        if "words" in tasks:
            cmap = font.getBestCmap()
            hmtx = font["hmtx"]
            for word in args.words.split():
                pieces, x = [], 0
                for ch in word:
                    name = cmap.get(ord(ch))
                    if name is None:
                        continue
                    if name in outlines:
                        pieces.append((outlines[name], x))
                    x += round(hmtx[name][0] * args.squeeze)
                if pieces:
                    compare("words", word, tallies["words", "skia"],
                            tallies["words", "blossom"], pieces, face)
        per_face[face] = tallies
        for key, t in tallies.items():
            o = overall[key]
            o.times += t.times
            o.errors += t.errors
            o.malformed += t.malformed
            o.skia_off += t.skia_off
            o.examples += t.examples
        print(f"{face}: {len(outlines)} glyphs with contours, {time.perf_counter() - start:.1f} s",
              flush=True)
        report(tallies, order, labels)
    if len(per_face) > 1:
        print(f"all {len(per_face)} faces:")
        report(overall, order, labels)
    examples = [e for k in order for e in overall[k, "blossom"].examples]
    if examples:
        print("blossom errors and malformed answers (first 20):")
        for e in examples[:20]:
            print("  " + e)
    if args.json:
        out = {face: {f"{k}/{tool}": {"times": t.times, "errors": t.errors}
                      for (k, tool), t in tallies.items()}
               for face, tallies in per_face.items()}
        with open(args.json, "w") as f:
            json.dump(out, f)


def report(tallies, order, labels):
    print(f"  {'task / tool':<34} {'total s':>10} {'median us':>10} {'p99 us':>10} "
          f"{'max us':>10} {'errors':>6}")
    for k in order:
        for tool in ("skia", "blossom"):
            t = tallies[k, tool]
            line = "  " + t.row(f"{labels[k]}: {tool}")
            if tool == "blossom" and k != "remove_draw":
                line += f"   malformed {t.malformed}, skia area off {t.skia_off}"
            print(line)
        s, b = tallies[k, "skia"].times, tallies[k, "blossom"].times
        if s and b:
            print(f"  {'':<34} blossom / skia: total {sum(b) / sum(s):.2f}, "
                  f"median {statistics.median(b) / statistics.median(s):.2f}")


if __name__ == "__main__":
    main()
