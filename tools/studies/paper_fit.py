"""Extraction and fitting of the paper's study: BEM curves -> MDR points -> alpha, beta.

Each BEM curve k(d) of one L/R is turned into its MDR profile (docs/theory.md, section
'MDR': x = k/(2E*), g(x) = d) and scaled by Li & Popov (2017), Eq. 8,

    x~ = k / (2 E* L),    g~ = d R / L^2,

and alpha, beta of Eq. 9, g~ = beta (alpha/x~ + 1) exp(-alpha/x~), are fitted to the
points. The paper does not say how it weighted the residuals, and alpha and beta are
strongly correlated, so several natural residuals are tried (:data:`RESIDUALS`); each
fit is judged by what a user gets from it: the largest relative error of F(d) and of
k(d) of the fitted closed form against the BEM points (:func:`errors`).

All closed forms are the runtime's (linecontact.lipopov: dimensionless_profile,
dimensionless_contact_radius, dimensionless_force, dimensionless_stiffness, and
lipopov_force / lipopov_stiffness for the errors); nothing here re-implements them.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares, minimize

from linecontact.errors import OutOfRangeError
from linecontact.lipopov import (dimensionless_contact_radius, dimensionless_force,
                                 dimensionless_profile, dimensionless_stiffness)

#: Residual choices for the fit of Eq. 9 to the extracted points (x~_i, g~_i):
#: name -> (numeric id used in the comparison table, description).
RESIDUALS = {
    "g_abs": (1, "absolute in g~: g~fit(x~_i) - g~_i"),
    "g_rel": (2, "relative in g~: (g~fit(x~_i) - g~_i) / g~_i"),
    "x_abs": (3, "absolute in x~: x~fit(g~_i) - x~_i"),
    "x_rel": (4, "relative in x~ (= relative in k): (x~fit(g~_i) - x~_i) / x~_i"),
    "F_abs": (5, "absolute in F: F~fit(d~_i) - F~_i"),
    "F_rel": (6, "relative in F: (F~fit(d~_i) - F~_i) / F~_i"),
    "Fk_rel": (7, "relative in F and in k together (both residual sets stacked)"),
    "minimax": (8, "largest relative error of F and k (minimax, Nelder-Mead)"),
}
#: The residual shipped in tables/lipopov_regenerated.csv (see tables/README.md).
SHIPPED_RESIDUAL = "minimax"


def curve_points(l_over_r, depth, force, stiffness):
    """Dimensionless BEM points of one L/R (R = E* = 1): d~, F~, k~, x~, g~.

    The MDR profile is extracted from the punch stiffness (docs/theory.md, section
    'MDR'): x = k/(2E*), g(x) = d, then scaled by Eq. 8. This is
    linecontact.mdr.mdr_profile_from_stiffness, used where k(d) is strictly
    increasing; on a fixed grid the discrete punch stiffness is a step function
    (constant while the contact set does not change), so equal neighbours are
    kept (a vertical step of the profile) and only a real decrease is refused.
    """
    from linecontact.mdr import mdr_profile_from_stiffness
    L = float(l_over_r)
    ok = np.isfinite(force) & np.isfinite(stiffness)
    d, F, k = depth[ok], force[ok], stiffness[ok]
    try:
        x, g = mdr_profile_from_stiffness(d, k, 1.0)
    except OutOfRangeError:
        drop = np.diff(k) < -1e-6 * k[1:]
        if np.any(drop):
            i = int(np.argmax(drop)) + 1
            raise ValueError(f"L/R = {L:g}: stiffness decreases from {k[i - 1]:.6g} to "
                             f"{k[i]:.6g} E* R at d/R = {d[i]:.6g}; the MDR needs k(d) "
                             "non-decreasing (F convex)") from None
        x, g = k / 2.0, d.copy()
    return dict(d=d / L**2, F=F / L**3, k=k / L, x=x / L, g=g / L**2)


def points_from_curves(cols):
    """{L/R: points of :func:`curve_points`} from the columns of bem_paper_curves.csv."""
    out = {}
    for q in np.unique(cols["L_over_R"]):
        m = cols["L_over_R"] == q
        pts = curve_points(q, cols["d_over_R"][m], cols["F_over_EstarR2"][m],
                           cols["k_over_EstarR"][m])
        pts["L"] = float(q)
        out[float(q)] = pts
    return out


def _residual(name, pts):
    """Residual vector of `name` as a function of p = (ln alpha, ln beta).

    The runtime refuses a depth at or beyond beta (the form's bound); an optimizer
    step there gets a large residual growing with the excess, never a clipped value."""
    d, F, k, x, g = pts["d"], pts["F"], pts["k"], pts["x"], pts["g"]
    size = 2 * d.size if name == "Fk_rel" else d.size

    def res(p):
        a, b = np.exp(p)
        try:
            if name == "g_abs":
                return dimensionless_profile(x, a, b) - g
            if name == "g_rel":
                return dimensionless_profile(x, a, b) / g - 1.0
            if name == "x_abs":
                return dimensionless_contact_radius(g, a, b) - x
            if name == "x_rel":
                return dimensionless_contact_radius(g, a, b) / x - 1.0
            if name == "F_abs":
                return dimensionless_force(d, a, b) - F
            if name == "F_rel":
                return dimensionless_force(d, a, b) / F - 1.0
            if name == "Fk_rel":
                return np.concatenate([dimensionless_force(d, a, b) / F - 1.0,
                                       dimensionless_stiffness(d, a, b) / k - 1.0])
        except OutOfRangeError:
            return np.full(size, 1e3 * (1.0 + max(np.max(d), np.max(g)) - b))
        raise ValueError(f"residual {name!r} is not one of {', '.join(RESIDUALS)}")
    return res


def errors(pts, alpha, beta):
    """Largest relative error of F(d) and of k(d) of Eq. 9 with alpha, beta against the
    BEM points, evaluated with the runtime (linecontact.lipopov_force, lipopov_stiffness;
    R = E* = 1, L = L/R). inf where a BEM depth is beyond the form's bound beta L^2/R."""
    from linecontact.lipopov import lipopov_force, lipopov_stiffness
    if np.max(pts["d"]) >= beta:
        return math.inf, math.inf
    L = pts["L"]
    d = pts["d"] * L**2
    Ff = np.asarray(lipopov_force(d, 1.0, L, 1.0, alpha=alpha, beta=beta))
    kf = np.asarray(lipopov_stiffness(d, 1.0, L, 1.0, alpha=alpha, beta=beta))
    eF = np.max(np.abs(Ff / (pts["F"] * L**3) - 1.0))
    ek = np.max(np.abs(kf / (pts["k"] * L) - 1.0))
    return float(eF), float(ek)


def _start(l_over_r, pts):
    """Starting point: the Table 1 spline inside its range, else pi/2 and a beta that
    puts the deepest point below the form's bound."""
    a0, b0 = math.pi / 2, 0.46
    try:
        from linecontact.lipopov import lipopov_coefficients
        a0, b0 = (float(v) for v in lipopov_coefficients(l_over_r, "published"))
    except ValueError:
        pass
    b0 = max(b0, 1.05 * float(np.max(pts["g"])))
    return np.log([a0, b0])


def fit(pts, residual, start=None):
    """alpha, beta of Eq. 9 fitted to one L/R's points with the chosen residual."""
    p0 = _start(pts["L"], pts) if start is None else np.log(start)
    if residual == "minimax":
        # start from the stacked relative F, k least squares, then minimise the max
        a1, b1 = fit(pts, "Fk_rel", start=None if start is None else start)

        def worst(p):
            a, b = np.exp(p)
            if np.max(pts["d"]) >= b:
                return 1e3 * (1 + np.max(pts["d"]) - b)
            r = _residual("Fk_rel", pts)(p)
            return float(np.max(np.abs(r)))
        best = minimize(worst, np.log([a1, b1]), method="Nelder-Mead",
                        options=dict(xatol=1e-10, fatol=1e-12, maxiter=4000))
        a, b = np.exp(best.x)
        return float(a), float(b)
    sol = least_squares(_residual(residual, pts), p0, method="lm", xtol=1e-14,
                        ftol=1e-14, gtol=1e-14, max_nfev=20000)
    a, b = np.exp(sol.x)
    return float(a), float(b)


def fit_all(points, residuals=tuple(RESIDUALS)):
    """{residual: {L/R: (alpha, beta, err_F, err_k)}}."""
    table = {}
    for name in residuals:
        table[name] = {}
        for q, pts in points.items():
            try:
                a, b = fit(pts, name)
                eF, ek = errors(pts, a, b)
            except (ValueError, RuntimeError, FloatingPointError):
                a = b = eF = ek = math.nan
            table[name][q] = (a, b, eF, ek)
    return table


def match(points, q):
    """The entry of `points` (a dict keyed by L/R) at L/R = q, or None."""
    for p, pts in points.items():
        if abs(p - q) < 1e-9:
            return pts
    return None


def summary(values):
    """Median and largest of the finite values."""
    v = np.array([r for r in values if np.isfinite(r)])
    return (float(np.median(v)), float(np.max(v))) if v.size else (math.nan, math.nan)


def published_rows(points):
    """(L/R, set, alpha, beta, err_F, err_k) of Table 1 (its own rows, set 1) and of
    Eq. 11 (L/R >= 5, set 2) on the BEM points."""
    from linecontact.lipopov import ALPHA_EQ11, BETA_EQ11
    from linecontact.tables import read_table
    t1 = read_table("lipopov_published").columns
    rows = []
    for q, a, b in zip(t1["L_over_R"], t1["alpha"], t1["beta"]):
        pts = match(points, q)
        if pts is not None:
            rows.append((q, 1, a, b, *errors(pts, a, b)))
    for q, pts in points.items():
        if q >= 5:
            rows.append((q, 2, ALPHA_EQ11, BETA_EQ11, *errors(pts, ALPHA_EQ11, BETA_EQ11)))
    return rows


def score_to_published(per, t1):
    """Median over the Table 1 rows of |alpha/alpha_1 - 1| + |beta/beta_1 - 1|."""
    d = []
    for q, a, b in zip(t1["L_over_R"], t1["alpha"], t1["beta"]):
        m = match(per, q)
        if m is not None and np.isfinite(m[0]):
            d.append(abs(m[0] / a - 1) + abs(m[1] / b - 1))
    return float(np.median(d)) if d else math.inf


def residual_report(fits):
    """Lines comparing the residual choices: distance to Table 1 and F, k errors."""
    from linecontact.tables import read_table
    t1 = read_table("lipopov_published").columns
    lines = []
    for name, per in fits.items():
        da, db = [], []
        for q, a, b in zip(t1["L_over_R"], t1["alpha"], t1["beta"]):
            m = match(per, q)
            if m is not None and np.isfinite(m[0]):
                da.append(abs(m[0] / a - 1))
                db.append(abs(m[1] / b - 1))
        med, mx = summary([max(v[2], v[3]) for v in per.values()])
        lines.append(
            f"{name:8s} Table 1: median |dalpha| {np.median(da) if da else math.nan:.2%}, "
            f"|dbeta| {np.median(db) if db else math.nan:.2%}, largest "
            f"{max(da) if da else math.nan:.2%}, {max(db) if db else math.nan:.2%}; "
            f"user error max(F,k): median {med:.2%}, largest {mx:.2%}")
    return lines
