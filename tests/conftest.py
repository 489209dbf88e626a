"""Shared test settings: hypothesis runs few, deadline-free examples so the suite stays
fast. The profiled-roller engine 'auto' is the C engine where its extension is built
and current, else the numpy reference, the same for every test (the two agree at
rounding: tests/test_slice_kernels_c_equal_numpy.py)."""
from hypothesis import settings

settings.register_profile("linecontact", max_examples=40, deadline=None)
settings.load_profile("linecontact")
