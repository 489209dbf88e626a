"""The optional C extensions are used only when built from the source beside them.

Facts checked: where an extension is built in this checkout, it carries the SHA-256 of
the C file it was compiled from and that is the file here (else the tests of the C
paths would run an older build, or skip); a build from another version of the source
is refused with a reason naming the rebuild and a RuntimeWarning, and the caller keeps
to numpy; an extension that is not built is reported as such; and each C source
compiles where a C compiler is present (setup.py declares the extensions optional, so a
source that fails to compile would otherwise leave the suite green, every C test
skipped).
"""
from __future__ import annotations

import importlib
import importlib.util
import shlex
import shutil
import subprocess
import sysconfig
import types
from pathlib import Path

import pytest

from linecontact._extensions import load_extension, source_digest

ROOT = Path(__file__).resolve().parent.parent
EXTENSIONS = [("linecontact.roller._ckernels", ROOT / "linecontact/roller/_ckernels.c"),
              ("linecontact._cstresses", ROOT / "linecontact/_cstresses.c")]
#: the flags setup.py adds to each (IEEE arithmetic; the stresses' -fno-math-errno),
#: with a low optimisation to keep the check under a second (-O1 for the stresses'
#: target_clones dispatch)
COMPILE_FLAGS = {"linecontact.roller._ckernels": ["-O0", "-ffp-contract=off",
                                                  "-fno-fast-math"],
                 "linecontact._cstresses": ["-O1", "-ffp-contract=off", "-fno-fast-math",
                                            "-fno-math-errno"]}


@pytest.mark.parametrize("name, source", EXTENSIONS, ids=[e[0] for e in EXTENSIONS])
def test_the_c_source_compiles_where_a_c_compiler_is_present(name, source, tmp_path):
    """setup.py declares each extension optional: where it fails to compile, `pip
    install -e .` (CI's install) still succeeds and every test of its C path skips, so
    an error in the source would leave the whole suite green. Where the C compiler
    Python was built with is present, the source must compile with setup.py's flags."""
    cc = sysconfig.get_config_var("CC")
    if not cc or shutil.which(shlex.split(cc)[0]) is None:
        pytest.skip(f"no C compiler here (sysconfig CC = {cc!r})")
    cmd = shlex.split(cc) + shlex.split(sysconfig.get_config_var("CCSHARED") or "") + [
        "-I", sysconfig.get_paths()["include"], *COMPILE_FLAGS[name], "-c", str(source),
        "-o", str(tmp_path / (source.stem + ".o"))]
    got = subprocess.run(cmd, capture_output=True, text=True)
    assert got.returncode == 0, f"{' '.join(cmd)}:\n{got.stderr[-3000:]}"


@pytest.mark.parametrize("name, source", EXTENSIONS, ids=[e[0] for e in EXTENSIONS])
def test_a_built_extension_is_built_from_the_source_here(name, source):
    if importlib.util.find_spec(name) is None:
        pytest.skip(f"{name} is not built here (no C compiler at install)")
    mod = importlib.import_module(name)
    assert getattr(mod, "SOURCE_SHA256", "") == source_digest(source), (
        f"{name} was built from another version of {source.name}: rebuild it "
        f"(pip install -e .)")
    got, why = load_extension(name, source)
    assert got is mod and why is None


def test_a_stale_build_is_refused_with_a_warning(monkeypatch, tmp_path):
    src = tmp_path / "_fake.c"
    src.write_text("/* today's source */\n")
    fake = types.ModuleType("fake_ext")
    fake.SOURCE_SHA256 = source_digest(src)
    monkeypatch.setattr(importlib, "import_module", lambda name: fake)
    assert load_extension("fake_ext", src) == (fake, None)
    src.write_text("/* the source edited after the build */\n")
    with pytest.warns(RuntimeWarning, match="stale build"):
        got, why = load_extension("fake_ext", src)
    assert got is None and "pip install -e ." in why


def test_a_build_without_its_source_beside_it_is_used(monkeypatch, tmp_path):
    fake = types.ModuleType("fake_ext")
    monkeypatch.setattr(importlib, "import_module", lambda name: fake)
    assert load_extension("fake_ext", tmp_path / "absent.c") == (fake, None)


def test_an_extension_not_built_says_so():
    got, why = load_extension("linecontact._no_such_extension", ROOT / "absent.c")
    assert got is None and "_no_such_extension" in why
