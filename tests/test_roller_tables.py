"""The tabulated laws of the roller models (arrays of _TABLE_MIN elements or more)
against the slice solves they replace.

The fact: a table of F(d) (or d(F)) built from solves at graded nodes, with each solve's
exact stiffness as the slope, equals a direct solve at random points to 1e-6 of F (or
of d - d0, the depth above first contact). 1e-6 is the table's own acceptance threshold
(checked at every cell's midpoint at build time; a cell that misses it is solved
directly), a thousandth of the models' error against the 3D BEM (about 1e-3). The ISO
slicing law is used (its solves cost a millisecond): with a tilt its 30 slices touch at
30 different depths, each a break of the law, so the pieces and their joins are all
exercised."""
import numpy as np
import pytest

import linecontact.roller.laws as laws
from linecontact.errors import OutOfRangeError
from linecontact.roller.laws import ISOSlicingModel

N = laws._TABLE_MIN
E = 115.38e9


def _model(tilt=5e-4, profile="circular:Rc=0.5"):
    return ISOSlicingModel(5e-3, 10e-3, E, profile=profile, tilt=tilt)


@pytest.mark.parametrize("tilt", [0.0, 5e-4])
def test_tabulated_force_and_depth_equal_the_solves_to_1e_6(tilt):
    """F(d) and d(F) of a large array equal direct solves at 200 random points to 1e-6
    of F and of d - d0, over a range from near first contact to 10 kN."""
    m = _model(tilt)
    rng = np.random.default_rng(7)
    d0 = m.first_contact_depth
    d1 = m.depth(1e4)
    d = d0 + (d1 - d0) * rng.random(N)
    F = m.force(d)
    assert m._tables["force"] is not None, "the table should be built and pass its check"
    k = rng.choice(N, 200, replace=False)
    ref = np.array([m.at_depth(float(x)).force for x in d[k]])
    assert np.max(np.abs(F[k] - ref) / ref) <= 1e-6
    if tilt == 0.0:
        return                       # d(F) once (its build solves 4000 forces)
    f = 1e4 * rng.random(N) + 1e-2
    D = m.depth(f)
    assert m._tables["depth"] is not None
    ref = np.array([m.at_force(float(x)).depth for x in f[k]])
    assert np.max(np.abs(D[k] - ref) / (ref - d0)) <= 1e-6


def test_small_arrays_take_the_direct_path_and_the_table_extends():
    """Below _TABLE_MIN elements the values are the solves themselves (no table built);
    a large array beyond the table's top rebuilds it over the new range and still equals
    the solves to 1e-6 F."""
    m = _model()
    d0 = m.first_contact_depth
    d = d0 + np.linspace(1e-8, 2e-6, 50)
    assert np.array_equal(m.force(d), [m.at_depth(float(x)).force for x in d])
    assert "_tables" not in m.__dict__
    m.force(d0 + np.linspace(1e-8, 2e-6, N))
    top = m._tables["force"].top
    big = d0 + np.linspace(1e-8, 4 * (top - d0), N)
    F = m.force(big)
    assert m._tables["force"].top >= big.max()
    ref = np.array([m.at_depth(float(x)).force for x in big[::997]])
    assert np.max(np.abs(F[::997] - ref) / ref) <= 1e-6


def test_out_of_range_values_raise_as_the_direct_path():
    """A depth at or below first contact (no contact) raises the same OutOfRangeError
    from a large array as from the direct solve; a non-positive force the same error as
    a small array."""
    m = _model()
    d0 = m.first_contact_depth
    d = d0 + np.linspace(1e-8, 2e-6, N)
    d[123] = d0 - 1e-9
    with pytest.raises(OutOfRangeError) as big:
        m.force(d)
    with pytest.raises(OutOfRangeError) as small:
        m.force(d[100:200])
    assert str(big.value) == str(small.value)
    f = np.linspace(1.0, 100.0, N)
    f[5] = -1.0
    with pytest.raises(OutOfRangeError, match=r"force = -1 N \(element \[5\].*\(0, inf\)"):
        m.depth(f)
    assert "_tables" not in m.__dict__ or "depth" not in m._tables


def test_a_changed_tilt_rebuilds_the_table():
    """The table is the law at the model's tilt: after ``tilt`` is reassigned, a large
    array gives the new tilt's law (the solves at the new tilt to 1e-6 F), not the old
    table's."""
    m = _model(tilt=0.0)
    d0 = m.first_contact_depth
    d = d0 + np.linspace(1e-8, 2e-6, N)
    m.force(d)
    m.tilt = 5e-4
    d = m.first_contact_depth + np.linspace(1e-8, 2e-6, N)
    F = m.force(d)
    ref = np.array([m.at_depth(float(x)).force for x in d[::1999]])
    assert np.max(np.abs(F[::1999] - ref) / ref) <= 1e-6


class _FakeTable:
    """Stands in for a built table: answers every value with the build's number."""

    def __init__(self, number):
        self.top, self.number = np.inf, number

    def __call__(self, v):
        return np.full(np.shape(v), float(self.number))


def _counting_builds(monkeypatch, fail_above=np.inf):
    """Replace _build_table by a counter (a table answering with the build's count, or
    a RuntimeError where the range reaches `fail_above`); returns the call list."""
    calls = []

    def build(self, which, hi):
        calls.append(hi)
        if hi >= fail_above:
            raise RuntimeError("the sweep failed")
        return _FakeTable(len(calls))

    monkeypatch.setattr(laws._SolvedRoller, "_build_table", build)
    return calls


def test_changing_the_profiled_rollers_own_settings_rebuilds_the_table(monkeypatch):
    """The profiled-roller law depends on its solver's settings (slice grading, end
    refinement, slice count): setting them on ``model.roller`` drops the tables, as
    setting the model's tilt does; an unchanged model keeps its table."""
    calls = _counting_builds(monkeypatch)
    m = laws.ProfiledRollerModel(5e-3, 10e-3, E, "circular:Rc=0.5", n_slices=20)
    d = m.first_contact_depth + np.linspace(1e-8, 1e-6, 4)
    assert m._tabulated(d, "force")[0] == 1
    assert m._tabulated(d, "force")[0] == 1 and len(calls) == 1, "kept while unchanged"
    m.roller.grading = 0.3
    assert m._tabulated(d, "force")[0] == 2, "a new grading must rebuild the table"
    m.roller.refine_ends = False
    assert m._tabulated(d, "force")[0] == 3, "a new refine_ends must rebuild the table"


def test_a_failed_table_build_is_tried_again_for_a_smaller_range(monkeypatch):
    """A build that fails (the solver cannot sweep the law up to the array's largest
    value) is answered by the direct path (None here) and not tried again up to that
    value; an array within a smaller range tries again and gets a table."""
    calls = _counting_builds(monkeypatch, fail_above=10e-6)
    m = _model()
    d0 = m.first_contact_depth
    assert m._tabulated(d0 + np.linspace(1e-8, 20e-6, 4), "force") is None
    assert m._tabulated(d0 + np.linspace(1e-8, 30e-6, 4), "force") is None
    assert len(calls) == 1, "a larger range than a failed one is not built again"
    assert m._tabulated(d0 + np.linspace(1e-8, 5e-6, 4), "force")[0] == 2


def test_changing_a_profiled_roller_models_geometry_changes_its_law():
    """`model.radius = ...` (or length, estar, n_slices) on a profiled-roller model
    changed the label and dropped the tables, but the roller it solves kept the old
    geometry: the same depth came back. Now the roller is built anew: the law equals a
    new model's with that geometry, and a bad value is refused by name."""
    m = laws.ProfiledRollerModel(5e-3, 10e-3, E, "circular:Rc=0.5", n_slices=20)
    m.radius = 7e-3
    m.n_slices = 24
    fresh = laws.ProfiledRollerModel(7e-3, 10e-3, E, "circular:Rc=0.5", n_slices=24)
    assert m.roller.radius == 7e-3 and m.roller.n_slices == 24
    assert m.depth(1e3) == fresh.depth(1e3)
    with pytest.raises(OutOfRangeError, match="^radius"):
        m.radius = -1.0
    assert m.radius == 7e-3, "a refused value leaves the model as it was"
