"""The optional C extension (linecontact._ckernels, from two sources) is used only when
built from the sources beside it.

Facts checked: where the extension is built in this checkout, it carries the SHA-256 of
the two C files it was compiled from and those are the files here (else the tests of
the C paths would run an older build, or skip); a build from other versions of the
sources is refused with a reason naming the rebuild and a RuntimeWarning, and the caller
keeps to numpy; an extension that is not built is reported as such; and each C source
compiles where a C compiler is present (setup.py declares the extension optional, so a
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

import pytest

from linecontact import _engine
from linecontact._engine import EXTENSION, SOURCES, load_extension, sources_digest

#: setup.py's flags (IEEE arithmetic; -fno-math-errno), with a low optimisation to keep
#: the check under a second (-O1 for the stresses' target_clones dispatch)
COMPILE_FLAGS = ["-O1", "-ffp-contract=off", "-fno-fast-math", "-fno-math-errno"]


@pytest.mark.parametrize("source", SOURCES, ids=[s.name for s in SOURCES])
def test_each_c_source_compiles_where_a_c_compiler_is_present(source, tmp_path):
    """setup.py declares the extension optional: where it fails to compile, `pip
    install -e .` (CI's install) still succeeds and every test of the C paths skips, so
    an error in a source would leave the whole suite green. Where the C compiler
    Python was built with is present, each source must compile with setup.py's flags."""
    cc = sysconfig.get_config_var("CC")
    if not cc or shutil.which(shlex.split(cc)[0]) is None:
        pytest.skip(f"no C compiler here (sysconfig CC = {cc!r})")
    cmd = shlex.split(cc) + shlex.split(sysconfig.get_config_var("CCSHARED") or "") + [
        "-I", sysconfig.get_paths()["include"], *COMPILE_FLAGS, "-c", str(source),
        "-o", str(tmp_path / (source.stem + ".o"))]
    got = subprocess.run(cmd, capture_output=True, text=True)
    assert got.returncode == 0, f"{' '.join(cmd)}:\n{got.stderr[-3000:]}"


def test_a_built_extension_is_built_from_the_sources_here():
    if importlib.util.find_spec(EXTENSION) is None:
        pytest.skip(f"{EXTENSION} is not built here (no C compiler at install)")
    mod = importlib.import_module(EXTENSION)
    assert getattr(mod, "SOURCE_SHA256", "") == sources_digest(SOURCES), (
        f"{EXTENSION} was built from other versions of its sources: rebuild it "
        f"(pip install -e .)")
    assert load_extension(EXTENSION, SOURCES) == (mod, None)
    assert _engine.ckernels() is mod and _engine.unavailable() is None
    # one module: the roller's kernels and the stresses' corner sums
    assert callable(mod.kernels) and callable(mod.love_sums)


def test_a_stale_build_is_refused_with_a_warning(monkeypatch, tmp_path):
    """An edit to either source after the build makes it stale."""
    srcs = [tmp_path / "a.c", tmp_path / "b.c"]
    for s in srcs:
        s.write_text(f"/* today's {s.name} */\n")
    fake = types.ModuleType("fake_ext")
    fake.SOURCE_SHA256 = sources_digest(srcs)
    monkeypatch.setattr(importlib, "import_module", lambda name: fake)
    assert load_extension("fake_ext", srcs) == (fake, None)
    for s in srcs:
        kept = s.read_text()
        s.write_text("/* the source edited after the build */\n")
        with pytest.warns(RuntimeWarning, match="stale build"):
            got, why = load_extension("fake_ext", srcs)
        assert got is None and "pip install -e ." in why and s.name in why
        s.write_text(kept)


def test_a_build_without_its_sources_beside_it_is_used(monkeypatch, tmp_path):
    fake = types.ModuleType("fake_ext")
    monkeypatch.setattr(importlib, "import_module", lambda name: fake)
    assert load_extension("fake_ext", [tmp_path / "absent.c"]) == (fake, None)


def test_an_extension_not_built_says_so(tmp_path):
    got, why = load_extension("linecontact._no_such_extension", [tmp_path / "absent.c"])
    assert got is None and "_no_such_extension" in why
