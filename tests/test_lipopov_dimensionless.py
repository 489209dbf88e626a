"""The dimensionless closed forms of Li & Popov (2017), Eq. 8-9, in linecontact.lipopov:
the one home the BEM studies (tools/studies/paper_fit.py, tools/studies/universal_study.py) and the
figures call.

Facts checked:
- self-similarity (Eq. 8): F = E* L^3/R F~(d R/L^2) and k = E* L k~(d R/L^2) for any
  R, L, E* (to rounding, 1e-12);
- x~(d~) inverts the profile of Eq. 9: g~(x~(d~)) = d~, and d~(F~) inverts F~(d~)
  (to rounding);
- k~ = dF~/dd~ (central differences, error O(h^2) ~ 1e-8 at h = 1e-5 d~);
- effective_beta inverts the force: the point (d~, F~(d~; alpha, beta)) gives beta back;
- the fit of Eq. 9 is exact on points of Eq. 9 and refuses too few points;
- d~ at or beyond beta is refused, never clipped.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linecontact.errors import OutOfRangeError
from linecontact.lipopov import (dimensionless_contact_radius, dimensionless_depth,
                                 dimensionless_force, dimensionless_profile, dimensionless_stiffness,
                                 effective_beta, fit_dimensionless_profile,
                                 lipopov_force, lipopov_stiffness)

coef = st.tuples(st.floats(0.5, 3.0), st.floats(0.1, 2.0))


@given(coef, st.floats(1e-6, 0.99), st.floats(1e-3, 1.0), st.floats(0.1, 50.0),
       st.floats(1e9, 3e11))
def test_self_similarity_of_force_and_stiffness(ab, frac, R, q, E):
    a, b = ab
    L = q * R
    dt = frac * b
    d = dt * L**2 / R
    F = lipopov_force(d, R, L, E, alpha=a, beta=b)
    k = lipopov_stiffness(d, R, L, E, alpha=a, beta=b)
    assert F == pytest.approx(E * L**3 / R * dimensionless_force(dt, a, b), rel=1e-12)
    assert k == pytest.approx(E * L * dimensionless_stiffness(dt, a, b), rel=1e-12)


@given(coef, st.floats(1e-8, 0.999))
def test_contact_radius_inverts_the_profile(ab, frac):
    a, b = ab
    dt = frac * b
    x = dimensionless_contact_radius(dt, a, b)
    assert dimensionless_profile(x, a, b) == pytest.approx(dt, rel=1e-10)
    assert dimensionless_stiffness(dt, a, b) == pytest.approx(2 * x, rel=1e-14)
    F = dimensionless_force(dt, a, b)
    if F < 2 * a * b:      # else F~ rounds onto its bound (d~ within 1e-8 of it)
        assert dimensionless_depth(F, a, b) == pytest.approx(dt, rel=1e-10)


def test_stiffness_is_the_derivative_of_the_force():
    a, b = 1.6048, 0.5376
    dt = np.linspace(0.01, 0.9, 30) * b
    h = 1e-5 * dt
    slope = (dimensionless_force(dt + h, a, b) - dimensionless_force(dt - h, a, b)) / (2 * h)
    np.testing.assert_allclose(dimensionless_stiffness(dt, a, b), slope, rtol=1e-7)


def test_effective_beta_gives_the_form_back():
    a, b = np.pi / 2, 0.4573
    dt = np.geomspace(1e-12, 0.4, 15)
    np.testing.assert_allclose(effective_beta(dt, dimensionless_force(dt, a, b), a), b,
                               rtol=1e-9)


def test_fit_is_exact_on_points_of_eq9():
    x = np.geomspace(0.05, 3.0, 30)
    a, b = fit_dimensionless_profile(x, dimensionless_profile(x, 1.2, 0.31),
                                     start=(1.5, 0.5))
    assert (a, b) == (pytest.approx(1.2, rel=1e-9), pytest.approx(0.31, rel=1e-9))
    with pytest.raises(ValueError, match="at least 2 points"):
        fit_dimensionless_profile([0.5], [0.1])


@pytest.mark.parametrize("func", [dimensionless_force, dimensionless_stiffness,
                                  dimensionless_contact_radius])
def test_depth_beyond_the_bound_is_refused(func):
    with pytest.raises(OutOfRangeError, match="d_tilde"):
        func(0.5, 1.5, 0.5)
    with pytest.raises(OutOfRangeError, match="d_tilde"):
        func(0.0, 1.5, 0.5)


def test_force_beyond_the_saturation_is_refused():
    with pytest.raises(OutOfRangeError, match="f_tilde"):
        dimensionless_depth(2 * 1.5 * 0.5, 1.5, 0.5)
