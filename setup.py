"""The optional C extension of the profiled-roller solver (engine "c",
linecontact/roller/_ckernels.c); the metadata is in pyproject.toml.

Built where a C compiler exists (pip install ., or pip install -e . in place); where the
build fails the install goes on without it (optional=True) and the numpy engine solves
(docs/profiled_rollers.md, "Engines"). IEEE arithmetic: no -ffast-math, and no fused
multiply-adds (-ffp-contract=off), so that the C loops round as numpy and numba do.
"""
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class BuildExt(build_ext):
    """build_ext with the floating-point flags of the compiler at hand."""

    def build_extensions(self):
        if self.compiler.compiler_type == "msvc":
            flags = ["/fp:precise"]
        else:
            flags = ["-ffp-contract=off", "-fno-fast-math"]
        for ext in self.extensions:
            ext.extra_compile_args = list(ext.extra_compile_args or []) + flags
        super().build_extensions()


setup(
    ext_modules=[Extension("linecontact.roller._ckernels",
                           ["linecontact/roller/_ckernels.c"], optional=True)],
    cmdclass={"build_ext": BuildExt},
)
