"""The slice and bearing solvers run their many small dense solves on one BLAS thread
(linecontact._numerics.serial_blas): a multithreaded BLAS on busy cores made a
profiled-roller solve 17 times dearer (tools/benchmarks/results/serial_blas.txt)."""
import numpy as np
import pytest

threadpoolctl = pytest.importorskip("threadpoolctl")

from linecontact._numerics import serial_blas  # noqa: E402


def _blas_threads():
    return [lib["num_threads"] for lib in threadpoolctl.threadpool_info()
            if lib["user_api"] == "blas"]


@pytest.fixture(autouse=True)
def two_blas_threads():
    """Every BLAS at two threads for the test (restored after), so that the limit to
    one is seen also where the environment already runs BLAS on one thread (CI with
    OPENBLAS_NUM_THREADS=1, a one-core machine)."""
    with threadpoolctl.threadpool_limits(2, user_api="blas"):
        if not _blas_threads() or min(_blas_threads()) < 2:
            pytest.skip("no BLAS that threadpoolctl can set to two threads")
        yield


@pytest.fixture(autouse=True)
def fresh_guard(monkeypatch):
    """The guard as a process's first solve builds it. It finds the BLAS libraries once,
    when first entered: numpy's, which the solvers' dense solves use, is loaded before
    any solve; one that earlier tests loaded after the process's guard was built (such
    as scipy's, which no solver calls) is not among its libraries, and would show two
    threads here."""
    from linecontact import _numerics
    monkeypatch.setattr(_numerics, "_SERIAL_BLAS", _numerics._SerialBlas())


def test_limit_inside_restored_after_and_reentrant():
    """Inside a decorated call every BLAS has one thread, also in a nested decorated
    call; after the outermost call returns (or raises) the original counts are back."""
    before = _blas_threads()
    seen = []

    @serial_blas
    def inner():
        seen.append(_blas_threads())

    @serial_blas
    def outer(fail):
        seen.append(_blas_threads())
        inner()
        seen.append(_blas_threads())
        if fail:
            raise RuntimeError("boom")

    outer(False)
    with pytest.raises(RuntimeError):
        outer(True)
    assert all(t == [1] * len(before) for t in seen), seen
    assert _blas_threads() == before


def test_roller_and_bearing_solves_use_one_thread(monkeypatch):
    """Every dense solve of a profiled-roller solve and of a bearing solve runs with one
    BLAS thread (recorded by wrapping numpy.linalg.solve during the calls)."""
    from linecontact.bearing import RadialRollerBearing
    from linecontact.roller import ProfiledRoller

    counts = []
    solve = np.linalg.solve

    def recording(*a, **k):
        counts.append(max(_blas_threads()))
        return solve(*a, **k)

    monkeypatch.setattr(np.linalg, "solve", recording)
    ProfiledRoller(5e-3, 14e-3, 115e9, "circular:Rc=0.5").at_force(4200.0, tilt=1e-3)
    n_roller = len(counts)
    RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="iso16281").solve(10e3, moment=5.0)
    assert n_roller > 0 and len(counts) > n_roller
    assert set(counts) == {1}, counts


def test_a_first_use_under_a_one_thread_limit_does_not_disable_it_later():
    """Whether BLAS runs several threads is decided at each outermost entry, not once
    per process: a first solve inside a caller's one-thread limit (a worker process
    that limits BLAS) must not leave the limit off for later solves outside it."""
    from linecontact._numerics import _SerialBlas

    if max(_blas_threads(), default=1) < 2:
        pytest.skip("BLAS runs one thread here: nothing to limit")
    fresh = _SerialBlas()
    with threadpoolctl.threadpool_limits(limits=1, user_api="blas"):
        with fresh:
            pass
    before = _blas_threads()
    assert max(before) >= 2
    with fresh:
        inside = _blas_threads()
    assert inside == [1] * len(before), inside
    assert _blas_threads() == before
