"""The docstring contract of the public API (numpydoc; see README "Conventions" and the
house style): every function and class named in the ``__all__`` of a linecontact module
has

- a one-line summary;
- a ``Parameters`` section when it takes parameters, naming every one of them, each
  numeric parameter's description ending with its unit in brackets (``[m]``, ``[N]``,
  ``[Pa]``, ``[-]``): at the end of the description or of a sentence of it, optionally
  followed by a parenthetical remark; parameters whose type is not a number (str, bool,
  a table, a callable, ...) carry no unit;
- when it takes a numeric parameter, its validity range: a ``Notes`` section, or a
  range in numbers (``0 < d < inf``, rendered by :func:`linecontact.checks.document`
  or written out);
- an ``Examples`` section with a doctest (they run with the test suite), except for
  exception classes;
- a ``References`` section when it is a formula (its docstring holds a ``.. math::``
  equation).

Every module of the package (bar the command line, the modules it is split into, and
private modules) must have
``__all__``. A failure names the object and what it lacks, so that a new module can be
fixed from the message alone.
"""
from __future__ import annotations

import importlib
import inspect
import pkgutil
import re

import pytest

import linecontact

#: Modules exempt from the contract: the command line and the modules it is split into
#: (input declarations, evaluation, rendering, CSV batches: their "API" is the command,
#: tested in tests/test_cli.py) and private modules (leading underscore).
EXEMPT_MODULES = {"cli", "__main__", "cases", "compute", "render", "batch"}

#: Known gaps, as (module, what is lacking) -> reason: a failure of an object defined in
#: that module whose phrase starts with that text is tolerated. Kept explicit and
#: small, one line per module and clause, each saying who fixes it; an entry that no
#: longer matches any failure makes test_allow_list_holds_only_real_gaps fail, so the
#: list can only shrink. Empty since issue 12.7 closed every gap: fix a new module's
#: docstrings from the failure message rather than listing it here.
ALLOWED = {}

#: Type words of a numeric parameter (which must carry a unit).
_NUMERIC = re.compile(r"^(float|int|array_like|array|ndarray|number|scalar)\b")
#: A unit in brackets that ends the description or a sentence or clause of it, with at
#: most a parenthetical remark after it: "... [m].", "... [-] (see Eq. 9).", "[m] (1D)",
#: "Normal force F [N]: one value or ...".
_UNIT = re.compile(r"\[[^\[\]]+\](\s*\([^()]*\))?[.;:,]?(\s|$)")
_RANGE = re.compile(r"(\d|\binf\b)[^\n]*<|<[^\n]*(\d|\binf\b)")


def _modules():
    names = ["linecontact"]
    for info in pkgutil.iter_modules(linecontact.__path__):
        if info.name.startswith("_") or info.name in EXEMPT_MODULES:
            continue
        names.append(f"linecontact.{info.name}")
    return names


def _sections(doc):
    """{section title: list of its lines} of a numpydoc docstring (dedented)."""
    lines = inspect.cleandoc(doc).splitlines()
    out, current = {"": []}, ""
    i = 0
    while i < len(lines):
        if (i + 1 < len(lines) and lines[i].strip() and set(lines[i + 1].strip()) == {"-"}
                and len(lines[i + 1].strip()) >= 3 and not lines[i].startswith(" ")):
            current = lines[i].strip()
            out[current] = []
            i += 2
            continue
        out[current].append(lines[i])
        i += 1
    return out


def _parameter_entries(lines):
    """[(names, type, description)] of a Parameters section."""
    entries = []
    for line in lines:
        if line.strip() and not line.startswith(" "):
            head, _, typ = line.partition(":")
            entries.append([head.strip(), typ.strip(), []])
        elif entries and line.strip():
            entries[-1][2].append(line.strip())
    return [(n, t, " ".join(d)) for n, t, d in entries]


def _signature_parameters(obj):
    target = obj.__init__ if inspect.isclass(obj) else obj
    try:
        sig = inspect.signature(target)
    except (TypeError, ValueError):
        return []
    return [p for p in sig.parameters.values()
            if p.name not in ("self", "cls")
            and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]


def contract_failures(obj):
    """What the docstring of `obj` lacks, as short phrases (empty when it passes)."""
    doc = inspect.getdoc(obj) if inspect.isclass(obj) else obj.__doc__
    if inspect.isclass(obj) and obj.__doc__ is None:
        doc = None
    if not doc or not doc.strip():
        return ["a docstring"]
    failures = []
    sec = _sections(doc)
    if not sec[""] or not sec[""][0].strip():
        failures.append("a one-line summary")
    params = _signature_parameters(obj)
    numeric = False
    if params:
        if "Parameters" not in sec:
            failures.append("a Parameters section")
        else:
            entries = _parameter_entries(sec["Parameters"])
            documented = {n.strip() for names, _, _ in entries for n in names.split(",")}
            missing = [p.name for p in params if p.name not in documented]
            if missing:
                failures.append(f"Parameters entries for {', '.join(missing)}")
            for names, typ, text in entries:
                if _NUMERIC.search(typ):
                    numeric = True
                    if not _UNIT.search(text):
                        failures.append(f"a unit in brackets ending the description of "
                                        f"parameter {names!r}")
    if numeric and "Notes" not in sec and not _RANGE.search(doc):
        failures.append("a validity range (a Notes section or a range in numbers)")
    is_exception = inspect.isclass(obj) and issubclass(obj, BaseException)
    if not is_exception and ("Examples" not in sec
                             or not any(">>>" in ln for ln in sec["Examples"])):
        failures.append("an Examples section with a doctest")
    if ".. math::" in doc and "References" not in sec:
        failures.append("a References section (it states a formula)")
    return failures


def _public_objects():
    seen = set()
    for modname in _modules():
        module = importlib.import_module(modname)
        for name in getattr(module, "__all__", []):
            obj = getattr(module, name, None)
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue          # constants and instances document themselves elsewhere
            home = f"{obj.__module__}.{obj.__qualname__}"
            if home in seen or not obj.__module__.startswith("linecontact"):
                continue          # a re-export is checked once, where it is defined
            seen.add(home)
            yield home, obj


PUBLIC = list(_public_objects())


@pytest.mark.parametrize("modname", _modules())
def test_every_module_declares_its_public_names(modname):
    module = importlib.import_module(modname)
    assert hasattr(module, "__all__"), f"{modname} has no __all__"
    missing = [n for n in module.__all__ if not hasattr(module, n)]
    assert not missing, f"{modname}.__all__ names what it does not define: {missing}"


def _allowed(obj, failure):
    return any(obj.__module__ == module and failure.startswith(clause)
               for module, clause in ALLOWED)


@pytest.mark.parametrize("home,obj", PUBLIC, ids=[h for h, _ in PUBLIC])
def test_public_docstring_contract(home, obj):
    failures = [f for f in contract_failures(obj) if not _allowed(obj, f)]
    assert not failures, f"{home} docstring lacks: " + "; ".join(failures)


def test_allow_list_holds_only_real_gaps():
    """Each allowed gap must still exist: a fixed one is removed from ALLOWED."""
    stale = [key for key in ALLOWED
             if not any(obj.__module__ == key[0] and f.startswith(key[1])
                        for _, obj in PUBLIC for f in contract_failures(obj))]
    assert not stale, f"remove from ALLOWED (no longer failing): {stale}"


def test_the_checker_sees_each_kind_of_gap():
    """The checker itself: each clause is detected on a function that breaks it, and a
    complete docstring passes."""
    def bare(depth):
        """Depth.

        .. math:: d = 1
        """

    def complete(depth, name="x"):
        """Depth of something.

        Parameters
        ----------
        depth : float
            Depth d, 0 < d < inf [m].
        name : str
            A label.

        Notes
        -----
        Valid for 0 < d < inf.

        Examples
        --------
        >>> complete(1.0)

        References
        ----------
        .. [1] A book.
        """

    def no_unit_no_range(depth, width):
        """Depth of something.

        Parameters
        ----------
        depth : float
            Depth d.

        Examples
        --------
        >>> no_unit_no_range(1.0, 2.0)
        """

    assert contract_failures(complete) == []
    got = contract_failures(bare) + contract_failures(no_unit_no_range)
    for what in ("a Parameters section", "Parameters entries for width",
                 "a unit in brackets ending the description of parameter 'depth'",
                 "a validity range", "an Examples section", "a References section"):
        assert any(what in g for g in got), f"{what!r} not detected: {got}"
