"""Classical closed forms (Li & Popov 2017 Eqs. 1-4, Kunz, Palmgren, ISO 16281).

Each test states the fact it checks in its docstring and assertion message.
"""
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linecontact.classical import (ISO16281_C, JOHNSON_CONSTANTS, PALMGREN_C,
                                   STEEL_ESTAR, STEEL_ESTAR_RANGE, effective_modulus,
                                   hertz_half_width, iso16281_depth, iso16281_force,
                                   johnson_constant, johnson_depth,
                                   johnson_equivalent_beta, johnson_force,
                                   johnson_stiffness, kunz_depth, kunz_force,
                                   palmgren_depth, palmgren_force,
                                   puttock_thwaite_depth, puttock_thwaite_force,
                                   puttock_thwaite_profile, puttock_thwaite_stiffness,
                                   puttock_thwaite_stiffness_at_depth)
from linecontact.errors import OutOfRangeError
from linecontact.lipopov import lipopov_depth

R, L = 5e-3, 10e-3
E_STEEL = 210e9 / (2 * (1 - 0.3**2))

forces = st.floats(1e-3, 1e6)


# ---- Eq. 3 -------------------------------------------------------------------------------
def test_effective_modulus_steel_on_steel():
    """Eq. 3, steel on steel (E = 210 GPa, nu = 0.3): E* = E / (2 (1 - nu^2)) = 115.38 GPa."""
    assert effective_modulus(210e9, 0.3, 210e9, 0.3) == pytest.approx(E_STEEL, rel=1e-15)
    assert STEEL_ESTAR == pytest.approx(E_STEEL, rel=1e-15)


@given(E1=st.floats(1e6, 1e12), n1=st.floats(0, 0.5, allow_subnormal=False), E2=st.floats(1e6, 1e12),
       n2=st.floats(0, 0.5, allow_subnormal=False))
def test_effective_modulus_is_symmetric_and_rigid_limit(E1, n1, E2, n2):
    """Eq. 3 is symmetric in the two bodies; a rigid body (E = inf) adds no compliance."""
    assert effective_modulus(E1, n1, E2, n2) == pytest.approx(
        effective_modulus(E2, n2, E1, n1), rel=1e-14)
    assert effective_modulus(E1, n1) == pytest.approx(E1 / (1 - n1**2), rel=1e-14)
    assert effective_modulus(np.inf, 0.2, E1, n1) == pytest.approx(E1 / (1 - n1**2), rel=1e-14)


@pytest.mark.parametrize("args, name", [((210e9, 0.51), "poisson1"), ((210e9, -0.1), "poisson1"),
                                        ((-1.0, 0.3), "modulus1"), ((np.nan, 0.3), "modulus1"),
                                        ((210e9, 0.3, 0.0, 0.3), "modulus2"),
                                        ((210e9, 0.3, 210e9, 0.7), "poisson2"),
                                        ((np.inf, 0.3, np.inf, 0.3), "modulus1")])
def test_effective_modulus_refuses_bad_input(args, name):
    """Poisson ratio outside [0, 0.5], non-positive/NaN moduli, two rigid bodies: raise
    OutOfRangeError naming the parameter."""
    with pytest.raises(OutOfRangeError) as err:
        effective_modulus(*args)
    assert err.value.parameter == name


def test_incompressible_poisson_ratio_gives_a_finite_modulus():
    """nu = 0.5 (rubber, incompressible coatings) is a valid material: Eq. 3 gives
    1/E* = 0.75/E1 + 0.75/E2, finite; e.g. rubber on rubber E* = E / 1.5, rubber on a
    rigid body E* = 4 E / 3 (exact in binary up to one rounding)."""
    E = 5e6
    assert effective_modulus(E, 0.5, E, 0.5) == pytest.approx(E / 1.5, rel=1e-15)
    assert effective_modulus(E, 0.5) == pytest.approx(4 * E / 3, rel=1e-15)
    assert effective_modulus(210e9, 0.3, E, 0.5) == pytest.approx(
        1 / ((1 - 0.09) / 210e9 + 0.75 / E), rel=1e-15)


def test_second_modulus_without_its_poisson_ratio_is_refused():
    """A finite modulus2 without poisson2 raises (as the CLI does) instead of taking a
    default nu2 = 0, which would make E* up to 25 % too small (1 - nu2^2 = 0.75 at
    nu2 = 0.5); a rigid second
    body (modulus2 omitted or inf) needs none."""
    with pytest.raises(OutOfRangeError) as err:
        effective_modulus(210e9, 0.3, 70e9)
    assert err.value.parameter == "poisson2" and "modulus2" in str(err.value)
    with pytest.raises(OutOfRangeError):
        effective_modulus(210e9, 0.3, np.array([np.inf, 70e9]))
    assert effective_modulus(210e9, 0.3, np.inf) == effective_modulus(210e9, 0.3)


# ---- Eq. 1, Eq. 2 ------------------------------------------------------------------------
@given(F=forces)
def test_eq2_two_forms_agree_through_the_hertz_half_width(F):
    """Eq. 2 written with ln(pi E* L^3/(R F)) equals the form with ln(4 L^2/b^2), b of Eq. 1."""
    b = hertz_half_width(F, R, L, E_STEEL)
    assert b == pytest.approx(math.sqrt(4 * R * F / (math.pi * E_STEEL * L)), rel=1e-14)
    form_b = F / (math.pi * L * E_STEEL) * (1 + math.log(4 * L**2 / b**2))
    assert puttock_thwaite_depth(F, R, L, E_STEEL) == pytest.approx(form_b, rel=1e-12)


def test_sanity_figure_puttock_thwaite():
    """Issue sanity figure: steel, R = 5 mm, L = 10 mm, 1 kN: Eq. 2 gives about 3.36 um."""
    assert puttock_thwaite_depth(1e3, R, L, E_STEEL) == pytest.approx(3.36e-6, abs=0.005e-6)


@given(F=forces)
def test_puttock_thwaite_force_inverts_depth(F):
    """Round trip: F(d(F)) = F for Eq. 2 (inverse through Lambert W_-1)."""
    d = puttock_thwaite_depth(F, R, L, E_STEEL)
    assert puttock_thwaite_force(d, R, L, E_STEEL) == pytest.approx(F, rel=1e-9)


@given(F=forces)
def test_eq2_stiffness_is_the_true_derivative(F):
    """k = pi L E*/ln(pi E* L^3/(R F)) equals 1/(dd/dF) from a central difference of Eq. 2;
    the printed Eq. 13, pi L E* ln(R F/(pi E* L^3)), is negative, hence wrong."""
    h = 1e-6 * F
    dd_dF = (puttock_thwaite_depth(F + h, R, L, E_STEEL)
             - puttock_thwaite_depth(F - h, R, L, E_STEEL)) / (2 * h)
    k = puttock_thwaite_stiffness(F, R, L, E_STEEL)
    assert k == pytest.approx(1 / dd_dF, rel=1e-6), "k = dF/dd of Eq. 2"
    assert k == pytest.approx(math.pi * L * E_STEEL / math.log(math.pi * E_STEEL * L**3 / (R * F)),
                              rel=1e-12)
    printed_eq13 = math.pi * L * E_STEEL * math.log(R * F / (math.pi * E_STEEL * L**3))
    assert printed_eq13 < 0 < k, "the paper's printed Eq. 13 is negative for physical loads"
    d = puttock_thwaite_depth(F, R, L, E_STEEL)
    assert puttock_thwaite_stiffness_at_depth(d, R, L, E_STEEL) == pytest.approx(k, rel=1e-9)


def test_eq2_refuses_force_beyond_its_maximum():
    """d(F) of Eq. 2 peaks at F = pi E* L^3/R; a larger force raises, naming force."""
    fmax = math.pi * E_STEEL * L**3 / R
    with pytest.raises(OutOfRangeError) as err:
        puttock_thwaite_depth(1.01 * fmax, R, L, E_STEEL)
    assert err.value.parameter == "force" and "L^2/R" in str(err.value)
    with pytest.raises(OutOfRangeError, match="depth"):
        puttock_thwaite_force(L**2 / R, R, L, E_STEEL)


def test_puttock_thwaite_profile_is_eq7_with_beta_1():
    """The MDR profile of Eq. 2 is Eq. 7 with alpha = pi/2, beta = 1; it tends to L^2/R."""
    x = np.array([0.1, 1.0, 10.0]) * L
    u = math.pi / 2 * L / x
    np.testing.assert_allclose(puttock_thwaite_profile(x, R, L),
                               L**2 / R * (u + 1) * np.exp(-u), rtol=1e-14)


# ---- Eq. 4 -------------------------------------------------------------------------------
@pytest.mark.parametrize("c", [1.0, 0.72, 0.572, "johnson1985", "0.72", "0.572", 0.3])
def test_johnson_depth_is_eq4(c):
    """johnson_depth equals Eq. 4, d = F/(pi L E*) (ln(4 pi E* L R/F) - c), typed here,
    for the named constants and for a number."""
    cc = JOHNSON_CONSTANTS[c] if isinstance(c, str) else c
    F = np.geomspace(1.0, 1e5, 7)
    eq4 = F / (math.pi * L * E_STEEL) * (np.log(4 * math.pi * E_STEEL * L * R / F) - cc)
    np.testing.assert_allclose(johnson_depth(F, R, L, E_STEEL, c=c), eq4, rtol=1e-12)


@given(F=forces, c=st.sampled_from([1.0, 0.72, 0.572]))
def test_johnson_inverse_and_stiffness(F, c):
    """Eq. 4: F(d(F)) = F, and k equals 1/(dd/dF) from a central difference."""
    d = johnson_depth(F, R, L, E_STEEL, c=c)
    assert johnson_force(d, R, L, E_STEEL, c=c) == pytest.approx(F, rel=1e-9)
    h = 1e-6 * F
    dd_dF = (johnson_depth(F + h, R, L, E_STEEL, c=c)
             - johnson_depth(F - h, R, L, E_STEEL, c=c)) / (2 * h)
    assert johnson_stiffness(F, R, L, E_STEEL, c=c) == pytest.approx(1 / dd_dF, rel=1e-6)


def test_johnson_is_lipopov_with_alpha_pi_over_2():
    """Eq. 4 equals the Li-Popov form with alpha = pi/2, beta = 4 exp(-(1 + c)) (R/L)^2."""
    F = np.geomspace(1.0, 1e5, 9)
    for c in (1.0, 0.72, 0.572):
        beta = johnson_equivalent_beta(R, L, c)
        np.testing.assert_allclose(lipopov_depth(F, R, L, E_STEEL, alpha=math.pi / 2, beta=beta),
                                   johnson_depth(F, R, L, E_STEEL, c=c), rtol=1e-12)


def test_johnson_constant_names():
    """c is chosen by name ('johnson1985' = 1 after Johnson 1985, '0.72', '0.572') or as a
    number; an unknown name raises, listing the names."""
    assert johnson_constant("johnson1985") == 1.0 and johnson_constant("1") == 1.0
    assert johnson_constant("0.72") == 0.72 and johnson_constant("0.572") == 0.572
    assert johnson_constant(0.5) == 0.5
    with pytest.raises(OutOfRangeError, match="johnson1985"):
        johnson_constant("hamrock")
    with pytest.raises(OutOfRangeError):
        johnson_constant(np.nan)


# ---- Kunz --------------------------------------------------------------------------------
@given(d=st.floats(1e-9, 1e-3))
def test_kunz_linear_law(d):
    """Kunz & de Maria: F = 0.175 E* L d, and kunz_depth inverts it."""
    F = kunz_force(d, L, E_STEEL)
    assert F == pytest.approx(0.175 * E_STEEL * L * d, rel=1e-15)
    assert kunz_depth(F, L, E_STEEL) == pytest.approx(d, rel=1e-14)


# ---- Palmgren, ISO 16281 ----------------------------------------------------------------
def test_sanity_figure_palmgren():
    """Issue sanity figure: steel, L = 10 mm, 1 kN: Palmgren gives about 3.05 um."""
    assert palmgren_depth(1e3, L, E_STEEL) == pytest.approx(3.05e-6, abs=0.005e-6)


@given(F=forces, Lmm=st.floats(1.0, 100.0))
def test_palmgren_and_iso_convert_mm_to_si(F, Lmm):
    """The source formulas are d[mm] = C F[N]^0.9 / L[mm]^0.8; the SI functions return
    exactly that depth in metres (C = 3.84e-5 Palmgren, 3.97e-5 ISO 16281)."""
    assert palmgren_depth(F, Lmm * 1e-3, E_STEEL) == pytest.approx(
        1e-3 * PALMGREN_C * F**0.9 / Lmm**0.8, rel=1e-12)
    assert iso16281_depth(F, Lmm * 1e-3, E_STEEL) == pytest.approx(
        1e-3 * ISO16281_C * F**0.9 / Lmm**0.8, rel=1e-12)


@given(F=forces)
def test_palmgren_and_iso_inverses(F):
    """Round trips: palmgren_force(palmgren_depth(F)) = F, same for ISO 16281."""
    assert palmgren_force(palmgren_depth(F, L, E_STEEL), L, E_STEEL) == pytest.approx(F, rel=1e-12)
    assert iso16281_force(iso16281_depth(F, L, E_STEEL), L, E_STEEL) == pytest.approx(F, rel=1e-12)


def test_iso16281_per_contact_is_half_the_whole_roller_form():
    """ISO 16281's whole-roller Q = 35948 L^(8/9) delta^(10/9) (N, mm) covers two
    contacts: half its delta is the per-contact 3.97e-5 F^0.9/L^0.8 (to the 3 digits of
    the coefficient)."""
    F, Lmm = 1e3, 10.0
    delta_roller_mm = (F / (35948 * Lmm ** (8 / 9))) ** 0.9
    assert iso16281_depth(F, Lmm * 1e-3, E_STEEL) * 1e3 == pytest.approx(
        delta_roller_mm / 2, rel=2e-3)


@pytest.mark.parametrize("fn", [palmgren_depth, iso16281_depth, palmgren_force, iso16281_force])
def test_steel_formulas_refuse_other_materials(fn):
    """Palmgren and ISO 16281 are steel-only: E* outside 115.38 GPa +- 10 % raises
    (aluminium on steel, E* ~ 38 GPa, is refused; 110 GPa is accepted)."""
    e_alu = effective_modulus(70e9, 0.33, 210e9, 0.3)
    with pytest.raises(OutOfRangeError) as err:
        fn(1e-6 if "force" in fn.__name__ else 1e3, L, e_alu)
    assert err.value.parameter == "estar" and "steel" in str(err.value)
    assert err.value.valid == str(STEEL_ESTAR_RANGE)
    fn(1e-6 if "force" in fn.__name__ else 1e3, L, 110e9)


def test_steel_range_is_rendered_in_the_docstring():
    """The validity range in the Notes is the enforced Interval, rendered from data."""
    assert STEEL_ESTAR_RANGE.describe() in palmgren_depth.__doc__
    assert "%(" not in palmgren_depth.__doc__
