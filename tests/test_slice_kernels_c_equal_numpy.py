"""The C engine of the coupled-slice equations (linecontact/roller/_cengine.py over the
extension linecontact._ckernels) agrees with the numpy reference (SliceEquations.kernels,
linearised, the bordered Newton step's lines) at rounding, whole solves with both agree,
and the engine is chosen as documented (docs/profiled_rollers.md, "Engines").

The agreement tests skip, with the reason, where the extension does not run here (pip
install -e . builds it where a C compiler is present; so does CI; test_extensions.py
checks that the source compiles there).

The C code evaluates the same series coefficients, the same spline table and the same
cached geometry with the same split into far field, near band and diagonal; it differs
only in the order of sums. So every entry agrees to a few units of rounding of the
matrix's largest entry: 1e-12 of it leaves three orders of margin and still catches any
term, pair or index taken wrongly (those are >= 1e-10 of the scale: the spline's own
error against the series).
"""
from __future__ import annotations

import pickle
import subprocess
import sys

import numpy as np
import pytest

from linecontact import OutOfRangeError, _engine
from linecontact.roller import ProfiledRoller
from linecontact.roller import slices as sl
from linecontact.roller.slices import SliceEquations
from linecontact.errors import UnknownNameError

TOL = 1e-12
needs_c = pytest.mark.skipif(
    sl.c_engine() is None,
    reason=f"the C engine does not run here ({_engine.unavailable()}): pip install -e . "
           "with a C compiler builds it")


def _equations(n, grading, refine, engine):
    # a quartic drop over an asymmetric overlap interval; dlo, dhi and the slope are
    # arbitrary numbers: the test compares two evaluations of the same formulas
    s = SliceEquations(5e-3, 1.15e11, -6e-3, 6.5e-3, n, lambda x: 1e-6 * (x / 6e-3) ** 4,
                       grading, refine, engine=engine)
    s.dlo, s.dhi = (0.1, -0.3), (-0.2, 0.4)
    s._over = 1e-6 + 1e-4 * s.x
    return s


def _close(a, b, what):
    """Elementwise |a - b| <= TOL times the largest |a| (a the numpy reference)."""
    if a is None:
        assert b is None, what
        return
    scale = np.max(np.abs(a))
    err = np.max(np.abs(np.asarray(a) - np.asarray(b))) / scale
    assert err <= TOL, f"{what}: {err:.2e} of the largest entry"


# uniform, graded, graded with refined ends, and above the far-field limit _N_FAR
# (every pair from the spline table)
GRIDS = [(60, 0.0, 0), (100, 0.8, 0), (100, 0.8, 2), (sl._N_FAR + 50, 0.5, 0)]


def _states(N, rng):
    """Loaded sets (all, contiguous, with gaps) and loads: q ~ 1e-7 m, b ~ 1e-4 m (the
    near band then spans a few slices)."""
    for S in (np.arange(N), np.arange(3, N - 5),
              np.sort(rng.choice(N, N // 2, replace=False))):
        q = np.zeros(N)
        c = np.zeros(N)
        q[S] = 1e-7 * (1 + rng.random(len(S)))
        c[S] = q[S] / (1e-4 * (0.5 + rng.random(len(S)))) ** 2
        yield S, q, c


@needs_c
@pytest.mark.parametrize("grid", GRIDS)
def test_c_kernels_equal_numpy(grid):
    """A, D, EA, ED (and A alone) from the C loops equal the numpy kernels within
    1e-12 of each matrix's largest entry, for every loaded set and target set."""
    a, b = _equations(*grid, "numpy"), _equations(*grid, "c")
    N = a.n
    rng = np.random.default_rng(1)
    for S, q, c in _states(N, rng):
        bS = np.sqrt(q[S] / c[S])
        for T in (None, np.arange(N), np.union1d(S, [0, N - 1])):
            for a_only in (False, True):
                ka = a.kernels(S, bS, targets=T, a_only=a_only)
                kb = b.kernels(S, bS, targets=T, a_only=a_only)
                for name, x, y in zip("A D EA ED".split(), ka, kb):
                    _close(x, y, f"{grid} {name} ns={len(S)} a_only={a_only}")


@needs_c
@pytest.mark.parametrize("grid", GRIDS[:3])
def test_c_far_field_takes_every_term(grid):
    """The C far field sums all 14 terms of the series over every target, as
    the numpy code does: the kernels agree within 1e-14 of each matrix's largest entry
    (rounding: 1.5e-15 observed). That is tight enough to see one term missing: the
    last (14th) term at the near band's edge, t/b = 3, is 4.6e-14 of ED's scale."""
    a, b = _equations(*grid, "numpy"), _equations(*grid, "c")
    rng = np.random.default_rng(1)
    for S, q, c in _states(a.n, rng):
        bS = np.sqrt(q[S] / c[S])
        for a_only in (False, True):
            ka = a.kernels(S, bS, a_only=a_only)
            kb = b.kernels(S, bS, a_only=a_only)
            for name, x, y in zip("A D EA ED".split(), ka, kb):
                if x is None:
                    continue
                err = np.max(np.abs(x - y)) / np.max(np.abs(x))
                assert err <= 1e-14, f"{grid} {name} ns={len(S)}: {err:.2e} of the scale"


@needs_c
@pytest.mark.parametrize("grid", GRIDS)
def test_c_linearised_equals_numpy(grid):
    """Residual, Jacobian, grid columns, gaps and the 2x2 grid terms of linearised()
    from the C loops equal the numpy ones within 1e-12 of each one's largest
    entry (all slices or a subset as targets)."""
    a, b = _equations(*grid, "numpy"), _equations(*grid, "c")
    N = a.n
    rng = np.random.default_rng(2)
    slope = 4e-6 * a.x ** 3 / 6e-3 ** 4
    for S, q, c in _states(N, rng):
        for T in (np.arange(N), np.union1d(S, [0, N - 1])):
            la = a.linearised(S, q, c, 1e-3, slope, T)
            lb = b.linearised(S, q, c, 1e-3, slope, T)
            for name, x, y in zip("res J rhs gap grid".split(), la, lb):
                _close(x, y, f"{grid} {name} ns={len(S)} nt={len(T)}")


@needs_c
def test_c_outside_the_spline_table():
    """Beyond the spline table, t/b >= 1e4 (a slice about to leave, its strip
    nanometres wide: b = 1e-12 m here), the C code takes the series itself and
    agrees with the numpy code (which does the same); below it, t/b < 1e-4 (a strip
    far wider than the slices, b = 20 m), the call goes to the numpy code (series and
    quadrature) under either engine. Both: 1e-12 of each matrix's largest entry."""
    a, b = _equations(60, 0.0, 0, "numpy"), _equations(60, 0.0, 0, "c")
    S = np.arange(60)
    tiny = np.full(60, 1e-4)
    tiny[[0, 7, 59]] = 1e-12                 # w/2b ~ 1e8 on those diagonals
    got = sl.c_engine().kernels(S, S, tiny, b.span, b.dg, b._tnear, b._tfar, b._logratio,
                            sl._far_geometry(*b._geometry), sl._FAR_COEF, False)
    assert got is not None, "the C code fell back to numpy beyond the table"
    assert sl.c_engine().kernels(S, S, np.full(60, 20.0), b.span, b.dg, b._tnear,
                                   b._tfar, b._logratio, sl._far_geometry(*b._geometry),
                                   sl._FAR_COEF, False) is None, "below the table: None"
    for bS in (tiny, np.full(60, 20.0)):
        for x, y, name in zip(a.kernels(S, bS), b.kernels(S, bS), "A D EA ED".split()):
            _close(x, y, name)


CASES = [
    # (profile, force [N], tilt): the ISO 16281 case of the speed benchmark at a given
    # and a free tilt, a crowned roller, and a logarithmic end at a high load (the end
    # refinement re-solves it on refined grids)
    ("iso16281", 4200.0, 2e-3),
    ("iso16281", 4200.0, "free"),
    ("circular:Rc=0.5", 1000.0, 1e-3),
    ("iso16281", 20000.0, 0.5e-3),
]


@needs_c
@pytest.mark.parametrize("case", CASES)
def test_whole_solves_agree_between_engines(case):
    """A solve at a force with the C engine and with numpy: depth, tilt, moment,
    peak pressure and stiffness agree within 1e-10 (the Newton tolerance is 1e-11; the
    engines differ by rounding only, so both reach the same converged state)."""
    profile, force, tilt = case
    sols = [ProfiledRoller(5e-3, 14e-3, 115.385e9, profile, engine=e).at_force(
        force, tilt=tilt) for e in ("numpy", "c")]
    a, b = sols
    assert a.depth == pytest.approx(b.depth, rel=1e-10)
    assert a.p_max == pytest.approx(b.p_max, rel=1e-10)
    assert a.tilt == pytest.approx(b.tilt, rel=1e-10, abs=1e-10 * 1e-3)
    assert abs(a.moment - b.moment) <= 1e-10 * force * 14e-3
    np.testing.assert_allclose(a.stiffness_matrix, b.stiffness_matrix, rtol=1e-10,
                               atol=1e-10 * np.max(np.abs(a.stiffness_matrix)))


def _random_step_system(seed):
    """A random Newton system of the bordered step (30 slices, 12 loaded; a Jacobian
    made well conditioned by 5 I) and the generator, drawn on after it by each test:
    (rng, n, ns, R, qsc, S, w, x, J)."""
    rng = np.random.default_rng(seed)
    n, ns, R, qsc = 30, 12, 5e-3, 2e-7
    S = np.sort(rng.choice(n, ns, replace=False))
    w, x = rng.random(n) * 1e-4, rng.random(n) * 1e-2 - 5e-3
    J = rng.normal(size=(2 * ns, 2 * ns)) + 5 * np.eye(2 * ns)
    return rng, n, ns, R, qsc, S, w, x, J


@needs_c
def test_c_step_helpers_equal_their_numpy_lines():
    """The four C helpers of the bordered Newton step (_cengine.scaled_system,
    bordered_sums, step_out, step_update) give what the numpy code they replace in
    SliceEquations.bordered gives (slices.scaled_system; the other lines written out
    here): the scaled system bit for bit (the same products), the sums to 1e-13 of
    their scale (another order of addition), the step's mask, its damping alpha (from
    the loads, the curvatures and the overlap, at a given tilt and with a tilt step),
    the slices that limited it and the largest changes. A whole solve cannot check the damping and the mask: a wrong alpha or
    hit_q changes the Newton path, not the converged answer."""
    jit = sl.c_engine()

    rng, n, ns, R, qsc, S, w, x, J0 = _random_step_system(3)
    res, rhs = rng.normal(size=2 * ns), rng.normal(size=(2 * ns, 2))
    # the scaled system
    J, Jn = J0.copy(), J0.copy()
    B = jit.scaled_system(J, res, rhs, ns, qsc, R)
    Bn = sl.scaled_system(Jn, res, rhs, ns, qsc, R)
    assert np.array_equal(J, Jn) and np.array_equal(B, Bn), "scaled_system"
    assert not np.array_equal(J, J0), "the scaling must change J (in place)"
    # the force and moment sums
    z0 = rng.normal(size=(2 * ns, 3))
    qs = qsc * (0.1 + rng.random(ns))
    z, zn = z0.copy(), z0.copy()
    wq, wxq, Wz = jit.bordered_sums(z, ns, qsc, R, w, x, S, qs)
    zn[:ns] *= qsc
    zn[ns:] *= 1.0 / R
    W = np.stack([w[S], w[S] * x[S]])
    assert np.array_equal(z, zn), "bordered_sums: z unscaled"
    _close(W @ qs, np.array([wq, wxq]), "bordered_sums: w.q, (w x).q")
    _close(W @ zn[:ns], Wz, "bordered_sums: Wz")
    # the step and the slices it drives below zero
    for s0, s1 in ((1e-7, 0.0), (-2e-7, 3e-5)):
        zs = zn * np.r_[np.full(ns, 1.0), np.full(ns, 1e3)][:, None]
        dz, out, k = jit.step_out(zs, s0, s1, ns, qs)
        dzn = zs[:, 0] + zs[:, 1:] @ np.array([s0, s1])
        _close(dzn, dz, "step_out: dz")
        assert np.array_equal(out, qs + dzn[:ns] < 0) and k == out.sum(), "step_out"
    # the damped update: alpha = 1, limited by q, by c, by the overlap (s1 = 0 and not)
    over = 1e-6 * (0.2 + rng.random(n))
    over[0] = 1.5e-6                                   # the largest first
    cs = 1.0 / (4 * R) * (0.5 + rng.random(ns))
    for case in range(5):
        dq, dc = 0.1 * qs * rng.normal(size=ns), 0.1 * cs * rng.normal(size=ns)
        s0, s1 = 1e-8, 0.0
        if case == 1:
            dq[[2, 7]] = [-0.97, -2.0] * qs[[2, 7]]     # to 3 % (limit 5 %) and below 0
        elif case == 2:
            dc[5] = -0.85 * cs[5]                       # to 15 % (limit 20 %)
        elif case == 3:
            s0 = -0.9 * over.max()
        elif case == 4:
            s0, s1 = -0.3 * over.max(), 2e-4           # the lowest at an end slice
        q, c = np.zeros(n), np.zeros(n)
        qn, cn = q.copy(), c.copy()
        alpha, hit_q, dmax, dqmax, dcmax = jit.step_update(q, c, S, qs, cs, dq, dc,
                                                           over, x, s0, s1)
        an, hit_n = sl._fraction_to_boundary(qs, cs, dq, dc)
        dmax_n = float(over.max())
        drop = -float((s0 + s1 * x[S]).min())
        if drop > 0.5 * dmax_n:
            an = min(an, 0.5 * dmax_n / drop)
        qn[S], cn[S] = qs + an * dq, cs + an * dc
        assert (alpha < 1.0) == (case > 0), f"case {case}: the damping was not reached"
        assert alpha == pytest.approx(an, rel=1e-14), f"step_update alpha, case {case}"
        assert np.array_equal(hit_q, hit_n), f"step_update hit_q, case {case}"
        assert dmax == dmax_n, f"step_update: largest overlap, case {case}"
        assert dqmax == np.abs(dq).max() and dcmax == np.abs(dc).max(), case
        _close(qn, q, f"step_update q, case {case}")
        _close(cn, c, f"step_update c, case {case}")


def _step_by_helpers(jit, J, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, target, mode,
                     q, c, over):
    """SliceEquations.bordered's step as the C helpers and the Python lines between
    them, written out (what _cengine.newton_step fuses)."""
    B = jit.scaled_system(J, res, rhs, ns, qsc, R)
    z, wq, wxq, Wz = jit.solve_sums(J, B, ns, qsc, R, w, x, S, qs)
    K = Wz[:, 1:] + grid
    lin = Wz[:, 0]
    if mode == 3:
        r = (target - wq - lin[0], -wxq - lin[1])
        step = sl._cramer(K, r)
        if step is None:
            return 2, B, z, K, r
    elif mode == 1:
        step = ((target - wq - lin[0]) / K[0, 0], 0.0)
    elif mode == 2:
        step = (0.0, (-wxq - lin[1]) / K[1, 1])
    else:
        step = (0.0, 0.0)
    dz, out, nout = jit.step_out(z, step[0], step[1], ns, qs)
    if nout and ns > 2:
        return 1, B, z, K, step, dz, out
    upd = jit.step_update(q, c, S, qs, cs, dz[:ns], dz[ns:], over, x, step[0], step[1])
    return 0, B, z, K, step, dz, out, upd


@needs_c
def test_c_newton_step_equals_the_helpers_it_fuses():
    """_cengine.newton_step, the bordered step after the linearisation in one C
    call, gives bit for bit what the helpers it replaces give with the Python lines
    between them (_step_by_helpers: scaled_system, solve_sums, K = Wz[:, 1:] + grid,
    the step of each mode, step_out, step_update): the same operations in the same
    order. Each mode (no row, force, moment, both by Cramer's rule), with loads large
    enough that the update is done (status 0) and with slices the step drives below
    zero (status 1); Cramer's rule on a K that is not finite hands the 2 x 2 system back
    (status 2), and a singular Jacobian the scaled system (None: numpy's solve)."""
    jit = sl.c_engine()

    rng, n, ns, R, qsc, S, w, x, J0 = _random_step_system(7)
    res, rhs = rng.normal(size=2 * ns), rng.normal(size=(2 * ns, 2))
    grid = rng.normal(size=(2, 2)) * 1e-3
    over = 1e-6 * (0.2 + rng.random(n))
    cs = 1.0 / (4 * R) * (0.5 + rng.random(ns))
    seen = set()
    for mode in range(4):
        for scale in (1e8, 1e-3):           # loads far above the step (|dq| ~ 1), below it
            qs = qsc * scale * (0.5 + rng.random(ns))
            J1, J2 = J0.copy(order="F"), J0.copy(order="F")
            q1, c1, q2, c2 = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
            got = jit.newton_step(J1, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, 3e-7,
                                  mode, q1, c1, over)
            want = _step_by_helpers(jit, J2, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs,
                                    3e-7, mode, q2, c2, over)
            status, B, z, K, st, dz, out, hit_q, upd = got
            assert status == want[0], f"mode {mode}, loads x{scale}: status"
            seen.add(status)
            assert np.array_equal(J1, J2) and np.array_equal(B, want[1]), "scaled system"
            assert np.array_equal(z, want[2]) and np.array_equal(K, want[3]), "z, K"
            assert tuple(st[:2]) == tuple(want[4]), f"mode {mode}: the step"
            assert np.array_equal(dz, want[5]) and np.array_equal(out, want[6]), "dz"
            if status == 0:
                alpha, hit_n, dmax, dqmax, dcmax = want[7]
                assert (upd[0], upd[1], upd[2], upd[3]) == (alpha, dmax, dqmax, dcmax)
                assert np.array_equal(hit_q, hit_n), "hit_q"
                assert np.array_equal(q1, q2) and np.array_equal(c1, c2), "q, c updated"
            else:
                assert not q1.any() and not c1.any(), "no update where slices leave"
    assert seen == {0, 1}, f"both outcomes must be reached: {seen}"
    # exactly one slice driven below zero (mode 0: dz does not depend on the loads)
    dq = jit.newton_step(J0.copy(order="F"), res, rhs, grid, ns, qsc, R, w, x, S,
                         np.full(ns, 1e8), cs, 3e-7, 0, np.zeros(n), np.zeros(n),
                         over)[5][:ns]
    i0 = int(np.argmin(dq))
    qs = np.abs(dq) + 1.0
    qs[i0] = -0.5 * dq[i0]
    got = jit.newton_step(J0.copy(order="F"), res, rhs, grid, ns, qsc, R, w, x, S, qs, cs,
                          3e-7, 0, np.zeros(n), np.zeros(n), over)
    assert got[0] == 1 and np.flatnonzero(got[6]).tolist() == [i0], "one slice leaves"
    # Cramer's rule on a K that is not finite: the 2 x 2 system handed back
    qs = qsc * (0.5 + rng.random(ns))
    bad = grid.copy()
    bad[0, 0] = np.nan
    got = jit.newton_step(J0.copy(order="F"), res, rhs, bad, ns, qsc, R, w, x, S, qs, cs,
                          3e-7, 3, np.zeros(n), np.zeros(n), over)
    want = _step_by_helpers(jit, J0.copy(order="F"), res, rhs, bad, ns, qsc, R, w, x, S,
                            qs, cs, 3e-7, 3, np.zeros(n), np.zeros(n), over)
    assert got[0] == want[0] == 2 and tuple(got[4][2:]) == tuple(want[4]), "status 2"
    # a singular Jacobian: numpy's solve refuses it; J and B come back scaled for the
    # caller's numpy solve, which raises as the numpy engine's would
    Js = np.zeros((2 * ns, 2 * ns), order="F")
    got = jit.newton_step(Js, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, 3e-7, 1,
                          np.zeros(n), np.zeros(n), over)
    assert got[0] is None
    assert np.array_equal(got[1], sl.scaled_system(np.zeros_like(Js), res, rhs, ns, qsc, R))


@needs_c
def test_c_engine_solves_in_threads():
    """The C loops run without the GIL, with their scratch memory per call: rollers
    solved by four threads at once (one roller per solve, as ProfiledRoller asks) give
    the same bits as the same solves one after another."""
    from concurrent.futures import ThreadPoolExecutor

    cases = [(F, tilt) for F in (1000.0, 3000.0, 6000.0) for tilt in (1e-3, "free")]

    def solve(case):
        return ProfiledRoller(5e-3, 14e-3, 115.385e9, "iso16281", engine="c").at_force(
            case[0], tilt=case[1])

    serial = [solve(c) for c in cases]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(solve, cases * 4))
    for a, b in zip(serial * 4, threaded):
        assert a.depth == b.depth and np.array_equal(a.q, b.q), "a threaded solve differs"


@needs_c
def test_the_c_extension_checks_its_arrays():
    """The C extension reads its arrays through the buffer protocol without numpy's
    help, so it checks them itself: an array of the wrong length, of the wrong type
    (int64 for float64), not contiguous, or a slice index outside the grid raises a
    ValueError naming the array, instead of reading or writing out of bounds."""
    from linecontact import _ckernels
    from linecontact.roller import _layout

    e = _equations(60, 0.0, 0, "c")
    S = np.arange(10, 20)
    b = np.full(10, 1e-4)
    tn, tf, lr, ltn, ltf, Gt = _layout.transposed(
        e._tnear, e._tfar, e._logratio, sl._far_geometry(*e._geometry))

    def call(S=S, b=b, A=None, dg=e.dg):
        A = np.empty((len(S), 60)) if A is None else A
        return _ckernels.kernels(S, np.arange(60), b, e.span, dg, tn, tf, lr, ltn, ltf,
                                 Gt, sl._FAR_COEF, True, A, None, None, None)

    assert call() is True
    for kwargs, name in ((dict(b=b[:-1]), "b"), (dict(A=np.empty((10, 59))), "A"),
                         (dict(S=np.r_[S[:-1], 60]), r"S\[9\] = 60"),
                         (dict(S=S.astype(float)), "S"), (dict(b=b.astype(np.int64)), "b"),
                         (dict(dg=np.r_[e.dg, e.dg][::2]), "dg"),
                         (dict(A=np.empty((60, 10)).T), "A")):
        with pytest.raises(ValueError, match=name):
            call(**kwargs)


@needs_c
def test_the_c_extension_refuses_a_negative_slice_count():
    """The Newton step's C functions take the loaded-slice count ns as a number and
    size their arrays by it (z: 2 ns x 3, qs: ns, ...); a length below zero means "any
    length" to the extension's checks, so a negative ns passed every check and the
    call returned a made-up answer (step_out: 0 slices leaving; bordered_sums: zero
    sums) instead of refusing it. Each now raises a ValueError naming ns."""
    from linecontact import _ckernels

    z, qs, dz, out = np.zeros(6), np.ones(1), np.zeros(2), np.zeros(1, dtype=bool)
    w, x, S = np.ones(3), np.ones(3), np.zeros(1, dtype=np.int64)
    calls = {
        "step_out": lambda ns: _ckernels.step_out(z, 0.0, 0.0, ns, qs, dz, out),
        "bordered_sums": lambda ns: _ckernels.bordered_sums(z, ns, 1.0, 1.0, w, x, S,
                                                            qs, np.zeros(6)),
        "newton_after": lambda ns: _ckernels.newton_after(
            z, np.zeros(4), ns, 1.0, 1.0, w, x, S, qs, qs, 1.0, 1, np.ones(3),
            np.ones(3), np.ones(3), np.zeros(4), np.zeros(4), dz, out,
            np.zeros(1, dtype=bool), np.zeros(4)),
    }
    for name, call in calls.items():
        call(1)                                  # (the arrays fit ns = 1)
        for ns in (-1, -2**62):
            with pytest.raises(ValueError, match="ns"):
                call(ns)
                pytest.fail(f"{name} accepted ns = {ns}")


@needs_c
@pytest.mark.parametrize("mode", [1, 2])
def test_c_newton_step_divides_as_numpy_by_a_zero_stiffness(mode):
    """The step of a force row (mode 1) or a moment row (mode 2) is its residual over
    K[0, 0] or K[1, 1]; where that entry is exactly zero the numpy lines divide numpy
    floats (IEEE: +-inf, NaN for 0/0) and go on. The fused C step must hand back what
    the helpers give (the same step, dz, mask, update; NaN compared as NaN), IEEE
    division included, not stop."""
    jit = sl.c_engine()

    rng, n, ns, R, qsc, S, w, x, J0 = _random_step_system(11)
    res, rhs = rng.normal(size=2 * ns), rng.normal(size=(2 * ns, 2))
    over = 1e-6 * (0.2 + rng.random(n))
    cs = 1.0 / (4 * R) * (0.5 + rng.random(ns))
    qs = qsc * (0.5 + rng.random(ns))
    K = jit.newton_step(J0.copy(order="F"), res, rhs, np.zeros((2, 2)), ns, qsc, R, w,
                        x, S, qs, cs, 3e-7, mode, np.zeros(n), np.zeros(n), over)[3]
    grid = np.zeros((2, 2))
    grid[mode - 1, mode - 1] = -K[mode - 1, mode - 1]      # K's entry exactly 0
    q1, c1, q2, c2 = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    got = jit.newton_step(J0.copy(order="F"), res, rhs, grid, ns, qsc, R, w, x, S, qs,
                          cs, 3e-7, mode, q1, c1, over)
    with np.errstate(divide="ignore", invalid="ignore"):
        want = _step_by_helpers(jit, J0.copy(order="F"), res, rhs, grid, ns, qsc, R, w,
                                x, S, qs, cs, 3e-7, mode, q2, c2, over)
    assert got[3][mode - 1, mode - 1] == 0.0
    assert got[0] == want[0]
    assert np.isinf(got[4][mode - 1]) and tuple(got[4][:2]) == tuple(want[4])
    assert np.array_equal(got[5], want[5], equal_nan=True), "dz"
    assert np.array_equal(got[6], want[6]), "the mask of slices leaving"
    if got[0] == 0:
        assert np.array_equal(q1, q2, equal_nan=True) and np.array_equal(c1, c2, equal_nan=True)


# -- the choice of engine (linecontact/_engine.py) --------------------------------------

def _without_c(monkeypatch, why="not built (blocked by the test)"):
    """As in a process where the extension does not run (not built, or stale: `why`)."""
    monkeypatch.setattr(_engine, "_LOADED", [(None, why)])
    monkeypatch.setattr(sl, "_C_ENGINE", [None])


def _roller(engine):
    return ProfiledRoller(5e-3, 14e-3, 1e11, "circular:Rc=0.5", n_slices=20, engine=engine)


def test_auto_is_c_where_the_extension_runs_else_numpy_whatever_ran_before(monkeypatch):
    """engine='auto' resolves to 'c' exactly where the extension runs here, else to
    'numpy', whatever the process solved before (nothing is counted): a solve repeated
    after a sweep of 30 gives the same bits. Without the extension 'auto' runs the
    numpy code: the same bits as engine='numpy'."""
    want = "c" if sl.c_engine() is not None else "numpy"
    assert _engine.resolve_engine("auto") == want
    first = _roller("auto").at_force(500.0, tilt=1e-3)
    _roller("auto").at_force(np.linspace(400.0, 8000.0, 30), tilt=1e-3)
    again = _roller("auto").at_force(500.0, tilt=1e-3)
    assert _engine.resolve_engine("auto") == want
    assert first.depth == again.depth and np.array_equal(first.q, again.q)
    _without_c(monkeypatch)
    assert _engine.resolve_engine("auto") == "numpy"
    a, b = (_roller(e).at_force(500.0, tilt=1e-3) for e in ("auto", "numpy"))
    assert a.depth == b.depth and np.array_equal(a.q, b.q)


def test_an_unknown_engine_or_c_where_it_does_not_run_is_refused_in_one_line(monkeypatch):
    """An unknown engine (a typo; 'numba', which is gone) is an UnknownNameError
    naming the engines that run here; 'c' where the extension does not run is an
    OutOfRangeError naming 'auto' and 'numpy', why 'c' does not run (the loader's
    reason) and how to build it. One line each."""
    for bad in ("fortran", "numba", None):
        with pytest.raises(UnknownNameError, match="engine") as err:
            _roller(bad)
        valid = "'auto', 'numpy', 'c'" if sl.c_engine() is not None else "'auto', 'numpy';"
        assert f"valid: {valid}" in str(err.value), str(err.value)
    why = "the extension linecontact._ckernels was built from other versions (test)"
    _without_c(monkeypatch, why)
    with pytest.raises(UnknownNameError, match="engine") as err:
        _roller("numba")
    assert str(err.value).endswith(f"valid: 'auto', 'numpy'; 'c' does not run here: {why}")
    with pytest.raises(OutOfRangeError, match="engine = 'c'") as err:
        _roller("c")
    msg = str(err.value)
    assert f"'auto' or 'numpy' ('c' does not run here: {why})" in msg, msg
    assert "C compiler" in msg and "\n" not in msg, msg


def test_an_engine_set_later_or_unpickled_where_c_does_not_run_is_refused(monkeypatch):
    """`engine` set on a built roller is checked at once, as at construction (the
    roller is built anew; a refused value leaves it as it was). A roller pickled with
    engine='c' to a process where the extension does not run (a Dask worker:
    unpickling sets the attribute without a check) is refused by name when it solves,
    never solved with numpy instead."""
    r = _roller("numpy")
    with pytest.raises(UnknownNameError, match="fortran"):
        r.engine = "fortran"
    assert r.engine == "numpy"
    _without_c(monkeypatch)
    with pytest.raises(OutOfRangeError, match="engine = 'c'"):
        r.engine = "c"
    assert r.engine == "numpy"
    w = pickle.loads(pickle.dumps(r))
    w.__dict__["engine"] = "c"                 # as unpickled from a process with C
    with pytest.raises(OutOfRangeError, match="engine = 'c'"):
        w.at_force(500.0)


@needs_c
def test_auto_takes_the_c_engine_from_the_first_solve():
    """Where the extension is built, one solve with the default engine in a fresh
    interpreter runs on it (the module _cengine imported) without importing scipy: a
    single solve takes the C loops at no start-up cost."""
    code = ("import sys\n"
            "from linecontact.roller import ProfiledRoller\n"
            "from linecontact._engine import resolve_engine\n"
            "r = ProfiledRoller(5e-3, 14e-3, 1e11, 'iso16281')\n"
            "r.at_force(4000.0, tilt=1e-3)\n"
            "print(resolve_engine(r.engine), 'linecontact.roller._cengine' in sys.modules,"
            " 'scipy' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["c", "True", "False"], f"engine, C engine / scipy imported: {out}"
