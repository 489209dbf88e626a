"""Write examples/cam_cycle.csv: one case per cam angle for ``linecontact calc``.

A disc cam (base circle Rb = 30 mm) drives a translating roller follower (steel roller,
radius 5 mm, length 15 mm, crowned with Rc = 500 mm) through a cycloidal rise of
h = 8 mm over 120 deg, a dwell of 60 deg, a cycloidal return over 120 deg and a dwell
of 60 deg, at 1500 rpm. Per angle the file gives:

- ``radius2``: the cam's radius of curvature at the contact, from the pitch curve
  r(phi) = Rb + Rr + h(phi) of a radial follower,
  rho_p = (r^2 + r'^2)^(3/2) / (r^2 + 2 r'^2 - r r''), rho_cam = rho_p - Rr
  (Norton, *Cam Design and Manufacturing Handbook*, 2009, ch. 7);
- ``load``: spring preload plus spring rate times lift plus the follower's inertia,
  F = F0 + k_s h + m h_ddot, with h_ddot = omega^2 h''(phi);
- ``tilt``: a misalignment growing with the load (a shaft that bends), 0.3 mrad at the
  largest load.

Run ``python examples/cam_cycle.py`` to rewrite the CSV, then
``linecontact calc examples/cam_cycle.csv -o cam_results.csv`` (docs/cam_cycle.md).
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

RB, RR, LENGTH, CROWN = 30e-3, 5e-3, 15e-3, 0.5     # m
LIFT, RISE, DWELL = 8e-3, math.radians(120), math.radians(60)
RPM, MASS, F0, K_SPRING, TILT_MAX = 1500.0, 0.5, 2000.0, 150e3, 0.3e-3


def lift(phi):
    """h, dh/dphi, d2h/dphi2 of the cycloidal rise-dwell-return-dwell cycle."""
    def cyc(u, beta):
        x = u / beta
        return (LIFT * (x - math.sin(2 * math.pi * x) / (2 * math.pi)),
                LIFT / beta * (1 - math.cos(2 * math.pi * x)),
                2 * math.pi * LIFT / beta ** 2 * math.sin(2 * math.pi * x))

    if phi < RISE:
        return cyc(phi, RISE)
    if phi < RISE + DWELL:
        return LIFT, 0.0, 0.0
    if phi < 2 * RISE + DWELL:
        h, d1, d2 = cyc(phi - RISE - DWELL, RISE)
        return LIFT - h, -d1, -d2
    return 0.0, 0.0, 0.0


def rows(step_deg=10):
    omega = RPM * 2 * math.pi / 60
    out = []
    for deg in range(0, 360, step_deg):
        h, d1, d2 = lift(math.radians(deg))
        r = RB + RR + h
        rho_p = (r ** 2 + d1 ** 2) ** 1.5 / (r ** 2 + 2 * d1 ** 2 - r * d2)
        force = F0 + K_SPRING * h + MASS * omega ** 2 * d2
        out.append((deg, rho_p - RR, force))
    f_max = max(f for _, _, f in out)
    return [(deg, rho, f, TILT_MAX * f / f_max) for deg, rho, f in out]


def main(path=Path(__file__).with_name("cam_cycle.csv")):
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["cam_angle_deg", "radius", "length", "modulus", "poisson", "modulus2",
                    "poisson2", "crown_radius", "radius2", "load", "tilt"])
        for deg, rho, f, tilt in rows():
            w.writerow([deg, f"{RR * 1e3:g}mm", f"{LENGTH * 1e3:g}mm", "210GPa", "0.3",
                        "210GPa", "0.3", f"{CROWN * 1e3:g}mm", f"{rho * 1e3:.4f}mm",
                        f"{f:.2f}N", f"{tilt * 1e3:.4f}mrad"])


if __name__ == "__main__":
    main()
