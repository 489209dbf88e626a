"""The data of the slice equations in the layout the C engine reads
(:mod:`linecontact.roller._cengine`): the spline table of the strip functions with a
point's sixteen coefficients together, and the cached unit geometry transposed so that
each source slice's column is contiguous.

Does not import the C extension (the numpy code in :mod:`linecontact.roller.slices`
keeps the originals).
"""
from __future__ import annotations

import numpy as np

from .._numerics import CACHE_BYTES, cache_nbytes
from .kernel import spline_table

__all__ = []

_TABLE = []


def table():
    """tau_min, tau_max, coef, z0, 1/h, h of the spline table (built once): coef as
    (segment, power, function), a point's 16 coefficients in two cache lines (in the
    table's (power, function, segment) order 16 lines apart)."""
    if not _TABLE:
        t = spline_table()
        _TABLE.append((float(t.tau_min), float(t.tau_max),
                       np.ascontiguousarray(t.coef.transpose(2, 0, 1)), float(t.z0),
                       1.0 / t.h, float(t.h)))
    return _TABLE[0]


#: G of an all-table geometry (no far field): a placeholder, never read
NO_G = np.zeros((1, 1, 1))
_T = {}


def transposed(tn, tf, lr, G):
    """The unit geometry as [source, target] (each source's column contiguous): tn,
    tf, lr, ln tn, ln tf, and G as (source, power, target) (NO_G where G is None).
    Kept for the last few geometries (the numpy code's caches hold the originals)."""
    got = _T.get(id(tn))
    if got is None or got[0] is not tn or got[1] is not G:
        if len(_T) >= 8 or cache_nbytes(_T) > CACHE_BYTES:
            _T.clear()
        Gt = NO_G if G is None else np.ascontiguousarray(G.transpose(0, 2, 1))
        tnt, tft = np.ascontiguousarray(tn.T), np.ascontiguousarray(tf.T)
        got = (tn, G, tnt, tft, np.ascontiguousarray(lr.T), np.log(tnt), np.log(tft), Gt)
        _T[id(tn)] = got
    return got[2:]
