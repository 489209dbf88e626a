"""The optional C extension linecontact._ckernels, the compiled engine: the
profiled-roller solver's kernels (engine "c", linecontact/roller/_ckernels.c) and the
subsurface stresses' corner sums (linecontact/_cstresses.c), two sources of one module;
the metadata is in pyproject.toml.

Built where a C compiler exists (pip install ., or pip install -e . in place); where the
build fails the install goes on without it (optional=True) and the numpy code, the
reference, runs instead (docs/profiled_rollers.md, "Engines"). IEEE arithmetic: no
-ffast-math, and no fused multiply-adds (-ffp-contract=off), so that the C loops round
as numpy does.
"""
import hashlib
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent

#: the extension's sources, in the order linecontact/_engine.py hashes them
SOURCES = ["linecontact/roller/_ckernels.c", "linecontact/_cstresses.c"]


def sources_digest(paths):
    """The SHA-256 (hex) of the sources' bytes one after another: the build carries it
    (SOURCE_SHA256) and linecontact/_engine.py refuses a build whose sources differ."""
    h = hashlib.sha256()
    for path in paths:
        h.update(Path(path).read_bytes())
    return h.hexdigest()


class BuildExt(build_ext):
    """build_ext with the floating-point flags of the compiler at hand."""

    def build_extensions(self):
        if self.compiler.compiler_type == "msvc":
            flags = ["/fp:precise"]
        else:
            # IEEE arithmetic kept; -O3 (Python's own default) and -fno-math-errno let
            # the corner loop vectorise (sqrt without errno's branch). Neither changes a
            # value: without -ffast-math no operation is reassociated or approximated,
            # and math-errno only decides whether sqrt and log also set errno
            flags = ["-ffp-contract=off", "-fno-fast-math", "-O3", "-fno-math-errno"]
        for ext in self.extensions:
            ext.extra_compile_args = list(ext.extra_compile_args or []) + flags
        super().build_extensions()


setup(
    ext_modules=[Extension(
        "linecontact._ckernels", SOURCES, optional=True,
        define_macros=[("LC_SOURCE_SHA256",
                        f'"{sources_digest(HERE / s for s in SOURCES)}"')])],
    cmdclass={"build_ext": BuildExt},
)
