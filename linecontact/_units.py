"""Unit parsing for the command line (the only place in linecontact that parses units).

The library itself is SI in and SI out; this module turns what a user types
("5mm", "0.2 in", "210 GPa", "1kN", or a bare number meaning SI) into SI floats.
Strings with a unit go through pint (https://pint.readthedocs.io); pint is imported
lazily, on the first string that is not a bare number, so a call with plain SI numbers
does not pay for it.

Every failure raises :class:`InputError`, which names the parameter, the value as typed
and what would have been valid; the CLI prints it as one line.
"""

from __future__ import annotations

import math
import re

__all__ = ["InputError", "DIMENSIONS", "parse_quantity", "parse_sweep"]

#: Physical kinds the CLI understands: pint dimensionality, SI unit, examples for messages.
DIMENSIONS = {
    "length": ("[length]", "m", "5mm, 0.2 in, 0.005"),
    "force": ("[force]", "N", "1kN, 200 lbf, 1000"),
    "pressure": ("[pressure]", "Pa", "210GPa, 30e6 psi, 2.1e11"),
    "dimensionless": ("", "", "0.3"),
}

_NUMBER_FIRST = re.compile(r"^\s*[-+]?(\d|\.\d)")

_REGISTRY = None


class InputError(ValueError):
    """A command-line value that cannot be used.

    Attributes
    ----------
    parameter : str
        Name of the parameter, as the user typed it (``--radius``, or a CSV column).
    value : str
        The value as typed.
    valid : str
        What would have been accepted (a range, a dimension, a format).
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


def _bare_float(text):
    """float(text) for a plain number (no unit), else None."""
    try:
        return float(text)
    except (TypeError, ValueError):
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
        One of :data:`DIMENSIONS`: ``length``, ``force``, ``pressure``, ``dimensionless``.
    positive : bool
        Require a value > 0 (all lengths, forces and moduli of this problem).
    bounds : tuple of (callable, str), optional
        ``(inside, text)``: require ``inside(value)``; ``text`` describes the range
        (for example ``(Interval.contains, Interval.describe())`` of
        :mod:`linecontact.validity`).

    Returns
    -------
    float
        The value in SI units (m, N, Pa, or [-]).

    Raises
    ------
    InputError
        Unparseable text, unknown unit, wrong dimension, non-finite, or out of range.

    Examples
    --------
    >>> parse_quantity("--radius", "0.005", "length")
    0.005
    >>> parse_quantity("--radius", "-1", "length")
    Traceback (most recent call last):
    ...
    linecontact._units.InputError: --radius = '-1': -1 m is not positive; valid: a length > 0 (e.g. 5mm, 0.2 in, 0.005)
    """
    dim, si, examples = DIMENSIONS[kind]
    what = "a number" if kind == "dimensionless" else f"a {kind}"
    valid = (
        bounds[1]
        if bounds
        else f"{what} > 0 (e.g. {examples})" if positive else f"{what} (e.g. {examples})"
    )
    raw = text
    text = str(text).strip()
    value = _bare_float(text)
    if value is None:
        if not text:
            raise InputError(parameter, raw, valid, "empty value")
        if not _NUMBER_FIRST.match(text):
            raise InputError(
                parameter, raw, valid, "expected a number, optionally followed by a unit"
            )
        ureg = _registry()
        try:
            q = ureg.Quantity(text)
        except Exception as exc:  # pint raises several unrelated types (incl. AssertionError)
            detail = str(exc).strip() or type(exc).__name__
            raise InputError(
                parameter, raw, valid, f"cannot read it as a quantity ({detail})"
            ) from None
        if kind == "dimensionless":
            if not q.dimensionless:
                raise InputError(
                    parameter,
                    raw,
                    valid,
                    f"expected a pure number, got units of {q.dimensionality}",
                )
            value = float(q.to("dimensionless").magnitude)
        else:
            if not q.check(dim):
                raise InputError(parameter, raw, valid, f"expected {what}, got {_describe_dim(q)}")
            value = float(q.to(si).magnitude)
    if not math.isfinite(value):
        raise InputError(parameter, raw, valid, "not a finite number")
    unit = f" {si}" if si else ""
    if bounds is not None:
        inside, _ = bounds
        if not inside(value):
            raise InputError(parameter, raw, valid, f"{value:g}{unit} is out of range")
    elif positive and not value > 0:
        raise InputError(parameter, raw, valid, f"{value:g}{unit} is not positive")
    return value


def _describe_dim(q):
    """Name the dimension of a pint quantity in words when it is a common one."""
    for name, (dim, _, _) in DIMENSIONS.items():
        if dim and q.check(dim):
            return f"a {name} ({q.units:~})"
    if q.dimensionless:
        return "a pure number"
    return f"units of {q.dimensionality} ({q.units:~})"


def parse_sweep(parameter, text, kind, *, linear=False, max_points=10000):
    """Parse a value or a range ``START:STOP:N`` into a list of SI floats.

    ``N`` values from ``START`` to ``STOP``, both included, spaced geometrically
    (equal ratios, as one wants for loads spanning decades) unless ``linear`` is true.
    Without a colon the result is a one-element list.

    Examples
    --------
    >>> parse_sweep("--load", "100:10000:3", "force")
    [100.0, 1000.0, 10000.0]
    >>> parse_sweep("--load", "100:300:3", "force", linear=True)
    [100.0, 200.0, 300.0]
    """
    text = str(text)
    if ":" not in text:
        return [parse_quantity(parameter, text, kind)]
    parts = text.split(":")
    fmt = f"START:STOP:N with START, STOP > 0 and 2 <= N <= {max_points}, e.g. 0.1kN:10kN:20"
    if len(parts) != 3:
        raise InputError(parameter, text, fmt, "a range needs exactly three fields")
    start = parse_quantity(f"{parameter} (START)", parts[0], kind)
    stop = parse_quantity(f"{parameter} (STOP)", parts[1], kind)
    try:
        n = int(parts[2].strip())
    except ValueError:
        raise InputError(parameter, text, fmt, f"N = {parts[2]!r} is not an integer") from None
    if not 2 <= n <= max_points:
        raise InputError(parameter, text, fmt, f"N = {n} is out of range")
    if linear:
        return [start + (stop - start) * i / (n - 1) for i in range(n)]
    ratio = stop / start
    values = [start * ratio ** (i / (n - 1)) for i in range(n)]
    values[-1] = stop  # exact end point
    return values
