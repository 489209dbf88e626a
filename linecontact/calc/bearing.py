"""``linecontact bearing``: a radial cylindrical or needle roller bearing from the command
line, one bearing or a CSV of bearings.

The inputs are declared once in :data:`PARAMETERS` (the calculator's
:class:`~linecontact.calc.feature.Parameter`): each is an option ``--NAME`` and a CSV
column ``NAME``, parsed to SI by the calculator's unit rules
(:func:`linecontact._units.parse_quantity`). The roller length and the materials are the
very parameters of ``linecontact calc`` (:data:`linecontact.calc.cases.CORE`): here
``--modulus``/``--poisson`` are the rings and ``--modulus2``/``--poisson2`` the rollers
(default: the rings' material), or ``--estar``; none of them: steel on steel.

All physics is :class:`linecontact.bearing.RadialRollerBearing`; this module reads,
asks, and prints. Nothing here runs at import.
"""
from __future__ import annotations

import json
import math
import sys

from .cases import BY_NAME as _CALC
from .feature import Field, Parameter, option_name

__all__ = ["PARAMETERS", "FIELDS", "add_parser", "run"]

_GEOM = "bearing geometry"
_LOAD = "load"
_MAT = "materials (rings: --modulus/--poisson; rollers: --modulus2/--poisson2)"
_MODEL = "contact model"

#: The bearing's inputs: option ``--NAME`` = CSV column ``NAME``.
PARAMETERS = (
    Parameter("rollers", "dimensionless", "number of rollers Z (>= 3)", _GEOM),
    Parameter("pitch_diameter", "length", "pitch diameter d_m", _GEOM),
    Parameter("roller_diameter", "length", "roller diameter D", _GEOM),
    _CALC["length"],
    Parameter("clearance", "length", "radial internal clearance P_d = d_o - d_i - 2D "
              "(negative: preload; default 0)", _GEOM, positive=False),
    Parameter("radial_load", "force", "radial load F_r", _LOAD),
    Parameter("tilting_moment", "moment", "tilting moment M on the inner ring about the "
              "axis normal to the load plane (e.g. 20Nm): the ring tilt is solved; the "
              "rollers by slices, free to tilt", _LOAD, positive=False),
    Parameter("misalignment", "angle", "given tilt of the inner ring against the outer "
              "ring in the load plane (e.g. 1mrad, 0.05deg, 3arcmin; positive: the rings "
              "close at +x on the loaded side), instead of --tilting-moment", _LOAD,
              positive=False),
    _CALC["modulus"], _CALC["poisson"], _CALC["modulus2"], _CALC["poisson2"],
    _CALC["estar"],
    Parameter("profile", "text", "roller profile spec (e.g. circular:Rc=500mm, "
              "iso16281, lundberg); default straight", _MODEL),
    Parameter("model", "text", "contact law of each contact: universal (default for a "
              "straight roller), iso16281 (the ISO spring), profiled-roller (default "
              "for a profile), iso16281-slicing, any key of linecontact calc", _MODEL),
    Parameter("n_slices", "dimensionless", "slices of a profiled roller (default 40)",
              _MODEL),
    Parameter("rating", "force", "basic dynamic load rating C_r (default: ISO 281 "
              "from the geometry)", _MODEL),
)

BY_NAME = {p.name: p for p in PARAMETERS}

#: Output quantities of one bearing: heading, SI unit, engineering unit, factor.
FIELDS = {
    "displacement": Field("delta_r", "m", "um", 1e6),
    "radial_stiffness": Field("K_rr", "N/m", "N/um", 1e-6),
    "tilt": Field("ring tilt theta", "rad", "mrad", 1e3),
    "moment": Field("moment M", "N m", "N m", 1.0),
    "stiffness_rt": Field("K_rt = dF_r/dtheta", "N/rad", "N/mrad", 1e-3),
    "stiffness_tr": Field("K_tr = dM/d delta_r", "N", "N m/um", 1e-6),
    "stiffness_tt": Field("K_tt = dM/dtheta", "N m/rad", "N m/mrad", 1e-3),
    "max_roller_load": Field("Q_max", "N", "N", 1.0),
    "load_zone": Field("load zone psi_l", "rad", "deg", 180 / math.pi),
    "loaded_rollers": Field("loaded", "-", "-", 1.0),
    "peak_pressure": Field("p_max", "Pa", "MPa", 1e-6),
    "rating": Field("C_r", "N", "kN", 1e-3),
    "life_iso281": Field("L10 ISO 281", "1e6 rev", "1e6 rev", 1.0),
    "life_iso16281": Field("L10r ISO 16281", "1e6 rev", "1e6 rev", 1.0),
    "tresca": Field("max Tresca shear", "Pa", "MPa", 1e-6),
    "tresca_depth": Field("  at depth", "m", "um", 1e6),
    "von_mises": Field("max von Mises", "Pa", "MPa", 1e-6),
    "von_mises_depth": Field("  at depth", "m", "um", 1e6),
    "orthogonal_shear": Field("max orthogonal shear", "Pa", "MPa", 1e-6),
    "orthogonal_shear_depth": Field("  at depth", "m", "um", 1e6),
}

_NOTES = {
    "clearance": "P_d is the radial internal clearance (ISO 5753-1), Harris' diametral "
                 "clearance d_o - d_i - 2D; roller j's approach is delta_r cos psi_j - "
                 "P_d/2.",
    "life": "L10 = (C_r/F_r)^(10/3) (ISO 281:2007); L10r: ISO 16281:2025 (ISO/TS "
            "16281:2008) lamina method on the lamina loads, exponent 4 of line contact "
            "(docs/iso16281.md).",
    "tilt": "with --tilting-moment or --misalignment each roller is solved by slices "
            "(profiled-roller for a straight roller with no --model), free to tilt "
            "between its rings; the ring sees theta cos psi_j at roller j. K_rt, K_tr, "
            "K_tt: the 2x2 stiffness d(F_r, M)/d(delta_r, theta), slice models only.",
    "stress": "subsurface stress: the most loaded roller, the worst of its two contacts "
              "(linecontact.stresses), no traction: under a slice model one Hertz strip "
              "per slice, the worst 3D-corrected (measured error in the notes below); "
              "under a law the plane-strain Hertz strip at the mean line load Q/L; von "
              "Mises with the rings' Poisson's ratio (0.3 if not given).",
}


def add_parser(sub):
    """Add the ``bearing`` subcommand to the ``linecontact`` parser."""
    p = sub.add_parser(
        "bearing",
        help="load distribution, stiffness and rating life of a radial roller bearing",
        description="Load distribution over the rollers, ring displacement, radial "
        "stiffness, load zone, peak pressure and rating lives (ISO 281, ISO 16281) of a "
        "radial cylindrical or needle roller bearing under a radial load. Values take "
        "one unit name ('70mm', '10kN'); bare numbers are SI.",
        epilog="Batch: FILE.csv with one bearing per row, columns named like the "
        "options (pitch_diameter for --pitch-diameter); results are appended. Exit "
        "status 2 on bad input.")
    p.add_argument("csv", nargs="?", metavar="FILE.csv", help="batch: one bearing per row")
    groups = {}
    for q in PARAMETERS:
        if q.group not in groups:
            groups[q.group] = p.add_argument_group(q.group)
        groups[q.group].add_argument(option_name(q.name), dest=q.name, metavar="VALUE",
                                     help=f"{q.help} [{q.kind}]")
    o = p.add_argument_group("output")
    o.add_argument("--si", action="store_true", help="output in SI units")
    o.add_argument("--json", action="store_true", help="machine-readable JSON (SI units)")
    o.add_argument("--figure", metavar="FILE.png", help="plot the load distribution "
                   "(needs matplotlib)")
    o.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")
    return p


def _value(name, text, label):
    from .._units import parse_quantity
    from .feature import bounds_of

    p = BY_NAME[name]
    if text is None or (isinstance(text, str) and not text.strip()):
        return None
    if p.kind == "text":
        return text.strip()
    return parse_quantity(label(name), text, p.kind, positive=p.positive,
                          bounds=bounds_of(p))


def _estar(v, label):
    from ..classical import effective_modulus
    from ..errors import CombinationError

    if v["estar"] is not None:
        if any(v[k] is not None for k in ("modulus", "poisson", "modulus2", "poisson2")):
            raise CombinationError({label("estar"): v["estar"]},
                                   "give --estar or the moduli, not both")
        return v["estar"]
    if v["modulus"] is None:
        if v["modulus2"] is not None:
            raise CombinationError({label("modulus2"): v["modulus2"]},
                                   f"give the rings' {label('modulus')} too")
        return 115.38e9  # steel on steel, 210 GPa and 0.3 each
    nu = v["poisson"] if v["poisson"] is not None else None
    if nu is None:
        raise CombinationError({label("modulus"): v["modulus"]},
                               f"give {label('poisson')} with {label('modulus')}")
    e2 = v["modulus2"] if v["modulus2"] is not None else v["modulus"]
    nu2 = v["poisson2"] if v["poisson2"] is not None else nu
    return float(effective_modulus(v["modulus"], nu, e2, nu2))


def solve_one(cells, label=option_name):
    """(bearing, solution) from the typed cells of one bearing (name -> text)."""
    from ..bearing import RadialRollerBearing
    from ..errors import OutOfRangeError

    v = {p.name: _value(p.name, cells.get(p.name), label) for p in PARAMETERS}
    for need in ("rollers", "pitch_diameter", "roller_diameter", "length", "radial_load"):
        if v[need] is None:
            raise OutOfRangeError(label(need), "missing", BY_NAME[need].help)
    kw = {}
    if v["n_slices"] is not None:
        kw["n_slices"] = v["n_slices"]
    if v["poisson"] is not None:
        kw["poisson"] = v["poisson"]
    b = RadialRollerBearing(v["rollers"], v["pitch_diameter"], v["roller_diameter"],
                            v["length"], v["clearance"] or 0.0, estar=_estar(v, label),
                            model=v["model"], profile=v["profile"], rating=v["rating"],
                            **kw)
    if v["tilting_moment"] is not None and v["misalignment"] is not None:
        from ..errors import CombinationError

        raise CombinationError({label("tilting_moment"): v["tilting_moment"],
                                label("misalignment"): v["misalignment"]},
                               "give one of them (the moment a misalignment needs is "
                               "an output)")
    return b, b.solve(v["radial_load"], moment=v["tilting_moment"],
                      misalignment=v["misalignment"])


def summary(s):
    """The one-bearing outputs (FIELDS order), SI; the tilt stiffnesses None under a
    law (no tilt), the stresses None where not computed or not converged (an
    edge-loaded roller: the notes say why)."""
    K = s.stiffness
    two = K.shape == (2, 2)
    st = s.stress or {}
    out = {
        "displacement": s.displacement,
        "radial_stiffness": float(K[0, 0]),
        "tilt": s.tilt,
        "moment": s.moment,
        "stiffness_rt": float(K[0, 1]) if two else None,
        "stiffness_tr": float(K[1, 0]) if two else None,
        "stiffness_tt": float(K[1, 1]) if two else None,
        "max_roller_load": s.max_roller_load,
        "load_zone": s.load_zone,
        "loaded_rollers": int((s.roller_loads > 0).sum()),
        "peak_pressure": s.peak_pressure,
        "rating": s.rating,
        "life_iso281": s.life_iso281,
        "life_iso16281": s.life_iso16281,
    }
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        w = st.get(m)
        shown = w and "withheld" not in w     # an edge-loaded roller's: "-", see notes
        out[m] = w["value"] if shown else None
        out[f"{m}_depth"] = w["depth"] if shown else None
    return out


def _num(x, si, field):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    v = x if si else x * field.factor
    return f"{v:.5g}"


def table(bearing, s, si=False):
    """The text output: the summary, then one row per roller."""
    lines = [f"radial roller bearing: Z = {bearing.rollers}, d_m = "
             f"{bearing.pitch_diameter * 1e3:.6g} mm, D = {bearing.roller_diameter * 1e3:.6g}"
             f" mm, L = {bearing.length * 1e3:.6g} mm, P_d = {bearing.clearance * 1e6:.6g} um,"
             f" E* = {bearing.estar / 1e9:.5g} GPa, F_r = {s.radial_load:.6g} N, "
             f"M = {s.moment:.6g} N m, theta = {s.tilt * (1 if si else 1e3):.6g} "
             + ("rad" if si else "mrad"),
             f"model: {s.model}", ""]
    vals = summary(s)
    w = max(len(f.heading) for f in FIELDS.values())
    for k, f in FIELDS.items():
        u = f.si if si else f.eng
        lines.append(f"  {f.heading:<{w}}  {_num(vals[k], si, f):>12} {u}")
    tilted = s.stiffness.shape == (2, 2)
    lines += ["", "  roller  psi [deg]  approach [" + ("m" if si else "um")
              + "]       Q [N]" + ("    M_j [N m]  tilt [" + ("rad" if si else "mrad")
                                   + "]" if tilted else "")]
    for j in range(len(s.azimuth)):
        a = s.approach[j] * (1 if si else 1e6)
        row = (f"  {j:>6}  {math.degrees(s.azimuth[j]):>9.2f}  {a:>13.5g}  "
               f"{s.roller_loads[j]:>10.5g}")
        if tilted:
            t = s.roller_tilts[j] * (1 if si else 1e3)
            row += f"  {s.roller_moments[j]:>11.5g}  {t:>11.5g}"
        lines.append(row)
    lines += [""] + [f"note: {t}" for t in _NOTES.values()]
    lines += [f"note: {t}" for t in s.notes]
    return "\n".join(lines) + "\n"


def _version():
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("linecontact")
    except PackageNotFoundError:
        return "unknown"


def to_json(argv, bearing, s):
    """JSON text: header (version, command, units, notes) and the solution in SI."""
    d = s.to_dict()
    d["summary"] = summary(s)
    doc = {"linecontact_version": _version(), "command": ["linecontact"] + list(argv),
           "units": {k: f.si for k, f in FIELDS.items()}, "notes": _NOTES,
           "bearing": {"rollers": bearing.rollers, "pitch_diameter": bearing.pitch_diameter,
                       "roller_diameter": bearing.roller_diameter,
                       "length": bearing.length, "clearance": bearing.clearance,
                       "estar": bearing.estar, "profile": bearing.profile.label},
           "solution": d}
    return json.dumps(_clean(doc), indent=1, allow_nan=False) + "\n"


def _clean(x):
    """JSON-safe: nan and inf (an edge-loaded roller's peak pressure, an infinite life)
    become null, numpy scalars plain numbers."""
    if isinstance(x, dict):
        return {k: _clean(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if hasattr(x, "item") and not isinstance(x, (str, bytes)):
        x = x.item()
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def figure(path, bearing, s):
    """Save a plot of the roller loads against azimuth (matplotlib)."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise OSError("--figure needs matplotlib: pip install matplotlib") from None
    import numpy as np

    order = np.argsort(s.azimuth)
    tilted = s.stiffness.shape == (2, 2)
    fig, axes = plt.subplots(2 if tilted else 1, 1, figsize=(6, 5.5 if tilted else 3.5),
                             sharex=True, squeeze=False)
    ax = axes[0, 0]
    psi = np.degrees(s.azimuth[order])
    width = 0.8 * 360 / bearing.rollers
    ax.bar(psi, s.roller_loads[order], width=width)
    ax.set_ylabel("roller load Q [N]")
    ax.set_title(f"Z = {bearing.rollers}, F_r = {s.radial_load:.4g} N, "
                 f"M = {s.moment:.4g} N m, theta = {s.tilt * 1e3:.4g} mrad, "
                 f"P_d = {bearing.clearance * 1e6:.3g} um ({s.model.split(' (')[0]})",
                 fontsize=8)
    if tilted:
        ax2 = axes[1, 0]
        ax2.bar(psi, s.roller_moments[order], width=width, color="tab:orange")
        ax2.set_ylabel("roller moment M_j [N m]")
        ax2.axhline(0.0, color="k", lw=0.5)
        K = s.stiffness
        ax2.text(0.01, 0.97, f"K = [[{K[0, 0] * 1e-6:.4g} N/um, {K[0, 1] * 1e-3:.4g} "
                 f"N/mrad], [{K[1, 0] * 1e-6:.4g} N m/um, {K[1, 1] * 1e-3:.4g} N m/mrad]]",
                 transform=ax2.transAxes, va="top", fontsize=7)
    axes[-1, 0].set_xlabel("roller azimuth psi from the load line [deg]")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _batch(args, argv):
    import csv
    import io

    from .batch import read_table

    header, rows, _ = read_table(args.csv)
    unknown = [h for h in header if h not in BY_NAME and h]
    out_cols = [f"{k} [{f.si if args.si else f.eng}]" for k, f in FIELDS.items()]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(list(header) + out_cols + ["error"])
    failed = 0
    for row in rows:
        cells = {h: c for h, c in zip(header, row) if h in BY_NAME}
        try:
            _, s = solve_one(cells, label=lambda n: n)
            vals = summary(s)
            res = [_num(vals[k], args.si, f) for k, f in FIELDS.items()] + [""]
        except ValueError as exc:
            failed += 1
            res = [""] * len(FIELDS) + [str(exc)]
        w.writerow(list(row) + res)
    _write(buf.getvalue(), args.output)
    if unknown:
        print(f"linecontact bearing: note: columns ignored (not inputs): "
              f"{', '.join(unknown)}", file=sys.stderr)
    return 2 if failed else 0


def _write(text, path):
    if path:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)


def run(args, argv):
    """Run the ``bearing`` subcommand; returns the exit status (errors propagate as
    ValueError/OSError for the caller's one-line message)."""
    if args.csv is not None:
        return _batch(args, argv)
    cells = {p.name: getattr(args, p.name) for p in PARAMETERS}
    bearing, s = solve_one(cells)
    _write(to_json(argv, bearing, s) if args.json else table(bearing, s, args.si),
           args.output)
    if args.figure:
        figure(args.figure, bearing, s)
    return 0
