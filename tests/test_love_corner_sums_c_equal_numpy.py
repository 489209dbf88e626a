"""The C corner sums of the stresses' 3D correction (linecontact/_cstresses.c, in the
extension linecontact._ckernels) against the numpy reference
(linecontact.stresses.love._love_weighted / _love_corner), and the stresses computed with
each: the same sums to rounding, the same worst values.

Skipped where the optional extension does not run here (no C compiler at install; a
stale build); tests/test_extensions.py checks that its sources compile where a C
compiler is present."""
from __future__ import annotations

import numpy as np
import pytest

from linecontact import _engine, stresses
from linecontact.roller import ProfiledRoller
from linecontact.stresses import love as st
from linecontact.stresses import search

needs_c = pytest.mark.skipif(
    st._cstresses is None,
    reason=f"the C extension does not run here ({_engine.unavailable()})")

ESTAR = 115.385e9


def _c(X, cy, w, py, pz, only=False):
    out = np.full((10, np.size(py)), np.nan)
    ok = st._cstresses.love_sums(np.ascontiguousarray(X, dtype=float),
                                 np.ascontiguousarray(cy, dtype=float),
                                 np.ascontiguousarray(w, dtype=float),
                                 np.ascontiguousarray(py, dtype=float),
                                 np.ascontiguousarray(pz, dtype=float), only, out)
    return out if ok else None


def _numpy(X, cy, w, py, pz, only=None):
    return st._love_corner(np.asarray(X, dtype=float)[None, :],
                           np.subtract.outer(py, cy), np.asarray(pz, dtype=float)[:, None],
                           np.asarray(w, dtype=float), only)


def _rel(a, b):
    """Largest difference per function over that function's largest magnitude."""
    scale = np.maximum(np.abs(b).max(axis=1, keepdims=True), 1e-300)
    return (np.abs(a - b) / scale).max()


@needs_c
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_c_corner_sums_equal_numpy(seed):
    """Random corners (a few hundred, offsets ~b and a few far ones at 1e6 L) and
    points (depths 0.01 b to 10 b): each of the ten sums agrees with numpy's to 1e-13
    of its largest value (both round each term to an ulp or two and sum several
    hundred terms in different orders: ~1e-15 measured); with `only`, d2 psi1/dydz
    alone and the other nine exactly 0."""
    rng = np.random.default_rng(seed)
    b = 1e-4
    nc = 301 + seed                      # not a multiple of the 8 lanes: the tail too
    X = rng.normal(size=nc) * 10 * b
    X[:4] = [-3e4, 3e4, -2e4, 2e4]       # the ends' extensions (1e6 L)
    cy = rng.normal(size=nc) * b
    w = rng.normal(size=nc)
    py = rng.normal(size=37) * b
    pz = b * 10 ** rng.uniform(-2, 1, 37)
    got, ref = _c(X, cy, w, py, pz), _numpy(X, cy, w, py, pz)
    assert _rel(got, ref) < 1e-13, f"C sums off numpy's by {_rel(got, ref):.2g}"
    got6 = _c(X, cy, w, py, pz, only=True)
    ref6 = _numpy(X, cy, w, py, pz, st._PYZ)
    assert _rel(got6[6:7], ref6[6:7]) < 1e-13
    assert not np.delete(got6, 6, axis=0).any(), "only: the other sums not 0"


@needs_c
def test_c_arctan_and_log_over_their_whole_range():
    """One corner with unit weight: out[9] = log(rho + z) and out[0] =
    -arctan(XY/(z rho)). X = Y = 0 (rho = z): log(2z) for z from 1e-59 to 1e59
    within 2 ulp of numpy's; X = Y = 1: the arctangent of arguments from ~1e59 down
    to ~1e-59 (both signs) within 2 ulp of numpy's arctan of the same argument,
    and exactly 0 where X = Y = 0 (d psi1/dz and d2 H1/dx2 of a corner below the
    point); all ten sums within 1e-13 of numpy's at the depths' extremes, a corner
    above the point and one offset by 1 m."""
    z = 10.0 ** np.linspace(-59, 59, 4001)
    zero = np.zeros(1)
    got = _c(zero, zero, np.ones(1), np.zeros(z.size), z)
    ref = np.log(z + z)
    assert np.all(np.abs(got[9] - ref) <= 2 * np.spacing(np.abs(ref)))
    assert not got[0].any() and not got[7].any() and not got[8].any()
    for sgn in (1.0, -1.0):
        got = _c(np.ones(1), zero, np.ones(1), np.full(z.size, sgn), z)
        rho = np.sqrt(1.0 + (1.0 + z * z))
        ref = -np.arctan(sgn / (z * rho))
        assert np.all(np.abs(got[0] - ref) <= 2 * np.spacing(np.abs(ref))), \
            "arctan off numpy's by more than 2 ulp"
    X, cy, w = np.array([0.0, 1.0]), np.array([0.0, -1.0]), np.array([1.0, -0.5])
    for zz in (1.1e-60, 1e-30, 1e-9, 1e30, 0.9e60):
        py, pz = np.array([0.0, 1e-9]), np.full(2, zz)
        assert _rel(_c(X, cy, w, py, pz), _numpy(X, cy, w, py, pz)) < 1e-13, zz


@needs_c
def test_c_corner_sums_refuse_what_they_do_not_cover():
    """Non-finite inputs, depths outside (1e-60, 1e60) m and offsets of 1e60 m return
    False (the caller takes numpy); a buffer of the wrong length, dtype or layout is a ValueError
    naming it, before anything is read."""
    one = np.ones(3)
    assert _c(one, one, one, np.ones(2), np.array([1.0, np.nan])) is None
    assert _c(one, one, one, np.ones(2), np.array([1.0, 1e-61])) is None
    assert _c(one, one, one, np.ones(2), np.array([1.0, 1e61])) is None
    assert _c(one, one, one, np.array([1.0, 1e60]), np.ones(2)) is None
    assert _c(one, one, one, np.ones(2), np.array([1.0, 0.0])) is None
    assert _c(np.array([1.0, np.inf, 1.0]), one, one, np.ones(2), np.ones(2)) is None
    f = st._cstresses.love_sums
    with pytest.raises(ValueError, match="cy has 2 items, 3 expected"):
        f(one, np.ones(2), one, one, one, False, np.empty(30))
    with pytest.raises(ValueError, match="out has 20 items, 30 expected"):
        f(one, one, one, one, one, False, np.empty(20))
    with pytest.raises(ValueError, match="w must hold float64"):
        f(one, one, np.ones(3, dtype=np.float32), one, one, False, np.empty(30))
    with pytest.raises(ValueError, match="X must be a C-contiguous"):
        f(np.ones(6)[::2], one, one, one, one, False, np.empty(30))
    with pytest.raises(ValueError, match="out must be a C-contiguous writable"):
        ro = np.empty(30)
        ro.flags.writeable = False
        f(one, one, one, one, one, False, ro)


def _worst(sol, model, corners, mu=0.0, nu=0.3):
    saved = st._CORNERS[0]
    st._CORNERS[0] = corners
    try:
        return stresses.roller_stresses(sol, mu, nu, roller=model).worst
    finally:
        st._CORNERS[0] = saved


@needs_c
@pytest.mark.parametrize("profile, force, tilt, mu, nu", [
    ("circular:Rc=0.5", 4200.0, 0.0, 0.0, 0.3),          # off the ends
    ("lundberg:design_force=11200", 4200.0, 2e-3, 0.0, 0.3),  # off the ends, tilted
    ("johns-gohar", 11.2e3, 0.0, 0.0, 0.3),              # edge loaded at both ends
    ("lundberg:design_force=11200", 11.2e3, 2e-3, 0.0, 0.3),  # the contact at an end
    ("lundberg:design_force=11200", 11.2e3, 2e-3, 0.4, 0.4),  # with friction
])
def test_c_and_numpy_stresses_give_the_same_worst(profile, force, tilt, mu, nu):
    """roller_stresses with the C corner sums and with numpy's: every measure's worst
    value within 1e-14 relative (the search takes the same steps: rounding-level
    differences of the field; largest 1.8e-15 over 300 random rollers with friction,
    tools/benchmarks/results/stresses_c_agreement.txt), at the same point, or at the
    mirror slice of an untilted roller (a tie)."""
    if profile == "johns-gohar":
        from tools.studies.roller_study import make_profile
        profile = make_profile("johns-gohar", 14e-3)
    model = ProfiledRoller(5e-3, 14e-3, ESTAR, profile)
    sol = model.at_force(force, tilt=tilt)
    c, n = _worst(sol, model, "c", mu, nu), _worst(sol, model, "numpy", mu, nu)
    for name in stresses.MEASURES:
        u, v = c[name], n[name]
        assert abs(u["value"] - v["value"]) <= 1e-14 * abs(v["value"]), name
        same = u["slice"] == v["slice"] or (tilt == 0.0
                                            and u["slice"] + v["slice"] == sol.x.size - 1)
        assert same, f"{name}: slice {u['slice']} (C) against {v['slice']} (numpy)"


@needs_c
def test_c_corners_are_numpy_s():
    """The corners of each loaded slice's pressure difference (_corners_many) built by
    C and by numpy: the same corners in the same order and the same weights, bit for
    bit (the same operations in the same order; the merge of coincident corners sums
    in lexsort's stable order), off the ends (the far cells and the ends' extensions)
    and with the near window at an end (its extension rows)."""
    from tools.studies.roller_study import make_profile
    saved = st._CORNERS[0]
    try:
        for profile, force, tilt in (("circular:Rc=0.5", 4200.0, 2e-3),
                                     (make_profile("johns-gohar", 14e-3), 11.2e3, 0.0)):
            sol = ProfiledRoller(5e-3, 14e-3, ESTAR, profile).at_force(force, tilt=tilt)
            x, b, q = (np.asarray(v) for v in (sol.x, sol.half_width, sol.q))
            loaded = (b > 0) & (q > 0)          # as roller_stresses
            p0 = np.where(loaded, 2 * q / (np.pi * np.where(loaded, b, 1.0)), 0.0)
            b = np.where(loaded, b, 0.0)
            ks = [int(k) for k in np.flatnonzero(loaded)]
            st._CORNERS[0] = "c"
            got = search._corners_many(x, b, p0, ks)
            st._CORNERS[0] = "numpy"
            ref = search._corners_many(x, b, p0, ks)
            for k, (g, r) in enumerate(zip(got, ref)):
                for a, e, what in zip(g, r, ("x", "y", "weights")):
                    assert np.array_equal(a, e), f"slice {k}: {what} differ"
    finally:
        st._CORNERS[0] = saved


@needs_c
def test_c_corners_refuse_bad_buffers():
    """corners(): a window outside the slices, or buffers too short for every corner,
    are ValueErrors before anything is read or written; a non-finite input returns -1
    (numpy builds those corners)."""
    n, ny = 5, 25
    xe, b = np.linspace(0, 1, n + 1), np.ones(n)
    ye, means = np.linspace(-1, 1, ny), np.ones(((n - 1) + 2) * (ny - 1))
    room = (n + 3) * ny + 4 * (n + 2)
    f = st._cstresses.corners
    with pytest.raises(ValueError, match="out of range"):
        f(xe, 1.0, b, b, b, 3, 1, 2, ye, means, np.empty(room), np.empty(room),
          np.empty(room))
    with pytest.raises(ValueError, match="w has"):
        f(xe, 1.0, b, b, b, 2, 0, 4, ye, np.ones(6 * (ny - 1)), np.empty(room),
          np.empty(room), np.empty(room - 1))
    with pytest.raises(ValueError, match="means has"):
        f(xe, 1.0, b, b, b, 2, 0, 4, ye, np.ones(5 * (ny - 1)), np.empty(room),
          np.empty(room), np.empty(room))
    bad = b.copy()
    bad[1] = np.nan
    assert f(xe, 1.0, bad, b, b, 2, 0, 4, ye, np.ones(6 * (ny - 1)), np.empty(room),
             np.empty(room), np.empty(room)) == -1


@needs_c
def test_where_c_declines_numpy_takes_over(monkeypatch):
    """Where the extension declines (love_sums False, corners -1: inputs it does not
    cover) the numpy path computes those sums and corners: roller_stresses then gives
    numpy's worst values exactly (the same code ran)."""
    class Declines:
        @staticmethod
        def love_sums(*args):
            return False

        @staticmethod
        def corners(*args):
            return -1

    model = ProfiledRoller(5e-3, 14e-3, ESTAR, "circular:Rc=0.5")
    sol = model.at_force(4200.0, tilt=2e-3)
    ref = _worst(sol, model, "numpy")
    monkeypatch.setattr(st, "_cstresses", Declines)
    got = _worst(sol, model, "c")
    for name in stresses.MEASURES:
        assert got[name] == ref[name], name


def test_the_corner_sums_cost_quoted_is_the_recorded_one():
    """docs/stresses.md and tools/benchmarks/README.md quote the C corner sums' time per
    corner and point against numpy's as ranges; every figure of the raw record
    (tools/benchmarks/bench_corner_sums.py -> results/corner_sums.txt, rows n = 16-48
    points) lies in those ranges once rounded to the ns, so the quoted figures trace to
    a rerunnable measurement."""
    import re
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    record = (root / "tools/benchmarks/results/corner_sums.txt").read_text()
    rows = [tuple(float(v) for v in m.groups()) for m in re.finditer(
        r"^\s*(\d+)\s+\d+\s+([\d.]+)\s+([\d.]+)\s+[\d.]+$", record, re.M)]
    rows = [r for r in rows if 16 <= r[0] <= 48]
    assert len(rows) == 3, record
    for doc in ("docs/stresses.md", "tools/benchmarks/README.md"):
        text = " ".join((root / doc).read_text().split())
        m = re.search(r"about (\d+)-(\d+) ns per corner and point against numpy's "
                      r"(\d+)-(\d+)", text, re.I)
        assert m, f"{doc}: no quoted cost per corner and point"
        c_lo, c_hi, n_lo, n_hi = map(int, m.groups())
        for _, c, n in rows:
            assert c_lo <= round(c) <= c_hi and n_lo <= round(n) <= n_hi, (
                f"{doc}: C {c_lo}-{c_hi} ns, numpy {n_lo}-{n_hi} quoted; recorded "
                f"C {c} ns, numpy {n} ns")
