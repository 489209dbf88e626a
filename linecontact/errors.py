"""The errors raised for input outside the library's valid ranges and names.

Every public function of :mod:`linecontact` checks its inputs in physical terms before
any formula sees them (:mod:`linecontact.checks`). A value outside its valid range raises
:class:`OutOfRangeError` (a :class:`ValueError`) whose message names the parameter, the
offending value and the valid range, for example::

    radius = -0.005 m is outside the valid range (0, inf) m

A name that is not one of the known names raises :class:`UnknownNameError`, a keyword
that a ``**options`` catch-all does not take :class:`UnknownKeywordError`, and inputs
valid each but not together :class:`CombinationError`. Each is one line, keeps what was
given as attributes and survives pickling (so it can cross process boundaries).
"""
from __future__ import annotations

import numpy as np

__all__ = [
    "OutOfRangeError",
    "UnknownNameError",
    "UnknownKeywordError",
    "CombinationError",
]


class OutOfRangeError(ValueError):
    """An input lies outside the range in which the formula or table is valid.

    Parameters
    ----------
    parameter : str
        Name of the offending parameter, as in the function signature.
    value : float or str
        The offending value (the first offending element of an array), in the unit
        `unit` [`unit`]; a str describes a value that is not a number.
    valid : str
        The valid range, e.g. ``"(0, inf) m"`` or ``"[0.1, 6]"``.
    unit : str, optional
        Unit of `value`, printed after it.
    hint : str, optional
        What to do instead; appended to the message.
    where : str, optional
        Where the value sits, printed in parentheses after it (e.g. ``"element [1] of
        shape (2,)"`` or ``"at depth 1e-06 m"``).

    Notes
    -----
    No range applies to the error itself: any name, value and range are accepted. A
    numeric value is printed with 6 significant digits (``%.6g``); the attributes
    ``parameter``, ``value``, ``valid``, ``unit``, ``hint`` and ``where`` keep what was
    given, and the error survives pickling (so it can cross process boundaries).

    Examples
    --------
    >>> err = OutOfRangeError("radius", -0.005, "(0, inf) m", unit="m")
    >>> str(err)
    'radius = -0.005 m is outside the valid range (0, inf) m'
    >>> isinstance(err, ValueError), err.parameter, err.value, err.valid
    (True, 'radius', -0.005, '(0, inf) m')
    """

    def __init__(self, parameter, value, valid, *, unit="", hint="", where=""):
        self.parameter = parameter
        self.value = value
        self.valid = valid
        self.unit = unit
        self.hint = hint
        self.where = where
        if isinstance(value, (float, int, np.floating, np.integer)):
            shown = f"{float(value):.6g}"
        else:
            shown = repr(value) if isinstance(value, str) else str(value)
        msg = f"{parameter} = {shown}{' ' + unit if unit else ''}"
        if where:
            msg += f" ({where})"
        msg += f" is outside the valid range {valid}"
        if hint:
            msg += f"; {hint}"
        super().__init__(msg)

    def __reduce__(self):  # keep picklable despite the keyword-only arguments
        return (_rebuild, (self.parameter, self.value, self.valid, self.unit, self.hint,
                           self.where))


def _rebuild(parameter, value, valid, unit, hint, where):
    return OutOfRangeError(parameter, value, valid, unit=unit, hint=hint, where=where)


class UnknownNameError(ValueError):
    """A name (a model key, a profile, an option, a method) that is not one of the known
    names; the message lists them.

    Parameters
    ----------
    parameter : str
        Name of the parameter that took the name, as in the function signature.
    value : object
        The unknown name (printed with repr).
    valid : iterable of str
        The names accepted there.
    hint : str, optional
        What to do instead; appended to the message.

    Notes
    -----
    Not an :class:`OutOfRangeError`: a name has no range. The attributes
    ``parameter``, ``value`` and ``valid`` (a tuple) keep what was given; the error
    survives pickling.

    Examples
    --------
    >>> err = UnknownNameError("model", "hertz", ["universal", "kunz"])
    >>> str(err)
    "model = 'hertz' is not a known name; valid: 'universal', 'kunz'"
    >>> isinstance(err, ValueError), isinstance(err, OutOfRangeError)
    (True, False)
    """

    def __init__(self, parameter, value, valid, *, hint=""):
        self.parameter = parameter
        self.value = value
        self.valid = tuple(valid)
        self.hint = hint
        names = ", ".join(repr(v) for v in self.valid)
        msg = f"{parameter} = {value!r} is not a known name; valid: {names}"
        super().__init__(msg + (f"; {hint}" if hint else ""))

    def __reduce__(self):
        return (_rebuild_name, (self.parameter, self.value, self.valid, self.hint))


def _rebuild_name(parameter, value, valid, hint):
    return UnknownNameError(parameter, value, valid, hint=hint)


class UnknownKeywordError(UnknownNameError, TypeError):
    """A keyword that a ``**options`` catch-all does not take: the message names it, the
    close match ("did you mean") and every keyword it does take.

    Raised where options are passed on rather than bound by Python: a model's
    constructor reached through :func:`~linecontact.models.get_model`,
    :func:`linecontact.depth` and the other one-liners or a contact's ``**options``,
    and :func:`~linecontact.calc.frame.calc_frame`; elsewhere an unknown keyword is
    Python's own ``TypeError``, which names it too.

    A :class:`UnknownNameError` (so a :class:`ValueError`, as every input error of the
    library) and a :class:`TypeError` (what Python raises for an unexpected keyword, so
    ``except TypeError`` still catches it).

    Parameters
    ----------
    function : str
        The callable's name as the user wrote it (``"JohnsonModel"``,
        ``"calc_frame"``).
    keyword : str
        The keyword it does not take.
    valid : iterable of str
        The keywords it takes.

    Notes
    -----
    One line, ``johnson_depth keyword = 'cc' is not a known name; valid: ...; did you
    mean 'c'?``; the close match is :func:`difflib.get_close_matches` (cutoff 0.6, and
    a case-insensitive equal name first). The attributes ``function``, ``keyword`` and
    ``valid`` keep what was given; the error survives pickling.

    Examples
    --------
    >>> err = UnknownKeywordError("johnson_depth", "cc",
    ...                           ["force", "radius", "length", "estar", "c"])
    >>> str(err)
    "johnson_depth keyword = 'cc' is not a known name; valid: 'force', 'radius', 'length', 'estar', 'c'; did you mean 'c'?"
    >>> isinstance(err, ValueError), isinstance(err, TypeError)
    (True, True)
    """

    def __init__(self, function, keyword, valid):
        import difflib

        self.function = function
        self.keyword = keyword
        valid = tuple(valid)
        same = [v for v in valid if str(v).lower() == str(keyword).lower()]
        close = same or difflib.get_close_matches(str(keyword), [str(v) for v in valid],
                                                  n=2, cutoff=0.6)
        hint = ("did you mean " + " or ".join(repr(c) for c in close) + "?") if close \
            else ""
        super().__init__(f"{function} keyword", keyword, valid, hint=hint)

    def __reduce__(self):
        return (UnknownKeywordError, (self.function, self.keyword, self.valid))


class CombinationError(ValueError):
    """Inputs that are each valid but whose combination is not defined physically (or
    not by the methods here): names every parameter and value involved, and why.

    Parameters
    ----------
    parameters : dict
        Parameter name -> the value given (numbers printed with 6 digits, other values
        with repr), in the order they should be named.
    reason : str
        Why the combination is refused (one clause, no trailing period).
    unit : dict, optional
        Parameter name -> unit of its value, printed after it.

    Notes
    -----
    One line, ``a = 1, b = 'x': reason``. The attributes ``parameters``, ``reason`` and
    ``unit`` keep what was given; the error survives pickling.

    Examples
    --------
    >>> err = CombinationError({"tilt": "free", "material2": "viscoelastic"},
    ...                        "Lee-Radok needs a contact shape fixed in time")
    >>> str(err)
    "tilt = 'free', material2 = 'viscoelastic': Lee-Radok needs a contact shape fixed in time"
    """

    def __init__(self, parameters, reason, unit=None):
        self.parameters = dict(parameters)
        self.reason = reason
        self.unit = dict(unit or {})
        parts = []
        for name, value in self.parameters.items():
            if isinstance(value, (float, int, np.floating, np.integer)) and not isinstance(
                    value, bool):
                shown = f"{float(value):.6g}"
            else:
                shown = repr(value)
            u = self.unit.get(name, "")
            parts.append(f"{name} = {shown}{' ' + u if u else ''}")
        super().__init__(f"{', '.join(parts)}: {reason}")

    def __reduce__(self):
        return (CombinationError, (self.parameters, self.reason, self.unit))
