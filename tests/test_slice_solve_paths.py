"""The fast paths of the coupled-slice roller solver (linecontact.roller.slices) give the
answers of the plain ones: the far-field series of the strip kernel against the spline
table it replaces, and a solve through the fast kernel, the bordered cold start and the
active-set rules against the same solve through the table or reached another way.

Tolerances: the spline table is accurate to 1e-10 of each function's scale
(linecontact.roller.kernel), the series to 4e-15 where it is used (near-edge tau >= 3,
14 terms), so kernels agree to 1e-10 of their largest entry; the Newton solves stop at
1e-11 of the largest slice load, so solutions reached by different paths agree to
1e-9 relative (the figure the speed-up promises).
"""
import numpy as np
import pytest

from linecontact.roller import ProfiledRoller
from linecontact.roller import slices as sl

E = 115.385e9
D, L = 10e-3, 14e-3
ISO = "iso16281:D=10mm"


def _equations(n, grading, force=4200.0, tilt=2e-3):
    # refine_ends=False: the solution on r's own grid (60 uniform slices leave this
    # peak unresolved, and the refined solve would use another grid)
    r = ProfiledRoller(D / 2, L, E, ISO, n_slices=n, grading=grading, refine_ends=False)
    s = r.at_force(force, tilt=tilt)
    eq = r._grid(s.depth, s.tilt)
    S = np.flatnonzero(s.q > 0)
    return eq, S, s.half_width[S]


@pytest.mark.parametrize("n, grading", [(50, 0.8), (100, 0.8), (60, 0.0)])
def test_far_field_kernels_equal_the_table(n, grading):
    """kernels() (series in (b/t)^2 where the near-edge tau >= 3, the table elsewhere)
    equals _kernels_table() (every pair from the spline table) to 1e-10 of the largest
    entry of each of A, D, EA, ED, for every target set the solver uses (all slices,
    the loaded ones, the unloaded ones) and strip widths from a tenth to five times the
    solution's (from nearly every pair in the far field to most pairs in the near
    band)."""
    eq, S, b = _equations(n, grading)
    rest = np.setdiff1d(np.arange(n), S)
    for scale in (0.1, 1.0, 5.0):
        for T in (np.arange(n), S, rest):
            fast = eq.kernels(S, b * scale, targets=T)
            ref = eq._kernels_table(S, b * scale, T)
            for name, x, y in zip(("A", "D", "EA", "ED"), fast, ref):
                err = np.max(np.abs(x - y)) / np.max(np.abs(y))
                assert err < 1e-10, (name, scale, len(T), err)
            a_only = eq.kernels(S, b * scale, targets=T, a_only=True)[0]
            # A alone: the same sums (the matrix product may round differently)
            assert np.max(np.abs(a_only - fast[0])) < 1e-14 * np.max(np.abs(fast[0]))


def test_non_contiguous_sources():
    """A loaded set with a hole (the contact split in two) takes the fancy-indexed path
    of the far-field product: the same kernels as the table (1e-10)."""
    eq, S, b = _equations(50, 0.8)
    keep = np.ones(len(S), bool)
    keep[len(S) // 2: len(S) // 2 + 3] = False
    S2, b2 = S[keep], b[keep]
    fast = eq.kernels(S2, b2, targets=np.arange(50))
    ref = eq._kernels_table(S2, b2, np.arange(50))
    for x, y in zip(fast, ref):
        assert np.max(np.abs(x - y)) / np.max(np.abs(y)) < 1e-10


@pytest.mark.parametrize("tilt", [2e-3, "free"])
def test_solution_through_the_table_is_the_same(monkeypatch, tilt):
    """The whole force-controlled solve with every kernel pair read from the spline
    table (the far field switched off: _N_FAR = 0) gives the same depth, tilt, moment,
    peak pressure and stiffness matrix within 1e-9 relative (moment: of F L/2)."""
    F = 4200.0
    fast = ProfiledRoller(D / 2, L, E, ISO, n_slices=50).at_force(F, tilt=tilt)
    monkeypatch.setattr(sl, "_N_FAR", 0)
    ref = ProfiledRoller(D / 2, L, E, ISO, n_slices=50).at_force(F, tilt=tilt)
    assert fast.depth == pytest.approx(ref.depth, rel=1e-9)
    assert fast.tilt == pytest.approx(ref.tilt, rel=1e-9, abs=1e-12)
    assert abs(fast.moment - ref.moment) < 1e-9 * F * L / 2
    assert fast.p_max == pytest.approx(ref.p_max, rel=1e-9)
    K, Kr = fast.stiffness_matrix, ref.stiffness_matrix
    scale = np.sqrt(np.outer(np.diag(np.abs(Kr)), np.diag(np.abs(Kr))))
    assert np.max(np.abs(K - Kr) / scale) < 1e-9


@pytest.mark.parametrize("n", [50, 100])
def test_cold_force_start_reaches_the_depth_solution(n):
    """The force-controlled solve (bordered cold start, Newton on loads and depth) and
    the depth-controlled solve at the depth it found (the frozen-width start at that
    depth, the active-set loop) are two paths to one solution: the same force (1e-9),
    slice loads (1e-9 of the largest) and loaded set."""
    F, tilt = 4200.0, 2e-3
    s = ProfiledRoller(D / 2, L, E, ISO, n_slices=n).at_force(F, tilt=tilt)
    t = ProfiledRoller(D / 2, L, E, ISO, n_slices=n).at_depth(s.depth, tilt)
    assert t.force == pytest.approx(F, rel=1e-9)
    assert np.max(np.abs(t.q - s.q)) < 1e-9 * np.max(s.q)
    assert np.array_equal(t.q > 0, s.q > 0)


class _ClearedByAnotherThread(dict):
    """A cache that another thread empties right after each store (its own new key
    pushing the cache over its size limit)."""

    def __setitem__(self, key, value):
        super().__setitem__(key, value)
        self.clear()


def test_geometry_caches_survive_a_concurrent_clear(monkeypatch):
    """The unit-geometry caches are module-wide and emptied when full: a call must
    return what it built even if another thread cleared the cache between the store and
    the read (no KeyError), and the same arrays as an undisturbed call (exactly)."""
    ref_geometry = sl._unit_geometry(37, 0.8, 1)
    ref_far = sl._far_geometry(37, 0.8, 1)
    monkeypatch.setattr(sl, "_GEOMETRY", _ClearedByAnotherThread())
    monkeypatch.setattr(sl, "_FAR", _ClearedByAnotherThread())
    for a, b in zip(sl._unit_geometry(37, 0.8, 1), ref_geometry):
        assert np.array_equal(a, b)
    assert np.array_equal(sl._far_geometry(37, 0.8, 1), ref_far)


def test_the_geometry_caches_are_bounded_in_bytes(monkeypatch):
    """The module-wide caches of slice geometry (n x n arrays, five of them per
    geometry with the C engine's layout) were bounded only in count: sixteen geometries at
    n = 4000 would hold gigabytes. With the bound set to 1 MB, after building four
    geometries of 0.9-2 MB each the cache holds at most the bound plus the newest."""
    from linecontact._numerics import cache_nbytes
    monkeypatch.setattr(sl, "CACHE_BYTES", 2**20)
    monkeypatch.setattr(sl, "_GEOMETRY", {})
    newest = 0
    for n in (200, 230, 260, 290):
        got = sl._unit_geometry(n, 0.8, 0)
        newest = sum(a.nbytes for a in got)
    assert cache_nbytes(sl._GEOMETRY) <= 2**20 + newest


def test_unloading_slices_equals_a_fresh_linearisation():
    """Slices leaving within a Newton step (slices._unloaded): the linear system with
    their loads set to zero through their Jacobian columns equals the one a fresh
    linearisation at q = 0 gives (a source's share of the gap and curvature rows is
    homogeneous of degree one in its (q, c)): the Jacobian to 1e-12 and the residual to
    1e-10 of their largest entries (rounding of the spline table's sums), at a state
    off the solution (loads and c perturbed by up to 5 %)."""
    r = ProfiledRoller(D / 2, L, E, ISO, refine_ends=False)
    sol = r.at_force(4200.0, tilt=2e-3)
    eq = r._grid(sol.depth, sol.tilt)
    eq._over = sol.depth + sol.tilt * eq.x - eq.P
    slope = eq.slope_at_slices()
    rng = np.random.default_rng(1)
    S = np.flatnonzero(sol.q > 0)
    q = sol.q / (np.pi * E) * (1 + 0.05 * rng.uniform(-1, 1, eq.n))
    c = np.full(eq.n, 1.0 / (4 * eq.R))
    c[S] = q[S] / sol.half_width[S] ** 2 * (1 + 0.05 * rng.uniform(-1, 1, len(S)))
    ns, R = len(S), eq.R
    qsc = q[S].max()

    def scaled(S):
        # the scaled system of SliceEquations.bordered (unknowns q/qsc and c R)
        res, J = eq.linearised(S, q, c, sol.tilt, slope, np.arange(eq.n))[:2]
        m = len(S)
        J[:m, m:] *= 1.0 / (qsc * R)
        J[m:, :m] *= qsc * R
        B = np.concatenate([-res[:m] / qsc, -res[m:] * R])[:, None]
        return J, B

    J, B = scaled(S)
    out = np.zeros(ns, bool)
    out[[0, 1, -1]] = True
    Ju, Bu = sl._unloaded(J, B, out, q[S] / qsc, c[S] * R)
    q[S[out]] = 0.0
    Jf, Bf = scaled(S[~out])
    assert np.max(np.abs(Ju - Jf)) < 1e-12 * np.max(np.abs(Jf))
    assert np.max(np.abs(Bu - Bf)) < 1e-10 * np.max(np.abs(Bf))


@pytest.mark.parametrize("profile, tilt", [("iso16281", 0.0), ("lundberg", 5e-4)])
def test_bordered_newton_converges_alone_at_refined_end_zones(monkeypatch, profile, tilt):
    """At 2000 N/mm the contact of a logarithmic profile ends in its refined end zone,
    where an end slice can sit between joining and leaving (table cases 28 and 45 of
    tables/roller_accuracy.csv; an unloading of leaving slices through their q columns
    alone cycled there): the bordered Newton settles the active set on its own, every
    refinement level included, the nested fallback never called."""
    from tools.studies.roller_study import make_profile

    def no_fallback(*args, **kwargs):
        raise AssertionError("the nested iteration was called")
    monkeypatch.setattr(ProfiledRoller, "_depth_at_force", no_fallback)
    r = ProfiledRoller(D / 2, L, E, make_profile(profile, L, D / 2, E))
    s = r.at_force(28000.0, tilt=tilt)
    assert s.force == pytest.approx(28000.0, rel=1e-10)
