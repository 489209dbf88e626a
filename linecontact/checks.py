"""Validity ranges as data, and the checks that refuse input outside them.

Every public function of :mod:`linecontact` checks its inputs in physical terms before
any formula sees them. A value outside its valid range raises
:class:`~linecontact.errors.OutOfRangeError` (a :class:`ValueError`) whose message names
the parameter, the offending value and the valid range, for example::

    radius = -0.005 m is outside the valid range (0, inf) m

Nothing is clamped and no NaN is returned silently.

The ranges themselves are :class:`Interval` objects, so that the same data renders the
Notes section of a docstring (:func:`document`) and the error message.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import OutOfRangeError

__all__ = [
    "Interval",
    "check_positive",
    "check_interval",
    "check_scaled",
    "check_flag",
    "document",
    "POSITIVE_LENGTH",
    "POSITIVE_FORCE",
    "POSITIVE_DEPTH",
    "POSITIVE_MODULUS",
    "POISSON_RATIO",
]


def _fmt(x):
    x = float(x)
    if np.isinf(x):
        return "inf" if x > 0 else "-inf"
    return f"{x:.6g}"


@dataclass(frozen=True)
class Interval:
    """A validity range ``low .. high`` with open or closed ends and a unit.

    Parameters
    ----------
    name : str
        The parameter the range applies to (used in messages).
    low, high : float
        Ends of the range, -inf <= low <= high <= inf; ``-inf``/``inf`` for unbounded
        [`unit`].
    low_open, high_open : bool
        Whether an end is excluded (default: both ends included, also an infinite
        one, so that e.g. a rigid body's E = inf can be accepted; pass
        ``high_open=True`` to exclude inf).
    unit : str
        Unit of the quantity, e.g. ``"m"``, ``"Pa"``; empty for dimensionless.
    rtol : float
        Rounding allowance at finite ends: a value within ``rtol * |end|`` outside an
        end counts as that end (and is returned as it), so that e.g. L/R computed as
        (1.9 * 25e-3)/(1.9 * 5e-3) = 4.999999999999999 is accepted at a closed end 5.
        Default 0 (exact); 0 <= rtol << 1 (the library uses 1e-12) [-].

    Examples
    --------
    >>> L_over_R = Interval("L/R", 0.1, 6)
    >>> str(L_over_R)
    '[0.1, 6]'
    >>> L_over_R.describe()
    '0.1 <= L/R <= 6'
    >>> L_over_R.check([0.5, 2.0])
    array([0.5, 2. ])
    >>> L_over_R.check(7.0)
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: L/R = 7 is outside the valid range [0.1, 6]
    """

    name: str
    low: float
    high: float
    low_open: bool = False
    high_open: bool = False
    unit: str = ""
    rtol: float = 0.0

    def __str__(self):
        left = "(" if self.low_open else "["
        right = ")" if self.high_open else "]"
        s = f"{left}{_fmt(self.low)}, {_fmt(self.high)}{right}"
        return f"{s} {self.unit}" if self.unit else s

    def describe(self):
        """The range as an inequality, for docstrings: ``'0 < radius < inf m'``."""
        lo = "<" if self.low_open else "<="
        hi = "<" if self.high_open else "<="
        s = f"{_fmt(self.low)} {lo} {self.name} {hi} {_fmt(self.high)}"
        return f"{s} {self.unit}" if self.unit else s

    def contains(self, value):
        """Elementwise membership (NaN is never inside)."""
        v = np.asarray(value, dtype=float)
        above = v > self.low if self.low_open else v >= self.low
        below = v < self.high if self.high_open else v <= self.high
        return above & below

    def check(self, value, *, name=None, hint=""):
        """Return `value` as a float array, or raise :class:`OutOfRangeError`.

        `name` overrides the interval's parameter name in the message.
        """
        if not self.rtol:
            return check_interval(
                name or self.name, value, self.low, self.high,
                low_open=self.low_open, high_open=self.high_open, unit=self.unit,
                hint=hint)
        v = _as_float_array(name or self.name, value, self.unit)
        lo, hi = self.low, self.high
        if np.isfinite(lo) and not self.low_open:
            v = np.where((v < lo) & (v >= lo - self.rtol * abs(lo)), lo, v)
        if np.isfinite(hi) and not self.high_open:
            v = np.where((v > hi) & (v <= hi + self.rtol * abs(hi)), hi, v)
        try:
            return check_interval(
                name or self.name, v, lo, hi, low_open=self.low_open,
                high_open=self.high_open, unit=self.unit, hint=hint)
        except OutOfRangeError:
            # report the value as given, not as rounded
            return check_interval(
                name or self.name, value, lo, hi, low_open=self.low_open,
                high_open=self.high_open, unit=self.unit, hint=hint)


#: pint unit of each unit string used in the checks (the library's SI units).
_PINT_UNITS = {"m": "meter", "N": "newton", "Pa": "pascal", "N/m": "newton / meter",
               "": "dimensionless"}


def _as_float_array(name, value, unit=""):
    """`value` as a float array in SI, refusing what would silently lose information.

    Refused (:class:`OutOfRangeError`): complex numbers with a nonzero imaginary part,
    masked arrays with masked elements (the mask would be dropped), booleans,
    datetimes and timedeltas, strings (the library takes numbers in SI; the command
    line parses units), and subnormal numbers (nonzero below 2.2e-308: precision lost).
    A pint Quantity is converted to `unit` (SI), or refused if its dimension differs;
    the check does not import pint (it recognises a Quantity by its attributes).
    """
    kind = type(value)
    if kind is float or (kind is np.ndarray and value.dtype == np.float64):
        v = np.asarray(value)  # the common case: nothing to refuse but subnormals
        return _refuse_subnormal(name, v, unit)
    if hasattr(value, "dimensionality") and hasattr(value, "magnitude") \
            and hasattr(value, "to"):
        target = _PINT_UNITS.get(unit, unit)
        try:
            value = value.to(target).magnitude
        except Exception as exc:  # pint's DimensionalityError or an unknown unit
            raise OutOfRangeError(
                name, str(value), f"a quantity in {unit or 'dimensionless units'}",
                hint=f"its dimension {value.dimensionality} is not that of "
                     f"{target}") from exc
    if np.ma.isMaskedArray(value) and np.ma.getmaskarray(value).any():
        raise OutOfRangeError(
            name, "a masked array with masked elements", "an array of real numbers",
            hint="the mask would be lost; fill or drop the masked values first "
                 "(numpy.ma.filled or .compressed())")
    if isinstance(value, (bool, np.bool_)) or (
            isinstance(value, (list, tuple)) and _has_bool(value)):
        raise OutOfRangeError(name, repr(value), "real numbers, not booleans")
    if isinstance(value, (str, bytes)):
        raise OutOfRangeError(name, value, f"a number in {unit or '[-]'} (SI)",
                              hint="the library takes numbers in SI; units are parsed "
                                   "by the command line")
    import datetime as _dt
    if isinstance(value, (_dt.date, _dt.time, _dt.timedelta, np.datetime64,
                          np.timedelta64)):
        raise OutOfRangeError(name, str(value), "real numbers, not dates or durations")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError) as exc:
        raise OutOfRangeError(name, str(value), "real numbers",
                              hint="it is not a number") from exc
    kind = arr.dtype.kind
    if kind == "b":
        raise OutOfRangeError(name, "an array of booleans", "real numbers, not booleans")
    if kind in "mM":
        raise OutOfRangeError(name, f"an array of {arr.dtype}",
                              "real numbers, not dates or durations")
    if kind in "USa":
        raise OutOfRangeError(name, "an array of strings", f"numbers in {unit or '[-]'}"
                              " (SI)", hint="the library takes numbers in SI; units are "
                              "parsed by the command line")
    if kind == "c":
        if np.any(arr.imag != 0):
            raise OutOfRangeError(name, "a complex value with a nonzero imaginary part",
                                  "real numbers",
                                  hint="the imaginary part would be dropped")
        arr = arr.real
    if kind == "O":
        flat = arr.ravel()
        if any(isinstance(x, (bool, np.bool_)) for x in flat):
            raise OutOfRangeError(name, repr(value), "real numbers, not booleans")
        if any(isinstance(x, complex) and x.imag != 0 for x in flat):
            raise OutOfRangeError(name, "a complex value with a nonzero imaginary part",
                                  "real numbers", hint="the imaginary part would be dropped")
        if any(hasattr(x, "dimensionality") for x in flat):
            raise OutOfRangeError(name, "an array of pint Quantities", "real numbers in SI, "
                                  "or one Quantity holding an array")
        if any(isinstance(x, (str, bytes, _dt.date, _dt.timedelta, np.datetime64,
                              np.timedelta64)) for x in flat):
            raise OutOfRangeError(name, repr(value), "real numbers")
        flat = [x.real if isinstance(x, complex) else x for x in flat]
        arr = np.asarray(flat).reshape(arr.shape)
    try:
        v = np.asarray(arr, dtype=float)
    except (TypeError, ValueError) as exc:
        raise OutOfRangeError(name, str(value), "real numbers",
                              hint="it is not a number") from exc
    return _refuse_subnormal(name, v, unit)


_TINY = float(np.finfo(float).tiny)
#: the largest integer a float holds exactly (larger ones take the general path)
_EXACT_INT = 2 ** 53


def _exact_scalar(x):
    """Whether check_interval's scalar fast path takes x (a value or a fixed end): a
    float, or an int a float holds exactly. The general path compares float arrays;
    the fast path compares the Python numbers themselves, which is the same only for
    these (an end of 2^53 + 1 rounds there; an int end of 10^400 overflows there)."""
    kind = type(x)
    return kind is float or kind is np.float64 or (
        kind is int and -_EXACT_INT <= x <= _EXACT_INT)


def _refuse_subnormal(name, v, unit):
    """`v`, or OutOfRangeError for its first subnormal element (precision lost)."""
    if v.ndim == 0:
        x = float(v)
        if x != 0.0 and -_TINY < x < _TINY:
            raise OutOfRangeError(name, x, f"0 or |{name}| >= {_TINY:.6g}", unit=unit,
                                  hint="a subnormal number has lost precision")
        return v
    if v.size:
        # two reductions, no temporaries: no subnormal when every element lies on one
        # side of zero beyond tiny (NaN makes both tests false: the full check below)
        vmin, vmax = v.min(), v.max()
        if vmin >= _TINY or vmax <= -_TINY:
            return v
    small = np.abs(v) < _TINY  # NaN compares False
    if small.any():
        sub = small & (v != 0)
        if sub.any():
            raise OutOfRangeError(name, float(v[sub].ravel()[0]),
                                  f"0 or |{name}| >= {_TINY:.6g}", unit=unit,
                                  hint="a subnormal number has lost precision")
    return v


def check_scaled(name, value, scale, scaled, unit=""):
    """`value` (checked positive), or OutOfRangeError where value/scale, the
    dimensionless variable `scaled` a model computes with, is below the smallest
    normal double (2.2e-308): a subnormal number has lost precision and its reciprocal
    overflows, so that a model would answer inf for a tiny input. The error names the
    parameter and the smallest value accepted (2.2e-308 times the scale).

    Parameters
    ----------
    name : str
        The parameter's name in the error [-].
    value : float or array_like
        The values, already checked positive [unit].
    scale : float or array_like
        The scale that makes them dimensionless (broadcast with `value`) [unit].
    scaled : str
        The dimensionless variable's description, for the error [-].
    unit : str, optional
        The unit of `value` and `scale` [-].

    Returns
    -------
    float or ndarray
        `value`, unchanged.

    Notes
    -----
    Accepts value/scale >= 2.2250738585072014e-308 (numpy.finfo(float).tiny).

    Examples
    --------
    >>> check_scaled("force", 1e-305, 4.6e3, "force F R/(E* L^3)", "N")
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: force = 1e-305 N is outside the valid range >= 1.02353e-304 N; below it the dimensionless force F R/(E* L^3) is a subnormal number (precision lost)
    """
    v = np.asarray(value)
    if v.size == 0:
        return value
    sc = np.asarray(scale, dtype=float)
    if sc.ndim == 0:
        if float(v.min()) >= _TINY * float(sc):
            return value
        ratio = np.broadcast_to(v / sc, v.shape)
    else:
        ratio = v / sc
        if float(ratio.min()) >= _TINY:
            return value
    bad = np.flatnonzero(np.ravel(ratio) < _TINY)
    k = int(bad[0])
    low = _TINY * float(np.ravel(np.broadcast_to(sc, ratio.shape))[k])
    where = f"element {k}" if ratio.ndim else ""
    raise OutOfRangeError(name, float(np.ravel(np.broadcast_to(v, ratio.shape))[k]),
                          f">= {low:.6g} {unit}".rstrip(), unit=unit, where=where,
                          hint=f"below it the dimensionless {scaled} is a subnormal "
                               "number (precision lost)")


def _has_bool(seq):
    """True if a (nested) list or tuple holds a bool anywhere."""
    for x in seq:
        if isinstance(x, (bool, np.bool_)):
            return True
        if isinstance(x, (list, tuple)) and _has_bool(x):
            return True
    return False


def check_interval(name, value, low, high, *, low_open=False, high_open=False, unit="",
                   hint=""):
    """Check that every element of `value` lies in the interval low..high.

    `low` and `high` may be arrays that broadcast against `value` (a bound that depends
    on other inputs, such as the depth bound beta L^2/R). NaN is always outside.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : array_like
        Values to check, in the unit `unit` (SI) [`unit`].
    low, high : float or array_like
        Ends of the range, in the same unit as `value` [`unit`].
    low_open, high_open : bool, optional
        Exclude the end points (closed by default).
    unit : str, optional
        Unit printed after the value and the range.
    hint : str, optional
        Appended to the error message.

    Returns
    -------
    ndarray of float
        `value` converted to a float array (0-d for a scalar) [`unit`].

    Raises
    ------
    OutOfRangeError
        Naming the first offending element, its value and the range.

    Notes
    -----
    Valid input: real numbers, -inf <= value <= inf, and ends -inf <= low, high <= inf,
    open or closed as asked. NaN is always outside; complex numbers with a nonzero
    imaginary part, booleans, strings, dates, masked arrays with masked elements and
    subnormal numbers (0 < |value| < 2.2e-308) are refused before the comparison; a
    pint Quantity is converted to `unit` first.

    Examples
    --------
    >>> check_interval("poisson", 0.3, 0.0, 0.5, high_open=True)
    array(0.3)
    >>> check_interval("poisson", [0.3, 0.5], 0.0, 0.5, high_open=True)
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: poisson = 0.5 (element [1] of shape (2,)) is outside the valid range [0, 0.5)
    """
    if _exact_scalar(value) and _exact_scalar(low) and _exact_scalar(high):
        # one Python number between fixed ends (every constructor and solve checks
        # several): the comparisons of the general path below on Python floats, the
        # same answer (NaN and subnormals fail here and take that path, which names
        # them) at a fraction of its numpy calls
        x = float(value)
        if ((x > low if low_open else x >= low) and (x < high if high_open else x <= high)
                and (x == 0.0 or not -_TINY < x < _TINY)):
            return np.asarray(x)
    v = _as_float_array(name, value, unit)
    lo = np.asarray(low, dtype=float)
    hi = np.asarray(high, dtype=float)
    if v.ndim and v.size and lo.ndim == 0 and hi.ndim == 0:
        # fixed ends: the smallest and largest element decide (NaN fails both tests
        # and takes the elementwise path below, which names it)
        vmin, vmax = v.min(), v.max()
        if ((vmin > lo if low_open else vmin >= lo)
                and (vmax < hi if high_open else vmax <= hi)):
            return v
    elif not v.ndim and lo.ndim == 0 and hi.ndim == 0:
        # a scalar between fixed ends (every constructor and solve checks several):
        # two comparisons, without the masks below (NaN fails them and takes that path)
        if ((v > lo if low_open else v >= lo)
                and (v < hi if high_open else v <= hi)):
            return v
    above = v > lo if low_open else v >= lo
    below = v < hi if high_open else v <= hi
    ok = above & below
    if ok.all():
        return v
    shape = ok.shape
    idx = tuple(int(i) for i in np.argwhere(~ok)[0]) if shape else ()
    bv = np.broadcast_to(v, shape)[idx]
    blo = np.broadcast_to(lo, shape)[idx]
    bhi = np.broadcast_to(hi, shape)[idx]
    left = "(" if low_open else "["
    right = ")" if high_open else "]"
    valid = f"{left}{_fmt(blo)}, {_fmt(bhi)}{right}" + (f" {unit}" if unit else "")
    where = f"element {list(idx)} of shape {shape}" if shape else ""
    raise OutOfRangeError(name, float(bv), valid, unit=unit, hint=hint, where=where)


def check_positive(name, value, unit="", *, hint=""):
    """Check that every element of `value` is finite and > 0; return a float array.

    The common case of :func:`check_interval`: the range is 0 < value < inf.

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : array_like
        Values to check, in the unit `unit` (SI) [`unit`].
    unit : str, optional
        Unit printed after the value and the range.
    hint : str, optional
        Appended to the error message.

    Returns
    -------
    ndarray of float
        `value` converted to a float array (0-d for a scalar) [`unit`].

    Raises
    ------
    OutOfRangeError
        Naming the first element that is not in 0 < value < inf.

    Examples
    --------
    >>> check_positive("radius", 0.005, "m")
    array(0.005)
    >>> check_positive("radius", -0.005, "m")
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: radius = -0.005 m is outside the valid range (0, inf) m
    """
    return check_interval(name, value, 0.0, np.inf, low_open=True, high_open=True,
                          unit=unit, hint=hint)


def document(**ranges):
    """Decorator: render validity ranges into a docstring.

    Each ``%(key)s`` in the docstring is replaced by ``ranges[key].describe()`` (an
    :class:`Interval`) or by ``str(ranges[key])`` for anything else, so the range printed
    in the Notes is the one the code enforces.

    Examples
    --------
    >>> @document(R=Interval("radius", 0, float("inf"), True, True, "m"))
    ... def f(radius):
    ...     "Valid for %(R)s."
    >>> f.__doc__
    'Valid for 0 < radius < inf m.'
    """
    def deco(func):
        doc = func.__doc__ or ""
        for key, rng in ranges.items():
            text = rng.describe() if isinstance(rng, Interval) else str(rng)
            doc = doc.replace(f"%({key})s", text)
        func.__doc__ = doc
        return func
    return deco


#: Ranges shared by many functions (rendered in their docstrings).
POSITIVE_LENGTH = Interval("length", 0.0, np.inf, True, True, "m")
POSITIVE_FORCE = Interval("force", 0.0, np.inf, True, True, "N")
POSITIVE_DEPTH = Interval("depth", 0.0, np.inf, True, True, "m")
POSITIVE_MODULUS = Interval("modulus", 0.0, np.inf, True, True, "Pa")
#: Poisson's ratio: 0.5 (incompressible: rubber, elastomer coatings) is included; E* of
#: Eq. 3 stays finite there, 1 - nu^2 = 0.75 (Li & Popov (2017), Eq. 3).
POISSON_RATIO = Interval("poisson", 0.0, 0.5, False, False, "")


def check_flag(name, value):
    """Check that a yes/no option is a real boolean; return it as a Python bool.

    A string such as ``"no"`` is truthy in Python, so ``bool("no")`` would silently
    turn the option on: only ``True``/``False`` (or numpy booleans) are accepted. The
    command line parses its words (true/false, yes/no, 1/0) before calling the library.

    Parameters
    ----------
    name : str
        Parameter name for the message [-].
    value : bool
        The option's value [-].

    Returns
    -------
    bool
        `value` [-].

    Raises
    ------
    OutOfRangeError
        Anything that is not a boolean (the message names the parameter and value).

    Notes
    -----
    Valid values: ``True``, ``False``, ``numpy.True_``, ``numpy.False_``.

    Examples
    --------
    >>> check_flag("extrapolate", False)
    False
    >>> check_flag("extrapolate", "no")
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: extrapolate = 'no' is outside the valid range True or False; a yes/no option takes a boolean, not a word or number

    References
    ----------
    Python Language Reference, section 'Truth Value Testing' (why bool('no') is True).
    """
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise OutOfRangeError(name, value, "True or False",
                          hint="a yes/no option takes a boolean, not a word or number")

