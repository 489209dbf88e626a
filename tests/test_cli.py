"""Tests of the ``linecontact calc`` command.

The first part runs ``python -m linecontact`` from this checkout's root in a
subprocess, as a user would (start-up, imports, exit status, stdout/stderr). Every such
command is started once, all of them in parallel at the start of the module (the
start-up of Python and numpy dominates), and each test then reads the result of the
command it names. The second part calls :func:`linecontact.calc.cli.main` in-process (the
same code without a start-up per test) for the input rules, the batch's guarantees and
the new output columns.
"""

from __future__ import annotations

import contextlib
import csv
import functools
import io
import json
import math
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

DATA = Path(__file__).parent / "data"
EXAMPLES = Path(__file__).parent.parent / "examples"

STEEL = ["--modulus", "210GPa", "--poisson", "0.3"]
CASE = ["calc", "--radius", "5mm", "--length", "10mm", *STEEL]
ONE = [*CASE, "--load", "1kN"]
SI_ONE = "calc --radius 0.005 --length 0.01 --modulus 2.1e11 --poisson 0.3 --load 1000".split()

IMPORTTIME = ["-X", "importtime", "-m", "linecontact"]

#: name -> argv of every command the tests look at (run in parallel, once). Each costs
#: a Python start-up with numpy and scipy, so related facts share a command.
COMMANDS = {
    "one": ONE,
    "one_json": [*ONE, "--json"],
    # python -m linecontact, with -X importtime: what a one-case call imports
    "units_importtime": [*IMPORTTIME, *ONE],
    "bare_json_importtime": [*IMPORTTIME, *SI_ONE, "--json"],
    # one profiled, tilted case: a coupled-slice solve, still without scipy
    "profiled_importtime": [*IMPORTTIME, *ONE, "--profile", "iso16281", "--tilt", "1mrad"],
    # a unit name outside the built-in table (1e8 dyn = 1 kN): pint is asked for it
    "dyne_json_importtime": [*IMPORTTIME, *CASE, "--load", "1e8 dyn", "--json"],
    "inch_json": [
        "calc",
        "--radius",
        "0.19685039in",
        "--length",
        "0.3937008 in",
        *STEEL,
        "--load",
        "224.80894 lbf",
        "--json",
    ],
    "two_bodies_json": [
        *CASE,
        "--modulus2",
        "210GPa",
        "--poisson2",
        "0.3",
        "--load",
        "1kN",
        "--json",
    ],
    "depth_json": [*CASE, "--depth", "2um", "--json"],
    "depth_sweep_si": [*CASE, "--depth", "1um:4um:3", "--si"],
    "sweep_geom_json": [*CASE, "--load", "0.1kN:10kN:5", "--json"],
    "sweep_lin_json": [*CASE, "--load", "100N:500N:5", "--linear", "--json"],
    "model_options_json": [*ONE, "--model", "johnson:c=0.72,li-popov:coefficients=eq11", "--json"],
    "batch": ["calc", str(EXAMPLES / "cases.csv")],
    "batch_all_json": ["calc", str(EXAMPLES / "cases.csv"), "--model", "all", "--json"],
    "batch_bad": ["calc", str(DATA / "bad_rows.csv")],
    "batch_defaults": [
        "calc",
        str(DATA / "loads_only.csv"),
        "--radius",
        "5mm",
        "--length",
        "10mm",
        *STEEL,
    ],
    # error paths: each must be one line on stderr, exit status 2
    "err_bad_unit": [*CASE, "--load", "1 kilofoo"],
    "err_wrong_dimension": ["calc", "--radius", "5N", "--length", "10mm", *STEEL, "--load", "1kN"],
    "err_negative": ["calc", "--radius", "-5mm", "--length", "10mm", *STEEL, "--load", "1kN"],
    "err_negative_eq": ["calc", "--radius=-5mm", "--length", "10mm", *STEEL, "--load", "1kN"],
    "err_no_load": CASE,
    "err_load_and_depth": [*CASE, "--load", "1kN", "--depth", "1um"],
    "err_missing_radius": ["calc", "--length", "10mm", *STEEL, "--load", "1kN"],
    "err_no_poisson": ["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
                       "--load", "1kN"],
    "err_poisson_range": ["calc", "--radius", "5mm", "--length", "10mm", "--modulus",
                          "210GPa", "--poisson", "0.7", "--load", "1kN"],
    "err_estar_and_modulus": [*CASE, "--estar", "100GPa", "--load", "1kN"],
    "err_modulus2_alone": [*CASE, "--modulus2", "70GPa", "--load", "1kN"],
    "err_sweep_fields": [*CASE, "--load", "1kN:2kN"],
    "err_unknown_model": [*ONE, "--model", "nosuchmodel"],
    "err_unknown_option": [*ONE, "--radious", "5mm"],
    "err_no_file": ["calc", str(DATA / "missing.csv")],
    "err_no_columns": ["calc", str(DATA / "no_case_columns.csv")],
}

#: error command -> (parameter named in the message, value shown in it)
ERRORS = {
    "err_bad_unit": ("--load", "1 kilofoo"),
    "err_wrong_dimension": ("--radius", "5N"),
    "err_negative": ("--radius", "-5mm"),
    "err_negative_eq": ("--radius", "-5mm"),
    "err_no_load": ("--load", ""),
    "err_load_and_depth": ("--load", "1kN"),
    "err_missing_radius": ("--radius", ""),
    "err_no_poisson": ("--poisson", ""),
    "err_poisson_range": ("--poisson", "0.7"),
    "err_estar_and_modulus": ("--modulus", "210GPa"),
    "err_modulus2_alone": ("--poisson2", ""),
    "err_sweep_fields": ("--load", "1kN:2kN"),
    "err_unknown_model": ("--model", "nosuchmodel"),
    "err_unknown_option": ("--radious", ""),
    "err_no_file": ("missing.csv", ""),
    "err_no_columns": ("no_case_columns.csv", ""),
}


ROOT = Path(__file__).parent.parent


def _run(argv, **kw):
    """Run `python -m linecontact ARGV` from the repository root, so that this checkout's
    linecontact is the one tested (the console script may belong to another install)."""
    if argv[0].startswith("-"):
        cmd = [sys.executable, *argv]
    else:
        cmd = [sys.executable, "-m", "linecontact", *argv]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=ROOT, **kw)


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    target = tmp_path_factory.mktemp("cli") / "out.csv"
    commands = dict(
        COMMANDS, batch_to_file=["calc", str(EXAMPLES / "cases.csv"), "-o", str(target)]
    )
    with ThreadPoolExecutor(max_workers=8) as pool:
        futures = {name: pool.submit(_run, argv) for name, argv in commands.items()}
        return {name: f.result() for name, f in futures.items()}


def _ok(results, name):
    r = results[name]
    assert r.returncode == 0, f"{name} failed (status {r.returncode}):\n{r.stderr}"
    return r


def _json(results, name):
    return json.loads(_ok(results, name).stdout)


def _library(radius=0.005, length=0.01, estar=210e9 / (1 - 0.3**2)):
    """The models the CLI should report, built in-process from SI inputs."""
    from linecontact import models

    return models.standard_models(radius, length, estar)


@functools.lru_cache(maxsize=None)
def _quantity():
    import pint

    return pint.UnitRegistry().Quantity


def _si_case(row):
    """(R, L, E*) in SI of a row of examples/cases.csv, by hand (not by the CLI)."""
    q = _quantity()
    R = q(row["radius"]).to("m").magnitude
    L = q(row["length"]).to("m").magnitude
    if row["estar"]:
        return R, L, q(row["estar"]).to("Pa").magnitude
    inv = (1 - float(row["poisson"]) ** 2) / q(row["modulus"]).to("Pa").magnitude
    if row["modulus2"]:
        inv += (1 - float(row["poisson2"]) ** 2) / q(row["modulus2"]).to("Pa").magnitude
    return R, L, 1 / inv


def _close(a, b, rtol=1e-9):
    if a is None or b is None:
        return a is b
    return math.isclose(a, b, rel_tol=rtol, abs_tol=0.0)


# ---------------------------------------------------------------------------------------
# one case


def test_table_has_one_row_per_standard_model_in_library_order(results):
    """One case prints one row per model of standard_models(), in its order (default
    best estimate first), and nothing on stderr."""
    r = _ok(results, "one")
    labels = [m.label for m in _library()]
    lines = r.stdout.splitlines()
    head = next(i for i, line in enumerate(lines) if line.startswith("model"))
    rows = lines[head + 1 : lines.index("", head)]  # the notes follow a blank line
    assert len(rows) == len(labels)
    for row, label in zip(rows, labels):
        assert row.startswith(label + " "), (row, label)
    assert r.stderr == ""


def test_table_columns_are_in_engineering_units_by_default_and_si_on_request(results):
    """Default output is kN, um, N/um, GPa; --si gives N, m, N/m, Pa."""
    eng = _ok(results, "one").stdout
    si = _ok(results, "depth_sweep_si").stdout
    for unit in ("[kN]", "[um]", "[N/um]", "GPa"):
        assert unit in eng
    for unit in ("[N]", "[m]", "[N/m]", "Pa"):
        assert unit in si


def test_json_results_equal_the_library_called_with_si_inputs(results):
    """The command converts units and hands SI to the library: its depth, stiffness and
    MDR radius at F = 1 kN equal those of the models built in-process (R = 5 mm,
    L = 10 mm, E* = 210 GPa / (1 - 0.3^2) by Eq. 3 with a rigid cylinder)."""
    from linecontact.errors import OutOfRangeError

    doc = _json(results, "one_json")
    assert math.isclose(doc["inputs"]["estar"], 210e9 / (1 - 0.09), rel_tol=1e-12)
    assert [m["label"] for m in doc["models"]] == [m.label for m in _library()]
    compared = 0
    for model, entry in zip(_library(), doc["models"]):
        row = entry["rows"][0]
        assert row["force"] == 1000.0
        try:
            depth = float(model.depth(1000.0))
        except OutOfRangeError:
            assert row["note"] and row["depth"] is None, model.key
            continue
        assert _close(row["depth"], depth), model.key
        assert _close(row["stiffness"], float(model.stiffness_at_force(1000.0))), model.key
        compared += 1
    # L/R = 2, rigid cylinder on steel: all rows answer but Eq. 11 (L/R >= 5) and the
    # steel-on-steel-only Palmgren and ISO 16281
    assert compared == len(doc["models"]) - 3, f"{compared} rows compared"


def test_json_carries_version_units_and_provenance(results):
    """--json states the package version, SI units, and every model's provenance as
    the library gives it (a table's file path aside: the installed copy and this
    checkout hold the same table in different places)."""
    import linecontact

    def without_path(prov):
        return {k: v for k, v in json.loads(json.dumps(prov)).items() if k != "path"}

    doc = _json(results, "one_json")
    assert doc["linecontact_version"] == linecontact.__version__
    assert doc["units"]["depth"] == "m" and doc["units"]["stiffness"] == "N/m"
    for model, entry in zip(_library(), doc["models"]):
        assert entry["provenance"], entry["label"]
        assert without_path(entry["provenance"]) == without_path(model.provenance), entry["label"]


def test_model_outside_its_range_gets_a_note_and_the_other_rows_stay(results):
    """A steel-only model (Palmgren) refuses E* = 230.8 GPa (steel half-space, rigid
    cylinder): its row carries the library's message and no values, while the physical
    models in the same table are computed."""
    rows = {m["label"]: m["rows"][0] for m in _json(results, "one_json")["models"]}
    assert rows["Palmgren"]["depth"] is None
    assert "outside the valid range" in rows["Palmgren"]["note"]
    assert rows["Puttock-Thwaite"]["note"] == "" and rows["Puttock-Thwaite"]["depth"] > 0


def test_model_option_selects_models_with_their_options(results):
    """--model KEY:OPTION=VALUE builds exactly those models with those options, in that
    order; a model refused for this cylinder (Eq. 11 needs L/R >= 5, here L/R = 2)
    keeps its row with the reason."""
    from linecontact import models

    doc = _json(results, "model_options_json")
    expected = [
        models.get_model("johnson", 0.005, 0.01, 1e11, c=0.72).label,
        models.get_model("li-popov", 0.005, 0.01, 1e11, coefficients="eq11").label,
    ]
    assert [m["label"] for m in doc["models"]] == expected
    assert doc["models"][0]["rows"][0]["depth"] > 0
    assert "L/R" in doc["models"][1]["rows"][0]["note"]


def test_bare_numbers_are_si_and_unit_strings_convert(results):
    """'5mm' equals the bare SI number 0.005, and inch/lbf inputs convert to the same
    case (0.19685039 in = 5 mm, 224.80894 lbf = 1 kN, to 8 digits)."""
    with_units = _json(results, "one_json")["models"]
    bare = _json(results, "bare_json_importtime")["models"]
    inch = _json(results, "inch_json")["models"]
    for a, b, c in zip(with_units, bare, inch):
        for ra, rb, rc in zip(a["rows"], b["rows"], c["rows"]):
            assert _close(ra["depth"], rb["depth"], 1e-12), a["label"]
            assert _close(ra["depth"], rc["depth"], 1e-6), a["label"]


def test_second_body_follows_eq3(results):
    """Two equal steel bodies halve E* of a steel half-space under a rigid cylinder
    (Eq. 3)."""
    two = _json(results, "two_bodies_json")["inputs"]["estar"]
    one = _json(results, "one_json")["inputs"]["estar"]
    assert math.isclose(two, one / 2, rel_tol=1e-12)


def test_depth_input_gives_force_and_depth_column_first(results):
    """With --depth each model returns the force at that depth (its force(d)), and the
    table's first value column is d."""
    from linecontact.errors import OutOfRangeError

    doc = _json(results, "depth_json")
    compared = 0
    for model, entry in zip(_library(), doc["models"]):
        row = entry["rows"][0]
        assert row["depth"] == 2e-6
        try:
            force = float(model.force(2e-6))
        except OutOfRangeError:
            assert row["note"], model.label
            continue
        assert _close(row["force"], force), model.label
        compared += 1
    # as above: Eq. 11, Palmgren and ISO 16281 refuse this case
    assert compared == len(doc["models"]) - 3, f"{compared} rows compared"
    header = next(
        line
        for line in _ok(results, "depth_sweep_si").stdout.splitlines()
        if line.startswith("model")
    )
    assert header.split()[1] == "d"


def _imported(stderr):
    """Top-level package names in a `python -X importtime` log."""
    return {
        line.split("|")[-1].strip().split(".")[0]
        for line in stderr.splitlines()
        if line.startswith("import time:")
    }


def test_python_dash_m_is_the_same_command(results):
    """`python -m linecontact` prints exactly what the console script prints."""
    assert _ok(results, "units_importtime").stdout == _ok(results, "one").stdout


def test_one_case_imports_pint_only_for_unusual_units_and_never_pandas(results):
    """Start-up: a one-case call in bare SI numbers or in the built-in units (mm, GPa,
    kN) loads neither pint nor pandas; a unit outside the built-in table (dyn) loads
    pint, still no pandas, and converts to the same case (1e8 dyn = 1 kN)."""
    bare = _imported(_ok(results, "bare_json_importtime").stderr)
    units = _imported(_ok(results, "units_importtime").stderr)
    dyne = _imported(_ok(results, "dyne_json_importtime").stderr)
    assert "linecontact" in bare and "numpy" in bare  # the log is really there
    assert "pint" not in bare and "pandas" not in bare
    assert "pint" not in units and "pandas" not in units
    assert "pint" in dyne and "pandas" not in dyne
    # nor (in the built-in units; pint's own import of a unit outside them loads it)
    # scipy: a one-case call, profiled or not, solves with the C engine where its
    # extension is built (it loads in 1-3 ms; test_slice_kernels_c_equal_numpy.py checks
    # that a default solve takes it), else with numpy
    profiled = _imported(_ok(results, "profiled_importtime").stderr)
    assert "linecontact" in profiled
    for names in (bare, units, profiled):
        assert "scipy" not in names
    a = json.loads(_ok(results, "dyne_json_importtime").stdout)["models"]
    b = _json(results, "one_json")["models"]
    for ma, mb in zip(a, b):
        assert _close(ma["rows"][0]["depth"], mb["rows"][0]["depth"], 1e-12), ma["label"]


# ---------------------------------------------------------------------------------------
# sweeps


def test_sweep_is_geometric_by_default(results):
    """--load 0.1kN:10kN:5 gives 5 loads per model with equal ratios (10^0.5), both
    ends included."""
    doc = _json(results, "sweep_geom_json")
    expected = [100 * 10 ** (i / 2) for i in range(5)]
    for entry in doc["models"]:
        forces = [row["force"] for row in entry["rows"]]
        assert all(math.isclose(f, e, rel_tol=1e-12) for f, e in zip(forces, expected))
        assert len(forces) == 5


def test_sweep_is_linear_with_flag(results):
    """--linear spaces the sweep evenly: 100, 200, ..., 500 N."""
    doc = _json(results, "sweep_lin_json")
    for entry in doc["models"]:
        assert [row["force"] for row in entry["rows"]] == pytest.approx([100, 200, 300, 400, 500])


def test_sweep_table_has_a_row_per_value_per_model(results):
    """A 3-point sweep prints 3 rows for every model."""
    out = _ok(results, "depth_sweep_si").stdout.splitlines()
    for model in _library():
        assert sum(1 for line in out if line.startswith(model.label + " ")) == 3, model.label


def test_stiffness_grows_with_load_in_a_sweep(results):
    """Line contact stiffens with load: k increases along a load sweep for every model
    that covers it."""
    for entry in _json(results, "sweep_geom_json")["models"]:
        ks = [row["stiffness"] for row in entry["rows"] if row["stiffness"] is not None]
        assert all(b >= a for a, b in zip(ks, ks[1:])), entry["key"]


# ---------------------------------------------------------------------------------------
# batch


def _csv(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_batch_keeps_rows_and_appends_results_of_the_default_model(results):
    """A batch writes every input row, its cells unchanged, with result columns
    appended, computed by the default best estimate (the first standard model), and
    E* from Eq. 3 or as given."""
    rows = _csv(_ok(results, "batch").stdout)
    with open(EXAMPLES / "cases.csv", newline="") as fh:
        inputs = list(csv.DictReader(fh))
    assert len(rows) == len(inputs)
    for out, inp in zip(rows, inputs):
        assert {k: out[k] for k in inp} == inp
        first = _library(*_si_case(inp))[0]
        assert out["model"] == first.label
        assert out["error"] == ""
        assert math.isclose(float(out["estar_GPa"]) * 1e9, _si_case(inp)[2], rel_tol=1e-5)
        for col in (
            "force_kN",
            "depth_um",
            "stiffness_N_per_um",
            "half_width_um",
            "contact_radius_um",
        ):
            assert col in out


def test_batch_output_file(results):
    """-o FILE writes the CSV to FILE and nothing to stdout."""
    r = _ok(results, "batch_to_file")
    assert r.stdout == ""
    written = _csv(Path(r.args[-1]).read_text())  # the path after -o
    assert written == _csv(_ok(results, "batch").stdout)


def test_batch_all_models_json_has_a_column_set_per_model_and_si(results):
    """--model all in a batch gives columns suffixed with each model's id (its label as
    a slug); --json is SI and lists the models with their provenance."""
    doc = _json(results, "batch_all_json")
    keys = [m["id"] for m in doc["models"]]
    assert doc["units"]["depth"] == "m"
    assert all("provenance" in m for m in doc["models"])
    for row in doc["rows"]:
        if row["error"]:
            continue
        for key in keys:
            assert f"depth_m_{key}" in row and f"note_{key}" in row


def test_batch_bad_rows_fail_alone_and_say_why(results):
    """Bad rows get an `error` naming the column, the others are still computed, and
    the command exits with status 2 and one line on stderr."""
    r = results["batch_bad"]
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1 and "Traceback" not in r.stderr
    rows = {row["name"]: row for row in _csv(r.stdout)}
    assert rows["good"]["error"] == "" and float(rows["good"]["depth_um"]) > 0
    assert rows["good after bad"]["error"] == ""
    assert (
        "radius" in rows["length given in N"]["error"]
        or "length" in rows["length given in N"]["error"]
    )
    assert (
        "length" in rows["length given in N"]["error"]
        and "5N" in rows["length given in N"]["error"]
    )
    assert (
        "radius" in rows["negative radius"]["error"] and "-1mm" in rows["negative radius"]["error"]
    )
    assert "load" in rows["no load"]["error"]
    assert "load" in rows["sweep in a row"]["error"]
    assert "foo" in rows["bad unit"]["error"]


def test_batch_options_fill_missing_columns(results):
    """Options on the command line fill columns the CSV lacks (here R, L, E, nu)."""
    rows = _csv(_ok(results, "batch_defaults").stdout)
    assert len(rows) == 3 and all(row["error"] == "" for row in rows)


# ---------------------------------------------------------------------------------------
# bad input


#: errors whose message is about a value: it says what would have been valid
_NO_RANGE = {"err_unknown_option", "err_no_file", "err_no_columns"}


def test_bad_input_is_one_line_naming_parameter_value_and_range(results):
    """The command's boundary as run from a shell, one table (ERRORS: the command, the
    parameter and the value the message names): exit status 2, no traceback, nothing on
    stdout, and exactly one line on stderr that names the parameter and the value as
    typed; every message about a value says what would have been valid ('valid:')."""
    failed = []
    for name, (parameter, value) in sorted(ERRORS.items()):
        r = results[name]
        lines = r.stderr.strip().splitlines()
        ok = (r.returncode == 2 and "Traceback" not in r.stderr and len(lines) == 1
              and parameter in lines[0] and value in lines[0] and r.stdout == ""
              and (name in _NO_RANGE or "valid:" in r.stderr))
        if not ok:
            failed.append((name, r.returncode, r.stdout, r.stderr))
    assert not failed, failed


# ---------------------------------------------------------------------------------------
# in-process: the same main() as the command, called directly (no start-up per test)


from doors import DOORS, IDS  # noqa: E402 - the commands whose batches keep the rules


def _main(capsys, *argv):
    """(status, stdout, stderr) of linecontact.calc.cli.main(argv)."""
    from linecontact.calc.cli import main

    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _main_json(capsys, *argv):
    status, out, err = _main(capsys, *argv, "--json")
    assert status == 0, err
    return json.loads(out)


def _write_csv(path, header, rows):
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(rows)
    return str(path)


STEEL_CASE = ("calc", "--length", "10mm", "--modulus", "210GPa", "--poisson", "0.3")


@pytest.mark.parametrize("argv, parameter", [
    (("--radius", "1,5mm", "--load", "1kN"), "--radius"),
    (("--radius", "5mm", "--load", "1kN+1kN"), "--load"),
    (("--radius", "5mm", "--load", "1e999N"), "--load"),
    (("--radius", "5mm", "--load", "1e-320N"), "--load"),
    (("--radius", "5mm", "--load", "nan"), "--load"),
    (("--radius", "5mm", "--diameter", "10mm", "--load", "1kN"), "--diameter"),
    (("--radius", "5mm", "--radius2", "-4mm", "--load", "1kN"), "--radius2"),
    (("--radius", "5mm", "--inner-raceway", "20mm", "--load", "1kN"), "--outer-raceway"),
    (("--radius", "5mm", "--inner-raceway", "20mm", "--outer-raceway", "40mm",
      "--load", "1kN"), "--outer-raceway"),
    (("--radius", "5mm", "--inner-raceway-diameter", "40mm", "--outer-raceway-diameter",
      "80mm", "--load", "1kN"), "--outer-raceway-diameter"),
    (("--radius", "5mm", "--load", "1kN", "--model", "li-popov:extrapolate=maybe"),
     "extrapolate"),
    (("--radius", "5mm", "--load", "1kN", "--model", "johnson:nosuch=1"), "--model"),
    # a decimal comma splits the model list: named as such, not "unknown model '5'"
    (("--radius", "5mm", "--load", "1kN", "--model", "johnson:c=1,5"), "decimal comma"),
    # finite inputs whose model scales are not: L^3 = 1e900 overflows, L^3 = 1e-330
    # underflows (was "universal: unexpected OverflowError")
    (("--radius", "5mm", "--length", "1e300", "--load", "1kN"), "--length"),
    (("--radius", "5mm", "--length", "1e-110", "--load", "1kN"), "--length"),
])
def test_bad_values_exit_2_with_one_line(capsys, argv, parameter):
    """Every refused input (decimal comma, expression, overflow, subnormal, NaN,
    conflicting or missing geometry, a yes/no option that is neither, a length whose
    scales overflow) is one line on
    stderr naming the parameter and the valid range, status 2, nothing on stdout."""
    base = STEEL_CASE if "--length" not in argv else STEEL_CASE[:1] + STEEL_CASE[3:]
    status, out, err = _main(capsys, *base, *argv)  # an option given once (twice: refused)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and parameter in err and "valid" in err, err


def test_no_means_false_for_a_yes_no_model_option(capsys):
    """extrapolate=no is False (Eq. 11 refuses L/R = 2, status 2); extrapolate=yes
    computes; 'no' used to mean True."""
    base = (*STEEL_CASE, "--radius", "5mm", "--load", "1kN", "--model")
    assert _main(capsys, *base, "li-popov:coefficients=eq11:extrapolate=no")[0] == 2
    doc = _main_json(capsys, *base, "li-popov:coefficients=eq11:extrapolate=yes")
    assert doc["models"][0]["rows"][0]["depth"] > 0


def test_unwritable_output_names_the_file(capsys, tmp_path):
    """-o into a missing directory: one line naming the file and why (was 'None: None')."""
    target = tmp_path / "missing" / "out.csv"
    status, out, err = _main(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN",
                             "-o", str(target))
    assert status == 2 and str(target) in err and "No such file" in err
    assert "None" not in err


def test_diameter_is_twice_the_radius(capsys):
    """--diameter 10mm gives exactly the results of --radius 5mm."""
    a = _main_json(capsys, *STEEL_CASE, "--diameter", "10mm", "--load", "1kN")
    b = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN")
    assert [m["rows"] for m in a["models"]] == [m["rows"] for m in b["models"]]


def test_second_radius_gives_the_effective_radius(capsys):
    """--radius2 R2: every model sees 1/R = 1/R1 + 1/R2 (two equal 5 mm cylinders act as
    one of 2.5 mm on a flat; a 40 mm concave bore around a 6 mm roller as 7.0588 mm)."""
    a = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--radius2", "5mm", "--load", "1kN")
    b = _main_json(capsys, *STEEL_CASE, "--radius", "2.5mm", "--load", "1kN")
    assert math.isclose(a["inputs"]["radius_eff"], 2.5e-3, rel_tol=1e-15)
    for ma, mb in zip(a["models"], b["models"]):
        for ra, rb in zip(ma["rows"], mb["rows"]):
            assert ra["depth"] == rb["depth"] or _close(ra["depth"], rb["depth"], 1e-14)
    c = _main_json(capsys, *STEEL_CASE, "--radius", "6mm", "--radius2", "-40mm", "--load",
                   "1kN")
    assert math.isclose(c["inputs"]["radius_eff"], 1 / (1 / 6e-3 - 1 / 40e-3), rel_tol=1e-14)


def test_hertz_peak_pressure_is_eq1_force_over_strip(capsys):
    """p0 = 2 F / (pi b L) with b of Eq. 1 (Johnson 1985, Eq. 4.45), for every row, and
    the output says that a straight roller's end pressure is higher."""
    status, text, _ = _main(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN")
    assert "singular" in text and "p0" in text
    doc = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "0.1kN:10kN:4")
    for m in doc["models"]:
        for row in m["rows"]:
            if row["depth"] is None:  # refused by that model: nothing covers the row
                assert row["half_width"] is None and row["peak_pressure"] is None
                continue
            p0 = 2 * row["force"] / (math.pi * row["half_width"] * 0.01)
            assert _close(row["peak_pressure"], p0, 1e-12)


def test_deviation_is_relative_to_the_best_estimate(capsys):
    """The deviation column of a model is its depth over the default best estimate's
    (the first standard model) minus 1, also when only other models are asked for."""
    doc = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN",
                     "--model", "johnson,puttock-thwaite")
    best = _library()[0].depth(1000.0)
    for m in doc["models"]:
        row = m["rows"][0]
        assert _close(row["deviation"], row["depth"] / best - 1, 1e-12)
    full = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN")
    assert full["models"][0]["rows"][0]["deviation"] == 0.0


def test_whole_roller_is_two_contacts_in_series(capsys):
    """--inner-raceway/--outer-raceway: the roller's deflection is the sum of the two
    contact depths at the same force (1/R = 1/R1 + 1/Ri and 1/R1 - 1/Ro), its stiffness
    the series value; the per-contact depth column is not filled."""
    from linecontact.models import get_model

    doc = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--inner-raceway", "20mm",
                     "--outer-raceway", "30mm", "--load", "2kN", "--model", "li-popov")
    row = doc["models"][0]["rows"][0]
    E = 210e9 / (1 - 0.09)
    inner = get_model("li-popov", 1 / (1 / 5e-3 + 1 / 20e-3), 0.01, E)
    outer = get_model("li-popov", 1 / (1 / 5e-3 - 1 / 30e-3), 0.01, E)
    d = inner.depth(2000.0) + outer.depth(2000.0)
    k = 1 / (1 / inner.stiffness_at_force(2000.0) + 1 / outer.stiffness_at_force(2000.0))
    assert _close(row["roller_deflection"], d, 1e-12)
    assert _close(row["roller_stiffness"], k, 1e-12)
    assert row.get("depth") is None and "depth_inner" in row


def test_poisson_half_is_allowed(capsys):
    """nu = 0.5 (incompressible) is accepted: E* = E / (1 - 0.25) by Eq. 3."""
    doc = _main_json(capsys, "calc", "--radius", "5mm", "--length", "10mm", "--modulus",
                     "3MPa", "--poisson", "0.5", "--load", "1N")
    assert math.isclose(doc["inputs"]["estar"], 3e6 / 0.75, rel_tol=1e-15)


def test_geometry_flags_on_every_row_of_every_model(capsys):
    """d > 0.15 R and b > L/2 are flagged on every model's row (not only the universal
    curve's): a depth of 0.2 R, and a roller of R = 5 mm, L = 0.1 mm under 1 kN (Eq. 1:
    b = 0.53 mm > 0.5 L)."""
    doc = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--depth", "1mm")
    assert all("d > 0.15 R" in m["rows"][0]["flags"] for m in doc["models"])
    doc = _main_json(capsys, "calc", "--radius", "5mm", "--length", "0.1mm",
                     "--modulus", "210GPa", "--poisson", "0.3", "--load", "1kN")
    for m in doc["models"]:
        row = m["rows"][0]
        if row["depth"] is None:  # refused by that model: nothing covers the row
            assert row["half_width"] is None and row["peak_pressure"] is None
            continue
        assert row["half_width"] > 0.5 * 0.1e-3 and "b > 0.5 L" in row["flags"]


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_batch_keeps_user_columns_named_like_results(capsys, tmp_path, door):
    """A user's model, note, error and result-named columns are written as they were
    (never a second 'error' or 'note' column); the result columns then carry the
    prefix result_ (all of them, one consistent set)."""
    load = door.header.split(",")[-1]
    model = "model" if door.name == "calc" else "model_used"  # the model's result column
    path = _write_csv(tmp_path / "u.csv",
                      ["name", model, "note", "error", door.result, load],
                      [["a", "mine", "keep me", "E", "1.0", "1kN"],
                       ["b", "", "x,y", "", "", "2kN"]])
    options = [o for o in door.row.split(",")[:-1]]
    argv = [x for c, v in zip(door.header.split(",")[:-1], options)
            for x in ("--" + c.replace("_", "-"), v)]
    status, out, err = _main(capsys, door.name, path, *argv)
    assert status == 0, err
    head = out.splitlines()[0].split(",")
    assert head.count("error") == 1 and head.count("note") == 1
    rows = _csv(out)
    assert [r[model] for r in rows] == ["mine", ""]
    assert [r["note"] for r in rows] == ["keep me", "x,y"]
    assert [r["error"] for r in rows] == ["E", ""] and rows[0][door.result] == "1.0"
    assert all(r["result_error"] == "" and float(r["result_" + door.result]) > 0
               for r in rows)


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_header_only_csv_is_a_clear_message(capsys, tmp_path, door):
    """A CSV with a header and no rows: one line saying so, status 2."""
    path = _write_csv(tmp_path / "h.csv", door.header.split(","), [])
    status, out, err = _main(capsys, door.name, path)
    assert status == 2 and "only a header row" in err and "Traceback" not in err


def test_unexpected_exception_in_one_row_is_reported_in_that_row(capsys, tmp_path,
                                                                 monkeypatch):
    """A model raising an unexpected exception for one element: that row's error says
    so, the other rows of the same cylinder (evaluated in the same vectorised call) are
    computed and written."""
    import numpy as np

    from linecontact import models

    original = models.ContactModel.evaluate

    def flaky(self, *, force=None, depth=None):
        if force is not None and np.any(np.asarray(force) == 777.0):
            raise RuntimeError("boom")
        return original(self, force=force, depth=depth)

    monkeypatch.setattr(models.ContactModel, "evaluate", flaky)
    many = models.UniversalModel.evaluate_many.__func__

    def flaky_many(cls, radius, length, estar, *, force=None, depth=None):
        if force is not None and np.any(np.asarray(force) == 777.0):
            raise RuntimeError("boom")
        return many(cls, radius, length, estar, force=force, depth=depth)

    # the batch's call over all rows at once raises too: the per-contact path then
    # isolates the exception to its row
    monkeypatch.setattr(models.UniversalModel, "evaluate_many", classmethod(flaky_many))
    loads = ["100N", "200N", "777N", "300N", "400N"]
    path = _write_csv(tmp_path / "b.csv", ["load"], [[x] for x in loads])
    status, out, err = _main(capsys, "calc", path, "--radius", "5mm", *STEEL_CASE[1:])
    rows = _csv(out)
    assert status == 2 and [r["load"] for r in rows] == loads
    assert "RuntimeError: boom" in rows[2]["error"]
    assert all(r["error"] == "" and float(r["depth_um"]) > 0 for i, r in enumerate(rows)
               if i != 2)


def test_batch_builds_one_model_per_distinct_cylinder(capsys, tmp_path, monkeypatch):
    """Speed by construction: 300 rows on 3 distinct cylinders build each model of
    --model all 3 times (plus a probe at R = 1 m that names the columns), not 300
    times; a default batch (the default model alone) builds one model object, for the
    column set's name and provenance: its rows are evaluated as arrays over their
    geometry (ContactModel.evaluate_many)."""
    from linecontact import models

    calls = []
    original = models.ContactModel.__init__

    def counting(self, radius, length, estar, **kw):
        calls.append(radius)
        original(self, radius, length, estar, **kw)

    monkeypatch.setattr(models.ContactModel, "__init__", counting)
    rows = [[r, f"{100 + i}N"] for i in range(100) for r in ("4mm", "5mm", "6mm")]
    path = _write_csv(tmp_path / "c.csv", ["radius", "load"], rows)
    for extra, per_set in (((), None), (("--model", "all"), len(_library()))):
        calls.clear()
        status, out, err = _main(capsys, "calc", path, *STEEL_CASE[1:], *extra)
        assert status == 0, err
        assert len(_csv(out)) == 300
        built = [r for r in calls if r != 1.0]  # R = 1 m: the probe naming the columns
        if per_set is None:
            assert len(built) == 1, built
            continue
        assert sorted(set(built)) == [0.004, 0.005, 0.006]
        assert len(built) == 3 * per_set, len(built)


def test_batch_rows_equal_one_case_calls(capsys, tmp_path):
    """Vectorised batch rows equal the one-case command for the same inputs (mixed
    loads and depths, repeated and distinct cylinders, one refused row in between)."""
    rows = [["5mm", "1kN", ""], ["5mm", "", "2um"], ["5mm", "1,5kN", ""],
            ["6mm", "2kN", ""], ["5mm", "3kN", ""]]
    path = _write_csv(tmp_path / "m.csv", ["radius", "load", "depth"], rows)
    status, out, _ = _main(capsys, "calc", path, *STEEL_CASE[1:], "--si")
    got = _csv(out)
    assert status == 2 and "decimal comma" in got[2]["error"]
    for (r, load, depth), g in zip(rows, got):
        if g["error"]:
            continue
        given = ("--load", load) if load else ("--depth", depth)
        one = _main_json(capsys, *STEEL_CASE, "--radius", r, *given, "--model", "universal")
        ref = one["models"][0]["rows"][0]
        assert _close(float(g["depth_m"]), ref["depth"], 1e-5)  # CSV keeps 6 digits
        assert _close(float(g["force_N"]), ref["force"], 1e-5)


def test_missing_table_is_named_not_none(capsys, monkeypatch):
    """A table file that cannot be found while building a model: one line that names
    it (it used to read 'None: None')."""
    from linecontact import models

    def missing(*a, **k):
        raise FileNotFoundError("table 'universal_curve' not found in /nowhere/tables")

    monkeypatch.setattr(models, "get_model", missing)
    status, out, err = _main(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN",
                             "--model", "universal")
    assert status == 2 and "universal_curve" in err and "None" not in err
    assert len(err.strip().splitlines()) == 1


def test_progress_bar_goes_to_stderr_only(capsys, tmp_path):
    """--progress shows a bar on stderr (tqdm, or a plain line without it) and changes
    nothing on stdout."""
    path = _write_csv(tmp_path / "p.csv", ["load"], [[f"{100 + i}N"] for i in range(50)])
    argv = ("calc", path, "--radius", "5mm", *STEEL_CASE[1:])
    status, with_bar, err = _main(capsys, *argv, "--progress")
    assert status == 0 and "50" in err
    status, plain, err = _main(capsys, *argv, "--no-progress")
    assert status == 0 and err == "" and plain == with_bar


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_ragged_rows_keep_every_cell_and_results_stay_aligned(capsys, tmp_path, door):
    """A row with more cells than the header keeps them (under a column named by its
    place, extra_3: no column without a name) and is
    an error in that row (its cells are shifted: issue 22), a shorter row is padded;
    the result columns line up under their names in both the unquoted (line-copy) and
    the quoted (csv module) paths; CRLF line ends are read."""
    for quote in ("", '"'):
        path = tmp_path / f"r{len(quote)}.csv"
        path.write_text(f"name,{door.load}\r\n{quote}a{quote},1kN,extra\r\nb\r\n"
                        "c,2kN\r\n", encoding="utf-8")
        status, out, err = _main(capsys, door.name, str(path), *door.options)
        rows = list(csv.reader(io.StringIO(out)))
        head = rows[0]
        assert head[:3] == ["name", door.load, "extra_3"] and status == 2  # b: no load
        assert "" not in head
        assert [r[:3] for r in rows[1:]] == [["a", "1kN", "extra"], ["b", "", ""],
                                             ["c", "2kN", ""]]
        result = head.index(door.result)
        error = head.index("error")
        assert rows[1][result] == "" and "3 cells under a header of 2" in rows[1][error]
        assert rows[2][result] == "" and float(rows[3][result]) > 0
        assert all(len(r) == len(head) for r in rows)


# ---------------------------------------------------------------------------------------
# every option of `calc --help` in a batch: as an option filling the cells, and as a column

#: A valid value of every parameter (as typed on the command line); the prony file is
#: written by the tests below (E_inf = 1 GPa, one term of 2 GPa at 0.1 s).
SAMPLE = {
    "radius": "5mm", "diameter": "10mm", "length": "10mm", "radius2": "30mm",
    "modulus": "210GPa", "poisson": "0.3", "modulus2": "210GPa", "poisson2": "0.3",
    "estar": "115GPa", "load": "1kN", "depth": "2um", "inner_raceway": "20mm",
    "outer_raceway": "40mm", "friction": "0.3", "tangential_load": "100N",
    "instantaneous_modulus": "3GPa", "long_term_modulus": "1GPa",
    "relaxation_time": "10s", "prony": "PRONY", "time": "10s",
    "crown_radius": "500mm", "profile": "iso16281", "tilt": "1mrad",
    "inner_raceway_diameter": "40mm", "outer_raceway_diameter": "50mm",
    "misalignment": "0.1mrad", "work_of_adhesion": "50mJ/m^2",
    "stresses": "yes", "sliding_friction": "0.1", "stress_field": "0mm",
    "surface_hardness": "700", "case_depth": "0.5mm", "core_hardness": "350",
    "hardness_profile": "HARDNESS",
}


def _sample(name, tmp_path, sample=None):
    if name == "hardness_profile":
        path = tmp_path / "hardness.csv"
        path.write_text("depth_m,HV\n0,700\n0.001,550\n0.005,350\n", encoding="utf-8")
        return str(path)
    if name == "spectrum":
        path = tmp_path / "spectrum.csv"
        path.write_text("time_share,radial_load,speed\n0.8,10kN,1500rpm\n"
                        "0.2,20kN,750rpm\n", encoding="utf-8")
        return str(path)
    if name != "prony":
        return (SAMPLE if sample is None else sample)[name]
    path = tmp_path / "prony.csv"
    path.write_text("# E_inf: 1GPa\ntau_s,E_Pa\n0.1,2e9\n", encoding="utf-8")
    return str(path)


#: A valid value of every input of `linecontact bearing`.
BEARING_SAMPLE = {
    "rollers": "14", "pitch_diameter": "70mm", "roller_diameter": "11mm",
    "length": "11mm", "clearance": "5um", "radial_load": "10kN",
    "tilting_moment": "5Nm", "misalignment": "0.2mrad", "modulus": "210GPa",
    "poisson": "0.3", "modulus2": "210GPa", "poisson2": "0.3", "estar": "115GPa",
    "profile": "iso16281", "model": "iso16281", "n_slices": "30", "rating": "60kN",
    "surface_hardness": "700", "case_depth": "0.5mm", "core_hardness": "350",
    "hardness_profile": "HARDNESS", "static_rating": "60kN", "speed": "1500rpm",
    "viscosity": "20.7cSt", "density": "860kg/m^3", "pressure_viscosity": "2e-8",
    "roughness_roller": "0.1um", "roughness_raceway": "0.15um",
    "film_formula": "dowson-higginson", "contamination": "0.5", "reliability": "0.99",
    "fatigue_load_limit": "8kN", "shaft_interference": "20um", "bore": "50mm",
    "shaft_bore": "20mm", "housing_interference": "10um", "outside_diameter": "100mm",
    "housing_diameter": "150mm", "ring_modulus": "210GPa",
    "temperature_difference": "10K", "axial_load": "1kN", "end_radius": "60mm",
    "flange_angle": "3deg", "inner_flange_height": "3.2mm",
    "outer_flange_height": "3.2mm", "overall_length": "11.5mm", "end_chamfer": "0.5mm",
    "axial_share": "equal", "spectrum": "SPECTRUM",
}

#: Per command: every input's sample value, and the case a batch completes.
SAMPLES = {"calc": (SAMPLE, {"name": ["a", "b"], "radius": ["5mm", "6mm"],
                             "length": ["10mm", "12mm"], "modulus": ["210GPa"] * 2,
                             "poisson": ["0.3"] * 2, "load": ["1kN", "2kN"]}),
           "bearing": (BEARING_SAMPLE, {"name": ["a", "b"], "rollers": ["14", "12"],
                                        "pitch_diameter": ["70mm", "60mm"],
                                        "roller_diameter": ["11mm", "10mm"],
                                        "length": ["11mm", "10mm"],
                                        "radial_load": ["10kN", "5kN"]})}
_EVERY = [(c, n) for c, (sample, _) in SAMPLES.items() for n in sorted(sample)]


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_sample_covers_every_option(door):
    """The tests below try every option of each command's --help: a new option without
    a sample value fails here, not silently untested."""
    assert set(SAMPLES[door.name][0]) == set(door.parameters)


#: Inputs whose result goes to the --json output only (Parameter.json_only).
_JSON_ONLY = {"stress_field"}


def _every_option_with_a_batch(capsys, tmp_path, command, name):
    """None, or why (command, name) broke the rule of the test below."""
    from linecontact.calc.feature import option_name

    sample, base = SAMPLES[command]
    src = _write_csv(tmp_path / "c.csv", list(base), list(zip(*base.values())))
    status, out, err = _main(capsys, command, src, option_name(name),
                             _sample(name, tmp_path, sample))
    if name in _JSON_ONLY:  # written to --json only: without it refused up front
        if not (status == 2 and out == "" and "with --json" in err):
            return "a --json-only input not refused without --json", err
        return None
    rows = list(csv.DictReader(io.StringIO(out)))
    if status not in (0, 2) or [r["name"] for r in rows] != ["a", "b"]:
        return status, err
    if status == 2 and not (any(r["error"] for r in rows) and "error" in err):
        return "a refused row that does not say so", err
    if command == "calc" and name in ("profile", "crown_radius", "tilt"):
        if not (status == 0 and all(r["model"].startswith("Profiled roller")
                                    and float(r["moment_N_m"]) >= 0 for r in rows)):
            return "no profiled-roller columns", err
    return None


def test_every_option_with_a_batch_runs_or_says_why_per_row(capsys, tmp_path):
    """One table, every option of every command (_EVERY): an option of any kind
    (length, time, text, path, angle, ...) given with a CSV batch fills the empty cells
    of its column: every row is written and either computed or refused in its own
    'error' cell, status 0 or 2, never an exception. The profile options (text, path
    kinds) used to crash with KeyError in _units; a profile option gives every row its
    profiled-roller columns (a batch takes every option)."""
    failed = [(c, n, why) for c, n in _EVERY
              if (why := _every_option_with_a_batch(capsys, tmp_path, c, n))]
    assert not failed, failed


def test_every_option_as_a_csv_column_runs_or_says_why_per_row(capsys, tmp_path):
    """The same table, each value as a CSV column (one row with it, one with the cell
    empty): status 0 or 2, both rows written, the empty cell's row computed."""
    failed = []
    for command, name in _EVERY:
        sample, base = SAMPLES[command]
        case = {k: v[0] for k, v in base.items() if k != "name"}
        if name in case:
            continue  # a column of the case itself: every test above has it
        src = _write_csv(tmp_path / "c.csv", list(case) + [name],
                         [list(case.values()) + [_sample(name, tmp_path, sample)],
                          list(case.values()) + [""]])
        status, out, err = _main(capsys, command, src, "--json")
        if name == "stress_field":  # a block of one case's JSON: a batch has none for it
            if not (status == 2 and "column 'stress_field'" in err and not out):
                failed.append((command, name, status, err))
            continue
        rows = json.loads(out)["rows"] if out else []
        if not (status in (0, 2) and len(rows) == 2 and rows[1]["error"] == ""):
            failed.append((command, name, status, err))
    assert not failed, failed


# ---------------------------------------------------------------------------------------
# fuzz: odd input for every option never ends in a traceback (status 0 or 2 only)

#: Odd values a user (or a spreadsheet) may produce; DIR and MISSING are replaced by a
#: directory and a missing file, NONUTF8 by a file that is not UTF-8 text.
ODD = ["", " ", "-", "0", "-0", "-1", "1e400", "1e-400", "1e-300", "1e300", "nan",
       "\u0663", "\uff15mm", "1,5", "1:2:3", "0:1:3", ":", "1e", ".", "5 furlong", "5 s",
       "5 deg", "a=b", "file:DIR", "file:MISSING", "file:NONUTF8", "DIR", "MISSING",
       "NONUTF8", "x\x00y", "iso16281:D=-1", "lundberg:F0=0", "circular:Rc=0"]


def _odd(value, tmp_path):
    bad = tmp_path / "nonutf8.csv"
    bad.write_bytes(b"\xff\xfe\x00x,\xe9\n")
    return (value.replace("NONUTF8", str(bad)).replace("MISSING", str(tmp_path / "no.csv"))
            .replace("DIR", str(tmp_path)))


def _no_traceback(capsys, *argv):
    from linecontact.calc.cli import main

    status = main(list(argv))  # an exception here fails the test with its traceback
    out, err = capsys.readouterr()
    assert status in (0, 2) and "Traceback" not in err, (argv, status, err)
    return status, out, err


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_odd_values_of_every_option_exit_0_or_2(capsys, tmp_path, door):
    """One table per command, every option (_EVERY) x every odd value (ODD), on the command line of a one-case call and as a
    cell of a batch: status 0 or 2, never an exception or 'Traceback'; a refused
    one-case value is one line on stderr. (This loop found: a NUL byte in a path, a
    non-UTF-8 profile or Prony file, and profiled-roller solver failures at a 6 um crown
    radius or a 1e-300 N load, all tracebacks before.)"""
    from linecontact.calc.feature import option_name

    for command, name in _EVERY:
        if command != door.name:
            continue
        base = {k: v[0] for k, v in SAMPLES[command][1].items() if k != "name"}
        for value in ODD:
            value = _odd(value, tmp_path)
            cells = {**base, name: value}
            argv = [command] + [a for k, v in cells.items() for a in (option_name(k), v)]
            status, out, err = _no_traceback(capsys, *argv)
            if status == 2 and out == "":
                assert len(err.strip().splitlines()) == 1, (command, name, value, err)
            src = _write_csv(tmp_path / "c.csv", list(cells), [list(cells.values())])
            _no_traceback(capsys, command, src)


@pytest.mark.parametrize("text", [
    "\ufeffradius,length,modulus,poisson,load\n5mm,10mm,210GPa,0.3,1kN\n",  # BOM
    "load\n1kN\n2kN\n",                             # only some columns (rest: options)
    "radius,load\n5mm,1kN\n,\n",                    # an empty row
    "radius,Radius\n5mm,5mm\n",                     # a column twice
    "foo,bar\n1,2\n",                               # no case column
    "radius,length,modulus,poisson,load\n",         # header only
    "",                                             # empty file
    "   \n\n",                                      # blank lines only
    'radius,load\n"5\nmm",1kN\n',                   # a quoted cell with a line break
    'radius,load\n"5mm,1kN\n',                      # an unclosed quote
    "radius;length;load\n5mm;10mm;1kN\n",           # semicolons
    "radius,load\r5mm,1kN\r",                       # old Mac line ends
    "radius,load\n5mm\x00,1kN\n",                   # a NUL byte
])
def test_odd_csv_files_exit_0_or_2(capsys, tmp_path, text):
    """Odd CSV files (a byte-order mark, only some columns, ragged, duplicated or
    unknown columns, header only, empty, quoted line breaks, an unclosed quote, other
    separators and line ends, a NUL): status 0 or 2, never a traceback."""
    path = tmp_path / "odd.csv"
    path.write_text(text, encoding="utf-8", newline="")
    opts = ("--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson", "0.3")
    _no_traceback(capsys, "calc", str(path), *opts)
    _no_traceback(capsys, "calc", str(path), "--json", "--model", "all")
    _no_traceback(capsys, "calc", str(path), "-o", str(tmp_path))  # a directory


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(sorted(SAMPLE)),
       value=st.text(alphabet="0123456789.eE+-:,; mkNGPasdegrµ\u0663=_%#\"'", max_size=10))
def test_random_text_for_any_option_exits_0_or_2(name, value):
    """Random short text for a random option (hypothesis): status 0 or 2, never a
    traceback."""
    from linecontact.calc.cli import main
    from linecontact.calc.feature import option_name

    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        status = main(["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
                       "--poisson", "0.3", "--load", "1kN", option_name(name), value])
    assert status in (0, 2) and "Traceback" not in err.getvalue(), (name, value, status)


def test_an_overflowing_result_is_flagged_not_printed_as_inf(capsys):
    """--load 1e300 N: p0 = sqrt(F E*/(pi R L)) overflows (F E* ~ 2e311 > 1.8e308), so
    p0 is '-' with a flag naming the overflow, never 'inf'; Kunz's own depth (finite) is
    still printed, and numpy's overflow warnings do not reach stderr (the
    one-line rule)."""
    argv = (*STEEL_CASE, "--radius", "5mm", "--load", "1e300", "--model", "kunz")
    status, out, err = _main(capsys, *argv)
    assert status == 0 and "inf" not in out and err == "", err
    assert "overflow" in out
    doc = _main_json(capsys, *argv)
    row = doc["models"][0]["rows"][0]
    assert row["peak_pressure"] is None and "p0 (Hertz)" in row["flags"]
    assert row["depth"] is not None and math.isfinite(row["depth"])


def test_every_listed_model_key_is_accepted_by_model_option():
    """The keys that --model's message lists as valid (models.available_models(), which
    includes the roller models registered on import of linecontact.roller) are all
    accepted: 'profiled-roller' was listed and then refused as 'unknown model'."""
    from linecontact.calc.compute import parse_model_option
    from linecontact.models import available_models

    for key in available_models():
        assert parse_model_option(key)[0][1] == key


def test_profiled_roller_model_option_runs(capsys):
    """--model profiled-roller computes the straight roller by coupled slices (status 0)
    and its depth is finite and positive."""
    doc = _main_json(capsys, *STEEL_CASE, "--radius", "5mm", "--load", "1kN", "--model",
                     "profiled-roller")
    d = doc["models"][0]["rows"][0]["depth"]
    assert d is not None and d > 0


def test_model_options_take_the_unit_their_docstring_gives():
    """A model option is read in the unit its docstring states (tilt [rad]): 1mrad is
    exactly the SI number 0.001 and 0.05deg is 0.05 pi/180 rad (to rounding);
    a length for an angle is refused naming the option and the valid kind; a number
    option keeps its integer type (n_slices); a named constant still passes as text."""
    from linecontact._units import InputError
    from linecontact.calc.compute import parse_model_option

    tilt = {t: parse_model_option(f"profiled-roller:tilt={t}")[0][2]["tilt"]
            for t in ("1mrad", "0.001", "0.05deg")}
    assert tilt["1mrad"] == tilt["0.001"] == 1e-3
    assert tilt["0.05deg"] == pytest.approx(0.05 * math.pi / 180, rel=1e-15)
    with pytest.raises(InputError, match="tilt.*expected an angle, got a length"):
        parse_model_option("profiled-roller:tilt=1mm")
    n = parse_model_option("iso16281-slicing:n_slices=40")[0][2]["n_slices"]
    assert n == 40 and type(n) is int
    assert parse_model_option("johnson:c=johnson1985")[0][2]["c"] == "johnson1985"


@pytest.mark.parametrize("spec,again", [("universal,universal", "'universal'"),
                                        ("johnson,johnson:c=1", "'johnson:c=1'")])
def test_a_model_named_twice_is_refused(capsys, tmp_path, spec, again):
    """The same model twice in --model ('johnson:c=1' is johnson at its default) gave
    two result sets under one id: a batch wrote each column name twice, so a reader
    (csv.DictReader, pandas, the JSON rows) kept one and lost the other without a word.
    It is refused in one line naming the repeat; distinct options are not."""
    src = _write_csv(tmp_path / "c.csv", ["radius", "length", "estar", "load"],
                     [["5mm", "10mm", "115GPa", "1kN"]])
    status, out, err = _main(capsys, "calc", src, "--model", spec)
    assert status == 2 and f"{again} is the same model as" in err and not out, err
    status, out, err = _main(capsys, "calc", src, "--model", "johnson,johnson:c=0.72")
    header = out.splitlines()[0].split(",")
    assert status == 0 and len(header) == len(set(header)), err


def test_a_swept_radius_or_length_has_its_column(capsys):
    """A sweep over the radius (or the length), alone or in a grid with the load, gives
    each row its value in a column: the rows of R = 5 and 10 mm at the same load were
    printed without it (radius and length are fields the text table does not print),
    so they could not be told apart."""
    status, out, err = _main(capsys, "calc", "--radius", "5mm:10mm:2", "--length", "10mm",
                             "--estar", "115GPa", "--load", "1kN:2kN:2", "--model",
                             "universal")
    assert status == 0, err
    lines = out.splitlines()
    head = next(i for i, line in enumerate(lines) if line.startswith("model"))
    assert "radius [mm]" in lines[head]
    assert [line.split()[3] for line in lines[head + 1:head + 5]] == ["5", "5", "10", "10"]
    status, out, err = _main(capsys, "calc", "--radius", "5mm", "--length",
                             "10mm:20mm:2", "--estar", "115GPa", "--load", "1kN",
                             "--model", "universal")
    assert status == 0 and "length [mm]" in out, err
