r"""The measured error of the roller stresses: the note each result carries.

The roller stresses' error against a 3D field (Love's and Cerruti's rectangles below
a 3D boundary-element pressure, tools/bem/stress.py) is measured in
tables/stress_accuracy.csv (tools/studies/stress_study.py); :func:`_accuracy` is the
one reader of that table here, :func:`stress_accuracy` the note and error of one
solution, :func:`reaches_end` which of the table's errors (off the ends or edge
loaded) applies.
"""
from __future__ import annotations

import numpy as np

__all__ = ["reaches_end"]

#: the table's fields, read once (:func:`_accuracy`)
#: the table's error fields: (3D-corrected?, friction?, edge loaded?) -> header key
_ERROR_KEYS = {(True, False, False): "error_3d_off_ends",
               (True, False, True): "error_3d_edge_loaded",
               (True, True, False): "error_3d_friction_off_ends",
               (True, True, True): "error_3d_friction_edge_loaded",
               (False, False, False): "slice_error_off_ends",
               (False, False, True): "slice_error_edge_loaded",
               (False, True, False): "slice_error_friction_off_ends",
               (False, True, True): "slice_error_friction_edge_loaded"}


def _accuracy():
    """The covered_* and error fields of tables/stress_accuracy.csv (or None):
    :func:`linecontact.accuracy.stress_coverage`."""
    from ..accuracy import stress_coverage

    return stress_coverage()


def reaches_end(solution):
    r"""Whether a slice solution's contact reaches a roller end or comes within half a
    slice width h of it.

    .. math:: \min(x_\text{start} - x_\text{lo},\; x_\text{hi} - x_\text{end}) < h/2

    with h the mean slice width (the slices' span over their number, whatever their
    grading).

    There the 3D contact may be edge loaded where the slices are not (in the study of
    tables/stress_accuracy.csv every such case was), so the stresses' error is the
    edge-loaded one (the study's ``rt_edge``).

    Parameters
    ----------
    solution : RollerSolution
        A slice solution (its ``x`` [m], ``q`` [N/m], ``edge_loaded``, and
        ``contact_start``/``contact_end`` [m] where it has them).

    Returns
    -------
    bool
        True at or near an end.

    Notes
    -----
    Valid for slices spanning the contact, equal or graded (their ``width``;
    linecontact.roller).

    Examples
    --------
    >>> from linecontact.roller import roller_contact
    >>> reaches_end(roller_contact(5e-3, 14e-3, 115.385e9, "circular:Rc=0.5", force=4200.0))
    False

    References
    ----------
    docs/stresses.md (the accuracy section).
    """
    if bool(getattr(solution, "edge_loaded", False)):
        return True
    x = np.asarray(solution.x, dtype=float)
    if x.size < 2:
        return False
    width = getattr(solution, "width", None)
    w = (np.asarray(width, dtype=float) if width is not None
         else np.full(x.size, float(x[1] - x[0])))
    lo, hi = x[0] - 0.5 * w[0], x[-1] + 0.5 * w[-1]
    # the margin is half the MEAN slice width: graded slices (fine at the ends) would
    # otherwise shrink it several-fold below the uniform slices of the study that
    # measured the errors, and classify a contact ending 30 um from the end as off it
    h = (hi - lo) / x.size
    start = getattr(solution, "contact_start", None)
    end = getattr(solution, "contact_end", None)
    if start is None or end is None:
        loaded = np.flatnonzero(np.asarray(solution.q) > 0)
        if loaded.size == 0:
            return False
        start = x[loaded[0]] - 0.5 * w[loaded[0]]
        end = x[loaded[-1]] + 0.5 * w[loaded[-1]]
    return bool(min(start - lo, hi - end) < 0.5 * h)


def _measured(value, lo, hi):
    """Whether `value` lies in the measured range [lo, hi], with a relative margin of
    1e-5 for the table's rounded bounds."""
    return lo * (1 - 1e-5) <= value <= hi * (1 + 1e-5)


def _relief_outside(roller, cov):
    """What of an end relief lies outside the measured range (list of phrases): a
    dub-off (no corner radius), the corner radius over the contact's effective radius,
    the relief length over L (the table's covered_end_relief_* fields; none for a
    table without them or another profile)."""
    prof = roller.profile
    if (getattr(prof, "key", None) != "end-relief" or cov.get("relief_corner") is None
            or cov.get("relief_fraction") is None):
        return []
    if prof.corner_radius is None:
        return ["an end relief without a corner radius (a dub-off; measured: corner "
                "radii)"]
    out = []
    for name, v, (lo, hi) in (
            ("corner radius over the contact's effective radius r/R",
             prof.corner_radius / roller.radius, cov["relief_corner"]),
            ("relief length over the roller length l/L",
             prof.relief_length / roller.length, cov["relief_fraction"])):
        if not _measured(v, lo, hi):
            out.append(f"{name} = {v:.3g} (measured {lo:.3g}-{hi:.3g})")
    return out


def stress_accuracy(solution, friction=0.0, roller=None, three_d=True):
    """The measured error of the roller stresses for this solution and its note.

    Returns (note, error): error maps each measure to the largest |rt/3D - 1| of
    tables/stress_accuracy.csv for this kind of case (3D-corrected or strips; without
    friction, with friction up to the table's ``high_friction_above`` or above it; off
    the ends or edge loaded), the profile's own where the table measured it apart
    (``<field>.<profile key>``: the end relief), the largest over every profile where
    `roller` (so the profile) is not given; None outside the measured range (L/(2R),
    q/(E* 2R) with R the contact's effective radius, tilt, profile, friction; an end
    relief's corner radius over R and relief length over L, or a dub-off), which the
    note names."""
    cov = _accuracy()
    where = "a 3D field below the 3D BEM pressure (tables/stress_accuracy.csv)"
    what = "3D-corrected stresses" if three_d else "slice (plane-strain) stresses"
    if cov is None:
        return f"the {what}' error against {where} is not known here", None
    outside = []
    if roller is not None:
        D = 2 * roller.radius
        # L/(2R) in the user's terms: R is the contact's effective radius (the
        # roller's on a flat; with a raceway's curvature added otherwise)
        ld = (f"L/(2R) = {roller.length / D:.2g} (roller length L = "
              f"{roller.length * 1e3:.4g} mm, the contact's effective radius R = "
              f"{roller.radius * 1e3:.4g} mm: the roller's L/D on a flat)")
        qn = solution.force / (roller.length * roller.estar * D)
        checks = [(ld, roller.length / D, cov["l_over_d"]),
                  (f"mean line load q/(E* 2R) = {qn:.2g}", qn, cov["line_load"])]
        outside += [f"{n} (measured {lo:.2g}-{hi:.2g})" for n, v, (lo, hi)
                    in checks if not _measured(v, lo, hi)]
        key = getattr(roller.profile, "key", None)
        if key not in cov["profiles"]:
            outside.append(f"profile '{key}' (measured: {', '.join(cov['profiles'])})")
        outside += _relief_outside(roller, cov)
    method = getattr(solution, "method", "coupled slices")
    if method != "coupled slices":
        # the study solved every case by ProfiledRoller; another slice model's loads
        # (ISO 16281's uncoupled slices) were not measured against the 3D field
        outside.append(f"slice model '{method}' (measured: the coupled slices of "
                       "linecontact.roller.ProfiledRoller)")
    lo, hi = cov["friction"]
    if not lo <= friction <= hi * (1 + 1e-9):
        outside.append(f"friction = {friction:.3g} (measured {lo:.3g}-{hi:.3g})")
    th = abs(float(getattr(solution, "tilt", 0.0)))
    lo, hi = cov["tilt"]
    if not lo <= th <= hi * (1 + 1e-5):
        outside.append(f"|tilt| = {th:.3g} rad (measured {lo:.3g}-{hi:.3g} rad)")
    edge = reaches_end(solution)
    key = _ERROR_KEYS[(bool(three_d), friction > 0, edge)]
    high = cov.get("high_friction_above")
    if high is not None and friction > high:
        # the largest shear at or near the surface: its own class (measured to the
        # table's largest friction)
        key = key.replace("_friction_", "_high_friction_")
    # a profile measured apart (the end relief) has its own errors; without the model
    # (its profile unknown) the largest of every profile's
    pkey = getattr(getattr(roller, "profile", None), "key", None)
    e = cov["errors"].get(f"{key}.{pkey}", cov["errors"].get(key))
    if roller is None and e is not None:
        fields = [v for k, v in cov["errors"].items() if k == key or k.startswith(key + ".")]
        e = {m: max(f[m] for f in fields) for m in e}
    state = ("contact at (or within half a slice of) a roller end" if edge
             else "contact off the ends") + (
        "" if friction <= 0 else ", with traction" if high is None or friction <= high
        else f", with traction of friction above {high:g}")
    if e is None:
        outside.append(f"{state} (not measured for the {what})")
        return (f"{'; '.join(outside)}: the {what}' error against {where} is not "
                "known here"), None
    errs = ", ".join(f"{k.replace('_', ' ')} {100 * v:.2g} %" for k, v in e.items())
    if outside:
        return (f"{'; '.join(outside)}: outside the range where the {what} were "
                f"measured against {where}; inside it, {state}: largest errors "
                f"{errs}"), None
    return (f"{what} against {where}, {state}: largest errors {errs} (maximum of each "
            "measure over the roller)"), dict(e)
