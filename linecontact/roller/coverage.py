"""Where the coupled-slice model's error is known: the range measured against a 3D
boundary-element solution in the header of ``tables/roller_accuracy.csv``
(tools/studies/roller_study.py), and the note each solution carries about it.
"""
from __future__ import annotations

import math

from .slices import DEFAULT_N_SLICES

__all__ = []


_COVERAGE = {}
#: relative slack on the covered bounds (the header prints 6 significant digits)
_COVER_SLACK = 1e-5


def _coverage():
    """tables/roller_accuracy.csv's covered range and largest errors
    (:func:`linecontact.accuracy.roller_coverage`) with those errors as the note states
    them, written once per table version (None if the table or the fields are
    missing)."""
    from ..accuracy import roller_coverage

    raw = roller_coverage()
    if _COVERAGE.get("raw", _COVERAGE) is not raw:     # first use, or a new table
        cov = None
        try:
            if raw is not None:
                off, edge = raw["off"], raw["edge"]
                cov = dict(raw, errors_edge_loaded=(
                    f"edge loaded: deflection {_pct(edge['depth'])}, moment "
                    f"{_pct(edge['moment'])}, zero-moment tilt {_pct(edge['tilt'])} "
                    "(peak pressure singular, not reported)"), errors_off_ends=(
                    f"contact off the ends: deflection {_pct(off['depth'])}, moment "
                    f"{_pct(off['moment'])} (tilted), peak pressure "
                    f"{_pct(off['p_max'])}, zero-moment tilt {_pct(off['tilt'])}"))
                z = raw.get("zone")
                if z is not None:
                    cov["errors_end_zone"] = (
                        f"contact in the end zone (within {raw['zone_gap']:g} L of a "
                        "roller end where the drop is infinite): deflection "
                        f"{_pct(z['depth'])}, moment {_pct(z['moment'])} (tilted), peak "
                        f"pressure {_pct(z['p_max'])}, zero-moment tilt {_pct(z['tilt'])}")
        except KeyError:                   # an error the note states is not measured
            cov = None
        _COVERAGE.update(raw=raw, cov=cov)
    return _COVERAGE["cov"]


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
    checks = [("L/(2R)", length / D, cov["l_over_d"], ""),
              ("mean line load q/(E* 2R)", force / (length * estar * D), cov["line_load"],
               ""),
              (f"|{tname}|", th, cov[tkey], " rad"),
              ("tilt drop |theta| L/2 over the approach", drop, cov["tilt_drop"], "")]
    outside = [(_slenderness(radius, length) if name == "L/(2R)" else
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
    in_zone = (not edge_loaded and end_gap is not None and "errors_end_zone" in cov
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
