"""blossom.restrict_curves: every layout and size gives each curve's Curve.specialize bit for
bit; a NaN anywhere (in any chunk the binding works on) is named by its index."""

import numpy as np
import pytest

import blossom

from conftest import random_nodes


def layouts(c_order):
    """The same curves as a C-ordered array, point after point, and in another layout."""
    point_major = np.ascontiguousarray(c_order.transpose(0, 2, 1)).transpose(0, 2, 1)
    other = np.asfortranarray(c_order)
    return {"C order": c_order, "point after point": point_major, "Fortran": other}


@pytest.mark.parametrize("d, k", [(1, 4), (2, 2), (2, 3), (2, 4), (2, 9), (2, 10), (3, 4), (3, 7), (4, 4)])
def test_every_layout_is_specialize_bit_for_bit(rng, d, k):
    for count in (1, 63, 65, 130):
        c_order = np.stack([random_nodes(rng, d, k - 1) for _ in range(count)])
        wanted = np.stack([blossom.Curve(c, k - 1).specialize(0.2, 0.9).nodes for c in c_order])
        for name, nodes in layouts(np.ascontiguousarray(c_order)).items():
            got = blossom.restrict_curves(nodes, 0.2, 0.9)
            assert got.shape == nodes.shape
            assert np.array_equal(got, wanted), (name, count)
            out = np.empty_like(got)
            if got.flags.c_contiguous or name == "point after point":
                assert blossom.restrict_curves(nodes, 0.2, 0.9, out=out) is out
                assert np.array_equal(out, wanted), (name, count)


@pytest.mark.parametrize("d, k", [(2, 4), (3, 3), (1, 5), (2, 12)])
def test_a_nan_in_any_chunk_is_named(d, k):
    for count, bad in [(200, (150, d - 1, k - 1)), (70, (64, 0, 0)), (3, (2, 0, 1))]:
        c_order = np.ones((count, d, k))
        c_order[bad] = np.nan
        for name, nodes in layouts(c_order).items():
            with pytest.raises(blossom.Error) as info:
                blossom.restrict_curves(nodes, 0.0, 0.5)
            assert info.value.path == "nodes[{}, {}, {}]".format(*bad), name
            assert info.value.kind == "NotFinite"
