"""General MDR transforms (docs/theory.md, section 'MDR'; Popov & Hess 2015).

Each test states the fact it checks in its docstring and assertion message.
"""
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linecontact.errors import OutOfRangeError
from linecontact.lipopov import (lipopov_contact_radius, lipopov_force, lipopov_profile,
                                 lipopov_stiffness)
from linecontact.mdr import (mdr_contact_radius, mdr_force, mdr_profile_from_force,
                             mdr_profile_from_stiffness, mdr_stiffness)

E = 210e9 / (2 * (1 - 0.3**2))
R, L = 5e-3, 10e-3


def test_sphere_profile_gives_hertz():
    """Known answer (docs/theory.md, section 'Verification'): the MDR profile of a sphere, g = x^2/R, gives Hertz,
    F = 4/3 E* sqrt(R) d^(3/2), and a = sqrt(R d)."""
    Rs = 10e-3
    d = np.geomspace(1e-9, 1e-4, 6)
    g = lambda x: x**2 / Rs
    np.testing.assert_allclose(mdr_force(d, g, E), 4 / 3 * E * math.sqrt(Rs) * d**1.5, rtol=1e-9)
    np.testing.assert_allclose(mdr_contact_radius(d, g), np.sqrt(Rs * d), rtol=1e-12)


@given(D=st.floats(1e-9, 0.98), q=st.floats(0.1, 20.0), a=st.floats(1.0, 4.0),
       b=st.floats(0.3, 20.0))
def test_quadrature_of_eq7_equals_closed_form(D, q, a, b):
    """MDR quadrature F = 2E* int_0^a (d - g) dx of the Li-Popov profile (Eq. 7) equals
    the closed form (Lambert W), and so do a(d) and k = 2 E* a."""
    Lq = q * R
    d = D * b * Lq**2 / R
    g = lambda x: lipopov_profile(x, R, Lq, alpha=a, beta=b)
    co = dict(alpha=a, beta=b)
    assert mdr_force(d, g, E, x_scale=Lq) == pytest.approx(
        lipopov_force(d, R, Lq, E, **co), rel=1e-8), "MDR quadrature of Eq. 7 = closed form"
    assert mdr_contact_radius(d, g, x_scale=Lq) == pytest.approx(
        lipopov_contact_radius(d, R, Lq, **co), rel=1e-10)
    assert mdr_stiffness(d, g, E, x_scale=Lq) == pytest.approx(
        lipopov_stiffness(d, R, Lq, E, **co), rel=1e-10)


def test_mdr_stiffness_is_derivative_of_mdr_force():
    """k = dF/dd = 2E* a for an arbitrary profile (here g = x^4/c^3): central difference."""
    c = 1e-3
    g = lambda x: x**4 / c**3
    d = 1e-6
    h = 1e-5 * d
    numeric = (mdr_force(d + h, g, E) - mdr_force(d - h, g, E)) / (2 * h)
    assert mdr_stiffness(d, g, E) == pytest.approx(numeric, rel=1e-7)


def test_x_scale_does_not_change_the_result():
    """The bracket start x_scale is only a hint: a far-off value gives the same a."""
    g = lambda x: lipopov_profile(x, R, L, alpha=1.6, beta=0.5)
    a1 = mdr_contact_radius(1e-6, g, x_scale=L)
    for xs in (1e-12, 1e3):
        assert mdr_contact_radius(1e-6, g, x_scale=xs) == pytest.approx(a1, rel=1e-12)


def test_extraction_from_stiffness_recovers_eq7_exactly():
    """Reverse MDR: sampled k(d) of the Li-Popov model -> x = k/(2E*), g = d lies on Eq. 7."""
    co = dict(alpha=1.6048, beta=0.5376)
    d = np.geomspace(1e-9, 0.9, 50) * co["beta"] * L**2 / R
    x, gx = mdr_profile_from_stiffness(d, lipopov_stiffness(d, R, L, E, **co), E)
    np.testing.assert_allclose(lipopov_profile(x, R, L, **co), gx, rtol=1e-9)


def test_extraction_from_force_samples_recovers_eq7():
    """Reverse MDR from sampled F(d) (finite differences): 400 log-spaced samples of the
    Li-Popov F(d) give x = k/(2E*) within 2e-4 of the exact MDR contact radius (5e-4 at
    the ends, one-sided), i.e. the points (x, d) lie on Eq. 7 (second-order differences)."""
    co = dict(alpha=1.7086, beta=0.7936)
    d = np.geomspace(1e-6, 0.5, 400) * co["beta"] * L**2 / R
    x, gx = mdr_profile_from_force(d, lipopov_force(d, R, L, E, **co), E)
    np.testing.assert_array_equal(gx, d)
    exact = lipopov_contact_radius(d, R, L, **co)
    np.testing.assert_allclose(x[3:-3], exact[3:-3], rtol=2e-4, err_msg="central differences")
    np.testing.assert_allclose(x, exact, rtol=5e-4, err_msg="one-sided at the ends")


def test_profile_to_force_to_profile_round_trip():
    """g -> F(d) by quadrature -> g by extraction returns the profile (g = x^3/c^2)."""
    c = 2e-3
    g = lambda x: x**3 / c**2
    d = np.geomspace(1e-7, 1e-5, 200)
    x, gx = mdr_profile_from_force(d, mdr_force(d, g, E), E)
    np.testing.assert_allclose(g(x), gx, rtol=2e-4)


def test_bounded_profile_refuses_unreachable_depth():
    """A depth the (bounded) profile never reaches raises OutOfRangeError naming depth."""
    g = lambda x: lipopov_profile(x, R, L, alpha=1.6, beta=0.5)
    with pytest.raises(OutOfRangeError) as err:
        mdr_force(0.5 * L**2 / R * 1.001, g, E)
    assert err.value.parameter == "depth" and "bounded" in str(err.value)


def test_extraction_refuses_bad_samples():
    """Extraction needs strictly increasing depths and a convex F(d) (k increasing, so
    that g is monotone); otherwise OutOfRangeError, not a silently wrong profile."""
    d = np.array([1e-6, 2e-6, 3e-6, 4e-6])
    with pytest.raises(OutOfRangeError, match="depth"):
        mdr_profile_from_force(d[::-1], d**1.5, E)
    with pytest.raises(OutOfRangeError, match="F\\(d\\) convex"):
        mdr_profile_from_force(d, np.sqrt(d), E)
    with pytest.raises(OutOfRangeError, match="force"):
        mdr_profile_from_force(d, [1.0, np.nan, 2.0, 3.0], E)
    with pytest.raises(OutOfRangeError, match="stiffness"):
        mdr_profile_from_stiffness(d, [4.0, 3.0, 2.0, 1.0], E)
