"""The compiled engine and the choice of engine.

The library's hot loops exist twice: as numpy code, the reference, and in C, the one
compiled engine: the optional extension module ``linecontact._ckernels``, built by
setup.py where a C compiler exists from two sources, the profiled-roller solver's
kernels (linecontact/roller/_ckernels.c, engine ``"c"``) and the subsurface stresses'
corner sums (linecontact/_cstresses.c). Both compute what the numpy code computes, in
IEEE arithmetic, and agree with it to rounding (docs/profiled_rollers.md, "Engines").

The extension carries the SHA-256 of the sources it was built from (``SOURCE_SHA256``,
a macro setup.py defines). Where those sources lie beside the package (a checkout, an
editable install) and differ from it, the build is stale: compiled from older sources,
whose functions may take other arguments. Such a build is not used: the numpy code
runs, and a RuntimeWarning says once how to rebuild.

The choice (:func:`resolve_engine`) is deterministic: ``"auto"`` is ``"c"`` wherever the
extension is built and current, else ``"numpy"``, from the first call of a process to
the last.
"""
from __future__ import annotations

import hashlib
import importlib
import warnings
from pathlib import Path

from .errors import OutOfRangeError, UnknownNameError

__all__ = []

#: the engines a caller may ask for (ProfiledRoller(engine=...))
ENGINES = ("auto", "numpy", "c")
#: the extension's import name, and its sources in the order setup.py hashes them
EXTENSION = "linecontact._ckernels"
_HERE = Path(__file__).resolve().parent
SOURCES = (_HERE / "roller" / "_ckernels.c", _HERE / "_cstresses.c")
#: how to build the C engine, said where it is asked for and does not run
C_BUILD_HINT = ("install a C compiler (gcc, clang, MSVC) and reinstall linecontact "
                "from its source (pip install . or pip install -e . in a checkout), or "
                "use engine='auto'")

_LOADED = []                 # (module or None, why it does not run or None), once


def sources_digest(paths):
    """The SHA-256 (hex) of the files at `paths`, their bytes one after another, as
    setup.py computes it for the build."""
    h = hashlib.sha256()
    for path in paths:
        h.update(Path(path).read_bytes())
    return h.hexdigest()


def load_extension(name, sources):
    """(module, None) for the extension `name` (an import name) built from the C files
    `sources`, or (None, why) where it is not built, does not import, or was built from
    other versions of them (then also a RuntimeWarning naming the rebuild). Where the
    sources are not there (an installed wheel) the build is taken as it is."""
    try:
        mod = importlib.import_module(name)
    except ImportError as err:           # not built (no C compiler at install)
        return None, str(err) or f"the extension {name} is not built"
    sources = [Path(s) for s in sources]
    if all(s.exists() for s in sources):
        if getattr(mod, "SOURCE_SHA256", "") != sources_digest(sources):
            why = (f"the extension {name} was built from other versions of "
                   f"{' and '.join(s.name for s in sources)} (a stale build); rebuild "
                   f"it: pip install -e . in the checkout, or reinstall the package")
            warnings.warn(f"linecontact: {why}; numpy is used instead", RuntimeWarning,
                          stacklevel=3)
            return None, why
    return mod, None


def ckernels():
    """The extension ``linecontact._ckernels`` where it runs here (built, and from the
    sources beside it), else None; loaded once per process (1-3 ms)."""
    if not _LOADED:
        _LOADED.append(load_extension(EXTENSION, SOURCES))
    return _LOADED[0][0]


def unavailable():
    """Why the C engine does not run here (a sentence), or None where it does."""
    ckernels()
    return _LOADED[0][1]


def check_engine(engine):
    """`engine` checked: one of :data:`ENGINES`, and "c" only where the extension runs
    here; else an UnknownNameError or OutOfRangeError naming the engines that run and,
    where "c" does not, why."""
    runs = ENGINES if ckernels() is not None else ("auto", "numpy")
    why = "" if ckernels() is not None else f"; 'c' does not run here: {unavailable()}"
    if not isinstance(engine, str) or engine not in ENGINES:
        raise UnknownNameError("engine", engine, runs, hint=why[2:])
    if engine not in runs:
        raise OutOfRangeError("engine", engine, "'auto' or 'numpy' (" + why[2:] + ")",
                              hint=C_BUILD_HINT)
    return engine


def resolve_engine(engine):
    """"numpy" or "c" for `engine`: "auto" is "c" where the extension runs here, else
    "numpy"; "numpy" and "c" are themselves once checked (:func:`check_engine`: a
    roller whose engine was set afterwards, or that was pickled to a process without
    the extension, is refused by name, never solved with another engine)."""
    if engine == "auto":
        return "c" if ckernels() is not None else "numpy"
    return check_engine(engine)
