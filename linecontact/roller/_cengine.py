"""The C engine of the coupled-slice equations (optional; ``engine="c"``).

:meth:`SliceEquations.kernels <linecontact.roller.slices.SliceEquations.kernels>` and
:meth:`~linecontact.roller.slices.SliceEquations.linearised` evaluated by the C
extension ``linecontact.roller._ckernels`` (linecontact/roller/_ckernels.c, built at
install where a C compiler exists): a port to C99 of the numba engine's loops
(:mod:`linecontact.roller._compiled`, ``kernels`` and ``linearised``) with the same
arithmetic in the same order, the same cached geometry and spline table
(:mod:`linecontact.roller._layout`), so it agrees with the numba and numpy engines to
rounding. The functions here have the signatures and return values of
``_compiled.kernels`` and ``_compiled.linearised``: they make the inputs contiguous
float64 / int64 and allocate the outputs (the Fortran-order matrices as the transposes
of C-order arrays, which the extension fills). Like the numba engine, a call returns
None where a spline argument falls below the table (tau < 1e-4) and the caller takes
the numpy path; the rest of the Newton step (the dense solve, the update) stays numpy.

Importing this module raises ImportError where the extension was not built (the
caller, :func:`linecontact.roller.slices.c_engine`, then keeps to numpy or numba).
"""
from __future__ import annotations

import numpy as np

from . import _ckernels
from ._layout import table, transposed
from .kernel import R_INF

__all__ = []

_tmin, _tmax, _coef, _z0, _ih, _h = table()
_ckernels.set_table(_coef, _tmin, _tmax, _z0, _ih, _h, float(R_INF))

_I8 = np.dtype(np.int64)
_F8 = np.dtype(np.float64)


def _ints(a):
    """`a` as a C-contiguous int64 array (itself where it is one)."""
    if type(a) is np.ndarray and a.dtype == _I8 and a.flags.c_contiguous:
        return a
    return np.ascontiguousarray(a, dtype=_I8)


def _floats(a):
    """`a` as a C-contiguous float64 array (itself where it is one)."""
    if type(a) is np.ndarray and a.dtype == _F8 and a.flags.c_contiguous:
        return a
    return np.ascontiguousarray(a, dtype=_F8)


def kernels(S, T, b, span, dg, tn, tf, lr, G, fc, a_only):
    """A, D, EA, ED (the others None with a_only) for targets T and sources S, each
    (len(T), len(S)) in Fortran order, or None where a spline argument falls below the
    table. G None: every pair from the table (as _compiled.kernels)."""
    S, T = _ints(S), _ints(T)
    nt, ns = len(T), len(S)
    tn, tf, lr, ltn, ltf, Gt = transposed(tn, tf, lr, G)
    At = np.empty((ns, nt))
    if a_only:
        EAt = Dt = EDt = None
    else:
        EAt, Dt, EDt = np.empty((ns, nt)), np.empty((ns, nt)), np.empty((ns, nt))
    if not _ckernels.kernels(S, T, _floats(b), float(span), _floats(dg), tn, tf, lr, ltn,
                             ltf, Gt, _floats(fc), G is not None, At, EAt, Dt, EDt):
        return None
    if a_only:
        return At.T, None, None, None
    return At.T, Dt.T, EAt.T, EDt.T


def linearised(S, T, spos, q, c, over, R, span, x, m, dg, slope, theta, dlo, dhi,
               tn, tf, lr, G, fc):
    """(res, J, rhs, gap, grid) of SliceEquations.linearised (J in Fortran order), or
    None where a spline argument falls below the table (as _compiled.linearised)."""
    S, T = _ints(S), _ints(T)
    ns, nt = len(S), len(T)
    res = np.empty(2 * ns)
    Jt = np.empty((2 * ns, 2 * ns))
    rhs = np.empty((2 * ns, 2))
    gap = np.empty(nt)
    grid = np.empty((2, 2))
    tn, tf, lr, ltn, ltf, Gt = transposed(tn, tf, lr, G)
    (dlo0, dlo1), (dhi0, dhi1) = dlo, dhi
    if not _ckernels.linearised(
            S, T, _ints(spos), _floats(q), _floats(c), _floats(over), float(R),
            float(span), _floats(x), _floats(m), _floats(dg), _floats(slope),
            float(theta), float(dlo0), float(dlo1), float(dhi0), float(dhi1), tn, tf, lr,
            ltn, ltf, Gt, _floats(fc), G is not None, res, Jt, rhs, gap, grid):
        return None
    return res, Jt.T, rhs, gap, grid
