"""The engines of the coupled-slice equations: the compiled kernels and linearisation
(linecontact/roller/_compiled.py, numba; linecontact/roller/_cengine.py over the C
extension _ckernels, the same loops in C) against the numpy reference
(SliceEquations.kernels, linearised), whole solves with every engine, and the choice of
engine (docs/profiled_rollers.md, "Engines").

Each agreement test runs for both compiled engines; one is skipped, with its reason,
where numba is not installed or the C extension is not built (pip install -e . builds
it where a C compiler is present; so does CI).

The compiled code evaluates the same series coefficients, the same spline table and the
same cached geometry with the same split into far field, near band and diagonal; it
differs only in the order of sums. So every entry agrees to a few units of rounding of
the matrix's largest entry: 1e-12 of it leaves three orders of margin and still catches
any term, pair or index taken wrongly (those are >= 1e-10 of the scale: the spline's
own error against the series).
"""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from linecontact import OutOfRangeError
from linecontact.errors import UnknownNameError
from linecontact.roller import ProfiledRoller
from linecontact.roller import slices as sl
from linecontact.roller.slices import SliceEquations

TOL = 1e-12
#: the compiled engines, each checked against the numpy reference
COMPILED = ["numba", "c"]


def _need(engine):
    """Skip unless `engine` can run here (numba installed; the C extension built)."""
    if engine == "numba":
        pytest.importorskip("numba")
    elif sl.c_engine() is None:
        pytest.skip("the C extension linecontact.roller._ckernels is not built here "
                    f"({sl._C_ENGINE[0]}): pip install -e . with a C compiler builds it")


def _module(engine):
    """The module of a compiled engine's kernels() and linearised()."""
    if engine == "numba":
        from linecontact.roller import _compiled
        return _compiled
    return sl.c_engine()


#: Python lines that make the C extension unimportable in a fresh interpreter (as
#: where it was not built): the engine 'auto' then keeps the numpy / numba policy
NO_C = "import sys; sys.modules['linecontact.roller._ckernels'] = None\n"


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


@pytest.mark.parametrize("engine", COMPILED)
@pytest.mark.parametrize("grid", GRIDS)
def test_compiled_kernels_equal_numpy(grid, engine):
    """A, D, EA, ED (and A alone) from the compiled loops equal the numpy kernels within
    1e-12 of each matrix's largest entry, for every loaded set and target set."""
    _need(engine)
    a, b = _equations(*grid, "numpy"), _equations(*grid, engine)
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


@pytest.mark.parametrize("engine", COMPILED)
@pytest.mark.parametrize("grid", GRIDS[:3])
def test_compiled_far_field_takes_every_term(grid, engine):
    """The compiled far field sums all 14 terms of the series over every target, as
    the numpy code does: the kernels agree within 1e-14 of each matrix's largest entry
    (rounding: 1.5e-15 observed). That is tight enough to see one term missing: the
    last (14th) term at the near band's edge, t/b = 3, is 4.6e-14 of ED's scale."""
    _need(engine)
    a, b = _equations(*grid, "numpy"), _equations(*grid, engine)
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


@pytest.mark.parametrize("engine", COMPILED)
@pytest.mark.parametrize("grid", GRIDS)
def test_compiled_linearised_equals_numpy(grid, engine):
    """Residual, Jacobian, grid columns, gaps and the 2x2 grid terms of linearised()
    from the compiled loops equal the numpy ones within 1e-12 of each one's largest
    entry (all slices or a subset as targets)."""
    _need(engine)
    a, b = _equations(*grid, "numpy"), _equations(*grid, engine)
    N = a.n
    rng = np.random.default_rng(2)
    slope = 4e-6 * a.x ** 3 / 6e-3 ** 4
    for S, q, c in _states(N, rng):
        for T in (np.arange(N), np.union1d(S, [0, N - 1])):
            la = a.linearised(S, q, c, 1e-3, slope, T)
            lb = b.linearised(S, q, c, 1e-3, slope, T)
            for name, x, y in zip("res J rhs gap grid".split(), la, lb):
                _close(x, y, f"{grid} {name} ns={len(S)} nt={len(T)}")


@pytest.mark.parametrize("engine", COMPILED)
def test_compiled_outside_the_spline_table(engine):
    """Beyond the spline table, t/b >= 1e4 (a slice about to leave, its strip
    nanometres wide: b = 1e-12 m here), the compiled code takes the series itself and
    agrees with the numpy code (which does the same); below it, t/b < 1e-4 (a strip
    far wider than the slices, b = 20 m), the call goes to the numpy code (series and
    quadrature) under either engine. Both: 1e-12 of each matrix's largest entry."""
    _need(engine)
    a, b = _equations(60, 0.0, 0, "numpy"), _equations(60, 0.0, 0, engine)
    S = np.arange(60)
    tiny = np.full(60, 1e-4)
    tiny[[0, 7, 59]] = 1e-12                 # w/2b ~ 1e8 on those diagonals
    got = _module(engine).kernels(S, S, tiny, b.span, b.dg, b._tnear, b._tfar, b._logratio,
                            sl._far_geometry(*b._geometry), sl._FAR_COEF, False)
    assert got is not None, "the compiled code fell back to numpy beyond the table"
    assert _module(engine).kernels(S, S, np.full(60, 20.0), b.span, b.dg, b._tnear,
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


@pytest.mark.parametrize("engine", COMPILED)
@pytest.mark.parametrize("case", CASES)
def test_whole_solves_agree_between_engines(case, engine):
    """A solve at a force with a compiled engine and with numpy: depth, tilt, moment,
    peak pressure and stiffness agree within 1e-10 (the Newton tolerance is 1e-11; the
    engines differ by rounding only, so both reach the same converged state)."""
    _need(engine)
    profile, force, tilt = case
    sols = [ProfiledRoller(5e-3, 14e-3, 115.385e9, profile, engine=e).at_force(
        force, tilt=tilt) for e in ("numpy", engine)]
    a, b = sols
    assert a.depth == pytest.approx(b.depth, rel=1e-10)
    assert a.p_max == pytest.approx(b.p_max, rel=1e-10)
    assert a.tilt == pytest.approx(b.tilt, rel=1e-10, abs=1e-10 * 1e-3)
    assert abs(a.moment - b.moment) <= 1e-10 * force * 14e-3
    np.testing.assert_allclose(a.stiffness_matrix, b.stiffness_matrix, rtol=1e-10,
                               atol=1e-10 * np.max(np.abs(a.stiffness_matrix)))


def test_engine_names_are_checked():
    """engine takes 'auto', 'numpy', 'numba' or 'c'; anything else is refused by
    name."""
    with pytest.raises(UnknownNameError, match="engine"):
        ProfiledRoller(5e-3, 14e-3, 1e11, engine="fortran")


def test_numpy_engine_without_numba():
    """Without numba and without the C extension (both imports blocked in a fresh
    interpreter) the numpy engine is used: 'auto' and 'numpy' solve, 'auto' stays
    numpy past the switching point, and 'numba' is refused with a message naming the
    parameter, the value and what to install."""
    code = (
        NO_C + "import sys; sys.modules['numba'] = None\n"
        "from linecontact.roller import ProfiledRoller, slices\n"
        "from linecontact import OutOfRangeError\n"
        "for e in ('auto', 'numpy'):\n"
        "    s = ProfiledRoller(5e-3, 14e-3, 1e11, 'circular:Rc=0.5', n_slices=20,"
        " engine=e).at_force(500.0)\n"
        "slices._NUMPY_STEPS[0] = slices.AUTO_SWITCH_STEPS\n"
        "assert slices.resolve_engine('auto') == 'numpy'\n"
        "try:\n"
        "    ProfiledRoller(5e-3, 14e-3, 1e11, engine='numba')\n"
        "except OutOfRangeError as err:\n"
        "    print(err)\n"
        "assert 'linecontact.roller._compiled' not in sys.modules\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert "engine" in out and "numba" in out and "pip install" in out, out


def test_auto_switches_after_the_numpy_steps(monkeypatch):
    """Where the C extension is not built (its import failed: monkeypatched here),
    engine='auto' resolves to numpy for a fresh process and to numba (where it is
    installed) once the process has taken AUTO_SWITCH_STEPS numpy steps."""
    monkeypatch.setattr(sl, "_C_ENGINE", ["No module named '_ckernels' (test)"])
    kept = sl._NUMPY_STEPS[0]
    try:
        sl._NUMPY_STEPS[0] = 0
        assert sl.resolve_engine("auto") == "numpy"
        sl._NUMPY_STEPS[0] = sl.AUTO_SWITCH_STEPS
        assert sl.resolve_engine("auto") == ("numba" if sl.numba_installed() else "numpy")
        assert sl.resolve_engine("numpy") == "numpy"
    finally:
        sl._NUMPY_STEPS[0] = kept


def test_auto_stays_numpy_where_numba_does_not_import():
    """engine='auto' with a numba that is installed but does not import (say, built for
    another numpy): past the switching point it warns once and keeps solving with
    numpy; engine='numba' is refused at construction, naming the parameter."""
    code = (
        NO_C + "import sys, warnings, importlib.util\n"
        "from linecontact.roller import ProfiledRoller, slices\n"
        "from linecontact import OutOfRangeError\n"
        "class Broken:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name == 'numba':\n"
        "            raise ImportError('numba built for another numpy')\n"
        "sys.modules.pop('numba', None)\n"
        "sys.meta_path.insert(0, Broken())\n"
        "slices._HAVE_NUMBA[:] = [True]\n"
        "slices._NUMPY_STEPS[0] = slices.AUTO_SWITCH_STEPS\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    s = ProfiledRoller(5e-3, 14e-3, 1e11, 'circular:Rc=0.5', n_slices=20)"
        ".at_force(500.0)\n"
        "print(sum('do not import' in str(x.message) for x in w))\n"
        "try:\n"
        "    ProfiledRoller(5e-3, 14e-3, 1e11, engine='numba')\n"
        "except OutOfRangeError as err:\n"
        "    print('refused:', err)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.splitlines()[0] == "1", out
    assert "refused: engine" in out and "does not import" in out, out


def test_a_single_solve_does_not_import_numba():
    """Cold start: one profiled-roller solve with the default engine ('auto') in a
    fresh interpreter never imports numba (its import and code loading cost about
    0.5 s, some 40 solves)."""
    code = ("import sys\n"
            "from linecontact.roller import ProfiledRoller\n"
            "ProfiledRoller(5e-3, 14e-3, 1e11, 'iso16281').at_force(4000.0, tilt=1e-3)\n"
            "print('numba' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "False"


def _twice(x):
    return 2.0 * x


def test_jit_falls_back_to_no_cache(monkeypatch):
    """Where numba finds no writable cache directory (every cache location refusing,
    as in a read-only install and home) the kernels' decorator compiles without a
    cache instead of failing, and warns (once per process)."""
    pytest.importorskip("numba")
    import numba.core.caching as caching

    from linecontact.roller import _compiled

    def refuse(self):
        raise OSError("read-only")

    monkeypatch.setattr(caching._CacheLocator, "ensure_cache_path", refuse)
    monkeypatch.setattr(_compiled, "_UNCACHED", [])
    with pytest.warns(RuntimeWarning, match="cannot be cached"):
        f = _compiled._jit(_twice)
    assert f(3.0) == 6.0
    assert _compiled._UNCACHED == ["_twice"]


@pytest.mark.slow
def test_compiled_engine_without_a_writable_cache():
    """Where numba finds no writable cache directory (a read-only install and home:
    simulated by making every cache location refuse), the compiled engine still
    works: it compiles in the process (about 5 s, hence slow), says so once with a
    RuntimeWarning, and solves as the numpy engine does (1e-10)."""
    pytest.importorskip("numba")
    code = (
        "import warnings\n"
        "import numba.core.caching as c\n"
        "def refuse(self):\n"
        "    raise OSError('read-only')\n"
        "c._CacheLocator.ensure_cache_path = refuse\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    from linecontact.roller import ProfiledRoller\n"
        "    a, b = (ProfiledRoller(5e-3, 14e-3, 1e11, 'circular:Rc=0.5', n_slices=20,"
        " engine=e).at_force(500.0, tilt=1e-3) for e in ('numpy', 'numba'))\n"
        "print(sum('cannot be cached' in str(x.message) for x in w))\n"
        "print(abs(a.depth / b.depth - 1) < 1e-10, abs(a.p_max / b.p_max - 1) < 1e-10)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out[0] == "1", f"{out[0]} warnings that the compiled code is not cached"
    assert out[1:] == ["True", "True"], out


def test_auto_switches_within_a_sweep():
    """A load sweep on one roller with engine='auto' (the switching point lowered to
    30 numpy steps, a few solves, in a fresh interpreter): the compiled kernels are
    imported part-way, and every row equals the numpy engine's sweep within 1e-10.
    (The C extension blocked: where it is built, 'auto' takes it from the start.)"""
    pytest.importorskip("numba")
    code = (
        NO_C + "import sys, numpy as np\n"
        "from linecontact.roller import ProfiledRoller, slices\n"
        "slices.AUTO_SWITCH_STEPS = 30\n"
        "F = np.linspace(500.0, 8000.0, 12)\n"
        "auto = ProfiledRoller(5e-3, 14e-3, 115.385e9, 'iso16281').at_force(F, tilt=1e-3)\n"
        "print('linecontact.roller._compiled' in sys.modules)\n"
        "ref = ProfiledRoller(5e-3, 14e-3, 115.385e9, 'iso16281', engine='numpy')"
        ".at_force(F, tilt=1e-3)\n"
        "print(max(max(abs(a.depth / r.depth - 1), abs(a.p_max / r.p_max - 1))"
        " for a, r in zip(auto, ref)))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out[0] == "True", "engine='auto' never switched to the compiled kernels"
    assert float(out[1]) <= 1e-10, out


def test_an_engine_set_after_construction_is_checked_at_once_and_at_the_solve():
    """`engine` set on a built roller is checked at once, as at construction (the
    roller is built anew): an unknown name is refused by name (it was silently solved
    with numpy), and 'numba' where numba does not import is an OutOfRangeError naming
    engine and what to install. A roller pickled with engine='numba' to a process
    without numba (a Dask worker; unpickling sets the attribute without a check) is
    refused the same way when it solves (it was a bare ImportError from deep in the
    solve). Likewise 'c' where the C extension is not built (a roller pickled with
    engine='c' to a process without it). Numba's and the extension's imports are
    blocked in a fresh interpreter."""
    code = (
        NO_C + "import sys, pickle; sys.modules['numba'] = None\n"
        "from linecontact.roller import ProfiledRoller\n"
        "from linecontact import OutOfRangeError\n"
        "from linecontact.errors import UnknownNameError\n"
        "r = ProfiledRoller(5e-3, 14e-3, 1e11, 'circular:Rc=0.5', n_slices=20,"
        " engine='numpy')\n"
        "for e, err in (('fortran', UnknownNameError), ('numba', OutOfRangeError),\n"
        "               ('c', OutOfRangeError)):\n"
        "    try:\n"
        "        r.engine = e\n"
        "        print('set', e)\n"
        "    except err as exc:\n"
        "        print('refused:', exc)\n"
        "    assert r.engine == 'numpy'\n"
        "    w = pickle.loads(pickle.dumps(r))\n"
        "    w.__dict__['engine'] = e          # as unpickled from a numba process\n"
        "    try:\n"
        "        w.at_force(500.0)\n"
        "        print('solved with', e)\n"
        "    except err as exc:\n"
        "        print('refused:', exc)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    assert len(out) == 6 and all(o.startswith("refused: engine") for o in out), out
    assert "fortran" in out[0] and "fortran" in out[1], out
    assert "pip install" in out[2] and "pip install" in out[3], out
    assert all("'c'" in o and "C compiler" in o for o in out[4:]), out


def test_each_test_starts_on_the_numpy_reference():
    """Which engine a test's default-engine solves use must not depend on the tests run
    before it in the process: the step counter of engine='auto' is zero at the start of
    every test (tests/conftest.py), so 'auto' is the C engine where its extension is
    built (from the first solve, whatever came before) and else the numpy reference
    until a test itself takes AUTO_SWITCH_STEPS steps. (Run after the rest of the
    suite, which takes far more than 1500 numpy steps, this failed.)"""
    assert sl._NUMPY_STEPS[0] == 0
    assert sl.resolve_engine("auto") == ("c" if sl.c_engine() is not None else "numpy")


def test_without_the_c_extension_auto_falls_back_and_c_is_refused(monkeypatch):
    """Where the C extension was not built (its import made to fail here, as without a
    C compiler at install), engine='auto' solves with numpy, and the same answer as
    engine='numpy' to the last bit (the same code); engine='c' is refused at
    construction by an OutOfRangeError naming engine, the value and how to build it."""
    import linecontact.roller as package
    for name in ("_ckernels", "_cengine"):        # (as in a process that never had them)
        monkeypatch.delattr(package, name, raising=False)
        monkeypatch.delitem(sys.modules, f"linecontact.roller.{name}", raising=False)
    monkeypatch.setitem(sys.modules, "linecontact.roller._ckernels", None)
    monkeypatch.setattr(sl, "_C_ENGINE", [])
    assert sl.c_engine() is None, "the blocked extension imported"
    assert sl.resolve_engine("auto") == "numpy"
    a, b = (ProfiledRoller(5e-3, 14e-3, 1e11, "circular:Rc=0.5", n_slices=20,
                           engine=e).at_force(500.0, tilt=1e-3) for e in ("auto", "numpy"))
    assert a.depth == b.depth and a.p_max == b.p_max
    with pytest.raises(OutOfRangeError, match="engine") as err:
        ProfiledRoller(5e-3, 14e-3, 1e11, engine="c")
    assert "'c'" in str(err.value) and "C compiler" in str(err.value), str(err.value)


def test_auto_takes_the_c_engine_from_the_first_solve():
    """Where the C extension is built, one solve with the default engine in a fresh
    interpreter runs on it (the module _cengine imported) and imports neither numba nor
    scipy: a single solve takes the compiled loops at no start-up cost."""
    _need("c")
    code = ("import sys\n"
            "from linecontact.roller import ProfiledRoller, slices\n"
            "r = ProfiledRoller(5e-3, 14e-3, 1e11, 'iso16281')\n"
            "r.at_force(4000.0, tilt=1e-3)\n"
            "print(slices.resolve_engine(r.engine), slices._NUMPY_STEPS[0],"
            " 'linecontact.roller._cengine' in sys.modules, 'numba' in sys.modules,"
            " 'scipy' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["c", "0", "True", "False", "False"], (
        f"engine, numpy steps, C engine / numba / scipy imported: {out}")


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


@pytest.mark.parametrize("engine", COMPILED)
def test_compiled_step_helpers_equal_their_numpy_lines(engine):
    """The four compiled helpers of the bordered Newton step (_compiled.scaled_system,
    bordered_sums, step_out, step_update) give what the numpy code they replace in
    SliceEquations.bordered gives (slices.scaled_system; the other lines written out
    here): the scaled system bit for bit (the same products), the sums to 1e-13 of
    their scale (another order of addition), the step's mask, its damping alpha (from
    the loads, the curvatures and the overlap, at a given tilt and with a tilt step),
    the slices that limited it and the largest changes. A whole solve cannot check the damping and the mask: a wrong alpha or
    hit_q changes the Newton path, not the converged answer."""
    _need(engine)
    jit = _module(engine)

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
    """SliceEquations.bordered's step before _compiled.newton_step fused it: the
    compiled helpers and the Python lines between them, written out."""
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


@pytest.mark.parametrize("engine", COMPILED)
def test_compiled_newton_step_equals_the_helpers_it_fuses(engine):
    """_compiled.newton_step, the bordered step after the linearisation in one compiled
    call, gives bit for bit what the helpers it replaces give with the Python lines
    between them (_step_by_helpers: scaled_system, solve_sums, K = Wz[:, 1:] + grid,
    the step of each mode, step_out, step_update): the same operations in the same
    order. Each mode (no row, force, moment, both by Cramer's rule), with loads large
    enough that the update is done (status 0) and with slices the step drives below
    zero (status 1); Cramer's rule on a K that is not finite hands the 2 x 2 system back
    (status 2), and a singular Jacobian the scaled system (None: numpy's solve)."""
    _need(engine)
    jit = _module(engine)

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
    # a singular Jacobian: numba refuses it; J and B come back scaled for numpy's solve
    Js = np.zeros((2 * ns, 2 * ns), order="F")
    got = jit.newton_step(Js, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, 3e-7, 1,
                          np.zeros(n), np.zeros(n), over)
    assert got[0] is None
    assert np.array_equal(got[1], sl.scaled_system(np.zeros_like(Js), res, rhs, ns, qsc, R))


@pytest.mark.parametrize("engine", COMPILED)
def test_compiled_dense_solves_equal_the_numpy_loops(engine):
    """The compiled engine's dense solves give what the numpy lines they replace give:
    _compiled.solve_sums the solution of np.linalg.solve (the same LAPACK routine;
    1e-12 of its scale allows another BLAS build) and bordered_sums' sums;
    _compiled.start_solve the cold start's active-set loop of
    SliceEquations.start_at_force (written out here: solve, remove the slices whose
    load is not positive, solve again), the same kept slices and solution, on a
    bordered system where slices leave in two rounds; a singular system falls back to
    numpy's solve, which raises numpy's LinAlgError. (The C engine's solve_sums is
    numpy's solve and the C sums; the cold start is numpy's under it: numba only.)"""
    _need(engine)
    jit = _module(engine)

    rng, n, ns, R, qsc, S, w, x, J = _random_step_system(5)
    B, qs = rng.normal(size=(2 * ns, 3)), rng.random(ns)
    z, wq, wxq, Wz = jit.solve_sums(J.copy(), B, ns, qsc, R, w, x, S, qs)
    zn = np.linalg.solve(J, B)
    want = jit.bordered_sums(zn, ns, qsc, R, w, x, S, qs)
    np.testing.assert_allclose(z, zn, rtol=0, atol=1e-12 * np.abs(zn).max())
    assert wq == pytest.approx(want[0], rel=1e-13)
    assert wxq == pytest.approx(want[1], rel=1e-13)
    np.testing.assert_allclose(Wz, want[2], rtol=1e-12, atol=1e-13 * np.abs(want[2]).max())
    if engine != "numba":
        return
    # the start's loop: loads of a diagonal-dominant system with some negative targets
    m, nb = 16, 2
    M = np.zeros((m + nb, m + nb))
    M[:m, :m] = np.eye(m) * 4 + rng.random((m, m)) * 0.3
    M[:m, m] = -1.0
    M[:m, m + 1] = -np.linspace(-1, 1, m)
    M[m, :m] = 1.0
    M[m + 1, :m] = np.linspace(-1, 1, m)
    rhs = np.concatenate([np.sin(np.arange(m)) * 3 - 1.0, [5.0, 0.0]])
    keep, Mk, rk, rounds = np.arange(m), M, rhs, 0
    while True:                                   # the numpy loop, as in slices.py
        zk = np.linalg.solve(Mk, rk)
        on = zk[:len(keep)] > 0
        if on.all():
            break
        rounds += 1
        rows = np.concatenate([np.flatnonzero(on), np.arange(len(keep), len(keep) + nb)])
        keep, Mk, rk = keep[on], Mk.take(rows, 0).take(rows, 1), rk[rows]
    assert rounds >= 2 and 0 < len(keep) < m, "the system should shed slices twice"
    zc, kept, k = jit.start_solve(M, rhs, m, nb)
    assert k == len(keep) and (kept == keep).all()
    np.testing.assert_allclose(zc, zk, rtol=0, atol=1e-12 * np.abs(zk).max())
    with pytest.raises(np.linalg.LinAlgError, match="Singular matrix"):
        jit.solve(np.zeros((3, 3)), np.ones(3))


def test_c_engine_solves_in_threads():
    """The C loops run without the GIL, with their scratch memory per call: rollers
    solved by four threads at once (one roller per solve, as ProfiledRoller asks) give
    the same bits as the same solves one after another."""
    _need("c")
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


def test_the_c_extension_checks_its_arrays():
    """The C extension reads its arrays through the buffer protocol without numpy's
    help, so it checks them itself: an array of the wrong length, of the wrong type
    (int64 for float64), not contiguous, or a slice index outside the grid raises a
    ValueError naming the array, instead of reading or writing out of bounds."""
    _need("c")
    from linecontact.roller import _ckernels, _layout

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


def test_the_c_extension_refuses_a_negative_slice_count():
    """The Newton step's C functions take the loaded-slice count ns as a number and
    size their arrays by it (z: 2 ns x 3, qs: ns, ...); a length below zero means "any
    length" to the extension's checks, so a negative ns passed every check and the
    call returned a made-up answer (step_out: 0 slices leaving; bordered_sums: zero
    sums) instead of refusing it. Each now raises a ValueError naming ns."""
    _need("c")
    from linecontact.roller import _ckernels

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


def test_the_geometry_caches_are_bounded_in_bytes(monkeypatch):
    """The module-wide caches of slice geometry (n x n arrays, five of them per
    geometry in the compiled engine) were bounded only in count: sixteen geometries at
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


@pytest.mark.parametrize("engine", COMPILED)
@pytest.mark.parametrize("mode", [1, 2])
def test_compiled_newton_step_divides_as_numpy_by_a_zero_stiffness(mode, engine):
    """The step of a force row (mode 1) or a moment row (mode 2) is its residual over
    K[0, 0] or K[1, 1]; where that entry is exactly zero the lines _compiled.newton_step
    replaced divided numpy floats (IEEE: +-inf, NaN for 0/0) and went on, where numba's
    compiled division raises ZeroDivisionError. The fused step must hand back what the
    helpers give (the same step, dz, mask, update; NaN compared as NaN), not raise."""
    _need(engine)
    jit = _module(engine)

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


def test_a_refused_engine_names_the_engines_that_run_here(monkeypatch):
    """The error that refuses an engine not available here gives as its valid range the
    engines that are: where numba is not installed but the C extension is built,
    engine='numba' was refused with "'auto' or 'numpy'", leaving out the C engine; where
    neither is, engine='c' was refused with "'auto', 'numpy' or 'numba'", naming an
    engine that is refused too."""
    _need("c")
    monkeypatch.setattr(sl, "_HAVE_NUMBA", [False])          # (as without numba)
    with pytest.raises(OutOfRangeError, match="engine") as err:
        ProfiledRoller(5e-3, 14e-3, 1e11, engine="numba")
    assert "'auto', 'numpy' or 'c' (numba is not installed)" in str(err.value), (
        str(err.value))
    monkeypatch.setattr(sl, "_C_ENGINE", ["not built (blocked by the test)"])
    with pytest.raises(OutOfRangeError, match="engine") as err:
        ProfiledRoller(5e-3, 14e-3, 1e11, engine="c")
    assert "range 'auto' or 'numpy' (the C extension" in str(err.value), str(err.value)
