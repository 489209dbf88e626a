"""Loading the optional C extensions (built by setup.py where a C compiler exists).

Each extension carries the SHA-256 of the C source it was built from (``SOURCE_SHA256``,
a macro setup.py defines). Where that source lies beside the built module (a checkout,
an editable install) and differs from it, the build is stale: a module compiled from an
older source, whose functions may take other arguments. Such a build is not used: the
caller keeps to its numpy code, and a RuntimeWarning says once how to rebuild.
"""
from __future__ import annotations

import hashlib
import importlib
import warnings
from pathlib import Path

__all__ = []


def source_digest(path):
    """The SHA-256 (hex) of the file at `path`, as setup.py computes it for the build."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def load_extension(name, source):
    """(module, None) for the extension `name` (an import name) built from the C file
    `source`, or (None, why) where it is not built, does not import, or was built from
    another version of `source` (then also a RuntimeWarning naming the rebuild)."""
    try:
        mod = importlib.import_module(name)
    except ImportError as err:           # not built (no C compiler at install)
        return None, str(err) or f"the extension {name} is not built"
    source = Path(source)
    if source.exists():
        built = getattr(mod, "SOURCE_SHA256", "")
        if built != source_digest(source):
            why = (f"the extension {name} was built from another version of "
                   f"{source.name} (a stale build); rebuild it: pip install -e . in the "
                   f"checkout, or reinstall the package")
            warnings.warn(f"linecontact: {why}; numpy is used instead", RuntimeWarning,
                          stacklevel=3)
            return None, why
    return mod, None
