"""The batch's vectorised output (issue 20, item 1): the result cells of all rows are
formatted at once as a byte matrix; the text must be exactly what formatting each row
in turn gives ('%.6g' for numbers, minimal CSV quoting for text)."""

from __future__ import annotations

import math
import sys

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from linecontact.calc.batch import _g6_bytes, _result_cells, _result_cells_by_row


def _texts(values):
    """The '%.6g' texts of _g6_bytes, one per value (its zero padding dropped)."""
    m = _g6_bytes(np.asarray(values, dtype=float))
    return [bytes(r[r != 0]).decode("ascii") for r in m]


def _python(values):
    return [format(v, ".6g") if math.isfinite(v) else "" for v in map(float, values)]


#: Values where a scaled-integer formatter could part from Python's: exact rounding
#: ties (1234565 = 1.234565e6 rounds half to even), the neighbours of ties, the carry
#: 999999.5 -> 1e+06, powers of ten and their neighbours (log10 one off), the ends of
#: the fixed notation (1e-4, 1e-5, 999999.x), negative zero, subnormals, the largest
#: doubles, NaN and infinities (empty cells).
EDGES = [0.0, -0.0, 1.0, -1.0, 10.0, 0.1, 0.2, 0.3, 1e-4, 9.99999e-5, 1e-5, 0.00012345,
         123456.5, 1234565.0, 999999.5, 999999.4, 9999995.0, 9.999995, 9.9999949,
         100000.0, 1e16, 1e-17, 9.9999e-18, 1e27, 1e28, 9.9999999e27, 1e-300,
         5e-324, sys.float_info.min, sys.float_info.max, float("nan"), float("inf"),
         float("-inf"), -1.5, 2.5e-7]
_P = [10.0 ** k for k in range(-30, 31)]
EDGES += _P + [np.nextafter(p, 0.0) for p in _P] + [np.nextafter(p, np.inf) for p in _P]
EDGES += [9.999995 * p for p in _P] + [np.nextafter(9.999995 * p, 0.0) for p in _P]
EDGES += [1.234565 * p for p in _P] + [-1.5 * p for p in _P]


def test_g6_equals_python_format_at_the_edges():
    """Each edge value formats exactly as format(x, '.6g') (NaN and inf: empty)."""
    assert _texts(EDGES) == _python(EDGES)


def test_g6_equals_python_format_on_integers_and_halves():
    """Integers and half-integers around 1e5, 1.2e5, 1e6 and 1.2e6, both signs: the
    exact ties of the sixth digit (x.5 below 1e6, xxxxxx5 above) round half to even as
    Python's, and the carry to a seventh digit."""
    x = np.concatenate([np.arange(c - 5000, c + 5000, 0.5)
                        for c in (100_000, 123_456, 1_000_000, 1_234_567)])
    x = np.concatenate([x, -x])
    assert _texts(x) == _python(x)


@given(st.lists(st.floats(allow_nan=True, allow_infinity=True), min_size=1, max_size=50))
def test_g6_equals_python_format_on_any_double(values):
    """Any doubles, every exponent and sign."""
    assert _texts(values) == _python(values)


@given(st.lists(st.floats(1e-5, 1e7), min_size=1, max_size=50), st.integers(-20, 20))
def test_g6_equals_python_format_across_decades(values, k):
    """Values spread over the decades a batch prints (the fixed and exponential forms)."""
    values = [v * 10.0 ** k for v in values]
    assert _texts(values) == _python(values)


_TEXT = st.sampled_from(["", "ok", "a,b", 'say "x"', "p > 1.5 GPa", "µm", "50 %",
                         "edge loaded; not converged", "x\ny", "nul\x00"])


@given(st.integers(1, 12), st.data())
def test_result_cells_equal_the_row_by_row_text(n, data):
    """The matrix path gives the text of the row-by-row path for any mix of numeric
    columns (NaN, constant, varying) and text columns (constant, varying, with commas,
    quotes, non-ASCII, a percent sign; a line end or a NUL takes the row-by-row path)."""
    cols = []
    for _ in range(data.draw(st.integers(1, 6))):
        kind = data.draw(st.sampled_from(["num", "const", "text", "consttext"]))
        if kind == "num":
            v = data.draw(st.lists(st.floats(allow_infinity=True, allow_nan=True),
                                   min_size=n, max_size=n))
            cols.append(("num", np.array(v)))
        elif kind == "const":
            cols.append(("num", np.full(n, data.draw(st.floats(-1e9, 1e9)))))
        elif kind == "text":
            cols.append(("text", data.draw(st.lists(_TEXT, min_size=n, max_size=n))))
        else:
            cols.append(("text", [data.draw(_TEXT)] * n))
    assert _result_cells(cols) == _result_cells_by_row(cols)


def test_a_column_of_zeros_of_both_signs_keeps_each_sign():
    """0.0 and -0.0 compare equal but '%.6g' writes them '0' and '-0': a column holding
    both is not constant, and each cell is the text of its own value (both paths)."""
    for values in ([0.0, -0.0, 0.0], [-0.0, 0.0]):
        cols = [("num", np.array(values))]
        want = ["," + t for t in _python(values)]
        assert _result_cells(cols) == want
        assert _result_cells_by_row(cols) == want


def test_a_column_of_one_infinite_value_is_empty_in_both_paths():
    """inf == inf, so a column holding only inf looked constant and the matrix path
    wrote 'inf' once for every row, where the row-by-row path writes a non-finite
    result as an empty cell (found by hypothesis in the test above). Every cell of
    such a column is empty in both paths, as a NaN's is."""
    for values in ([np.inf], [np.inf, np.inf], [-np.inf] * 3):
        cols = [("num", np.array(values)), ("num", np.arange(len(values), dtype=float))]
        want = [",," + format(float(k), ".6g") for k in range(len(values))]
        assert _result_cells(cols) == want
        assert _result_cells_by_row(cols) == want
