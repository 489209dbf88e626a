"""The tabulated partial-slip laws of TangentialContact (arrays of _TABLE_MIN elements or
more) against the direct evaluation they replace: the force with the BEM slip
correction against its root (Illinois regula falsi to 1e-15), the shift of both
methods against the closed form u = c(q) (mu/r) [d - d(F (1 - q))].

The tolerance, 1e-12 of mu F (force) or of u* (shift), is the table's own acceptance
threshold (_TABLE_TOL, checked at every cell midpoint when the table is built); a
cubic Hermite table in s = (1 - x)^(1/4) on 4097 nodes is measured at 2e-13 at most
over the straight-cylinder models, which leaves a factor 5 of margin. The direct
values are themselves exact to rounding (1e-15), so the difference is the table's."""
import numpy as np
import pytest

import linecontact.tangential.contact as tangential
from linecontact._numerics import UniformHermite
from linecontact.errors import OutOfRangeError
from linecontact.models import get_model
from linecontact.tangential import STRAIGHT_CYLINDER_MODELS, TangentialContact

E = 115.38e9
N = tangential._TABLE_MIN + 12345


def _contact(key, force, method):
    return TangentialContact(get_model(key, 5e-3, 10e-3, E), 0.3, 0.8 * E, force=force,
                             method=method)


def _direct_shift(tc, ft):
    q = np.minimum(np.abs(ft) / tc.gross_slip_force, 1.0)
    return np.sign(ft) * tc._corrected_shift(q)


@pytest.mark.parametrize("key", sorted(STRAIGHT_CYLINDER_MODELS))
@pytest.mark.parametrize("force", [10.0, 1e3, 3e4])
def test_tabulated_bem_force_equals_the_root_to_1e_12_mu_f(key, force):
    """F_t(u) from the table equals mu F q with q the root of u_law(q) c(q) = |u| to
    1e-12 mu F over [-u*, u*], the end values included (u* gives mu F exactly)."""
    tc = _contact(key, force, "bem")
    u = np.linspace(-1.0, 1.0, N) * tc.gross_slip_shift
    fast = tc.force(u)
    assert tc._table("force") is not None, "the table should pass its midpoint check"
    ref = np.sign(u) * tc._q_of_shift_reference(np.abs(u)) * tc.gross_slip_force
    ref[np.abs(u) >= tc.gross_slip_shift] = np.sign(u[np.abs(u) >= tc.gross_slip_shift]) \
        * tc.gross_slip_force
    assert np.max(np.abs(fast - ref)) <= 1e-12 * tc.gross_slip_force
    assert fast[0] == -tc.gross_slip_force and fast[-1] == tc.gross_slip_force
    assert fast[N // 2] == 0.0


@pytest.mark.parametrize("key", sorted(STRAIGHT_CYLINDER_MODELS))
@pytest.mark.parametrize("method", ["mdr", "bem"])
@pytest.mark.parametrize("force", [10.0, 1e3, 3e4])
def test_tabulated_shift_equals_the_closed_form_to_1e_12_of_gross_slip(key, method,
                                                                       force):
    """u(F_t) from the table equals c(q) (mu/r) [d - d(F(1 - q))] to 1e-12 u*."""
    tc = _contact(key, force, method)
    ft = np.linspace(-1.0, 1.0, N) * tc.gross_slip_force
    fast = tc.shift(ft)
    assert tc._table("shift") is not None
    assert np.max(np.abs(fast - _direct_shift(tc, ft))) <= 1e-12 * tc.gross_slip_shift


def test_small_arrays_take_the_direct_path_and_agree_with_the_table():
    """Below _TABLE_MIN elements force and shift are the direct evaluation (no table is
    built), and the table's values agree with them to 1e-12."""
    tc = _contact("universal", 1e3, "bem")
    u = np.linspace(0.0, 1.0, 1001) * tc.gross_slip_shift
    small = tc.force(u)
    assert "_tables" not in tc.__dict__
    big = tc.force(np.tile(u, N // 1001 + 1))[:u.size]
    assert np.max(np.abs(big - small)) <= 1e-12 * tc.gross_slip_force


def test_kink_cells_are_solved_by_the_root():
    """Elements in a cell holding a kink of the slip correction (linear in q between its
    Q nodes) are not interpolated: they equal the root to rounding."""
    tc = _contact("universal", 1e3, "bem")
    table = tc._table("force")
    assert table.bad.sum() >= len(tc._kinks())
    cells = np.flatnonzero(table.bad)
    n = table.poly.n - 1
    s = (np.repeat(cells, 20) + np.tile(np.linspace(0.02, 0.98, 20), cells.size)) / n
    u = (1.0 - s ** 4) * tc.gross_slip_shift
    u = np.resize(u, N)
    ref = tc._q_of_shift_reference(u) * tc.gross_slip_force
    assert np.max(np.abs(tc.force(u) - ref)) <= 1e-15 * tc.gross_slip_force


def test_tabulated_force_keeps_the_gross_slip_policy():
    """Beyond u* the table path raises as the direct one does, or saturates at mu F."""
    tc = _contact("universal", 1e3, "bem")
    u = np.linspace(0.0, 1.5, N) * tc.gross_slip_shift
    with pytest.raises(OutOfRangeError, match="shift"):
        tc.force(u)
    sat = tc.force(-u, beyond="saturate")
    assert np.all(sat[u >= tc.gross_slip_shift] == -tc.gross_slip_force)


def test_a_table_that_misses_its_midpoints_is_not_used():
    """A table whose midpoint error exceeds its tolerance reports itself unusable (the
    contact then keeps the direct evaluation)."""
    tc = _contact("universal", 1e3, "mdr")
    ustar = tc.gross_slip_shift
    t = tangential._EndTable(
        lambda q: (tc._corrected_shift(q) / ustar, tc._shift_slope(q) / ustar),
        lambda q: tc._corrected_shift(q) / ustar, (), nodes=9, tol=1e-12)
    assert not t.usable and t.error > 1e-12


def test_uniform_hermite_converges_at_fourth_order():
    """The cubic Hermite interpolant with exact slopes has error O(h^4) (de Boor 1978):
    halving h divides the error of exp on [0, 1] by 16 (14-18 allowing for the
    constant's variation)."""
    s = np.linspace(0.0, 1.0, 100001)
    errs = []
    for n in (17, 33, 65):
        x = np.linspace(0.0, 1.0, n)
        errs.append(np.max(np.abs(UniformHermite(np.exp(x), np.exp(x))(s) - np.exp(s))))
    for a, b in zip(errs, errs[1:]):
        assert 14 < a / b < 18


@pytest.mark.parametrize("method", ["mdr", "bem"])
def test_changing_a_setting_after_a_table_is_built_rebuilds_it(method):
    """The tables are built from the contact's friction (and depth, ratio, ...): after
    ``friction`` is reassigned, a large array gives the law of the new friction (equal
    to the direct evaluation of the new contact to the tables' 1e-12 of u*), not the
    stale table's. (The MDR shift table is in u/u* against q, which friction does not
    change; the BEM force table's correction depends on it, so that case fails without
    the guard.)"""
    tc = _contact("universal", 1e3, method)
    ft = np.linspace(-1.0, 1.0, N) * tc.gross_slip_force
    tc.shift(ft)
    assert tc._table("shift") is not None
    tc.friction = 0.15
    fresh = TangentialContact(tc.model, 0.15, 0.8 * E, force=1e3, method=method)
    ft = np.linspace(-1.0, 1.0, N) * fresh.gross_slip_force
    assert np.max(np.abs(tc.shift(ft) - _direct_shift(fresh, ft))) \
        <= 1e-12 * fresh.gross_slip_shift
    if method == "bem":
        u = np.linspace(-1.0, 1.0, N) * fresh.gross_slip_shift
        assert np.max(np.abs(tc.force(u) - fresh.force(u))) \
            <= 1e-12 * fresh.gross_slip_force
