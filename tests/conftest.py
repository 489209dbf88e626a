"""Shared test settings: hypothesis runs few, deadline-free examples so the suite stays
fast; every test starts with the profiled-roller engine 'auto' where a fresh process
has it: the C engine where its extension is built, else the numpy reference (the
engines' agreement with numpy: tests/test_roller_engine.py)."""
import pytest
from hypothesis import settings

settings.register_profile("linecontact", max_examples=40, deadline=None)
settings.load_profile("linecontact")


@pytest.fixture(autouse=True)
def _numpy_steps_from_zero():
    """engine='auto' switches to numba after 1500 numpy steps per process (some 150
    solves, a few test files): without this reset, which engine a test ran depended on
    the tests before it, and most of the suite checked the compiled kernels instead of
    the numpy reference. Tests of the switch set the counter themselves."""
    from linecontact.roller import slices
    slices._NUMPY_STEPS[0] = 0
    yield
