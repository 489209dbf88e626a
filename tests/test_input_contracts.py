"""The library's input rules of issue 22 (API side), each over a class of inputs.

- every registered model's constructor (hence get_model's options) refuses an unknown
  keyword with one line naming it and listing the valid keywords
  (UnknownNameError, a ValueError), never Python's bare TypeError;
- every public function of the library (outside the profiled rollers) that takes a
  force or a depth takes arrays, element by element equal to its scalar calls.
"""
from __future__ import annotations

import inspect
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from linecontact.errors import UnknownNameError
from linecontact.models import MODELS, available_models, get_model

names = st.text(alphabet="abcdefghijklmnopqrstuvwxyz_", min_size=1, max_size=12)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(available_models()), names)
def test_an_unknown_model_keyword_lists_the_valid_ones(key, keyword):
    """get_model(key, R, L, E*, **{keyword: 1}) with a keyword the model does not take
    raises UnknownNameError naming it and every keyword the model does take, on one
    line (cc= for Johnson's c was a bare TypeError)."""
    get_model(key, 5e-3, 10e-3, 115e9)  # the model exists; now a wrong keyword
    cls = MODELS[key]
    valid = [n for n, p in inspect.signature(cls.__init__).parameters.items()
             if n != "self" and p.kind is not p.VAR_KEYWORD]
    if keyword in valid:
        return
    with pytest.raises(UnknownNameError) as info:
        get_model(key, 5e-3, 10e-3, 115e9, **{keyword: 1.0})
    msg = str(info.value)
    assert "\n" not in msg and repr(keyword) in msg
    assert all(repr(n) in msg for n in valid), msg


def _keyword_table():
    """The library's keyword boundary, one table. Each row: (the door, the keyword, a
    call passing it, the error it must raise, the words its message must hold)."""
    from linecontact import depth
    from linecontact.errors import UnknownKeywordError

    # self is positional-only in every model's constructor, so self= is an unknown
    # keyword like any other, not Python's TypeError 'got multiple values for argument
    # self' (hypothesis drew it once; here it is checked for every model on every run)
    rows = [(f"get_model({key!r})", "self",
             lambda key=key: get_model(key, 5e-3, 10e-3, 115e9, self=1.0),
             UnknownNameError, "'self'")
            for key in available_models()]
    # the case of issue 22: Johnson's constant is c, and cc= says so, also through the
    # functions taking **options (linecontact.depth, get_model), which pass them on
    rows += [("get_model('johnson')", "cc",
              lambda: get_model("johnson", 5e-3, 10e-3, 115e9, cc=0.72),
              UnknownKeywordError, "did you mean 'c'"),
             ("linecontact.depth", "cc",
              lambda: depth(1e3, _R, _L, _E, model="johnson", cc=0.7),
              UnknownKeywordError, "did you mean 'c'")]
    return rows


def test_an_unknown_keyword_is_refused_naming_it():
    """The keyword boundary, one table (every registered model, and the catch-alls
    that pass **options on): an unknown keyword raises UnknownNameError (a
    ValueError; UnknownKeywordError through a **options catch-all) naming it or its
    close match."""
    failed = []
    for door, keyword, call, error, words in _keyword_table():
        try:
            call()
        except UnknownNameError as exc:
            if not isinstance(exc, error) or words not in str(exc):
                failed.append((door, keyword, str(exc)))
        else:
            failed.append((door, keyword, "not refused"))
    assert not failed, failed


#: (module, function, keyword arguments) of the public functions taking a force or a
#: depth, with a valid case: steel roller R = 5 mm, L = 10 mm.
_R, _L, _E = 5e-3, 10e-3, 115.38e9


def _law_cases():
    from linecontact import classical
    from linecontact.models import get_model as gm

    m = gm("li-popov", _R, _L, _E)
    cases = []
    for name in classical.__all__:
        f = getattr(classical, name)
        if not inspect.isfunction(f):
            continue
        params = inspect.signature(f).parameters
        for arg, val in (("force", 1e3), ("depth", 1e-6)):
            if arg in params:
                kw = {k: v for k, v in dict(radius=_R, length=_L, estar=_E).items()
                      if k in params}
                cases.append((f, arg, val, kw))
    for meth in ("force", "depth", "stiffness", "evaluate"):
        arg = "force" if meth == "depth" else "depth"
        cases.append((getattr(m, meth), arg, 1e3 if arg == "force" else 1e-6, {}))
    return cases


@pytest.mark.parametrize("case", _law_cases(), ids=lambda c: getattr(c[0], "__qualname__", "f"))
def test_functions_of_a_force_or_depth_take_arrays(case):
    """An array of forces (depths) gives the array of the scalar results, element by
    element (rtol 1e-14: the same arithmetic; a root solved per element may differ by
    its tolerance, 1e-12)."""
    f, arg, val, kw = case
    xs = val * np.array([0.5, 1.0, 2.0])
    try:
        scalar = [f(**{arg: x}, **kw) for x in xs]
    except Exception:  # noqa: BLE001 - a function outside its range here is not tested
        pytest.skip("scalar call refused for this case")
    arr = f(**{arg: xs}, **kw)
    if isinstance(arr, dict):
        for k in arr:
            got = np.asarray(arr[k], dtype=float)
            want = np.array([float(np.asarray(s[k])) for s in scalar])
            assert np.allclose(got, want, rtol=1e-12, atol=0, equal_nan=True), k
    else:
        got = np.asarray(arr, dtype=float)
        want = np.array([float(np.asarray(s)) for s in scalar])
        assert np.allclose(got, want, rtol=1e-12, atol=0), f


@pytest.mark.parametrize("method,values", [("at_force", [500.0, 1000.0]),
                                          ("at_depth", [5e-6, 7e-6])])
def test_profiled_roller_takes_arrays_of_forces_and_depths(method, values):
    """ProfiledRoller.at_force / at_depth (a bare TypeError for an array before) take
    an array and give the array of the scalar solutions (to 1e-9: the solver's
    tolerance is 1e-10 and it starts from the previous solution)."""
    from linecontact.roller import ProfiledRoller

    r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5", n_slices=30)
    solve = getattr(r, method)
    arr = solve(np.array(values))
    assert arr.shape == (2,)
    for s, v in zip(arr, values):
        one = solve(v)
        assert s.force == pytest.approx(one.force, rel=1e-9, abs=0)
        assert s.depth == pytest.approx(one.depth, rel=1e-9, abs=0)


# ---- a geometry outside a table's or formula's range is named as the cause ----------

@settings(max_examples=40, deadline=None)
@given(st.sampled_from(["universal", "puttock-thwaite", "li-popov"]),
       st.floats(-4.0, 4.0), st.floats(-6.0, -0.83))
def test_a_refusal_caused_by_the_geometry_names_l_over_r(key, log_lr, log_d):
    """A depth within the models' parabolic-gap range (d/R < 0.15) that a model refuses
    is refused because of the geometry (the universal table's end d R/L^2 = 30, Eq. 2's
    largest depth L^2/R, Li-Popov's table of L/R): the message names L/R, its value and
    the range that would be covered, not only the depth."""
    import re

    from linecontact.errors import OutOfRangeError

    R = 5e-3
    L = R * 10 ** log_lr
    m = get_model(key, R, L, 115e9)
    try:
        m.force(R * 10 ** log_d)
    except OutOfRangeError as exc:
        msg = str(exc)
        found = re.search(r"L/R = ([0-9.e+-]+)", msg)
        assert found, msg
        assert float(found.group(1)) == pytest.approx(L / R, rel=1e-3), msg
        assert re.search(r"L/R >= [0-9.]|\[[0-9.]+, [0-9.]+\]", msg), msg


def test_exactly_one_of_depth_and_force_is_a_one_line_range_error():
    """Giving both or neither of depth and force (TangentialContact, a model's evaluate)
    is a bad value of an input, so it is the project's OutOfRangeError naming the
    choice, like roller_contact, not Python's TypeError."""
    from linecontact.errors import OutOfRangeError
    from linecontact.models import get_model
    from linecontact.tangential import TangentialContact

    m = get_model("universal", 5e-3, 10e-3, 115e9)
    with pytest.raises(OutOfRangeError, match="exactly one of"):
        TangentialContact(m, 0.1, 80e9)
    with pytest.raises(OutOfRangeError, match="both"):
        TangentialContact(m, 0.1, 80e9, depth=1e-6, force=1e3)
    with pytest.raises(OutOfRangeError, match="neither"):
        m.evaluate()


# ---- the range check's fast path for one number refuses what the array path refuses ----

def test_scalar_check_matches_the_array_path():
    """check_interval's fast path for one Python number returns the 0-d float array of
    the general path (the value checked as a 1-element array, then reshaped), and
    refuses exactly what it refuses (NaN, out of range, subnormal; 2^60 below an open
    end of 2^53 + 1, which rounds to 2^53 as a float: refused there, as 2^53 is).
    One table: every value below against every kind of interval."""
    from linecontact.checks import check_interval
    from linecontact.errors import OutOfRangeError

    values = [0.005, 50, -0.0, 0.0, 1e308, 2.3e-308, -0.05, 0.1, float("nan"),
              float("inf"), 5e-320, -5e-320, 2 ** 60, 2 ** 53]
    intervals = [(0.0, np.inf, True, True), (-0.1, 0.1, True, True),
                 (0.0, 0.5, False, False), (10, 4000, False, False),
                 (0, 2 ** 53 + 1, False, True)]
    failed = []
    for lo, hi, lo_open, hi_open in intervals:
        kw = dict(low_open=lo_open, high_open=hi_open)
        for value in values:
            try:
                ref = check_interval("v", np.array([float(value)]), lo, hi, **kw)[0]
            except OutOfRangeError:
                try:
                    check_interval("v", value, lo, hi, **kw)
                except OutOfRangeError:
                    continue
                failed.append((value, (lo, hi, lo_open, hi_open), "not refused"))
                continue
            got = check_interval("v", value, lo, hi, **kw)
            if not (got.shape == () and got.dtype == np.float64 and got.item() == ref
                    and math.copysign(1, got.item()) == math.copysign(1, ref)):
                failed.append((value, (lo, hi, lo_open, hi_open), repr(got)))
    assert not failed, failed
