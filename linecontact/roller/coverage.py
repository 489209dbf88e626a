"""Where the coupled-slice model's error is known: the range measured against a 3D
boundary-element solution in the header of ``tables/roller_accuracy.csv``
(tools/studies/roller_study.py), and the note each solution carries about it.
"""
from __future__ import annotations

import math

from .slices import DEFAULT_N_SLICES

__all__ = []


_COVERAGE = []
_ACCURACY_TABLE = "roller_accuracy"
#: relative slack on the covered bounds (the header prints 6 significant digits)
_COVER_SLACK = 1e-5


def _coverage():
    """The covered_* and runtime_error_* fields of tables/roller_accuracy.csv, parsed
    once on first use (None if the table or the fields are missing)."""
    if not _COVERAGE:
        from ..tables import read_table
        try:
            meta = read_table(_ACCURACY_TABLE).meta

            def pair(key):
                lo, hi = (float(v) for v in meta[key].split(","))
                return lo, hi

            def errors(key):
                return {k: float(v) for k, v in
                        (item.split() for item in meta[key].split(","))}

            cov = dict(
                l_over_d=pair("covered_l_over_d"),
                line_load=pair("covered_line_load_over_estar_d"),
                given_tilt=pair("covered_given_tilt_rad"),
                free_tilt=pair("covered_free_tilt_rad"),
                tilt_drop=pair("covered_tilt_drop_over_approach"),
                profiles=tuple(k.strip() for k in meta["covered_profiles"].split(",")),
                # optional (tables before issue 20 lack it): None, not measured
                end_gap=(pair("covered_infinite_end_gap_over_length")
                         if "covered_infinite_end_gap_over_length" in meta else None),
                off=errors("runtime_error_off_ends"),
                edge=errors("runtime_error_edge_loaded"),
                # optional (tables before issue 32 lack it): the end zone's own errors
                zone=(errors("runtime_error_end_zone")
                      if "runtime_error_end_zone" in meta else None),
                zone_gap=float(meta.get("end_zone_gap_over_length", 0.0)))
            # the largest errors as coverage_note states them, written once
            off, edge = cov["off"], cov["edge"]
            cov["errors_edge_loaded"] = (
                f"edge loaded: deflection {_pct(edge['depth'])}, moment "
                f"{_pct(edge['moment'])}, zero-moment tilt {_pct(edge['tilt'])} (peak "
                "pressure singular, not reported)")
            cov["errors_off_ends"] = (
                f"contact off the ends: deflection {_pct(off['depth'])}, moment "
                f"{_pct(off['moment'])} (tilted), peak pressure {_pct(off['p_max'])}, "
                f"zero-moment tilt {_pct(off['tilt'])}")
            if cov["zone"] is not None:
                z = cov["zone"]
                cov["errors_end_zone"] = (
                    f"contact in the end zone (within {cov['zone_gap']:g} L of a roller "
                    f"end where the drop is infinite): deflection {_pct(z['depth'])}, "
                    f"moment {_pct(z['moment'])} (tilted), peak pressure "
                    f"{_pct(z['p_max'])}, zero-moment tilt {_pct(z['tilt'])}")
        except (FileNotFoundError, KeyError, ValueError):
            cov = None
        _COVERAGE.append(cov)
    return _COVERAGE[0]


def geometry_cause(radius, length, estar, force=None):
    """Why a coupled-slice solve may fail, in numbers: L/(2R), R the contact's
    effective radius (the roller's L/D on a flat), against the table's covered range
    and, given a force, the plane-strain Hertz half-width b = sqrt(4 R F/(pi L E*))
    (Johnson 1985, Eq. 4.45) against the length (each slice is a strip across the
    roller, which asks for b well below L)."""
    cov = _coverage()
    text = _slenderness(radius, length, 3)
    if cov is not None:
        lo, hi = cov["l_over_d"]
        text += f" (the accuracy table covers {lo:.3g}-{hi:.3g})"
    if force is not None:
        b = math.sqrt(4 * radius * force / (math.pi * length * estar))
        text += f"; at {force:.6g} N the Hertz half-width b = {b:.3g} m is {b / length:.3g} L"
    return text


def _slenderness(radius, length, digits=2):
    """The contact's slenderness in the user's terms: L over twice the contact's
    effective radius R (the roller's L/D where it runs on a flat; against a raceway
    1/R = 1/R_roller + 1/R_raceway, so L/(2R) exceeds the roller's L/D on an inner
    raceway and falls below it on an outer one)."""
    return (f"L/(2R) = {length / (2 * radius):.{digits}g} (roller length L = "
            f"{length * 1e3:.4g} mm, the contact's effective radius R = "
            f"{radius * 1e3:.4g} mm: the roller's L/D on a flat)")


def _pct(v):
    return f"{100 * v:.2g} %"


def coverage_note(radius, length, estar, profile_key, force, tilt, approach,
                   free_tilt=False, edge_loaded=False, n_slices=DEFAULT_N_SLICES,
                   end_gap=None):
    """The note on where a coupled-slice case lies relative to the range measured in
    tables/roller_accuracy.csv (L/(2R) and F/(L E* 2R) with R the contact's effective
    radius, named so in the note; |theta| given or free,
    the tilt drop |theta| L/2 over the largest rigid overlap `approach` [m], the profile
    key, n_slices >= DEFAULT_N_SLICES (the table's), and `end_gap`, the contact's distance from a roller end where
    the profile's drop is infinite over L, None if there is no such end): names each
    quantity outside, and states the table's largest errors (off the ends, or edge
    loaded). Bounds with a relative slack of 1e-5 (the header prints 6 digits)."""
    cov = _coverage()
    where = "the 3D BEM (tables/roller_accuracy.csv)"
    if cov is None:
        return (f"this model's error against {where} is not known here: the table or "
                "its covered_* fields are missing")
    D = 2 * radius
    th = abs(tilt)
    tkey, tname = ("free_tilt", "zero-moment tilt") if free_tilt else (
        "given_tilt", "tilt")
    drop = th * length / 2 / approach if approach > 0 else (0.0 if th == 0 else math.inf)
    checks = [(_slenderness(radius, length).split(" = ")[0], length / D, cov["l_over_d"],
               ""),
              ("mean line load q/(E* 2R)", force / (length * estar * D), cov["line_load"],
               ""),
              (f"|{tname}|", th, cov[tkey], " rad"),
              ("tilt drop |theta| L/2 over the approach", drop, cov["tilt_drop"], "")]
    outside = [(_slenderness(radius, length) if name.startswith("L/(2R)") else
                f"{name} = {v:.2g}{u}") + f" (measured {lo:.2g}-{hi:.2g}{u})"
               for name, v, (lo, hi), u in checks
               if not lo * (1 - _COVER_SLACK) <= v <= hi * (1 + _COVER_SLACK)]
    if profile_key not in cov["profiles"]:
        outside.append(f"profile '{profile_key}' (measured: "
                       f"{', '.join(cov['profiles'])})")
    if end_gap is not None and cov["end_gap"] is not None and (
            end_gap < cov["end_gap"][0] * (1 - _COVER_SLACK)):
        outside.append(f"the contact ends {end_gap:.2g} L from a roller end where the "
                       f"drop is infinite (measured down to {cov['end_gap'][0]:.2g} L)")
    if n_slices < DEFAULT_N_SLICES:
        outside.append(f"n_slices = {n_slices} (measured with {DEFAULT_N_SLICES})")
    in_zone = (not edge_loaded and end_gap is not None and cov["zone"] is not None
               and end_gap < cov["zone_gap"])
    errs = (cov["errors_edge_loaded"] if edge_loaded else
            cov["errors_end_zone"] if in_zone else cov["errors_off_ends"])
    if outside:
        return (f"{'; '.join(outside)}: outside the range where this model's error was "
                f"measured against {where}; inside it the largest errors are, {errs}")
    inside = f"{_slenderness(radius, length)} and mean line load q/(E* 2R) = " \
             f"{force / (length * estar * D):.2g}"
    return (f"{inside} are inside the range where this model's error was measured "
            f"against {where}: largest errors there, {errs}")
