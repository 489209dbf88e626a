"""The optional C extensions: the profiled-roller solver's (engine "c",
linecontact/roller/_ckernels.c) and the subsurface stresses' corner sums
(linecontact/_cstresses.c); the metadata is in pyproject.toml.

Built where a C compiler exists (pip install ., or pip install -e . in place); where the
build fails the install goes on without it (optional=True) and the numpy engine solves
(docs/profiled_rollers.md, "Engines"). IEEE arithmetic: no -ffast-math, and no fused
multiply-adds (-ffp-contract=off), so that the C loops round as numpy and numba do.
"""
import hashlib
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent


def extension(name, source):
    """An optional Extension from one C file, which carries the SHA-256 of the source it
    was built from (SOURCE_SHA256: linecontact/_extensions.py refuses a stale build)."""
    digest = hashlib.sha256((HERE / source).read_bytes()).hexdigest()
    return Extension(name, [source], optional=True,
                     define_macros=[("LC_SOURCE_SHA256", f'"{digest}"')])


class BuildExt(build_ext):
    """build_ext with the floating-point flags of the compiler at hand."""

    def build_extensions(self):
        if self.compiler.compiler_type == "msvc":
            flags = ["/fp:precise"]
        else:
            flags = ["-ffp-contract=off", "-fno-fast-math"]
        for ext in self.extensions:
            more = []
            if ext.name == "linecontact._cstresses" and self.compiler.compiler_type != "msvc":
                # the corner loop vectorised: -O3, and sqrt without errno's branch
                # (the same values; IEEE arithmetic kept)
                more = ["-O3", "-fno-math-errno"]
            ext.extra_compile_args = list(ext.extra_compile_args or []) + flags + more
        super().build_extensions()


setup(
    ext_modules=[extension("linecontact.roller._ckernels", "linecontact/roller/_ckernels.c"),
                 extension("linecontact._cstresses", "linecontact/_cstresses.c")],
    cmdclass={"build_ext": BuildExt},
)
