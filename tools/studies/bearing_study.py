"""Radial stiffness and maximum roller load of cylindrical roller bearings over a range of
catalogue sizes: the universal curve (the BEM law of a finite cylinder) against the
ISO/TS 16281 spring law (Q = 35948 L^(8/9) delta^(10/9), N and mm, the roller between
its two raceways).

Sizes: the bore d, outside diameter D and width B of the ISO 15 dimension series 02
(the NU 2.. series, NU 204 to NU 230). The internal geometry is not published by the
manufacturers; it is built from d, D, B by fixed rules (stated in the table header):
roller diameter D_we = 0.27 (D - d), effective length L_we = 0.65 B, pitch diameter
d_m = (d + D)/2, rollers Z = floor(pi d_m / (1.25 D_we)). Steel on steel (E* = 115.38
GPa), each bearing at zero clearance and at the clearance P_d = 2e-4 d_m (about the
middle of the normal group), under F_r = 0.05 C_r and 0.2 C_r (C_r by ISO 281 from the
same geometry). Each bearing is one solve of milliseconds, so the study runs serially
(a few seconds); no task runner is needed.

Writes tables/bearing_stiffness.csv and docs/figures/bearing_stiffness.png.
"""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]

#: ISO 15 dimension series 02: name -> (bore d, outside D, width B) [mm].
SERIES_02 = {
    "NU 204": (20, 47, 14), "NU 206": (30, 62, 16), "NU 208": (40, 80, 18),
    "NU 210": (50, 90, 20), "NU 212": (60, 110, 22), "NU 216": (80, 140, 26),
    "NU 220": (100, 180, 34), "NU 224": (120, 215, 40), "NU 230": (150, 270, 45),
}
LOAD_FRACTIONS = (0.05, 0.2)
CLEARANCE_PER_DM = (0.0, 2e-4)
MODELS = ("universal", "iso16281")


def geometry(d, D, B):
    """(Z, d_m, D_we, L_we) [-, m, m, m] of the rules in the module docstring."""
    Dwe = 0.27 * (D - d) * 1e-3
    Lwe = 0.65 * B * 1e-3
    dm = 0.5 * (d + D) * 1e-3
    Z = int(math.floor(math.pi * dm / (1.25 * Dwe)))
    return Z, dm, Dwe, Lwe


def add_arguments(parser):
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder of the table (default tables/)")
    parser.add_argument("--figure", type=Path,
                        default=REPO / "docs" / "figures" / "bearing_stiffness.png",
                        help="figure file ('' for none)")


def compute():
    from linecontact.bearing import RadialRollerBearing, dynamic_load_rating

    cols = {k: [] for k in ("bore", "outside_diameter", "width", "rollers",
                            "pitch_diameter", "roller_diameter", "length", "clearance",
                            "rating", "radial_load", "K_universal", "K_iso",
                            "Qmax_universal", "Qmax_iso", "delta_universal", "delta_iso")}
    names = []
    for name, (d, D, B) in SERIES_02.items():
        Z, dm, Dwe, Lwe = geometry(d, D, B)
        C = dynamic_load_rating(Z, dm, Dwe, Lwe)
        for cpd in CLEARANCE_PER_DM:
            for frac in LOAD_FRACTIONS:
                F = frac * C
                res = {}
                for m in MODELS:
                    s = RadialRollerBearing(Z, dm, Dwe, Lwe, cpd * dm, model=m).solve(F)
                    res[m] = s
                    if abs(s.roller_loads @ np.cos(s.azimuth) / F - 1) > 1e-9:
                        raise RuntimeError(f"{name}: equilibrium not met")
                names.append(name)
                for k, v in (("bore", d * 1e-3), ("outside_diameter", D * 1e-3),
                             ("width", B * 1e-3), ("rollers", Z), ("pitch_diameter", dm),
                             ("roller_diameter", Dwe), ("length", Lwe),
                             ("clearance", cpd * dm), ("rating", C), ("radial_load", F),
                             ("K_universal", res["universal"].stiffness[0, 0]),
                             ("K_iso", res["iso16281"].stiffness[0, 0]),
                             ("Qmax_universal", res["universal"].max_roller_load),
                             ("Qmax_iso", res["iso16281"].max_roller_load),
                             ("delta_universal", res["universal"].displacement),
                             ("delta_iso", res["iso16281"].displacement)):
                    cols[k].append(v)
    cols = {k: np.array(v, dtype=float) for k, v in cols.items()}
    cols["K_ratio"] = cols["K_universal"] / cols["K_iso"]
    cols["Qmax_ratio"] = cols["Qmax_universal"] / cols["Qmax_iso"]
    return names, cols


def figure(path, cols):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for cpd, ls in zip(CLEARANCE_PER_DM, ("-", "--")):
        for frac, mk in zip(LOAD_FRACTIONS, ("o", "s")):
            sel = (np.isclose(cols["clearance"], cpd * cols["pitch_diameter"])
                   & np.isclose(cols["radial_load"], frac * cols["rating"]))
            lab = f"F_r = {frac:g} C_r, P_d = {cpd * 1e4:g}e-4 d_m"
            axes[0].plot(cols["bore"][sel] * 1e3, cols["K_ratio"][sel], ls, marker=mk,
                         label=lab)
            axes[1].plot(cols["bore"][sel] * 1e3, cols["Qmax_ratio"][sel], ls, marker=mk,
                         label=lab)
    axes[0].set_ylabel("K_rr universal / K_rr ISO spring")
    axes[1].set_ylabel("Q_max universal / Q_max ISO spring")
    for ax in axes:
        ax.set_xlabel("bore d [mm] (NU 2.. series)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Cylindrical roller bearings: universal curve against the ISO/TS 16281 "
                 "spring law", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)


def run(args):
    from linecontact.tables import write_table
    from .runner import table_meta

    t0 = time.perf_counter()
    names, cols = compute()
    wall = time.perf_counter() - t0
    k, q = cols["K_ratio"], cols["Qmax_ratio"]
    meta = table_meta(
        args.command_line,
        title="Radial stiffness K_rr and maximum roller load Q_max of cylindrical roller "
              "bearings (ISO dimension series 02, NU 204 to NU 230) with the universal "
              "curve against the ISO/TS 16281 spring law",
        source="computed by linecontact.bearing.RadialRollerBearing (roller between "
               "raceways from linecontact.raceway; universal curve: tables/"
               "universal_curve.csv; ISO spring: ISO/TS 16281:2008); sizes: bore, "
               "outside diameter and width of ISO 15 series 02; internal geometry by rule: "
               "D_we = 0.27 (D - d), L_we = 0.65 B, d_m = (d + D)/2, Z = floor(pi d_m/"
               "(1.25 D_we)) (not manufacturers' data); steel E* = 115.38 GPa; rows: "
               + ", ".join(dict.fromkeys(names)),
        units="bore, outside_diameter, width, pitch_diameter, roller_diameter, length, "
              "clearance (radial internal clearance P_d), delta_* (ring displacement) [m]; "
              "rollers [-]; rating (ISO 281 C_r), radial_load, Qmax_* [N]; K_* [N/m]; "
              "K_ratio = K_universal/K_iso, Qmax_ratio = Qmax_universal/Qmax_iso [-]",
        grid=f"9 sizes x clearance P_d/d_m in {list(CLEARANCE_PER_DM)} x F_r/C_r in "
             f"{list(LOAD_FRACTIONS)}",
        accuracy=f"equilibrium sum Q_j cos psi_j = F_r to 1e-9 (checked per row); "
                 f"K_rr exact derivative of the equilibrium; the laws' own accuracy: "
                 f"tables/universal_curve.csv header; K_ratio in [{k.min():.3f}, "
                 f"{k.max():.3f}], Qmax_ratio in [{q.min():.4f}, {q.max():.4f}]",
        wall_time=f"{wall:.1f} s (serial)",
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "bearing_stiffness.csv"
    write_table(path, meta, cols)
    print(f"wrote {path}: K_ratio {k.min():.3f}..{k.max():.3f}, Qmax_ratio "
          f"{q.min():.4f}..{q.max():.4f} ({wall:.1f} s)")
    if str(args.figure):
        figure(args.figure, cols)
        print(f"wrote {args.figure}")
    return 0
