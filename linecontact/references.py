"""The literature the package cites, each reference written once and referred to by key.

Docstrings name a reference by its key, e.g. ``Li & Popov (2017) [li-popov-2017], Eq.
3``; :data:`CITATIONS` holds the full entry and :func:`cite` returns it.

==================  ===================================================================
key                 reference
==================  ===================================================================
``li-popov-2017``   Q. Li, V. L. Popov, "Normal line contact of finite-length
                    cylinders", Facta Universitatis, Series Mechanical Engineering
                    15(1) (2017) 63-71, doi:10.22190/FUME170222003L.
==================  ===================================================================
"""
from __future__ import annotations

__all__ = ["CITATIONS", "cite"]

#: Key -> full reference.
CITATIONS = {
    "li-popov-2017": ('Q. Li, V. L. Popov, "Normal line contact of finite-length '
                      'cylinders", Facta Universitatis, Series Mechanical Engineering '
                      "15(1) (2017) 63-71, doi:10.22190/FUME170222003L"),
}


def cite(key):
    """The full reference of a citation key.

    Parameters
    ----------
    key : str
        A key of :data:`CITATIONS`, e.g. ``"li-popov-2017"``.

    Returns
    -------
    str
        The reference.

    Raises
    ------
    UnknownNameError
        An unknown key (the message lists the known ones).

    Examples
    --------
    >>> cite("li-popov-2017")[:40]
    'Q. Li, V. L. Popov, "Normal line contact'
    """
    if key not in CITATIONS:
        from .errors import UnknownNameError

        raise UnknownNameError("key", key, sorted(CITATIONS))
    return CITATIONS[key]
