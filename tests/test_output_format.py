"""Output people can read (issue 36): every number of the calculator's table in a
unit that fits its column (engineering prefixes chosen from the magnitudes, one helper:
:func:`linecontact._units.display_unit`), round-off shown as zero
(:func:`linecontact._units.format_numbers`), and the table's numbers equal to the JSON's
SI values to the 4 significant digits shown."""

from __future__ import annotations

import contextlib
import io
import json
import re

import numpy as np
import pytest

from linecontact._units import (BUILTIN_UNITS, NOISE, display_unit, engineering_unit,
                                format_numbers)
from linecontact.calc.cli import main


def _calc(argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["calc", *argv]) in (0, None)
    return out.getvalue()


def _factor(unit):
    """SI factor of a table unit such as 'kN', 'um', 'N/um', 'MPa', 'kN/m', 'N m/mrad'."""
    prefixes = {"p": 1e-12, "n": 1e-9, "u": 1e-6, "\u00b5": 1e-6, "m": 1e-3, "": 1.0,
                "k": 1e3, "M": 1e6, "G": 1e9, "T": 1e12}
    if unit in ("-", "%"):
        return 1.0 if unit == "-" else 0.01
    num, _, den = unit.partition("/")
    num = num.split(" ")[0]
    f = next(prefixes[num[:-len(b)]] for b in ("Pa", "N", "m", "J", "s")
             if num.endswith(b) and num[:-len(b)] in prefixes)
    if den:
        f /= next(prefixes[den[:-len(b)]] for b in ("rad", "m")
                  if den.endswith(b) and den[:-len(b)] in prefixes)
    return f


#: Cases from a gel to steel (the modulus spans 6 decades, the load 7): every column
#: must read without an exponent and in the unit that fits it.
CASES = [("3MPa", "0.45", "0.1N"), ("30MPa", "0.45", "2N"), ("3GPa", "0.35", "50N"),
         ("210GPa", "0.3", "1kN"), ("210GPa", "0.3", "100kN")]


@pytest.mark.parametrize("modulus,poisson,load", CASES)
def test_every_column_reads_in_a_unit_that_fits_and_equals_the_json(modulus, poisson, load):
    """Each numeric cell lies in [0.1, 10000) of its column's unit (the usual unit
    kept when it reads so, else the SI prefix putting the largest value in [1, 1000)),
    or is 0 or '-'; cell x unit factor equals the JSON's SI value to the 4 digits shown
    (relative 5e-4: half a unit of the 4th digit)."""
    argv = ["--radius", "5mm", "--length", "10mm", "--modulus", modulus, "--poisson",
            poisson, "--load", load, "--model", "universal,johnson"]
    text = _calc(argv).splitlines()
    doc = json.loads(_calc(argv + ["--json"]))
    header = text[2]
    heads = re.findall(r"(\S[^\[]*?) \[([^\]]+)\]", header)
    rows = {m["label"]: m["rows"][0] for m in doc["models"]}
    fields = list(doc["models"][0]["rows"][0])
    for line in text[3:5]:
        label = next(k for k in rows if line.startswith(k))
        cells = line[len(label):].split()[:len(heads)]
        for (head, unit), cell, field in zip(heads, cells, fields):
            if cell in ("-", "0"):
                continue
            x = float(cell)
            assert 0.1 <= abs(x) < 1e4 or field == "deviation", (head, unit, cell)
            si = rows[label][field]
            assert abs(x * _factor(unit) - si) <= 5e-4 * abs(si), (head, unit, cell, si)
    # the case line: E* with the prefix that fits (no '0.002667 GPa')
    estar = re.search(r"E\* = (\S+) (\S+)", text[0])
    assert 1 <= float(estar.group(1)) < 1000, text[0]


@pytest.mark.parametrize("values,si,eng,factor,expected", [
    ([1.2e-4], "N", "kN", 1e-3, "\u00b5N"),    # a gel's force: not 0.0001 kN
    ([2.667e6], "Pa", "GPa", 1e-9, "MPa"),     # a rubber's E*: not 0.002667 GPa
    ([1e3, 1e5], "N", "kN", 1e-3, "kN"),       # steel: the usual unit kept
    ([5e-9], "m", "um", 1e6, "nm"),
    ([0.0, np.nan], "N", "kN", 1e-3, "kN"),    # nothing to fit: the usual unit
    ([3e4], "m", "mm", 1e3, "m"),               # no km: lengths stop at m
])
def test_display_unit_fits_the_magnitude(values, si, eng, factor, expected):
    """The unit chosen puts the column's largest value in [0.1, 10000) (usual unit) or
    [1, 1000) (SI prefix); lengths are never shown in km."""
    f, unit = display_unit(values, si, eng, factor)
    assert unit == expected
    top = np.nanmax(np.abs(values)) * f
    assert top == 0 or 0.1 <= top < 1e4 or unit == "m"


@pytest.mark.parametrize("values,scale,expected", [
    ([759.55, -2.96e-14 * 1e-3], None, ["759.5", "0"]),     # aligned bearing's K_rt
    ([-2.96e-14], 7.6e5, ["0"]),                             # against its matrix's scale
    ([1e-3, 5.0, -0.0], None, ["0.001", "5", "0"]),          # real small values stay
    ([1e-9], None, ["1e-09"]),                               # alone, a value is its scale
    ([np.nan, None], None, ["-", "-"]),
])
def test_round_off_is_shown_as_zero_relative_to_its_scale(values, scale, expected):
    """A value below NOISE (1e-13, ~500 ulps) of its quantity's scale is round-off and
    shows as 0; anything above keeps 4 significant digits."""
    assert format_numbers(values, scale=scale) == expected
    assert NOISE < 1e-12


def _rollers(argv):
    """The bearing's rollers table: {roller: (M_j cell, tilt cell)} and the JSON's."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["bearing", *argv]) == 0
    lines = out.getvalue().splitlines()
    k = next(i for i, ln in enumerate(lines) if ln.startswith("roller "))
    head = re.split(r"\s{2,}", lines[k])
    jm, jt = head.index("M_j [N m]"), head.index("tilt [mrad]")
    cells = {}
    for ln in lines[k + 1:]:
        if not ln.strip():
            break
        c = ln.split()
        cells[int(c[0])] = (c[jm], c[jt])
    return cells


def test_the_bearing_rollers_moments_and_tilts_show_round_off_as_zero():
    """An aligned ISO-profiled bearing: symmetry makes each roller's moment zero, and
    the solve leaves round-off (|M_j| ~ 1e-16 N m, below NOISE of Q_max L ~ 34 N m):
    the rollers table prints 0, as the summary's K_rt. A misaligned one keeps its real
    moments (about 1e-1 N m) to 4 digits."""
    from linecontact.bearing import RadialRollerBearing

    base = ["--rollers", "14", "--pitch-diameter", "70mm", "--roller-diameter", "11mm",
            "--length", "11mm", "--radial-load", "10kN", "--profile", "iso16281"]
    s = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="iso16281").solve(10e3)
    scale = s.max_roller_load * 11e-3
    assert np.any(s.roller_moments != 0)          # the round-off is there ...
    assert np.all(np.abs(s.roller_moments) <= NOISE * scale)
    assert all(m == "0" and t == "0" for m, t in _rollers(base).values())  # ... not shown
    tilted = _rollers(base + ["--misalignment", "0.5mrad"])
    sm = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="iso16281").solve(
        10e3, misalignment=0.5e-3)
    for j, (m, _) in tilted.items():
        assert m == format_numbers([sm.roller_moments[j]], scale=scale)[0]
    assert any(m != "0" for m, _ in tilted.values())


def test_plot_uses_the_one_engineering_unit():
    """The figures' prefixes and the table's come from one function."""
    import linecontact.plot as plot

    # (plot's public names carry the keyword guard, a wrapper of the same function)
    assert getattr(plot.engineering_unit, "__wrapped__", plot.engineering_unit) \
        is engineering_unit or plot.engineering_unit.__module__ == "linecontact._units"
    assert set(BUILTIN_UNITS["length"]) >= {"mm", "um", "nm"}
