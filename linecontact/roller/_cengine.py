"""The C engine of the coupled-slice equations (``engine="c"``).

:meth:`SliceEquations.kernels <linecontact.roller.slices.SliceEquations.kernels>` and
:meth:`~linecontact.roller.slices.SliceEquations.linearised` evaluated by the C
extension ``linecontact._ckernels`` (linecontact/roller/_ckernels.c, built at install
where a C compiler exists; loaded by :mod:`linecontact._engine`), with the cached
geometry and spline table of :mod:`linecontact.roller._layout`: the numpy code's
arithmetic, its sums in another order, so results agree with it to rounding. The
functions here make the inputs contiguous float64 / int64 and allocate the outputs
(the Fortran-order matrices as the transposes of C-order arrays, which the extension
fills). A call returns None where a spline argument falls below the table (tau <
1e-4) and the caller takes the numpy path. The bordered Newton step's arithmetic
around its dense solve (the scaled system; the sums, the step, its mask and the damped
update) is C too (``newton_step``, ``scaled_system``, ``solve_sums``, ``step_out``,
``step_update``: the lines of ``SliceEquations.bordered`` in their order); the dense
solves themselves are numpy's (``np.linalg.solve``: no LAPACK is linked into the
extension), and so is the cold start.

Used only where the extension runs (:func:`linecontact.roller.slices.c_engine`); it
imports anywhere (so that every module of the package does).
"""
from __future__ import annotations

import numpy as np

from .._engine import ckernels
from ._layout import table, transposed
from .kernel import R_INF

#: the extension, or None where it does not run here
_ckernels = ckernels()
if _ckernels is not None:
    _tmin, _tmax, _coef, _z0, _ih, _h = table()
    _ckernels.set_table(_coef, _tmin, _tmax, _z0, _ih, _h, float(R_INF))

__all__ = []

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
    table. G None: every pair from the table."""
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
    None where a spline argument falls below the table."""
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


# -- the bordered Newton step's small arithmetic (SliceEquations.bordered) ------------
# its numpy lines in C; the dense solve between them is numpy's (np.linalg.solve: the
# numpy engine's LAPACK call)

def _jacobian(J):
    """(array whose C-order buffer holds J, whether it is J's transpose): J itself in
    place, or None where J is neither C- nor Fortran-contiguous."""
    if J.flags.f_contiguous:
        return J.T, True
    if J.flags.c_contiguous:
        return J, False
    return None, False


def scaled_system(J, res, rhs, ns, qsc, R):
    """The scaled Newton system of SliceEquations.bordered: J scaled in place, B new."""
    B = np.empty((2 * ns, 3))
    buf, fortran = _jacobian(J)
    if buf is None:                          # (a strided J: scaled in a copy)
        Jf = np.asfortranarray(J)
        B = scaled_system(Jf, res, rhs, ns, qsc, R)
        J[...] = Jf
        return B
    _ckernels.scaled_system(buf, fortran, _floats(res), _floats(rhs), ns,
                            1.0 / (qsc * R), qsc * R, -1.0 / qsc, 1.0 / qsc, float(R), B)
    return B


def bordered_sums(z, ns, qsc, R, w, x, S, qs):
    """(w.q, (w x).q, Wz) of SliceEquations.bordered, z unscaled in place (z C order)."""
    Wz = np.empty((2, 3))
    wq, wxq = _ckernels.bordered_sums(z, ns, qsc, 1.0 / R, _floats(w), _floats(x),
                                      _ints(S), _floats(qs), Wz)
    return wq, wxq, Wz


def _solved(J, B):
    """np.linalg.solve(J, B) as a C-order array (its own, writable)."""
    z = np.linalg.solve(J, B)
    return z if z.flags.c_contiguous and z.flags.writeable else np.array(z, order="C")


def solve_sums(J, B, ns, qsc, R, w, x, S, qs):
    """(z, w.q, (w x).q, Wz) of SliceEquations.bordered's step: numpy's dense solve and
    :func:`bordered_sums`."""
    z = _solved(J, B)
    return (z,) + bordered_sums(z, ns, qsc, R, w, x, S, qs)


def step_out(z, s0, s1, ns, qs):
    """(dz, out, count) of SliceEquations.bordered's step."""
    dz = np.empty(2 * ns)
    out = np.empty(ns, dtype=np.bool_)
    k = _ckernels.step_out(_floats(z), float(s0), float(s1), ns, _floats(qs), dz, out)
    return dz, out, k


def step_update(q, c, S, qs, cs, dq, dc, over, x, s0, s1):
    """(alpha, hit_q, largest overlap, largest |dq|, largest |dc|) of
    SliceEquations.bordered's damped update, q and c updated in place."""
    hit_q = np.empty(len(S), dtype=np.bool_)
    res = np.empty(4)
    _ckernels.step_update(q, c, _ints(S), _floats(qs), _floats(cs), _floats(dq),
                          _floats(dc), _floats(over), _floats(x), float(s0), float(s1),
                          hit_q, res)
    return float(res[0]), hit_q, float(res[1]), float(res[2]), float(res[3])


def newton_step(J, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, target, mode, q, c,
                over):
    """One step of SliceEquations.bordered after the linearisation: (status, B, z, K,
    step, dz, out, hit_q, upd), the scaled system and the arithmetic after numpy's
    dense solve in C. (None,
    B) where numpy's solve refuses the system (singular): J and B are scaled, and the
    caller's own solve raises as the numpy engine's would."""
    B = scaled_system(J, res, rhs, ns, qsc, R)
    try:
        z = _solved(J, B)
    except np.linalg.LinAlgError:
        return None, B
    K = np.empty((2, 2))
    st = np.empty(4)
    dz = np.empty(2 * ns)
    out = np.empty(ns, dtype=np.bool_)
    hit_q = np.empty(ns, dtype=np.bool_)
    upd = np.empty(4)
    status = _ckernels.newton_after(z, _floats(grid), ns, float(qsc), 1.0 / R, _floats(w),
                                    _floats(x), _ints(S), _floats(qs), _floats(cs),
                                    float(target), int(mode), q, c, _floats(over), K, st,
                                    dz, out, hit_q, upd)
    if status == 2:
        dz, out = np.empty(0), np.empty(0, dtype=np.bool_)
    return status, B, z, K, st, dz, out, hit_q, upd
