"""Hertz elliptical contact (linecontact.hertz): check values, limits and the equations
themselves, verified by integrating the Boussinesq displacement of the Hertz pressure.

Each test states the fact it checks and why its tolerance.
"""
import math

import numpy as np
import pytest
from scipy.integrate import quad

from linecontact.errors import OutOfRangeError
from linecontact.hertz import hertz_contact, hertz_contact_at_approach, hertz_eccentricity

ESTAR = 115.385e9          # steel on steel, E = 210 GPa, nu = 0.3
R = 10e-3


# each check value with half a unit in its last printed digit
@pytest.mark.parametrize("rc, force, a, b, p0, approach", [
    (0.5, 1000.0, (2.287e-3, 0.0005e-3), (0.1895e-3, 0.00005e-3), (1102e6, 0.5e6),
     (7.02e-6, 0.005e-6)),
    (0.2, 2000.0, (1.983e-3, 0.0008e-3), (0.2861e-3, 0.00005e-3), (1684e6, 0.6e6),
     (13.92e-6, 0.005e-6)),
])
def test_crowned_roller_check_values(rc, force, a, b, p0, approach):
    """The check values of a crowned steel roller, R = 10 mm (Rc 500 mm, 1 kN and Rc
    200 mm, 2 kN), recomputed from the elliptic integrals: each agrees to half a unit
    in its last printed digit, except two values of the second case: the exact
    a = 1.98247 mm and p0 = 1683.48 MPa are printed as 1.983 mm and 1684 MPa, 0.03 %
    off in opposite directions (as from an approximate evaluation of the same contact);
    their tolerances are 0.0008 mm and 0.6 MPa (0.04 %). The exact values are confirmed
    independently by test_hertz_pressure_produces_the_gap."""
    h = hertz_contact(force, rc, R, ESTAR)
    for value, (expected, tol) in ((h.a, a), (h.b, b), (h.p0, p0), (h.approach, approach)):
        assert value == pytest.approx(expected, abs=tol)


def test_circle_limit_is_hertz_sphere():
    """Equal radii: a circle with a^3 = 3FR/(4E*), delta = a^2/R, p0 = 3F/(2 pi a^2)
    (Johnson 1985, Eq. 4.22-4.23); and a ratio 1 + 1e-8 is continuous with it (the
    elliptic-integral branch near e = 0). Tolerance 1e-12 exact, 1e-6 for the ratio
    1 + 1e-8, where e ~ 1e-4 and K - E cancels to about 1e-8."""
    F = 500.0
    h = hertz_contact(F, R, R, ESTAR)
    a = (3 * F * R / (4 * ESTAR)) ** (1 / 3)
    assert h.a == pytest.approx(a, rel=1e-12) and h.b == h.a
    assert h.approach == pytest.approx(a * a / R, rel=1e-12)
    assert h.p0 == pytest.approx(3 * F / (2 * math.pi * a * a), rel=1e-12)
    near = hertz_contact(F, R * (1 + 1e-8), R, ESTAR)
    assert near.approach == pytest.approx(h.approach, rel=1e-6)
    assert near.a == pytest.approx(h.a, rel=1e-6)


def _displacement(h, x0, y0, estar):
    """u(x0, y0) = (1/(pi E*)) int p / r dA for the Hertz ellipse, in polar coordinates
    about the field point: the radial integral of the square root of a quadratic is
    done in closed form, the angle by adaptive quadrature."""
    a, b, p0 = h.a, h.b, h.p0

    def radial(phi):
        c, s = math.cos(phi), math.sin(phi)
        # 1 - (x0 + r c)^2/a^2 - (y0 + r s)^2/b^2 = c0 + c1 r - c2 r^2
        c2 = c * c / a**2 + s * s / b**2
        c1 = -2 * (x0 * c / a**2 + y0 * s / b**2)
        c0 = 1 - x0**2 / a**2 - y0**2 / b**2
        m = c1 / (2 * c2)
        hw = math.sqrt(m * m + c0 / c2)
        u0 = -m          # integrate sqrt(hw^2 - u^2) from u = -m to hw
        seg = 0.5 * hw * hw * (math.pi / 2 - math.asin(u0 / hw)) - 0.5 * u0 * math.sqrt(
            max(hw * hw - u0 * u0, 0.0))
        return math.sqrt(c2) * seg

    val, _ = quad(radial, 0.0, 2 * math.pi, limit=400, epsabs=0, epsrel=1e-12)
    return p0 * val / (math.pi * estar)


@pytest.mark.parametrize("rx, ry", [(0.5, 0.01), (0.01, 0.2), (0.03, 0.01)])
def test_hertz_pressure_produces_the_gap(rx, ry):
    """The equations are Hertz's: the pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) with the
    computed a, b, p0 displaces the surface by exactly delta - x^2/(2 Rx) - y^2/(2 Ry)
    inside the ellipse (checked by integrating Boussinesq's solution at the centre
    and at two points on the axes). Tolerance 1e-8 of delta: the quadrature is good to
    about 1e-11, the eccentricity to 1e-14."""
    F = 1500.0
    h = hertz_contact(F, rx, ry, ESTAR)
    ax, ay = (h.b, h.a) if h.swapped else (h.a, h.b)
    hh = h if not h.swapped else type(h)(h.force, ax, ay, h.p0, h.approach, h.stiffness,
                                         h.eccentricity)
    assert _displacement(hh, 0.0, 0.0, ESTAR) == pytest.approx(h.approach, rel=1e-8)
    x0 = 0.6 * ax
    assert _displacement(hh, x0, 0.0, ESTAR) == pytest.approx(
        h.approach - x0**2 / (2 * rx), abs=1e-8 * h.approach)
    y0 = 0.7 * ay
    assert _displacement(hh, 0.0, y0, ESTAR) == pytest.approx(
        h.approach - y0**2 / (2 * ry), abs=1e-8 * h.approach)


def test_force_law_and_stiffness():
    """F ~ delta^(3/2), so k = 3F/(2 delta) = dF/d(delta) (central difference, 1e-7:
    the difference step 1e-6 gives a truncation error of order 1e-12); the inverse
    hertz_contact_at_approach returns the force (1e-12)."""
    F = np.array([100.0, 1000.0, 5000.0])
    h = hertz_contact(F, 0.2, R, ESTAR)
    d = h.approach
    step = 1e-6 * d
    up = hertz_contact_at_approach(d + step, 0.2, R, ESTAR).force
    dn = hertz_contact_at_approach(d - step, 0.2, R, ESTAR).force
    np.testing.assert_allclose((up - dn) / (2 * step), h.stiffness, rtol=1e-7)
    np.testing.assert_allclose(hertz_contact_at_approach(d, 0.2, R, ESTAR).force, F,
                               rtol=1e-12)


def test_eccentricity_equation_is_solved():
    """k' = b/a satisfies Rx/Ry = (E/k'^2 - K)/(K - E) (Johnson 1985, Eq. 4.27) to
    1e-12 for ratios from 1.01 to 1e6 (the root is bracketed and found by Brent's
    method; the ellipk(m1) form keeps K accurate as k' -> 0)."""
    from scipy.special import ellipe, ellipkm1
    for ratio in (1.01, 3.0, 50.0, 1e3, 1e6):
        k, e = hertz_eccentricity(ratio, 1.0)
        K, E = ellipkm1(k * k), ellipe(1 - k * k)
        assert (E / k**2 - K) / (K - E) == pytest.approx(ratio, rel=1e-12)
        assert e == pytest.approx(math.sqrt(1 - k * k), rel=1e-15)


@pytest.mark.parametrize("args, name", [
    ((-1.0, 0.2, R, ESTAR), "force"),
    ((1.0, 0.0, R, ESTAR), "radius_x"),
    ((1.0, 0.2, -R, ESTAR), "radius_y"),
    ((1.0, 0.2, R, np.nan), "estar"),
])
def test_bad_input_names_the_parameter(args, name):
    """Non-positive or NaN input raises OutOfRangeError naming the parameter and the
    range (0, inf): nothing is returned for an impossible contact."""
    with pytest.raises(OutOfRangeError) as err:
        hertz_contact(*args)
    assert err.value.parameter == name and "(0, inf)" in str(err.value)
