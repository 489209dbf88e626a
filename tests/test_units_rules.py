"""The input rules of issue 11.1, each held by a property over generated inputs.

Command line and CSV cells (linecontact._units): a value is one decimal number with a
decimal point and at most one unit name; everything else is refused with one line
naming the parameter, the value and the valid range. Python API (linecontact.checks):
numbers in SI; nothing that would lose information (an imaginary part, a mask, a unit)
passes silently.
"""

from __future__ import annotations

import datetime
import functools
import math
import sys

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from linecontact._units import InputError, parse_bool, parse_column, parse_quantity
from linecontact.checks import check_positive
from linecontact.errors import OutOfRangeError

#: units and their exact SI factor (definitions: 1 in = 25.4 mm, 1 lbf = 4.4482216152605 N)
UNITS = {
    "length": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "cm": 1e-2, "in": 0.0254},
    "force": {"N": 1.0, "kN": 1e3, "lbf": 4.4482216152605},
    "pressure": {"Pa": 1.0, "MPa": 1e6, "GPa": 1e9},
}

normal = st.floats(min_value=1e-300, max_value=1e300, allow_nan=False, allow_infinity=False)
kinds = st.sampled_from(sorted(UNITS))


def _refused(text, kind="length"):
    with pytest.raises(InputError) as info:
        parse_quantity("--x", text, kind)
    msg = str(info.value)
    # one line, naming the parameter, the value as typed and the valid range
    head = f"--x = {text!r}" if text else "--x: empty value"
    assert "\n" not in msg and msg.startswith(head) and "; valid: " in msg
    return msg


@given(normal, kinds, st.data())
def test_a_number_with_one_unit_converts_by_that_units_factor(x, kind, data):
    """'<x><unit>' and '<x> <unit>' are x times the unit's SI factor (to 1e-15: pint's
    factor is computed in floating point), and a bare number is SI exactly."""
    unit = data.draw(st.sampled_from(sorted(UNITS[kind])))
    factor = UNITS[kind][unit]
    assume(1e-300 < x * factor < 1e300)
    text = repr(x)
    assert parse_quantity("--x", text, kind) == x
    for sep in ("", " "):
        got = parse_quantity("--x", text + sep + unit, kind)
        assert math.isclose(got, x * factor, rel_tol=1e-15)


@given(st.integers(0, 10**6), st.integers(0, 10**6), st.sampled_from(["", "mm", " kN"]))
def test_decimal_comma_is_refused_never_misread(a, b, unit):
    """'1,5mm' is refused (it was read as 15 mm): no decimal comma, no thousands
    separator, whatever the digits."""
    kind = "force" if "kN" in unit else "length"
    assert "decimal comma" in _refused(f"{a},{b}{unit}", kind)


quantity_text = st.builds(lambda x, u: f"{x:g}{u}", st.floats(0.001, 1000),
                          st.sampled_from(["mm", "m", "", " mm", "in"]))


@given(quantity_text, st.sampled_from(["+", "-", "*", "/", "**", "^", " * ", " / ", " + "]),
       quantity_text)
def test_expressions_are_refused_never_evaluated(q1, op, q2):
    """Sums, products, quotients and powers of quantities are refused (pint used to
    evaluate them, and 9**9**9**9 hung the command)."""
    _refused(q1 + op + q2)


def test_a_huge_power_is_refused_without_evaluating_it(monkeypatch):
    """The input that hung the command (pint evaluated 9**9**9**9) is refused by the
    grammar alone: pint is never asked, so nothing can be evaluated."""
    import linecontact._units as units

    def no_pint():
        raise AssertionError("pint was asked to read an expression")

    monkeypatch.setattr(units, "_registry", no_pint)
    monkeypatch.setattr(units, "_FACTORS", {})
    _refused("9**9**9**9")
    _refused("9mm**9**9**9")


@given(st.integers(309, 100000))
def test_overflow_is_refused(e):
    """A number beyond the largest double (1.8e308) is refused, not read as inf."""
    assert "too large" in _refused(f"1e{e}")


@given(st.integers(-100000, -324))
def test_underflow_to_zero_is_refused(e):
    """A nonzero number below the smallest subnormal is refused, not read as 0."""
    assert "too small" in _refused(f"1e{e}")


@given(st.floats(min_value=5e-324, max_value=sys.float_info.min, exclude_max=True))
def test_subnormal_numbers_are_refused(x):
    """Subnormal numbers (lost precision; one returned the clamp limit as a depth) are
    refused."""
    assert "subnormal" in _refused(repr(x))


@given(st.floats(1e306, 1e308))
def test_overflow_after_unit_conversion_is_refused(x):
    """A value that is finite as typed but overflows in SI (1e308 km) is refused."""
    assert "too large" in _refused(f"{x!r} km")


@pytest.mark.parametrize("text", ["inf", "-inf", "nan", "Infinity", "1_000", "0x10",
                                  "\u0663", "5 m m", "5mm2", "(5)mm", "5 mm;", ""])
def test_non_numbers_are_refused(text):
    """Words Python's float() accepts (inf, nan, 1_000, non-ASCII digits) are not numbers
    here; neither is anything but one number and one unit name."""
    _refused(text)


def _assert_parses_like_its_cells(cells, kind):
    """parse_column gives parse_quantity's float, or its message and NaN, cell by cell."""
    values, errors = parse_column("--x", cells, kind)
    for cell, v, e in zip(cells, values, errors):
        try:
            expected = parse_quantity("--x", cell, kind)
        except InputError as exc:
            assert e == str(exc) and math.isnan(v), (cell, e)
        else:
            assert e == "" and v == expected, (cell, v, expected)


@given(st.lists(st.one_of(quantity_text, st.text(max_size=8),
                          st.builds(lambda x: repr(x), normal)), max_size=30), kinds)
def test_a_column_parses_exactly_like_its_cells(cells, kind):
    """parse_column (the batch's fast path, numpy and one pint call per unit) gives the
    same float and the same message as parse_quantity, cell by cell."""
    _assert_parses_like_its_cells(cells, kind)


#: Cells near the edges of the grammar, where a split of the column by string
#: operations (the unit is what rstrip of letters and spaces leaves off) could part from
#: the regular expression: exponents next to unit letters, a unit alone, inf and nan
#: with units, float()'s extras (underscores, other scripts' digits and spaces, the
#: ASCII separators \x1c-\x1f it strips), spaces inside, compound names.
EDGE_CELLS = ["5em", "1e3mm", "1e3", "1E-3 m", "5e", "5 e", "1.e2mm", ".5mm", "5.mm",
              "+5mm", "-5mm", "--5mm", "mm", " mm", "5 mm ", "\t5\tmm\t", "5 m m",
              "5mm5", "1_000mm", "\u0663mm", "5\u00a0mm", "\x1c5mm", "5mm\x1c",
              "5\x1fmm", "infmm", "1e5inf", "nan", "-inf", "5 inf", "0mm", "0.0",
              "-0", "1e-320mm", "1e309", "1e308km", "5\u00b5m", "5 \u03bcm", "5MM",
              "50mJ/m^2", "5N/m", "5 N m", "5kN", "5 lbf", "2.1e11", "0.3", "1,5mm",
              "5mm ", " 5", "5\n", "5 \x0bmm"]


@given(st.lists(st.sampled_from(EDGE_CELLS), min_size=1, max_size=12), kinds)
def test_a_column_of_edge_cells_parses_exactly_like_its_cells(cells, kind):
    """The column's string-operation split (all cells plain) and its per-cell matching
    (some cell refused) both give parse_quantity's float and message, cell by cell,
    also when a column mixes the two kinds of cell."""
    for column in (cells, cells + ["5mm", "0.005"], ["1kN"] * 3 + cells):
        _assert_parses_like_its_cells(column, kind)


@given(st.lists(st.builds(lambda x, u: repr(x) + u, normal,
                          st.sampled_from(["", "mm", " m", "in", "kN", "GPa", " psi"])),
                min_size=1, max_size=30), kinds)
def test_a_column_of_plain_cells_parses_exactly_like_its_cells(cells, kind):
    """Plain cells (a number and a unit name, of any unit, fit for the kind or not)
    take the column's fast split; it gives parse_quantity's float and message exactly."""
    _assert_parses_like_its_cells(cells, kind)


@given(st.lists(st.sampled_from(["5", "1.", ".5", "+5", "-2", "1e3", "1E-3", "0", "7 ",
                                  " 7", "1e5", "12.5"]), min_size=1, max_size=10),
       st.sampled_from(["mm", "m", "kN", "GPa", "e", "em", "mm ", " mm", ""]),
       st.one_of(st.none(), st.sampled_from(EDGE_CELLS)), st.integers(0, 10), kinds)
def test_a_column_of_one_unit_parses_exactly_like_its_cells(numbers, unit, odd, at, kind):
    """A column whose cells all carry one unit (the usual file, split by removing that
    unit before each line end of the joined column), with or without one odd cell
    anywhere (another unit, spaces, a refused cell), gives parse_quantity's float and
    message cell by cell."""
    cells = [x + unit for x in numbers]
    if odd is not None:
        cells.insert(min(at, len(cells)), odd)
    _assert_parses_like_its_cells(cells, kind)


@given(st.text(max_size=10))
def test_booleans_are_exactly_true_false_yes_no_1_0(text):
    """A yes/no option accepts six words (any case, surrounding spaces) and nothing
    else; 'no' is False."""
    word = text.strip().lower()
    if word in ("true", "yes", "1"):
        assert parse_bool("opt", text) is True
    elif word in ("false", "no", "0"):
        assert parse_bool("opt", text) is False
    else:
        with pytest.raises(InputError):
            parse_bool("opt", text)


# ---------------------------------------------------------------------------------------
# Python API: linecontact.checks refuses what would lose information


@given(normal, st.floats(allow_nan=False, allow_infinity=False).filter(lambda y: y != 0))
def test_complex_with_an_imaginary_part_is_refused(x, y):
    """The imaginary part is never dropped silently."""
    with pytest.raises(OutOfRangeError, match="imaginary"):
        check_positive("force", complex(x, y), "N")
    with pytest.raises(OutOfRangeError, match="imaginary"):
        check_positive("force", np.array([x, complex(x, y)]), "N")


@given(normal)
def test_complex_with_zero_imaginary_part_is_its_real_part(x):
    """x + 0j carries no more information than x."""
    assert float(check_positive("force", complex(x, 0.0), "N")) == x


@given(st.lists(st.booleans(), min_size=1, max_size=5).filter(any))
def test_masked_elements_are_refused(mask):
    """A masked array with masked elements is refused (the mask would be lost)."""
    arr = np.ma.masked_array(np.ones(len(mask)), mask=mask)
    with pytest.raises(OutOfRangeError, match="mask"):
        check_positive("force", arr, "N")


@pytest.mark.parametrize("value", [
    True, np.bool_(False), [1.0, True], np.array([True, False]),
    np.datetime64("2026-01-01"), np.array([1, 2], dtype="m8[s]"),
    datetime.timedelta(seconds=1), datetime.datetime(2026, 1, 1), "0.005", [b"1"],
])
def test_booleans_dates_durations_and_strings_are_not_numbers(value):
    """True is not 1 N, a duration is not a force, and '0.005' is not 5 mm."""
    with pytest.raises(OutOfRangeError):
        check_positive("force", value, "N")


@given(st.floats(1e-6, 1e6))
def test_pint_quantities_are_converted_to_si(x):
    """A Quantity is converted to the SI unit of the parameter (x mm = x/1000 m,
    x kN = 1000 x N), also through a model."""
    ureg = _ureg()
    assert math.isclose(float(check_positive("radius", x * ureg.mm, "m")), x / 1000,
                        rel_tol=1e-15)
    assert math.isclose(float(check_positive("force", x * ureg.kN, "N")), x * 1000,
                        rel_tol=1e-15)


def test_pint_quantity_of_the_wrong_dimension_is_refused_and_models_convert():
    """A force where a length is expected is refused; a model given mm and kN answers
    as given m and N."""
    from linecontact.models import get_model

    ureg = _ureg()
    with pytest.raises(OutOfRangeError, match="dimension"):
        check_positive("radius", 5 * ureg.N, "m")
    m = get_model("li-popov", 5 * ureg.mm, 10 * ureg.mm, 115.38 * ureg.GPa)
    ref = get_model("li-popov", 5e-3, 10e-3, 115.38e9)
    assert math.isclose(m.depth(1 * ureg.kN), ref.depth(1000.0), rel_tol=1e-14)
    r = ref.evaluate(depth=3 * ureg.um)
    assert math.isclose(r["force"], ref.force(3e-6), rel_tol=1e-14)


@functools.lru_cache(maxsize=None)
def _ureg():
    import pint

    return pint.UnitRegistry()


@given(st.floats(min_value=5e-324, max_value=sys.float_info.min, exclude_max=True))
def test_api_refuses_subnormal_numbers(x):
    """A subnormal force (one returned the clamp limit as the depth) is refused by the
    library's checks too, naming the parameter."""
    with pytest.raises(OutOfRangeError, match="subnormal"):
        check_positive("force", x, "N")


def test_built_in_unit_factors_equal_pints():
    """Every unit converted without pint has pint's factor (to 1e-15, rounding of the
    prefix powers), so the fast path and pint agree on every name both know (the
    moments 'Nm', which pint reads as number-metre, against its 'N*m')."""
    from linecontact._units import BUILTIN_UNITS, DIMENSIONS, PINT_SPELLING

    ureg = _ureg()
    for kind, table in BUILTIN_UNITS.items():
        si = DIMENSIONS[kind][1]
        for name, factor in table.items():
            expected = ureg.Quantity(1.0, PINT_SPELLING.get(name, name)).to(si).magnitude
            assert math.isclose(factor, expected, rel_tol=1e-15), (kind, name)


@given(st.floats(-300, 300), st.floats(-300, 300), st.integers(2, 50))
def test_a_geometric_sweep_has_equal_ratios_and_stays_finite(e0, e1, n):
    """START:STOP:N: N values with exact ends and a constant ratio (STOP/START)^(1/(N-1)),
    for any ends in the double range; the middle value is the geometric mean, so
    1e-300 N:1e300 N:3 gives 1 N (it was inf: the ratio 1e600 overflowed). The ratio of
    neighbours is checked in logarithms to 1e-9 of the whole span (rounding of ~N
    exp/log evaluations at up to 700 in magnitude, each to ~1e-16 relative)."""
    from linecontact._units import parse_sweep

    start, stop = 10.0**e0, 10.0**e1
    v = parse_sweep("--load", f"{start!r}:{stop!r}:{n}", "force")
    assert len(v) == n and v[0] == start and v[-1] == stop
    assert all(math.isfinite(x) and x > 0 for x in v)
    steps = np.diff(np.log(v))
    span = abs(math.log(stop) - math.log(start))
    assert np.allclose(steps, (math.log(stop) - math.log(start)) / (n - 1),
                       rtol=0, atol=1e-9 * max(span, 1.0))


from linecontact._units import BUILTIN_UNITS  # noqa: E402

_CASE_VARIANTS = [(kind, unit) for kind, names in BUILTIN_UNITS.items() for unit in names]


@given(st.sampled_from(_CASE_VARIANTS),
       st.sampled_from([str.upper, str.lower, str.swapcase, str.title, str.capitalize]),
       st.floats(0.01, 1000))
def test_a_unit_in_the_wrong_case_is_refused_with_did_you_mean(pair, change, x):
    """A unit name typed in the wrong case ('5MM' is megamolar to pint, '1KN' unknown)
    is either a unit of the same kind as typed (SI names are case-sensitive: 'Mm' is a
    megametre, accepted as such) or refused with 'did you mean' naming the unit of that
    kind it matches apart from case; never read as something else."""
    kind, unit = pair
    typed = change(unit)
    assume(typed != unit)
    text = f"{x!r}{typed}"
    try:
        value = parse_quantity("--x", text, kind)
    except InputError as exc:
        assert "did you mean" in str(exc) and repr(unit) in str(exc), str(exc)
    else:
        # accepted only as a genuine unit of this kind, converting by its own factor
        import linecontact._units as units

        factor = units._unit_factor(typed, kind)
        assert isinstance(factor, float) and math.isclose(value, x * factor, rel_tol=1e-15)


@pytest.mark.parametrize("column", [["2.5e-310kN"], ["2.5e-310 kN", "5kN"],
                                    ["2.5e-310kN", "x"], ["1e-310GPa", "1e3"]])
def test_a_subnormal_number_is_refused_in_a_column_even_when_its_unit_scales_it_up(column):
    """parse_quantity refuses a typed number below 2.2e-308 (it has lost precision)
    whatever its unit; parse_column must too, also where the unit's factor (kN, GPa)
    brings the SI value back into the normal range."""
    kind = "pressure" if "GPa" in column[0] else "force"
    values, errors = parse_column("--x", column, kind)
    with pytest.raises(InputError) as exc:
        parse_quantity("--x", column[0], kind)
    assert errors[0] == str(exc.value) and math.isnan(values[0]), (values[0], errors[0])


#: Units as people write them (issue 36), per kind: text -> SI value. A moment as the
#: package prints it ("M [N m]") and with a product sign; a surface energy with the
#: power's caret left out or as a superscript; the degree sign; typographic minus and
#: spaces (U+2212, U+00A0, U+2009, U+202F), which a word processor or a web page puts in.
WRITTEN = {
    "moment": [("20 N m", 20.0), ("20 N·m", 20.0), ("20 N*m", 20.0), ("20 N\u22c5m", 20.0),
               ("20Nm", 20.0), ("1.5 kN m", 1500.0), ("300 N mm", 0.3)],
    "surface_energy": [("50mJ/m2", 0.05), ("50 mJ/m^2", 0.05), ("50 mJ/m\u00b2", 0.05),
                       ("0.05 J/m2", 0.05)],
    "angle": [("0.05°", 0.05 * math.pi / 180), ("0.05 °", 0.05 * math.pi / 180),
              ("0.05deg", 0.05 * math.pi / 180)],
    "length": [("\u22125mm", -0.005), ("5\u00a0mm", 0.005), ("5\u2009mm", 0.005),
               ("5\u202fmm", 0.005), ("\u22121e\u22123", None)],
    "force": [("\u22121 kN", -1000.0), ("10\u00a0kN", 1e4)],
}


@pytest.mark.parametrize("kind,text,si", [(k, t, v) for k, rows in WRITTEN.items()
                                          for t, v in rows])
def test_units_as_people_write_them_convert_the_same_in_a_cell_and_an_option(kind, text, si):
    """Each written form converts to its SI value (1e-15: one product of factors), and
    a CSV column of it to the same float as the option (one rule for both doors).
    '\u22121e\u22123' keeps the Unicode minus only in the mantissa's place: the exponent's
    is read too, so it is -1e-3 m."""
    si = -1e-3 if si is None else si
    got = parse_quantity("--x", text, kind, positive=False)
    assert math.isclose(got, si, rel_tol=1e-15), (text, got, si)
    values, errors = parse_column("--x", [text, text], kind, positive=False)
    assert errors == ["", ""] and values.tolist() == [got, got]


#: A unit in the wrong case, per kind: what is suggested (first) and what must never be
#: said (pint reads 'MM' as megamolar, a concentration: no word about it for a length).
CASE_ERRORS = [("5MM", "length", "'mm'"), ("1KN", "force", "'kN'"),
               ("210 GPA", "pressure", "'GPa'"), ("3 MRAD", "angle", "'mrad'"),
               ("12 NM", "moment", "'Nm'")]


@pytest.mark.parametrize("text,kind,first", CASE_ERRORS)
def test_a_unit_in_the_wrong_case_is_a_case_error_with_the_unit_of_that_kind(text, kind,
                                                                            first):
    """Refused as a case error naming the unit of the kind first, never explained as a
    unit of another dimension."""
    msg = _refused(text, kind)
    assert "case-sensitive" in msg and f"did you mean {first}" in msg, msg
    assert "substance" not in msg and "molar" not in msg and "got" not in msg, msg


@pytest.mark.parametrize("text,kind,other", [("5 N m", "length", "a moment"),
                                             ("5 kN", "moment", "a force"),
                                             ("5 mJ/m2", "pressure", "a surface energy")])
def test_a_built_in_unit_of_another_kind_is_named_by_its_kind(text, kind, other):
    """A compound name of the wrong kind says what kind it is (without pint)."""
    assert f"got {other}" in _refused(text, kind)


@given(st.lists(st.one_of(st.integers(-5, 5000).map(str), st.floats(-10, 5000).map(repr),
                          st.sampled_from(["3mm", "1e1", "40.5", "14.0", " 7 ", "x"])),
                min_size=1, max_size=12))
def test_a_count_is_a_whole_number_never_rounded(cells):
    """A count (rollers, slices) is a whole number: a fraction is refused naming
    'integer' (40.5 slices were truncated to 40), a unit is refused, 14.0 and 1e1 are
    the integers they write; a column gives each cell's result."""
    _assert_parses_like_its_cells(cells, "count")
    for cell in cells:
        try:
            v = parse_quantity("--n", cell, "count")
        except InputError as exc:
            assert "valid: an integer" in str(exc)
        else:
            assert v == int(v) and v > 0


@pytest.mark.parametrize("text,kind,unit,other", [("5MM", "force", "'mm'", "a length"),
                                                 ("5MM", "pressure", "'mm'", "a length"),
                                                 ("5KN", "length", "'kN'", "a force"),
                                                 ("2MRAD", "length", "'mrad'", "an angle")])
def test_a_unit_of_another_kind_in_the_wrong_case_is_named_by_its_kind(text, kind, unit,
                                                                       other):
    """'5MM' given for a force is neither a force nor, as pint would explain it, a
    concentration ('[substance] / [length] ** 3'): the message says that unit names are
    case-sensitive and which kind the unit it matches apart from case is."""
    msg = _refused(text, kind)
    assert "case-sensitive" in msg and f"{unit} is {other}" in msg, msg
    assert "substance" not in msg and "molar" not in msg, msg
