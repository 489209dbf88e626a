"""The one reader of the accuracy and coverage tables: what each method's error was
measured to be, and over which range.

Four shipped tables (tables/README.md) hold a study against a 3D boundary-element
solution each:

- ``tables/model_accuracy.csv``: the straight-cylinder laws' F and k errors by L/R and
  d/R (tools/studies/accuracy.py), read whole (:func:`model_accuracy`);
- ``tables/roller_accuracy.csv``: the coupled-slice model's covered range and largest
  errors, in its header (``covered_*``, ``runtime_error_*``; :func:`roller_coverage`);
- ``tables/stress_accuracy.csv``: the runtime stresses' covered range and largest
  errors, in its header (``covered_*``, ``error_*``, ``slice_error_*``;
  :func:`stress_coverage`);
- ``tables/tangential_profiles.csv``: the tangential law by direction of profiled
  rollers (the equivalent ellipse's ratio), its covered range and largest errors across
  and along the roller in its header (``covered_*``, ``runtime_error_*``;
  :func:`tangential_coverage`).

Each is read once per file version (a rebuilt table is read again) and parsed here; a
missing table or field gives None, and its users say "not measured". The header fields
are ``lo, hi`` ranges, comma-separated names, or comma-separated ``name value`` errors
(read by this module's ``_range_field``, ``_names_field``, ``_errors_field``).
"""
from __future__ import annotations

import os

__all__ = [
    "MODEL_ACCURACY",
    "ROLLER_ACCURACY",
    "STRESS_ACCURACY",
    "model_accuracy",
    "roller_coverage",
    "stress_coverage",
    "TANGENTIAL_PROFILES",
    "tangential_coverage",
]

#: Table stems (tables/<stem>.csv) of the three accuracy studies.
MODEL_ACCURACY = "model_accuracy"
ROLLER_ACCURACY = "roller_accuracy"
STRESS_ACCURACY = "stress_accuracy"
#: Table stem of the profiled rollers' tangential study.
TANGENTIAL_PROFILES = "tangential_profiles"

#: (stem, path, mtime) -> what was read or parsed from that file version
_CACHE: dict = {}


def _read(stem, parse=None):
    """tables/<stem>.csv read (and parsed by `parse`) once per file version; None if
    the table is absent (or `parse` finds a field missing or malformed)."""
    from .tables import read_table, table_path

    try:
        path = table_path(stem)
    except FileNotFoundError:
        return None
    key = (stem, parse, str(path), os.stat(path).st_mtime_ns)
    if key not in _CACHE:
        if parse is None:
            _CACHE[key] = read_table(stem)
        else:
            try:
                _CACHE[key] = parse(read_table(stem).meta)
            except (FileNotFoundError, KeyError, ValueError):  # TableError included
                _CACHE[key] = None
    return _CACHE[key]


def _range_field(meta, key):
    """A header field ``lo, hi`` as the pair of floats (lo, hi).

    Examples
    --------
    >>> _range_field({"covered_l_over_d": "1.4, 3"}, "covered_l_over_d")
    (1.4, 3.0)
    """
    lo, hi = (float(v) for v in meta[key].split(","))
    return lo, hi


def _names_field(meta, key):
    """A header field ``a, b, c`` as the tuple of names ('a', 'b', 'c').

    Examples
    --------
    >>> _names_field({"covered_profiles": "circular, iso16281"}, "covered_profiles")
    ('circular', 'iso16281')
    """
    return tuple(k.strip() for k in meta[key].split(","))


def _errors_field(meta, key):
    """A header field ``name value, name value`` as {name: value} [-].

    Examples
    --------
    >>> _errors_field({"e": "depth 0.0003, moment 0.002"}, "e")
    {'depth': 0.0003, 'moment': 0.002}
    """
    return {k: float(v) for k, v in (item.split() for item in meta[key].split(","))}


def model_accuracy():
    """tables/model_accuracy.csv, the straight-cylinder laws' measured errors.

    Returns
    -------
    linecontact.tables.Table or None
        Columns ``L_over_R``, ``d_over_R``, ``F_err_<tag>``, ``k_err_<tag>`` [-]
        (98: the law does not apply, 99: no answer); None if the table is absent.

    Examples
    --------
    >>> t = model_accuracy()
    >>> float(t.columns["L_over_R"].min()), float(t.columns["L_over_R"].max())
    (0.1, 20.0)
    """
    return _read(MODEL_ACCURACY)


def _roller(meta):
    return dict(
        l_over_d=_range_field(meta, "covered_l_over_d"),
        line_load=_range_field(meta, "covered_line_load_over_estar_d"),
        given_tilt=_range_field(meta, "covered_given_tilt_rad"),
        free_tilt=_range_field(meta, "covered_free_tilt_rad"),
        tilt_drop=_range_field(meta, "covered_tilt_drop_over_approach"),
        profiles=_names_field(meta, "covered_profiles"),
        # optional (tables before issue 20 lack it): None, not measured
        end_gap=(_range_field(meta, "covered_infinite_end_gap_over_length")
                 if "covered_infinite_end_gap_over_length" in meta else None),
        off=_errors_field(meta, "runtime_error_off_ends"),
        edge=_errors_field(meta, "runtime_error_edge_loaded"),
        # optional (tables before issue 32 lack them): the end zone of a profile whose
        # drop is infinite at the roller end, its own errors; None: not stated apart
        zone=(_errors_field(meta, "runtime_error_end_zone")
              if "runtime_error_end_zone" in meta else None),
        zone_gap=(float(meta["end_zone_gap_over_length"])
                  if "end_zone_gap_over_length" in meta else None))


def roller_coverage():
    """The coupled-slice model's measured range and largest errors
    (tables/roller_accuracy.csv's header).

    Returns
    -------
    dict or None
        ``l_over_d``, ``line_load`` (q/(E* D)), ``given_tilt``, ``free_tilt`` [rad],
        ``tilt_drop``, ``end_gap`` (or None) as (lo, hi); ``profiles`` (names);
        ``off`` and ``edge``: {output: largest relative error} off the ends and edge
        loaded; ``zone`` the same within ``zone_gap`` L of an end where the profile's
        drop is infinite (None for a table without them). None if the table or a
        field is missing.

    Examples
    --------
    >>> roller_coverage()["l_over_d"]
    (0.5, 12.0)
    """
    return _read(ROLLER_ACCURACY, _roller)


def _stress(meta):
    errs = {key: _errors_field(meta, key) for key in meta
            if key.startswith(("error_", "slice_error_"))}
    return dict(l_over_d=_range_field(meta, "covered_l_over_d"),
                line_load=_range_field(meta, "covered_line_load_over_estar_d"),
                tilt=_range_field(meta, "covered_tilt_rad"),
                friction=_range_field({"f": meta.get("covered_friction", "0, 0")}, "f"),
                profiles=_names_field(meta, "covered_profiles"),
                # optional (tables before issue 32's relief set lack them): the end
                # relief's measured corner radii (over R) and relief lengths (over L)
                relief_corner=(_range_field(
                    meta, "covered_end_relief_corner_radius_over_radius")
                    if "covered_end_relief_corner_radius_over_radius" in meta else None),
                relief_fraction=(_range_field(meta, "covered_end_relief_fraction")
                                 if "covered_end_relief_fraction" in meta else None),
                # optional: the friction above which the high-friction errors apply
                high_friction_above=(float(meta["high_friction_above"])
                                     if "high_friction_above" in meta else None),
                errors=errs)


def stress_coverage():
    """The runtime stresses' measured range and largest errors
    (tables/stress_accuracy.csv's header).

    Returns
    -------
    dict or None
        ``l_over_d``, ``line_load`` (q/(E* D)), ``tilt`` [rad], ``friction`` as
        (lo, hi); ``profiles`` (names); ``relief_corner`` (corner radius over the
        contact's effective radius) and ``relief_fraction`` (relief length over L) of
        the end reliefs measured, as (lo, hi) or None; ``high_friction_above``: the
        friction above which the ``error_3d_high_friction_*`` fields apply (or None);
        ``errors``: {field: {measure:
        largest relative error}} for each ``error_*`` and ``slice_error_*`` field (a
        field ``<name>.<profile key>`` holds that profile's own errors). None if the
        table or a field is missing.

    Examples
    --------
    >>> c = stress_coverage()
    >>> c["l_over_d"], c["errors"]["error_3d_off_ends"]["tresca"]
    ((0.5, 12.0), 0.0109)
    """
    return _read(STRESS_ACCURACY, _stress)


def _tangential(meta):
    return dict(l_over_d=_range_field(meta, "covered_l_over_d"),
                line_load=_range_field(meta, "covered_line_load_over_estar_d"),
                nu=_range_field(meta, "covered_nu"),
                profiles=_names_field(meta, "covered_profiles"),
                across=_errors_field(meta, "runtime_error_across"),
                along=_errors_field(meta, "runtime_error_along"))


def tangential_coverage():
    """The measured range and largest errors of the profiled rollers' tangential law by
    direction, the equivalent ellipse's Mindlin ratio (tables/tangential_profiles.csv's
    header).

    Returns
    -------
    dict or None
        ``l_over_d``, ``line_load`` (q/(E* D)), ``nu`` as (lo, hi); ``profiles``
        (profile keys); ``across`` and ``along``: {``stiffness_ratio``: largest relative
        error of k_t/k_n, grid error included; ``partial_slip``: largest force error
        over the partial-slip curve relative to mu F; ``dissipation``: largest
        |W/W_BEM - 1| per fretting cycle} [-]. None if the table or a field is missing.

    Examples
    --------
    >>> c = tangential_coverage()
    >>> c["nu"], c["across"]["stiffness_ratio"] < 0.01
    ((0.0, 0.5), True)
    """
    return _read(TANGENTIAL_PROFILES, _tangential)
