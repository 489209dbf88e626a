"""The ContactModel interface shared by all models, the registry and the one-liners.

Each test states the fact it checks in its docstring and assertion message.
"""
import importlib
import pkgutil
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import linecontact
from linecontact import models as mm
from linecontact import tables as tb
from linecontact.errors import OutOfRangeError
from linecontact.mdr import mdr_force
from linecontact.models import (MODELS, ContactModel, get_model, register,
                                standard_models)
from linecontact.tables import read_table, write_table

E = 210e9 / (2 * (1 - 0.3**2))

# A cylinder for which every model applies: L/R = 5 is inside Table 1 and Eq. 11.
R5, L5 = 5e-3, 25e-3


def _register_every_model():
    """Import every linecontact module, so that a model registered anywhere in the
    package (not only in models.py) is in MODELS when the law tests are collected."""
    for info in pkgutil.iter_modules(linecontact.__path__):
        if info.name != "__main__":
            importlib.import_module(f"linecontact.{info.name}")
    return sorted(MODELS)


# Every registered model with its default options, plus the option variants the CLI
# prints: a model added with @register joins the law tests below without an edit here.
ALL = ([(key, {}) for key in _register_every_model()]
       + [("li-popov", dict(coefficients="eq11")), ("johnson", dict(c=0.72)),
          ("johnson", dict(c=0.572))])
IDS = [f"{k}{'-' + '-'.join(map(str, o.values())) if o else ''}" for k, o in ALL]
DEPTHS = np.geomspace(1e-8, 1e-5, 7)   # m, well inside every model's range at R5, L5
# (d/R <= 2e-3; d R/L^2 from 8e-8 to 8e-5, inside the universal table)


def _model(key, opts, R=R5, L=L5, estar=E):
    return get_model(key, R, L, estar, **opts)


# ---- the sanity figures ----------------------------------------------------------
def test_sanity_figures_steel_roller():
    """Steel on steel (E = 210 GPa, nu = 0.3), R = 5 mm, L = 10 mm, F = 1 kN:
    Li-Popov with Eq. 11 about 3.15 um, Puttock-Thwaite about 3.36 um, Palmgren about
    3.05 um (issue 2). Eq. 11 is outside its L/R >= 5 range here, so it is asked for
    explicitly (extrapolate=True); without that it is refused."""
    estar = linecontact.effective_modulus(210e9, 0.3, 210e9, 0.3)
    R, L, F = 5e-3, 10e-3, 1e3
    eq11 = get_model("li-popov", R, L, estar, coefficients="eq11", extrapolate=True)
    assert eq11.depth(F) == pytest.approx(3.15e-6, abs=0.005e-6)
    assert get_model("puttock-thwaite", R, L, estar).depth(F) == pytest.approx(3.36e-6, abs=0.005e-6)
    assert get_model("palmgren", R, L, estar).depth(F) == pytest.approx(3.05e-6, abs=0.005e-6)
    with pytest.raises(OutOfRangeError, match=r"L/R = 2 is outside the valid range \[5, inf\)"):
        get_model("li-popov", R, L, estar, coefficients="eq11").depth(F)


# ---- laws every model obeys ----------------------------------------------------------------
@pytest.mark.parametrize("key, opts", ALL, ids=IDS)
def test_depth_inverts_force(key, opts):
    """Round trip: depth(force(d)) = d for every model."""
    m = _model(key, opts)
    np.testing.assert_allclose(m.depth(m.force(DEPTHS)), DEPTHS, rtol=1e-9)


@pytest.mark.parametrize("key, opts", ALL, ids=IDS)
def test_stiffness_is_derivative_of_force(key, opts):
    """k(d) = dF/dd (central difference) and k(F(d)) = k(d), for every model."""
    m = _model(key, opts)
    h = 1e-6 * DEPTHS
    numeric = (m.force(DEPTHS + h) - m.force(DEPTHS - h)) / (2 * h)
    k = m.stiffness(DEPTHS)
    np.testing.assert_allclose(k, numeric, rtol=1e-6, err_msg="k = dF/dd")
    np.testing.assert_allclose(m.stiffness_at_force(m.force(DEPTHS)), k, rtol=1e-9)
    np.testing.assert_allclose(m.contact_radius(DEPTHS), k / (2 * E), rtol=1e-12,
                               err_msg="MDR contact radius a = k/(2E*)")


@pytest.mark.parametrize("key, opts", ALL, ids=IDS)
def test_force_and_stiffness_are_monotone(key, opts):
    """F(d) increases strictly and k(d) does not decrease (F convex) for every model."""
    m = _model(key, opts)
    d = np.geomspace(1e-9, 1e-5, 25)   # 6 points a decade over four decades
    assert np.all(np.diff(m.force(d)) > 0)
    assert np.all(np.diff(m.stiffness(d)) >= 0)


@pytest.mark.parametrize("key, opts", ALL, ids=IDS)
@settings(max_examples=15, deadline=None)   # models that solve a BEM/slicing problem per
@given(lam=st.floats(0.01, 100.0))          # call join this test too: keep it affordable
def test_scaling_law(key, opts, lam):
    """F(lambda R, lambda L, lambda d) = lambda^2 F(R, L, d) at fixed E*, every model
    (even Palmgren: F ~ (d L^0.8)^(1/0.9) scales as lambda^2)."""
    d = 1e-6
    F1 = _model(key, opts).force(d)
    F2 = _model(key, opts, R=lam * R5, L=lam * L5).force(lam * d)
    assert F2 == pytest.approx(lam**2 * F1, rel=1e-9)


@pytest.mark.parametrize("key, opts", ALL, ids=IDS)
def test_profile_reproduces_the_force_law_by_mdr(key, opts):
    """For models with an MDR profile, 2E* int_0^a (d - g) dx of that profile equals the
    model's F(d): profile and force law are one model. (Empirical laws have no profile
    and the coupled-slice roller models have none either: each says why in its
    NotImplementedError, and the skip repeats that reason.)"""
    m = _model(key, opts)
    assert callable(m.profile), (
        f"{m.label}: ContactModel.profile(x) is the MDR profile method; an attribute "
        f"of type {type(m.profile).__name__} shadows it")
    try:
        m.profile(1e-3)
    except NotImplementedError as exc:
        pytest.skip(str(exc))
    for d in (1e-8, 1e-6):
        assert mdr_force(d, m.profile, E, x_scale=L5) == pytest.approx(m.force(d), rel=1e-8)


@pytest.mark.parametrize("key", ["kunz", "palmgren", "iso16281"])
def test_empirical_laws_have_no_profile(key):
    """Purely empirical laws raise NotImplementedError for profile(), saying so."""
    with pytest.raises(NotImplementedError, match="empirical force-depth law"):
        _model(key, {}).profile(1e-3)


@pytest.mark.parametrize("key, reason", [
    ("profiled-roller", "coupled-slice solution"),
    ("iso16281-slicing", "uncoupled slices"),
])
def test_slice_models_say_why_they_have_no_profile(key, reason):
    """The roller models of linecontact.roller have no MDR profile for their own
    reason, not "an empirical force law" (the coupled-slice model is a half-space
    solution, not an empirical fit)."""
    with pytest.raises(NotImplementedError, match=reason) as err:
        _model(key, {}).profile(1e-3)
    assert "empirical force-depth law" not in str(err.value)


# ---- validity -----------------------------------------------------------------------------
@pytest.mark.parametrize("arg, value", [("radius", -0.005), ("length", 0.0), ("estar", np.nan),
                                        ("radius", np.inf)])
def test_construction_refuses_bad_cylinder(arg, value):
    """Non-positive or non-finite R, L, E* raise OutOfRangeError at construction, with
    a message like 'radius = -0.005 m is outside the valid range (0, inf) m'."""
    kw = dict(radius=R5, length=L5, estar=E)
    kw[arg] = value
    for key in MODELS:
        with pytest.raises(OutOfRangeError) as err:
            get_model(key, **kw)
        assert err.value.parameter == arg and err.value.valid.startswith("(0, inf)")
    if arg == "radius" and value == -0.005:
        assert str(err.value) == "radius = -0.005 m is outside the valid range (0, inf) m"


@pytest.mark.parametrize("method, value", [("force", 0.0), ("force", -1e-6), ("depth", np.nan),
                                           ("depth", -1.0), ("stiffness", np.inf)])
def test_evaluations_refuse_bad_input(method, value):
    """Non-positive or non-finite depth/force raise OutOfRangeError in every model: no NaN
    is returned silently."""
    for key, opts in ALL:
        with pytest.raises(OutOfRangeError):
            getattr(_model(key, opts), method)(value)


def test_out_of_range_models_are_built_but_refuse_to_evaluate():
    """L/R = 10 is outside Table 1 and an aluminium E* outside the steel formulas: the
    models are built (so the CLI can list them), check_applicable and every evaluation
    raise OutOfRangeError naming the parameter and range."""
    pub = get_model("li-popov", 1e-3, 10e-3, E)
    with pytest.raises(OutOfRangeError) as err:
        pub.check_applicable()
    assert err.value.parameter == "L/R" and err.value.valid == "[0.1, 6]"
    with pytest.raises(OutOfRangeError):
        pub.force(1e-6)
    get_model("li-popov", 1e-3, 10e-3, E, coefficients="eq11").check_applicable()
    alu = linecontact.effective_modulus(70e9, 0.33, 210e9, 0.3)
    palm = get_model("palmgren", R5, L5, alu)
    with pytest.raises(OutOfRangeError, match="steel"):
        palm.check_applicable()
    with pytest.raises(OutOfRangeError, match="estar"):
        palm.depth(1e3)


def test_li_popov_depth_bound_raises():
    """A depth at or beyond beta L^2/R raises for the model (no clamping)."""
    m = get_model("li-popov", R5, L5, E, coefficients="eq11")
    with pytest.raises(OutOfRangeError, match="depth"):
        m.force(0.4573 * L5**2 / R5)


# ---- registry and one-liners ------------------------------------------------------------------
def test_standard_models_order_and_labels():
    """The CLI row set, in order: [universal], Li-Popov Table 1 spline, Eq. 11,
    [regenerated], Puttock-Thwaite, Johnson c = 1, 0.72, 0.572, Kunz, Palmgren, ISO."""
    rows = [m for m in standard_models(5e-3, 10e-3, E)
            if m.key != "universal" and getattr(m, "coefficients", "") != "regenerated"]
    assert [m.label for m in rows] == [
        "Li-Popov (Table 1 spline)", "Li-Popov (Eq. 11)", "Puttock-Thwaite",
        "Johnson (c = 1)", "Johnson (c = 0.72)", "Johnson (c = 0.572)", "Kunz (c = 0.175)",
        "Palmgren", "ISO 16281"]
    for m in rows:
        assert isinstance(m, ContactModel) and isinstance(m.provenance, dict)


def test_regenerated_table_drops_in_without_code_change(tmp_path, monkeypatch):
    """A tables/lipopov_regenerated.csv with the columns of Table 1 is used by name
    (coefficients='regenerated') and joins standard_models after the Eq. 11 row."""
    src = read_table("lipopov_published")
    uni = read_table("universal_curve")
    write_table(tmp_path / "universal_curve.csv", uni.meta, uni.columns)
    for name in ("lipopov_published", "lipopov_regenerated"):
        cols = dict(src.columns)
        if name == "lipopov_regenerated":
            cols["beta"] = cols["beta"] * 1.01
        write_table(tmp_path / f"{name}.csv", {**src.meta, "title": name}, cols)
    monkeypatch.setattr(tb, "tables_dir", lambda: tmp_path)
    m = get_model("li-popov", 5e-3, 10e-3, E, coefficients="regenerated")
    assert m.label == "Li-Popov (regenerated table)"
    assert m.alpha_beta[1] == pytest.approx(0.7936 * 1.01, rel=1e-12)
    assert m.provenance["title"] == "lipopov_regenerated"
    labels = [r.label for r in standard_models(5e-3, 10e-3, E) if r.key != "universal"]
    assert labels[:3] == ["Li-Popov (Table 1 spline)", "Li-Popov (Eq. 11)",
                          "Li-Popov (regenerated table)"]


def test_unknown_model_key_lists_valid_keys():
    """An unknown key raises UnknownNameError (a ValueError, not an OutOfRangeError: a
    name has no range) listing the registered keys."""
    from linecontact.errors import UnknownNameError

    with pytest.raises(UnknownNameError) as err:
        get_model("hertz", R5, L5, E)
    assert not isinstance(err.value, OutOfRangeError)
    for key in ("li-popov", "puttock-thwaite", "johnson", "kunz", "palmgren", "iso16281"):
        assert key in err.value.valid and repr(key) in str(err.value)


def test_register_adds_a_model(monkeypatch):
    """@register makes a ContactModel subclass available to get_model by its key."""
    monkeypatch.setattr(mm, "MODELS", dict(MODELS))

    @register
    class Linear(ContactModel):
        key = "test-linear"
        label = "Linear"
        provenance = {"equation": "F = E* L d"}

        def force(self, depth):
            return self.estar * self.length * np.asarray(depth)

        def depth(self, force):
            return np.asarray(force) / (self.estar * self.length)

        def stiffness(self, depth):
            return self.estar * self.length + 0 * np.asarray(depth)

    m = get_model("test-linear", R5, L5, E)
    assert m.force(1e-6) == pytest.approx(E * L5 * 1e-6)
    assert m.contact_radius(1e-6) == pytest.approx(L5 / 2), "a = k/(2E*) by default"


def test_top_level_one_liners_match_the_models():
    """linecontact.force/depth/stiffness equal the model methods they wrap."""
    m = get_model("li-popov", 5e-3, 10e-3, E)
    assert linecontact.force(1e-6, 5e-3, 10e-3, E, model="li-popov") == m.force(1e-6)
    assert linecontact.depth(1e3, 5e-3, 10e-3, E, model="li-popov") == m.depth(1e3)
    assert linecontact.stiffness(1e-6, 5e-3, 10e-3, E, model="johnson", c=0.72) == \
        get_model("johnson", 5e-3, 10e-3, E, c=0.72).stiffness(1e-6)
    d = linecontact.depth(np.array([1e2, 1e3]), 5e-3, 10e-3, E, model="puttock-thwaite")
    assert d.shape == (2,), "vectorised over force"


def test_one_case_imports_numpy_only():
    """A one-case computation (every row the CLI prints, at one force) imports numpy and
    linecontact only: no scipy (its interpolate and special modules cost ~300 ms of a
    cold start, issue 11.6), no importlib.metadata (the version is read only when asked
    for), no tools/, pandas or pint."""
    code = ("import sys, linecontact; from linecontact.models import standard_models\n"
            "for m in standard_models(5e-3, 1e-2, 1.15e11):\n"
            "    try:\n"
            "        m.stiffness(m.depth(1e3))\n"
            "    except linecontact.OutOfRangeError:\n"
            "        pass\n"
            "bad = sorted(m for m in sys.modules if m.split('.')[0] in "
            "('scipy', 'pandas', 'pint', 'tools') or m == 'importlib.metadata')\n"
            "assert not bad, bad")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_universal_is_registered_by_importing_models():
    """The default model is an ordinary registered model: importing linecontact.models
    alone registers it (no plugin loading on first use)."""
    code = ("import linecontact.models as m; import sys; "
            "assert 'universal' in m.MODELS and m.DEFAULT_MODEL == 'universal'")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_models_defined_elsewhere_are_built_by_key_in_a_fresh_process():
    """Every key of DEFINED_IN is listed by available_models() and built by get_model()
    without the caller importing its module first, and that module registers exactly
    the keys the table says (so the table cannot drift from the code)."""
    code = ("import importlib, linecontact.models as m\n"
            "assert set(m.DEFINED_IN) <= set(m.available_models())\n"
            "for key, mod in m.DEFINED_IN.items():\n"
            "    model = m.get_model(key, 5e-3, 10e-3, 115.38e9)\n"
            "    assert type(model).__module__ == mod and model.key == key, (key, mod)\n")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_missing_universal_table_is_an_error_naming_the_file(tmp_path, monkeypatch):
    """Without tables/universal_curve.csv the best estimate is not dropped silently:
    get_model('universal') and standard_models raise FileNotFoundError naming the file
    and how to regenerate it."""
    src = read_table("lipopov_published")
    write_table(tmp_path / "lipopov_published.csv", src.meta, src.columns)
    monkeypatch.setattr(tb, "tables_dir", lambda: tmp_path)
    for build in (lambda: get_model("universal", R5, L5, E),
                  lambda: standard_models(R5, L5, E),
                  lambda: linecontact.depth(1e3, R5, L5, E)):
        with pytest.raises(FileNotFoundError) as err:
            build()
        assert str(tmp_path / "universal_curve.csv") in str(err.value)
        assert "tools.build_tables universal" in str(err.value)


def test_version_is_a_string():
    """__version__ comes from the installed metadata, or '0+unknown' in a bare checkout."""
    assert isinstance(linecontact.__version__, str) and linecontact.__version__


# ---- the error and the ranges themselves ---------------------------------------------------
def test_out_of_range_error_message_and_attributes():
    """OutOfRangeError is a ValueError carrying parameter, value and valid range; its
    message reads 'NAME = VALUE UNIT is outside the valid range RANGE[; hint]' and it
    survives pickling (e.g. from worker processes)."""
    import pickle
    from linecontact.checks import check_interval, check_positive
    with pytest.raises(OutOfRangeError) as err:
        check_positive("force", [1.0, -2.0], "N", hint="loads push")
    e = err.value
    assert isinstance(e, ValueError)
    assert (e.parameter, e.value, e.valid) == ("force", -2.0, "(0, inf) N")
    assert str(e) == ("force = -2 N (element [1] of shape (2,)) is outside the valid "
                      "range (0, inf) N; loads push")
    assert str(pickle.loads(pickle.dumps(e))) == str(e)
    with pytest.raises(OutOfRangeError, match=r"depth = 3 m .* \(0, 2\) m"):
        check_interval("depth", [1.0, 3.0], 0.0, [2.0, 2.0], low_open=True,
                       high_open=True, unit="m")


def test_interval_renders_and_checks():
    """An Interval renders as '[lo, hi)' with its unit and as an inequality for docs, and
    its check() is what the formulas enforce (NaN is never inside)."""
    from linecontact.checks import POISSON_RATIO, Interval
    assert str(POISSON_RATIO) == "[0, 0.5]"  # 0.5: incompressible (issue 11.4)
    assert POISSON_RATIO.describe() == "0 <= poisson <= 0.5"
    iv = Interval("radius", 0.0, np.inf, True, True, "m")
    assert str(iv) == "(0, inf) m" and iv.describe() == "0 < radius < inf m"
    assert list(iv.contains([1.0, 0.0, np.nan, np.inf])) == [True, False, False, False]
    with pytest.raises(OutOfRangeError, match="radius = nan m"):
        iv.check(np.nan)


# ---- the accuracy study covers every printed model --------------------------------------------
def test_every_printed_model_has_its_measured_error():
    """Every row the CLI prints, except the universal curve (the reference), has its F and
    k error columns in tables/model_accuracy.csv, and its provenance states the measured
    error range at this cylinder's L/R (issue 11.7: no model printed without a word on
    its accuracy)."""
    table = read_table("model_accuracy")
    for m in standard_models(5e-3, 10e-3, E):
        if m.key == "universal":
            assert "accuracy" in m.provenance, "its own accuracy: the table header"
            continue
        assert f"F_err_{m.accuracy_tag}" in table.columns, m.label
        assert f"k_err_{m.accuracy_tag}" in table.columns, m.label
        text = m.provenance["measured_error"]
        assert "against the BEM at L/R = 2" in text and " % to " in text, (m.label, text)


def test_measured_error_is_the_range_of_the_table_rows():
    """Puttock-Thwaite at L/R = 2.5: the stated range is the min and max of the study's
    F errors at the bracketing rows L/R = 2 and 3 (two significant digits)."""
    c = read_table("model_accuracy").columns
    rows = (c["L_over_R"] == 2) | (c["L_over_R"] == 3)
    e = c["F_err_eq2"][rows]
    e = e[e < 98]
    text = get_model("puttock-thwaite", 4e-3, 10e-3, E).measured_error
    assert f"F {e.min() * 100:+.2g} % to {e.max() * 100:+.2g} %" in text
    assert "L/R = 2 and 3" in text
    assert "not measured at L/R = 30" in get_model("puttock-thwaite", 1e-3, 30e-3,
                                                   E).measured_error


@pytest.mark.parametrize("row", [0, 137, 402, 611, 898])
def test_accuracy_table_rows_are_reproduced_by_the_code(row):
    """Data and code cannot drift apart: each model's error in tables/model_accuracy.csv
    at a grid point is model/universal - 1 recomputed now, to 1e-9 (the models are closed
    forms and the universal spline; 1e-9 leaves room for rounding in the ratios only),
    or the same flag (98 not applicable, 99 no answer)."""
    from tools.studies.accuracy import (NO_ANSWER, NOT_APPLICABLE, comparison_models,
                                model_errors)
    c = read_table("model_accuracy").columns
    lr, dr = c["L_over_R"][row], c["d_over_R"][row]
    models = comparison_models()
    errs = model_errors(models, np.array([lr]), np.array([dr]))
    for tag, _, _, _ in models:
        eF, ek, applies = errs[tag]
        for q, e in (("F", eF[0, 0]), ("k", ek[0, 0])):
            want = NOT_APPLICABLE if not applies[0] else NO_ANSWER if np.isnan(e) else e
            assert c[f"{q}_err_{tag}"][row] == pytest.approx(want, rel=1e-9, abs=1e-12), \
                f"{q}_err_{tag} at L/R = {lr:g}, d/R = {dr:.3g}"


@pytest.mark.parametrize("key", ["li-popov", "universal"])
@pytest.mark.parametrize("word", ["no", "false", 0, None])
def test_extrapolate_takes_a_boolean_not_a_truthy_word(key, word):
    """bool('no') is True in Python: a yes/no option given anything but a boolean is
    refused with the parameter's name, never read as 'on'."""
    with pytest.raises(OutOfRangeError, match="extrapolate"):
        get_model(key, R5, L5, E, extrapolate=word)


@pytest.mark.parametrize("key", ["palmgren", "iso16281", "johnson", "universal"])
def test_stiffness_of_a_pint_depth_equals_the_si_value(key):
    """A pint Quantity is converted to SI before any arithmetic: k(3 um) is the same
    N/m whether the depth is given as 3e-6 or as 3 micrometre (Palmgren's k = F/(0.9 d)
    once divided by the raw magnitude 3)."""
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    m = get_model(key, R5, L5, E)
    assert m.stiffness(3 * u.um) == pytest.approx(m.stiffness(3e-6), rel=1e-12)
    F = m.force(3e-6)
    assert m.stiffness_at_force(F * u.N) == pytest.approx(m.stiffness_at_force(F), rel=1e-12)


@pytest.mark.parametrize("key", ["universal", "kunz", "puttock-thwaite", "johnson", "li-popov"])
@pytest.mark.parametrize("length", [1e300, 1e-110])
def test_cylinders_whose_scales_overflow_are_refused_by_every_model(key, length):
    """A finite L whose self-similar scales (L^2, L^3, L^2/R, E* L^3/R) overflow or
    underflow is refused at construction, naming the length, for every model alike
    (before: an OverflowError from one, depth 0 or NaN from others)."""
    with pytest.raises(OutOfRangeError, match="length = 1e[+-]"):
        get_model(key, R5, length, E)


def test_universal_table_end_that_rounds_above_d_max_is_accepted():
    """R = 0.5 mm, L = 1 um: the table's end d~_max L^2/R divided back by L^2/R rounds
    one ulp above d~_max = 30. The model must still give its force limit and accept a
    load at that limit (it refused every load with 'd_tilde = 30 is outside (0, 30]'),
    and evaluate_many must cover the cylinder with the model's own values (it returned
    None, dropping a whole batch off its array path)."""
    import numpy as np

    from linecontact.models import UniversalModel

    R, L, E = 0.5e-3, 1e-6, 230e9
    m = UniversalModel(R, L, E)
    assert m.depth_limit / m._dscale > m.curve.d_max  # the rounding this test is about
    F = np.array([m.force_limit, 0.5 * m.force_limit])
    one = m.evaluate(force=F)
    assert abs(one["depth"][0] / m.depth_limit - 1) < 1e-12, "F_max maps to d_max"
    got = UniversalModel.evaluate_many([R, R], [L, L], [E, E], force=F)
    assert got is not None and got[1].all()
    for k in ("force", "depth", "stiffness", "contact_radius"):
        assert np.array_equal(got[0][k], one[k]), k  # the same operations: equal values


def test_evaluate_many_leaves_a_subnormal_psi_to_its_model():
    """F = 1e-301 N on a steel roller (a normal double) gives Psi = F R/(E* L^3) below
    the smallest normal double, which one model refuses. evaluate_many must mark that
    element outside (its model words the refusal) and still cover the others; it
    returned None, sending a whole batch with one such row off its array path."""
    import numpy as np

    from linecontact.errors import OutOfRangeError
    from linecontact.models import UniversalModel

    R, L, E = 5e-3, 1e-2, 2e11
    F = np.array([1e-301, 1e3])
    with pytest.raises(OutOfRangeError):
        UniversalModel(R, L, E).evaluate(force=F[:1])
    got = UniversalModel.evaluate_many([R, R], [L, L], [E, E], force=F)
    assert got is not None and got[1].tolist() == [False, True]
    one = UniversalModel(R, L, E).evaluate(force=F[1:])
    assert got[0]["depth"][1] == one["depth"][0] and np.isnan(got[0]["depth"][0])


@pytest.mark.parametrize("key", ["universal", "li-popov", "puttock-thwaite", "johnson"])
def test_a_force_whose_dimensionless_value_is_subnormal_is_refused_by_name(key):
    """F = 1e-305 N on R 5 mm, L 10 mm, E* 231 GPa: F R/(E* L^3) = 2e-313 is a subnormal
    number, whose reciprocal overflows (the Li-Popov family answered d = inf, which the
    calculator then called 'd > 0.15 R', and the universal curve named its internal
    Psi). The refusal names the force and the smallest force accepted, 2.2e-308 E* L^3/R;
    twice that force is answered with a finite, tiny depth. Depths likewise."""
    m = get_model(key, 5e-3, 10e-3, 2.30769e11)
    low = np.finfo(float).tiny * 2.30769e11 * 1e-6 / 5e-3
    with pytest.raises(OutOfRangeError, match=r"^force = 1e-305 N .*>= 1\.02\d*e-300 N"):
        m.depth(1e-305)
    d = m.depth(2 * low)
    assert np.isfinite(d) and 0 < d < 1e-290, "a force above the floor has a tiny depth"
    with pytest.raises(OutOfRangeError, match=r"^depth = 1e-310 m"):
        m.force(1e-310)


def _every_model_key():
    import linecontact.roller  # noqa: F401  (registers the roller models)
    return sorted(MODELS)


@pytest.mark.parametrize("key", _every_model_key())
def test_every_registered_model_pickles_and_answers_alike(key):
    """A model sent to another process (a process pool, a Dask worker) is pickled: every
    registered model must round-trip and give the same depth at 1 kN. The universal
    curve held its spline's derivatives as lambdas, which do not pickle."""
    import pickle

    kw = {"profile": "circular:Rc=0.5"} if key in ("profiled-roller",
                                                   "iso16281-slicing") else {}
    m = get_model(key, 5e-3, 10e-3, 115.38e9, **kw)
    assert pickle.loads(pickle.dumps(m)).depth(1e3) == m.depth(1e3)
