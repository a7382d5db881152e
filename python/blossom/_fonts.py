"""Overlap removal on fontTools' ``TTFont`` with blossom's certified booleans.

``remove_overlaps`` does what ``fontTools.ttLib.removeOverlaps.removeOverlaps`` does, with
``CurvedRegion.simplify()`` in place of skia-pathops' ``simplify``: the same glyphs are
processed in the same order, the same tables are rewritten the same way (glyf through
``TTGlyphPen``, which rounds the coordinates to integers with ``otRound``; CFF and CFF2 through
``T2CharStringPen``), hinting is dropped as fontTools drops it, and composite glyphs are
decomposed only where their components overlap (a certified intersection of positive area).
Every answer is certified and there is no fallback: a glyph whose overlap removal is refused
(its estimated work over ``max_work``) raises, it is never left as it was.

fontTools is imported when ``remove_overlaps`` runs, not when ``blossom`` is imported.
"""

from difflib import get_close_matches
from itertools import combinations

from ._blossom import Error, RegionPen

__all__ = ["remove_overlaps"]


def _region(glyph_set, name):
    """The glyph's outline as a CurvedRegion (components decomposed; nonzero, TrueType's and
    CFF's fill rule)."""
    pen = RegionPen(glyph_set)
    glyph_set[name].draw(pen)
    return pen.region()


def _component_region(glyph_set, component):
    base, transformation = component.getComponentInfo()
    pen = RegionPen(glyph_set)
    pen.addComponent(base, transformation)
    return pen.region()


def _error(path, kind, message):
    """A blossom.Error on the argument `path`, as the extension raises them."""
    error = Error(f"{path}: {message}")
    error.path, error.kind = path, kind
    return error


def _glyph_error(name, error):
    """`error` (a blossom.Error) raised again, naming the glyph."""
    path = f"glyphs[{name!r}]" + (f".{error.path}" if error.path else "")
    message = str(error)
    if error.path and message.startswith(error.path + ": "):
        message = message[len(error.path) + 2:]
    out = Error(f"{path}: {message}")
    out.path, out.kind = path, error.kind
    return out


def _components_overlap(glyph, glyph_set, max_work):
    """Whether two components of a composite glyph overlap (their intersection has positive
    area), as fontTools' componentsOverlap asks of skia-pathops."""
    if len(glyph.components) < 2:
        return False
    regions = {}

    def region(i):
        if i not in regions:
            regions[i] = _component_region(glyph_set, glyph.components[i])
        return regions[i]

    def overlap(i, j):
        a, b = region(i), region(j)
        box_a, box_b = a._control_box(), b._control_box()
        # Each region lies in the box of its control points: boxes that meet at most along
        # an edge leave no intersection of positive area.
        if box_a is None or box_b is None or (
            box_a[2] <= box_b[0] or box_b[2] <= box_a[0]
            or box_a[3] <= box_b[1] or box_b[3] <= box_a[1]
        ):
            return False
        # A regularized intersection with a loop has positive area.
        return len(a.intersection(b, max_work=max_work).holes) > 0

    return any(overlap(i, j) for i, j in combinations(range(len(glyph.components)), 2))


def _simplified(glyph_set, name, max_work):
    """The glyph's overlap removal, or None when it is the glyph's own outline."""
    try:
        result = _region(glyph_set, name).simplify(max_work=max_work)
    except Error as e:
        raise _glyph_error(name, e) from e
    return None if result._draws_input() else result


def _remove_glyf_overlaps(font, glyph_names, glyph_set, remove_hinting, max_work):
    from fontTools.pens.ttGlyphPen import TTGlyphPen

    glyf_tag = "GLYF" if "GLYF" in font else "glyf"
    glyf = font[glyf_tag]
    hmtx = font["HMTX" if glyf_tag == "GLYF" else "hmtx"]
    # Simple glyphs first, then composites by increasing component depth, so that the base
    # glyphs are simplified before their composites are tested for overlaps (as fontTools).
    cache = {}
    glyph_names = sorted(
        glyph_names,
        key=lambda name: (
            glyf[name].getCompositeMaxpValues(glyf, maxpValuesCache=cache).maxComponentDepth
            if glyf[name].isComposite()
            else 0,
            name,
        ),
    )
    modified = set()
    for name in glyph_names:
        glyph = glyf[name]
        if glyph.numberOfContours > 0 or (
            glyph.isComposite() and _components_overlap(glyph, glyph_set, max_work)
        ):
            result = _simplified(glyph_set, name, max_work)
            if result is not None:
                pen = TTGlyphPen(glyphSet=None)
                result.draw(pen)
                glyf[name] = glyph = pen.glyph()
                glyph.recalcBounds(glyfTable=None)
                # hmtx's left side bearing is the glyph's xMin (the origin stays at x = 0).
                width, lsb = hmtx[name]
                if lsb != glyph.xMin:
                    hmtx[name] = (width, glyph.xMin)
                modified.add(name)
                continue
        if remove_hinting:
            glyph.removeHinting()
    return modified


def _remove_cff_overlaps(font, glyph_names, glyph_set, remove_hinting,
                         remove_unused_subroutines, max_work):
    from fontTools.pens.t2CharStringPen import T2CharStringPen

    tag = "CFF " if "CFF " in font else "CFF2"
    cff = font[tag].cff
    char_strings = cff[0].CharStrings
    modified = set()
    for name in glyph_names:
        result = _simplified(glyph_set, name, max_work)
        if result is None:
            continue
        old = char_strings[name]
        if tag == "CFF2":
            pen = T2CharStringPen(width=None, glyphSet=None, CFF2=True)
        else:
            # The width as fontTools writes it: none when it is the default width, else the
            # difference to the nominal width.
            width = None if old.width == old.private.defaultWidthX else (
                old.width - old.private.nominalWidthX)
            pen = T2CharStringPen(width=width, glyphSet=None)
        result.draw(pen)
        char_strings[name] = pen.getCharString(old.private, old.globalSubrs)
        modified.add(name)
    if modified:
        if remove_hinting:
            cff.remove_hints()
        if remove_unused_subroutines:
            cff.remove_unused_subroutines()
    return modified


def remove_overlaps(font, glyph_names=None, remove_hinting=True, *,
                    remove_unused_subroutines=True, max_work=None):
    """Removes the overlaps of the glyphs of a fontTools ``TTFont`` in place, certified: what
    ``fontTools.ttLib.removeOverlaps.removeOverlaps`` does, with blossom's
    ``CurvedRegion.simplify()`` (nonzero rule) in place of skia-pathops.

    ``glyph_names``: the glyphs to process (default: all, in glyph order). glyf glyphs with
    contours are simplified, composite glyphs decomposed and simplified where two components
    overlap (else kept as composites); CFF and CFF2 glyphs are simplified. A glyph whose
    result is its own outline (no overlap, contours already in the font's direction) is left
    as it is; the others are redrawn with the font's contour direction (that of the glyph's
    outline: clockwise outer contours in TrueType fonts), glyf coordinates rounded by
    ``TTGlyphPen`` (``otRound``) and the hmtx left side bearing set to the new xMin as
    fontTools sets it. ``remove_hinting`` drops the hinting of every processed glyf glyph (a
    rewritten glyph has none), and of the CFF font when a glyph changed;
    ``remove_unused_subroutines`` then prunes CFF subroutines. ``max_work`` bounds each
    boolean as in ``CurvedRegion.simplify``; a glyph over it raises ``blossom.Error`` (path
    ``glyphs['name'].max_work``): no glyph is ever left with its overlaps.

    Returns the set of the names of the glyphs that were rewritten. Raises
    ``NotImplementedError`` for a font without glyf, CFF or CFF2 outlines (as fontTools).
    """
    if not (hasattr(font, "getGlyphSet") and hasattr(font, "getGlyphOrder")):
        raise _error("font", "Invalid", f"expected a fontTools TTFont, found {type(font).__name__}")
    # max_work is read (and refused when bad) even when no glyph needs a boolean.
    RegionPen().region().simplify(max_work=max_work)
    if not any(tag in font for tag in ("glyf", "GLYF", "CFF ", "CFF2")):
        raise NotImplementedError(
            "No outline data found in the font: missing 'glyf', 'GLYF', 'CFF ', or 'CFF2' table"
        )
    order = font.getGlyphOrder()
    if glyph_names is None:
        glyph_names = order
    elif isinstance(glyph_names, (str, bytes)):
        raise _error("glyph_names", "Invalid", "expected an iterable of glyph names, found a single "
                     f"{type(glyph_names).__name__} (pass [{glyph_names!r}] for one glyph)")
    try:
        glyph_names = list(glyph_names)
    except TypeError:
        raise _error("glyph_names", "Invalid",
                     f"expected an iterable of glyph names, found {type(glyph_names).__name__}") from None
    known = set(order)
    for k, name in enumerate(glyph_names):
        if not isinstance(name, str) or name not in known:
            near = []
            if isinstance(name, str):
                by_case = [n for n in order if n.lower() == name.lower()]
                near = by_case or get_close_matches(name, order, n=1)
            hint = f" (did you mean {near[0]!r}?)" if near else ""
            raise _error(f"glyph_names[{k}]", "Invalid", f"{name!r} is not a glyph of the font{hint}")
    glyph_set = font.getGlyphSet()
    modified = set()
    if "glyf" in font or "GLYF" in font:
        modified |= _remove_glyf_overlaps(font, glyph_names, glyph_set, remove_hinting, max_work)
    if "CFF " in font or "CFF2" in font:
        modified |= _remove_cff_overlaps(font, glyph_names, glyph_set, remove_hinting,
                                         remove_unused_subroutines, max_work)
    return modified
