"""Unit parsing for the command line and CSV cells (the only place in linecontact that
parses units).

The library itself is SI in and SI out; this module turns what a user types into SI
floats. The rule, for the command line and for every CSV cell alike, is *a number with
a unit, and nothing more*:

- the number is a plain decimal: optional sign, digits with a decimal POINT, optional
  exponent (``5``, ``0.2``, ``.5``, ``2.1e11``); a decimal comma (``1,5mm``), thousands
  separators, ``inf``, ``nan``, hexadecimal and non-ASCII digits are refused;
- the unit is ONE unit name, letters only, with or without a space before it (``mm``,
  ``GPa``, ``kN``, ``lbf``, ``in``, ``psi``, ``um``, ``µm``, ``°``), or one of the
  compound names of :data:`BUILTIN_UNITS` as people write them (a moment ``N m``,
  ``N·m``, ``N*m``, ``Nm``; a surface energy ``mJ/m^2``, ``mJ/m2``, ``mJ/m²``); any
  other product, quotient, power, sum or expression is refused, never evaluated;
- typography is read as what it means (:func:`normalize`): the Unicode minus sign
  (U+2212) as ``-``, the no-break and thin spaces (U+00A0, U+2009, U+202F, U+2007) as
  a space, the middle dots (U+00B7, U+22C5) as ``*``, the superscript two as ``^2``;
- unit names are case-sensitive (``MM`` is not ``mm``): a name that matches a unit
  of the right kind apart from letter case is refused with a "did you mean", never
  read as some other unit (pint would read ``MM`` as megamolar). The common
  names (:data:`BUILTIN_UNITS`: SI prefixes of m, N, Pa, and inch-pound units) have
  their exact factors here; for any other name pint (https://pint.readthedocs.io) is
  asked only for the size of that one unit in SI, once per distinct unit, so a wrong
  dimension or an unknown name is still refused by name;
- a bare number is SI (m, N, Pa); neither it nor a built-in unit imports pint;
- the value must be a normal, finite float before and after the conversion: a number
  that overflows to inf, or underflows to zero or a subnormal (below 2.2e-308), is
  refused, never clamped.

:func:`parse_quantity` parses one value and :func:`parse_column` a whole column of a
CSV file with the same rules (the same regular expression and the same per-unit SI
factor: one value typed in a cell or on the command line converts to the same float);
the column version parses the numbers with numpy and asks pint once per distinct unit,
which is what makes a 100 000-row batch fast.

Every failure raises (or, for a column, reports per cell) :class:`InputError`, which
names the parameter, the value as typed and what would have been valid; the CLI prints
it as one line and exits with status 2.
"""

from __future__ import annotations

import math
import re
import sys

__all__ = [
    "InputError",
    "DIMENSIONS",
    "BUILTIN_UNITS",
    "parse_quantity",
    "parse_column",
    "parse_sweep",
    "parse_bool",
    "engineering_unit",
    "display_unit",
    "format_numbers",
]

#: Physical kinds the CLI understands: pint dimensionality, SI unit, examples for messages.
DIMENSIONS = {
    "length": ("[length]", "m", "5mm, 0.2 in, 0.005"),
    "force": ("[force]", "N", "1kN, 200 lbf, 1000"),
    "pressure": ("[pressure]", "Pa", "210GPa, 30e6 psi, 2.1e11"),
    "dimensionless": ("", "", "0.3"),
    "count": ("", "", "3, 14, 40"),
    "angle": ("[]", "rad", "0.5mrad, 0.03 deg, 0.03°, 0.0005"),
    "time": ("[time]", "s", "10s, 5min, 2h, 100"),
    "surface_energy": ("[mass] / [time] ** 2", "J/m^2", "50mJ/m^2, 0.05 J/m^2, 0.05"),
    "moment": ("[mass] * [length] ** 2 / [time] ** 2", "N*m", "12 N m, 1.5kNm, 12"),
    "angular_speed": ("1 / [time]", "rad/s", "1500rpm, 157rad/s, 157"),
    "kinematic_viscosity": ("[length] ** 2 / [time]", "m^2/s", "20.7cSt, 2.07e-5"),
    "density": ("[mass] / [length] ** 3", "kg/m^3", "860kg/m^3, 0.86g/cm^3, 860"),
    "inverse_pressure": ("1 / [pressure]", "1/Pa", "2e-8"),
    "temperature_difference": ("[temperature]", "K", "10K, 10"),
}
#: Kinds converted by their built-in names only, never by pint: a temperature
#: difference in 'degC' would be read by pint as an absolute temperature (+273.15), and
#: a speed in 'Hz' as rad/s (pint's radian is a pure number), not revolutions.
_BUILTIN_ONLY = {"temperature_difference", "angular_speed"}

#: A number and an optional single unit name; ASCII digits only (``re.ASCII``).
_NAME = r"[A-Za-z\u00b5\u03bc\u039c\u00b0]+"
QUANTITY = re.compile(
    r"^\s*(?P<number>[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)"
    rf"\s*(?P<unit>{_NAME}(?:(?:\s*\*\s*|\s+){_NAME})*(?:/[A-Za-z]+(?:\^?[0-9])?)?)?\s*$",
    re.ASCII,
)
# re.ASCII: \s and the class above never match other scripts' digits or spaces; the
# micro sign \u00b5 and the Greek mu \u03bc are listed explicitly (for "5 µm"), and the
# capital \u039c so that "5 ΜM" (µm typed in capitals) gets its "did you mean".
# the degree sign \u00b0 too ("0.05°"). A compound name (``mJ/m^2``, ``N m``, ``N*m``) is
# matched as ONE name and converted only if its canonical spelling (:func:`_canonical`)
# is a built-in unit (the moments and surface energies of BUILTIN_UNITS); it is never
# handed to pint.

#: Typography read as what it means (:func:`normalize`): minus sign, no-break, thin
#: and figure spaces, middle dots as a product, superscript two.
_TYPOGRAPHY = str.maketrans({"\u2212": "-", "\u00a0": " ", "\u2009": " ", "\u202f": " ",
                             "\u2007": " ", "\u00b7": "*", "\u22c5": "*", "\u00b2": "^2"})


def normalize(text):
    """`text` with its typography read as ASCII: the Unicode minus (U+2212) as ``-``,
    the no-break, thin, narrow and figure spaces as a space, the middle dots (U+00B7,
    U+22C5) as ``*``, ``²`` as ``^2``; anything else unchanged (other scripts' digits
    and spaces stay refused).

    Examples
    --------
    >>> normalize("\u22125\u00a0mm"), normalize("20 N\u00b7m"), normalize("50 mJ/m\u00b2")
    ('-5 mm', '20 N*m', '50 mJ/m^2')
    """
    return text.translate(_TYPOGRAPHY)

#: Smallest positive normal float: below it a value has lost precision (subnormal).
_TINY = sys.float_info.min

_REGISTRY = None
_FACTORS: dict = {}


class InputError(ValueError):
    """A command-line value or CSV cell that cannot be used.

    Attributes
    ----------
    parameter : str
        Name of the parameter, as the user typed it (``--radius``, or a CSV column).
    value : str
        The value as typed.
    valid : str
        What would have been accepted (a range, a dimension, a format).
    reason : str
        What is wrong with it.
    """

    def __init__(self, parameter, value, valid, reason=""):
        self.parameter = parameter
        self.value = value
        self.valid = valid
        self.reason = reason
        head = f"{parameter}" if value is None or str(value) == "" else f"{parameter} = {value!r}"
        if reason:
            head += f": {reason}"
        super().__init__(f"{head}; valid: {valid}")


def _registry():
    """The shared pint UnitRegistry, created on first use (with pint's disk cache)."""
    global _REGISTRY
    if _REGISTRY is None:
        import pint

        try:
            _REGISTRY = pint.UnitRegistry(cache_folder=":auto:")
        except Exception:  # unwritable cache folder etc.: slower but correct
            _REGISTRY = pint.UnitRegistry()
    return _REGISTRY


def _valid_text(kind, positive, bounds):
    dim, si, examples = DIMENSIONS[kind]
    what = _a(kind)
    if bounds:
        return f"an integer, {bounds[1]}" if kind == "count" else bounds[1]
    if positive:
        return f"{what} > 0 (e.g. {examples})"
    return f"{what} (e.g. {examples})"


_PREFIXES = {"p": 1e-12, "n": 1e-9, "u": 1e-6, "\u00b5": 1e-6, "\u03bc": 1e-6, "m": 1e-3,
             "c": 1e-2, "d": 1e-1, "": 1.0, "k": 1e3, "M": 1e6, "G": 1e9, "T": 1e12}
_INCH = 0.0254  # m, exact by definition (1959)
_LBF = 4.4482216152605  # N, exact: 0.45359237 kg x 9.80665 m/s^2

#: Prefixes offered, largest first (their factors are :data:`_PREFIXES`, the one home
#: of the SI prefixes); shown with the micro sign.
_ENGINEERING = ("T", "G", "M", "k", "", "m", "u", "n", "p")
_SHOWN = {"u": "\u00b5"}
#: Units that take a prefix (the first symbol of a compound such as N/m or N m).
_SI_SYMBOLS = ("m", "N", "Pa", "J", "s", "rad")
#: Units shown without the prefixes above 1 (no km, ks, krad).
_NOT_LARGER = ("m", "s", "rad")


def engineering_unit(values, unit):
    """The SI prefix that fits an array's magnitude: the factor and the prefixed unit.

    The prefix puts the largest finite magnitude of `values` in [1, 1000): a force of
    1.2e-3 N is shown in mN (1e-4 N in µN, not as 0.0001 kN), 2e3 N in kN, a modulus
    of 6.7e4 Pa in kPa. Lengths, times and angles are not shown above their base unit
    (no km, ks, krad).

    Parameters
    ----------
    values : float or array_like
        Values in the SI unit `unit` (NaN and zeros ignored) [`unit`].
    unit : str
        The SI unit: m, N, Pa, J, s, rad, or a compound whose first symbol is one
        (``"N/m"``, ``"N m"``); any other unit (``"-"``, ``"HV"``) is returned as is.

    Returns
    -------
    factor : float
        Multiply the SI values by it [-].
    unit : str
        The prefixed unit (the micro sign for 1e-6).

    Notes
    -----
    Valid for any finite values; the prefixes run from p (1e-12) to T (1e12), the
    factors :data:`_PREFIXES` of the unit parser (one table). Without a finite
    non-zero value the unit is returned unprefixed (factor 1).

    Examples
    --------
    >>> engineering_unit([0.0, 1.2e-3], "N")
    (1000.0, 'mN')
    >>> engineering_unit(6.7e4, "Pa"), engineering_unit(2e3, "N/m")
    ((0.001, 'kPa'), (0.001, 'kN/m'))
    >>> engineering_unit(7e-6, "m"), engineering_unit(3.0, "m")
    ((1000000.0, 'µm'), (1.0, 'm'))
    """
    import numpy as np

    first = unit.replace("/", " ").split(" ")[0]
    if first not in _SI_SYMBOLS:
        return 1.0, unit
    v = np.abs(np.asarray(values, dtype=float)).ravel()
    v = v[np.isfinite(v) & (v > 0)]
    if v.size == 0:
        return 1.0, unit
    top = float(v.max())
    for p in _ENGINEERING:
        f = _PREFIXES[p]
        if f > 1 and first in _NOT_LARGER:
            continue
        if top >= f * (1 - 1e-12) or p == _ENGINEERING[-1]:
            return 1.0 / f, _SHOWN.get(p, p) + unit
    raise AssertionError("unreachable: the last prefix is always taken")


def display_unit(values, si_unit, unit=None, factor=1.0):
    """The unit a column of values is shown in: the usual one where it reads well,
    else the SI prefix that fits (a soft contact's force in mN, not 0.0001 kN).

    Parameters
    ----------
    values : float or array_like
        The column in SI [`si_unit`] (NaN ignored).
    si_unit : str
        Its SI unit (``"N"``, ``"Pa"``, ``"N/m"``).
    unit, factor : str, float, optional
        The usual engineering unit of the column and its factor from SI (``"kN"``,
        1e-3); default the SI unit.

    Returns
    -------
    factor : float
        Multiply the SI values by it [-].
    unit : str
        The unit shown.

    Notes
    -----
    The usual unit is kept when the column's largest finite magnitude in it lies in
    [0.1, 10 000) (read with 4 significant digits without an exponent) or the column
    has no finite non-zero value; otherwise :func:`engineering_unit` picks the prefix
    of the SI unit that puts it in [1, 1000).

    Examples
    --------
    >>> display_unit([1.2e-3, 3e-4], "N", "kN", 1e-3)
    (1000.0, 'mN')
    >>> display_unit([1500.0], "N", "kN", 1e-3), display_unit(2.667e6, "Pa", "GPa", 1e-9)
    ((0.001, 'kN'), (1e-06, 'MPa'))
    """
    import numpy as np

    unit = si_unit if unit is None else unit
    v = np.abs(np.asarray(values, dtype=float)).ravel()
    v = v[np.isfinite(v) & (v > 0)]
    if v.size == 0 or 0.1 <= float(v.max()) * factor < 1e4:
        return factor, unit
    if si_unit.replace("/", " ").split(" ")[0] not in _SI_SYMBOLS:
        return factor, unit  # a unit without prefixes (-, %, HV)
    f, u = engineering_unit(v, si_unit)
    if float(v.max()) * f < 1:  # below the smallest prefix (round-off): as usual
        return factor, unit
    return f, u


#: Round-off: a value below this fraction of its quantity's scale (the largest entry of
#: its column or matrix) is shown as 0. About 500 units in the last place of a double
#: (2.2e-16): the error of sums over a few hundred terms, far below 4 significant digits
#: of any value shown beside it (a sweep spans at most a few decades).
NOISE = 1e-13


def format_numbers(values, digits=4, scale=None):
    """Values as table cells: `digits` significant digits, '-' for none (NaN, None),
    and '0' for round-off (below :data:`NOISE` times `scale`).

    Parameters
    ----------
    values : array_like
        The numbers, already in the unit shown.
    digits : int
        Significant digits.
    scale : float, optional
        The magnitude of the quantity they are parts of (a stiffness matrix's largest
        entry for its off-diagonal terms); default the largest finite magnitude of
        `values`, in their unit.

    Returns
    -------
    list of str

    Examples
    --------
    >>> format_numbers([759.55, -2.96e-17, float("nan")])
    ['759.5', '0', '-']
    >>> format_numbers([-2.96e-14], scale=7.6e5), format_numbers([1e-3, 5.0])
    (['0'], ['0.001', '5'])
    """
    import numpy as np

    v = np.array([np.nan if x is None else x for x in np.ravel(values).tolist()], float)
    if scale is None:
        finite = np.abs(v[np.isfinite(v)])
        scale = float(finite.max()) if finite.size else 0.0
    tiny = NOISE * abs(scale)
    return ["-" if x != x else "0" if abs(x) <= tiny and x != 0 and math.isfinite(x)
            else format(x + 0.0, f".{digits}g") for x in v.tolist()]


#: Unit names converted without pint: the SI prefixes of m, N and Pa, and the inch-pound
#: units of engineering drawings, with their exact definitions. Each factor equals
#: pint's to rounding (a test holds it); any other unit name is asked of pint.
BUILTIN_UNITS = {
    "length": {**{p + "m": f for p, f in _PREFIXES.items()},
               "in": _INCH, "inch": _INCH, "ft": 12 * _INCH, "foot": 12 * _INCH,
               "thou": _INCH / 1000},
    "force": {**{p + "N": f for p, f in _PREFIXES.items()},
              "lbf": _LBF, "kip": 1000 * _LBF, "kgf": 9.80665},
    "pressure": {**{p + "Pa": f for p, f in _PREFIXES.items()},
                 "psi": _LBF / _INCH**2, "ksi": 1000 * _LBF / _INCH**2, "bar": 1e5},
    "angle": {"rad": 1.0, "mrad": 1e-3, "urad": 1e-6, "deg": 3.141592653589793 / 180,
              "\u00b0": 3.141592653589793 / 180},
    "time": {"s": 1.0, "ms": 1e-3, "us": 1e-6, "min": 60.0, "h": 3600.0, "d": 86400.0},
    "surface_energy": {"J/m^2": 1.0, "mJ/m^2": 1e-3, "uJ/m^2": 1e-6, "N/m": 1.0,
                       "mN/m": 1e-3},
    "moment": {"Nm": 1.0, "kNm": 1e3, "Nmm": 1e-3, "MNm": 1e6},
    "angular_speed": {"rad/s": 1.0, "rpm": 3.141592653589793 / 30},
    "kinematic_viscosity": {"cSt": 1e-6, "St": 1e-4},
    "density": {"kg/m^3": 1.0, "g/cm^3": 1e3},
    "temperature_difference": {"K": 1.0},
}
#: Built-in names that pint spells otherwise (pint reads 'Nm' as number-metre): the
#: expression pint gives the same factor for (held by a test).
PINT_SPELLING = {"Nm": "N*m", "kNm": "kN*m", "Nmm": "N*mm", "MNm": "MN*m"}
#: The products of unit names people write for the built-in compound names ("N m",
#: "N*m", "N·m" for "Nm"): factors -> built-in name (:func:`_canonical`).
_PRODUCTS = {tuple(v.split("*")): k for k, v in PINT_SPELLING.items()}


def _canonical(unit):
    """The built-in spelling of a unit name as typed, or the name itself: a product
    of names (``N m``, ``N*m``) -> ``Nm`` when it is a built-in moment, else the
    factors joined by ``*``; a power of the denominator without its caret (``m2``) ->
    ``m^2``.

    Examples
    --------
    >>> _canonical("N m"), _canonical("kN * m"), _canonical("mJ/m2"), _canonical("m m")
    ('Nm', 'kNm', 'mJ/m^2', 'm*m')
    """
    num, slash, den = unit.partition("/")
    factors = tuple(re.split(r"\s*\*\s*|\s+", num.strip()))
    num = _PRODUCTS.get(factors, "*".join(factors))
    if slash:
        den = re.sub(r"\^?([0-9])$", r"^\1", den)
    return num + slash + den


def _a(kind):
    """'a length', 'an angle', 'a number' (for 'dimensionless'), 'an integer' (for
    'count': rollers, slices)."""
    if kind == "dimensionless":
        return "a number"
    if kind == "count":
        return "an integer"
    return f"{'an' if kind[0] in 'aeiou' else 'a'} {kind.replace('_', ' ')}"


def _unit_factor(unit, kind):
    """SI factor of ONE unit name for a quantity of `kind`, or a reason string.

    From :data:`BUILTIN_UNITS`, else asks pint for the unit alone (never for an
    expression), once per (unit, kind).
    """
    key = (unit, kind)
    if key in _FACTORS:
        return _FACTORS[key]
    dim, si, _ = DIMENSIONS[kind]
    name = _canonical(unit)
    other = next((k for k, units in BUILTIN_UNITS.items() if name in units), None)
    if kind in ("dimensionless", "count"):
        result = f"expected a pure number, got the unit {unit!r}"
    elif name in BUILTIN_UNITS.get(kind, ()):
        result = BUILTIN_UNITS[kind][name]
    elif other is not None:  # a built-in unit of another kind: say which, without pint
        result = f"expected {_a(kind)}, got {_a(other)} ({unit})"
    elif any(n.casefold() == name.casefold() for n in BUILTIN_UNITS.get(kind, ())):
        # 'MM', 'KN': a unit of this kind in the wrong case, never read as another
        # unit (pint reads 'MM' as megamolar): unit names are case-sensitive
        result = (f"unknown unit {unit!r} (unit names are case-sensitive: "
                  + _did_you_mean(unit, kind)[2:])
    elif (near := next(((k, n) for k, units in BUILTIN_UNITS.items() for n in units
                        if n.casefold() == name.casefold()), None)) is not None:
        # 'MM' for a force: a unit of ANOTHER kind in the wrong case; pint would
        # explain it as megamolar ('[substance] / [length] ** 3'): say what it is
        result = (f"expected {_a(kind)}, got {unit!r} (unit names are case-sensitive: "
                  f"{near[1]!r} is {_a(near[0])})")
    elif kind in _BUILTIN_ONLY:
        result = (f"unknown unit {unit!r} for {_a(kind)} (the units understood are "
                  f"{', '.join(BUILTIN_UNITS[kind])})")
    elif "/" in name or "*" in name:
        names = [n for units in BUILTIN_UNITS.values() for n in units
                 if "/" in n or n in PINT_SPELLING]
        result = (f"unknown unit {unit!r} (the compound names understood are "
                  f"{', '.join(names)})")
    else:
        ureg = _registry()
        try:
            u = ureg.Unit(unit)
        except Exception:  # pint raises several unrelated types for unknown names
            result = f"unknown unit {unit!r}"
        else:
            if not u.is_compatible_with(si):
                result = f"expected {_a(kind)}, got {_describe_unit(u)}"
            else:
                result = float(ureg.Quantity(1.0, u).to(si).magnitude)
    if isinstance(result, str) and "did you mean" not in result:
        result += _did_you_mean(unit, kind)
    _FACTORS[key] = result
    return result


#: Typical size of each kind in SI, to order the suggestions of :func:`_did_you_mean`
#: (the unit nearest to it first: 'MM' -> 'mm' before 'Mm').
_TYPICAL = {"length": 1e-3, "force": 1e3, "pressure": 1e9, "angle": 1e-3, "time": 1.0,
            "moment": 1.0}


def _did_you_mean(unit, kind):
    """' (did you mean 'mm'?)' for a refused unit name: the units of `kind` that differ
    from it only in letter case ('5MM' is megamolar, '1KN' nothing), else a close
    spelling (difflib); '' when there is none."""
    import difflib
    import math

    names = BUILTIN_UNITS.get(kind, {})
    same = [u for u in names if u.casefold() == unit.casefold() and u != unit]
    if not same:
        same = difflib.get_close_matches(unit, list(names), n=2, cutoff=0.75)
    if not same:
        return ""
    typical = math.log10(_TYPICAL.get(kind, 1.0))
    same.sort(key=lambda u: abs(math.log10(names[u]) - typical))
    return " (did you mean " + " or ".join(repr(u) for u in same) + "?)"


def _describe_unit(u):
    """Name the dimension of a pint unit in words when it is a common one."""
    for name, (dim, si, _) in DIMENSIONS.items():
        if dim and u.is_compatible_with(si):
            return f"{_a(name)} ({u:~})"
    if u.dimensionless:
        return f"a pure number ({u})"
    return f"units of {u.dimensionality} ({u:~})"


def _format_reason(text):
    """Why a string is not 'a number with a unit': the commonest mistakes by name."""
    s = normalize(text).strip()
    if not s:
        return "empty value"
    if "," in s:
        return "a decimal comma or thousands separator (write 1.5mm, not 1,5mm)"
    low = s.lower()
    if re.search(r"\b(inf|infinity|nan)\b", low):
        return "not a finite number"
    if any(c in s for c in "*/^+()") or "**" in s or re.search(r"[A-Za-z]\s+[A-Za-z0-9]", s):
        return "an expression; give one number and one unit name (e.g. 5mm, 210GPa)"
    return "expected a number, optionally followed by one unit name"


def _check_magnitude(value, nonzero):
    """None if `value` is a usable float, else a reason; `nonzero`: the number as
    typed is not zero (so 0.0 means it underflowed)."""
    if value != value:  # NaN (cannot come from the regex, kept for safety)
        return "not a finite number"
    if value in (float("inf"), float("-inf")):
        return "too large: overflows a double-precision number (above 1.8e308)"
    if value == 0.0 and nonzero:
        return "too small: underflows to zero (below 2.2e-308)"
    if value != 0.0 and abs(value) < _TINY:
        return "too small: a subnormal number (below 2.2e-308) has lost precision"
    return None


def parse_quantity(parameter, text, kind, *, positive=True, bounds=None):
    """Parse one value typed by the user into an SI float.

    Parameters
    ----------
    parameter : str
        Name used in error messages (``--radius``).
    text : str or float
        ``"5mm"``, ``"0.2 in"``, ``"210 GPa"``, or a bare number (SI).
    kind : str
        One of :data:`DIMENSIONS`: ``length``, ``force``, ``pressure``, ``dimensionless``,
        ``count`` (a whole number: rollers, slices; a fraction is refused, never
        truncated), ...
    positive : bool
        Require a value > 0 (all lengths, forces and moduli of this problem).
    bounds : tuple of (callable, str), optional
        ``(inside, text)``: require ``inside(value)``; ``text`` describes the range
        (for example ``(Interval.contains, Interval.describe())`` of
        :mod:`linecontact.checks`).

    Returns
    -------
    float
        The value in SI units (m, N, Pa, or [-]).

    Raises
    ------
    InputError
        Not a number with one unit name, unknown unit, wrong dimension, overflow,
        underflow, or out of range.

    Examples
    --------
    >>> parse_quantity("--radius", "0.005", "length")
    0.005
    >>> parse_quantity("--radius", "5 mm", "length")
    0.005
    >>> parse_quantity("--radius", "1,5mm", "length")
    Traceback (most recent call last):
    ...
    linecontact._units.InputError: --radius = '1,5mm': a decimal comma or thousands separator (write 1.5mm, not 1,5mm); valid: a length > 0 (e.g. 5mm, 0.2 in, 0.005)
    >>> parse_quantity("--radius", "-1", "length")
    Traceback (most recent call last):
    ...
    linecontact._units.InputError: --radius = '-1': -1 m is not positive; valid: a length > 0 (e.g. 5mm, 0.2 in, 0.005)
    """
    valid = _valid_text(kind, positive, bounds)
    value, reason = _parse_one(str(text), kind)
    if reason is None:
        reason = _range_reason(value, kind, positive, bounds)
    if reason is not None:
        raise InputError(parameter, text, valid, reason)
    return value


def _parse_one(text, kind):
    """(SI value, None) or (None, reason) for one string: the rule of the module."""
    text = normalize(text)
    m = QUANTITY.match(text)
    if m is None:
        return None, _format_reason(text)
    number, unit = m.group("number"), m.group("unit")
    value = float(number)
    nonzero = re.search(r"[1-9]", re.split(r"[eE]", number)[0]) is not None
    reason = _check_magnitude(value, nonzero)
    if reason is not None:
        return None, reason
    if unit is not None:
        factor = _unit_factor(unit, kind)
        if isinstance(factor, str):
            return None, factor
        value = value * factor
        reason = _check_magnitude(value, nonzero)
        if reason is not None:
            return None, reason + f" after conversion of {unit} to SI"
    return value, None


def _range_reason(value, kind, positive, bounds):
    si = DIMENSIONS[kind][1]
    unit = f" {si}" if si else ""
    if kind == "count" and value != int(value):
        return f"{value:g} is not an integer (a count is never rounded)"
    if bounds is not None:
        inside, _ = bounds
        if not inside(value):
            return f"{value:g}{unit} is out of range"
    elif positive and not value > 0:
        return f"{value:g}{unit} is not positive"
    return None


def parse_column(parameter, cells, kind, *, positive=True, bounds=None):
    """Parse a column of CSV cells with the rules of :func:`parse_quantity`.

    Parameters
    ----------
    parameter : str
        Column name for messages.
    cells : sequence of str
        The cells as read (empty cells must be filtered out by the caller).
    kind, positive, bounds
        As for :func:`parse_quantity`.

    Returns
    -------
    values : ndarray of float
        SI values; NaN where the cell was refused.
    errors : list of str
        ``""`` for a good cell, else the one-line message of the :class:`InputError`
        that :func:`parse_quantity` raises for it.

    Notes
    -----
    The numbers are converted by numpy in one call and pint is asked once per distinct
    unit. When every cell is a plain number with at most one unit name (the usual
    file), the column is split into number and unit by C-level string operations on
    the whole column, without a regular-expression match per cell; otherwise each cell
    is matched (and a refused one gets its reason). The result equals
    ``parse_quantity`` cell by cell (tested property).

    Examples
    --------
    >>> v, e = parse_column("radius", ["5mm", "0.005", "1,5mm"], "length")
    >>> v[:2].tolist(), e[:2], e[2].split(":")[0]
    ([0.005, 0.005], ['', ''], "radius = '1,5mm'")
    """
    import numpy as np

    valid = _valid_text(kind, positive, bounds)
    n = len(cells)
    errors = [""] * n
    split = _split_column(cells) if n else None
    if split is not None:  # every cell a plain number and at most one unit name
        raw, units, codes = split
        groups = [(u, slice(None) if len(units) == 1 else np.flatnonzero(codes == k))
                  for k, u in enumerate(units) if u is not None]
    else:  # some cell needs the regular expression (and perhaps its message)
        raw, groups = _match_column(parameter, cells, valid, errors)
    factors = np.ones(n)
    for unit, idx in groups:
        f = _unit_factor(unit, kind)
        if isinstance(f, str):  # refused: the cell's first reason, as parse_quantity
            for i in (range(n) if isinstance(idx, slice) else idx):  # (a magnitude
                if not errors[i]:                                   # before the unit)
                    errors[i] = str(InputError(parameter, cells[i], valid,
                                               _parse_one(str(cells[i]), kind)[1]))
            factors[idx] = np.nan
        else:
            factors[idx] = f
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        values = raw * factors
    # slow path only for the cells whose magnitude or range is suspect
    tiny = _TINY
    # the typed number too: a subnormal one has lost precision (parse_quantity refuses
    # it) even where its unit's factor (kN, GPa) brings the SI value back above tiny
    ok = np.isfinite(values) & (np.abs(values) >= tiny) & (np.abs(raw) >= tiny)
    if bounds is not None:
        ok &= np.asarray(bounds[0](values), dtype=bool)
    elif positive:
        ok &= values > 0
    if kind == "count":  # a fraction gets its reason from the slow path below
        with np.errstate(invalid="ignore"):
            ok &= values == np.round(values)
    for i in np.flatnonzero(~ok):
        if errors[i]:
            continue
        value, reason = _parse_one(str(cells[i]), kind)
        if reason is None:
            reason = _range_reason(value, kind, positive, bounds)
        if reason is not None:
            errors[i] = str(InputError(parameter, cells[i], valid, reason))
        else:
            values[i] = value  # an exact zero where zero is allowed
    if any(errors):
        values[np.array(list(map(bool, errors)), dtype=bool)] = np.nan
    return values, errors


#: What :func:`_split_column` strips from the right of a cell to leave its number: the
#: unit name's letters (those of :data:`QUANTITY`) and the ASCII spaces around it.
_UNIT_CHARS = ("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
               "\u00b5\u03bc\u039c \t\n\r\x0b\x0c")
#: The characters a number of :data:`QUANTITY` is written with (and the spaces before it).
_NUMBER_CHARS = "0123456789.eE+- \t\n\r\x0b\x0c"
#: str.translate table deleting those characters: what is left is what no number has
#: (one C pass over a joined column, faster than str.strip with a character set).
_NOT_NUMBER = str.maketrans("", "", _NUMBER_CHARS)
#: What is left of a cell after its number: at most one unit name, spaces around it.
_UNIT_ONLY = re.compile(r"\s*(?P<unit>[A-Za-z\u00b5\u03bc\u039c]+)?\s*", re.ASCII)


def _split_column(cells):
    """(numbers, units, codes) of a column whose cells are ALL a plain number and at
    most one unit name of letters, else None (then the regular expression decides,
    cell by cell). `numbers` as typed (float array), `units` the distinct unit names
    (None for a bare number), `codes` the index into `units` of each cell.

    The same split as :data:`QUANTITY`, without a match per cell: the unit is what
    ``str.rstrip`` of letters and spaces removes (a number ends in a digit or a point,
    never a letter), and the rest must be made of the characters of a number only
    (ASCII digits, point, exponent, sign: no underscore, inf, nan or other script's
    digit, all of which Python's float accepts) and be read by numpy's float
    conversion, which refuses any other arrangement of them.
    """
    import itertools

    import numpy as np

    one = _one_unit(cells)
    if one is not None:
        return one
    try:
        numbers = list(map(str.rstrip, cells, itertools.repeat(_UNIT_CHARS)))
    except TypeError:
        return None  # a cell that is not text
    joined = "".join(numbers)
    if joined.translate(_NOT_NUMBER):
        return None  # a character no number has
    try:
        raw = np.array(numbers, dtype=float)
    except ValueError:
        return None  # e.g. '1e', '--5', '' (a unit alone), '5 5'
    if len(joined) == sum(map(len, cells)):  # nothing stripped: bare numbers (SI)
        return raw, [None], None
    rest = list(map(str.removeprefix, cells, numbers))
    if rest.count(rest[0]) == len(rest):
        distinct, codes = [rest[0]], None
    else:
        distinct = list(dict.fromkeys(rest))
        code = {u: k for k, u in enumerate(distinct)}
        codes = np.fromiter(map(code.__getitem__, rest), dtype=np.intp, count=len(rest))
    units = []
    for text in distinct:
        m = _UNIT_ONLY.fullmatch(text)
        if m is None:
            return None  # e.g. '5 m m': refused by the regular expression, with its reason
        units.append(m.group("unit"))
    return raw, units, codes


def _one_unit(cells):
    """:func:`_split_column` of the usual column, every cell a number followed by the
    SAME unit name as the first cell (or every cell a bare number), in whole-column
    string operations: the cells joined by line ends, the first cell's unit removed
    before each line end (all n of them, or this is not such a column), split again.
    None when the column is not of that kind (the general split decides)."""
    import numpy as np

    n = len(cells)
    try:
        text = "\n".join(cells) + "\n"
    except TypeError:
        return None  # a cell that is not text
    if text.count("\n") != n:
        return None  # a line end inside a cell
    first = cells[0]
    unit = first[len(first.rstrip(_UNIT_CHARS)):]
    if unit:
        if unit[0] in _NUMBER_CHARS or text.count(unit + "\n") != n:
            return None  # spaces before the first unit, or another unit somewhere
        text = text.replace(unit + "\n", "\n")
    if text.translate(_NOT_NUMBER):
        return None  # a character no number has (a unit after all, ...)
    try:
        raw = np.array(text.split("\n")[:-1] if unit else cells, dtype=float)
    except ValueError:
        return None  # e.g. '1e', '--5', '' (a unit alone), '5 5'
    return raw, [unit.strip() or None], None


def _match_column(parameter, cells, valid, errors):
    """(numbers, [(unit, indices)]) of a column by :data:`QUANTITY`, one match per
    cell; a cell that does not match gets its message in `errors` and NaN."""
    import numpy as np

    n = len(cells)
    # one C-level pass (typography read as ASCII first, as parse_quantity does)
    matches = [QUANTITY.match(normalize(c)) if isinstance(c, str) else QUANTITY.match(c)
               for c in cells]
    if None in matches:
        numbers = [""] * n
        units = [None] * n
        for i, (cell, m) in enumerate(zip(cells, matches)):
            if m is None:
                errors[i] = str(InputError(parameter, cell, valid,
                                           _format_reason(str(cell))))
                numbers[i] = "nan"
            else:
                numbers[i], units[i] = m.group("number"), m.group("unit")
    else:
        numbers = [m.group("number") for m in matches]
        units = [m.group("unit") for m in matches]
    raw = np.array(numbers, dtype=float) if n else np.zeros(0)
    distinct = set(units) - {None}
    every = len(distinct) == 1 and None not in units
    groups = [(unit, slice(None) if every else [i for i, u in enumerate(units) if u == unit])
              for unit in distinct]
    return raw, groups


def range_error_parts(exc):
    """(valid, reason) of an OutOfRangeError raised on the contents of an input (a row
    of a file, an option of a spec), for the one-line :class:`InputError` of the option
    that named that input: what is wrong and where (``E_inf = '1,5GPa' ('# E_inf'
    line): a decimal comma ...``) and what would have been valid there, not a second
    "is outside the valid range ... valid:" inside the first (and not "outside the
    valid range" for a format problem such as a missing value or a bad row).

    Examples
    --------
    >>> from linecontact.errors import OutOfRangeError
    >>> range_error_parts(OutOfRangeError("design_force", "missing", "(0, inf) N",
    ...                                   hint="the lundberg profile needs it"))
    ('(0, inf) N', "design_force = 'missing': the lundberg profile needs it")
    >>> range_error_parts(OutOfRangeError("x", -0.005, "(> 0) m", unit="m",
    ...                                   where="row 3 of p.csv"))
    ('(> 0) m', 'x = -0.005 m (row 3 of p.csv) is out of range')
    """
    text = isinstance(exc.value, str)
    value = exc.value if text else f"{float(exc.value):.6g}"
    unit = f" {exc.unit}" if exc.unit and not text else ""
    reason = f"{exc.parameter} = {value!r}" if text else f"{exc.parameter} = {value}{unit}"
    if exc.where:
        reason += f" ({exc.where})"
    if exc.hint:
        reason += f": {exc.hint}"
    elif not text:
        reason += " is out of range"
    return exc.valid, reason

def parse_bool(parameter, text):
    """A yes/no option: exactly true/false, yes/no, 1/0 (any case), nothing else.

    Examples
    --------
    >>> parse_bool("extrapolate", "no"), parse_bool("extrapolate", "True")
    (False, True)
    >>> parse_bool("extrapolate", "nope")
    Traceback (most recent call last):
    ...
    linecontact._units.InputError: extrapolate = 'nope': not a yes/no value; valid: true/false, yes/no or 1/0
    """
    s = str(text).strip().lower()
    if s in ("true", "yes", "1"):
        return True
    if s in ("false", "no", "0"):
        return False
    raise InputError(parameter, text, "true/false, yes/no or 1/0", "not a yes/no value")


#: A sweep of each kind for the messages of :func:`parse_sweep`.
_SWEEP_EXAMPLES = {"force": "0.1kN:10kN:20", "length": "0.1um:10um:20",
                   "time": "1s:1h:20", "pressure": "1GPa:100GPa:20"}


def parse_sweep(parameter, text, kind, *, linear=False, max_points=100000, positive=True):
    """Parse a value or a range ``START:STOP:N`` into a list of SI floats.

    ``N`` values from ``START`` to ``STOP``, both included, spaced geometrically
    (equal ratios, as one wants for loads spanning decades) unless ``linear`` is true.
    Without a colon the result is a one-element list. ``positive=False`` accepts
    START or STOP <= 0 (a time sweep from 0) in a linear sweep only.

    Examples
    --------
    >>> parse_sweep("--load", "100:10000:3", "force")
    [100.0, 1000.0, 10000.0]
    >>> parse_sweep("--load", "100:300:3", "force", linear=True)
    [100.0, 200.0, 300.0]
    """
    text = str(text)
    if ":" not in text:
        return [parse_quantity(parameter, text, kind, positive=positive)]
    parts = text.split(":")
    example = _SWEEP_EXAMPLES.get(kind, "1:100:20")
    ends = "START, STOP > 0" if positive else "START, STOP >= 0 (> 0 unless --linear)"
    fmt = f"START:STOP:N with {ends} and 2 <= N <= {max_points}, e.g. {example}"
    if len(parts) != 3:
        raise InputError(parameter, text, fmt, "a range needs exactly three fields")
    start = parse_quantity(f"{parameter} (START)", parts[0], kind, positive=positive)
    stop = parse_quantity(f"{parameter} (STOP)", parts[1], kind, positive=positive)
    if not linear and not (start > 0 and stop > 0):
        raise InputError(parameter, text, fmt + " (or --linear for a range through 0)",
                         "a geometric sweep needs START, STOP > 0")
    if not re.fullmatch(r"\s*[0-9]+\s*", parts[2], re.ASCII):
        raise InputError(parameter, text, fmt, f"N = {parts[2]!r} is not an integer")
    n = int(parts[2])
    if not 2 <= n <= max_points:
        raise InputError(parameter, text, fmt, f"N = {n} is out of range")
    if linear:
        return [start + (stop - start) * i / (n - 1) for i in range(n)]
    import numpy as np

    # equal ratios, exact ends; in logarithms, so that a ratio stop/start beyond the
    # double range (1e-300 N:1e300 N) does not turn the middle values into inf
    return np.geomspace(start, stop, n).tolist()
