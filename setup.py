"""Builds ``kanat._kernels``, the kernels compiled ahead of time (``src/kanat/aot.py`` says why).

Everything else about the package is in ``pyproject.toml``. The extension is optional: when it
cannot be built (no C compiler, say), the install goes on and runs compile their kernels with
numba on first use, as they would without it.
"""
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_ext import build_ext

sys.path.insert(0, str(Path(__file__).parent / "src"))


class BuildKernels(build_ext):
    """``build_ext`` that compiles numba's ``pycc`` extensions first, and skips one that fails."""

    def build_extension(self, ext):
        try:
            if hasattr(ext, "_prepare_object_files"):
                ext._prepare_object_files(self)
            super().build_extension(ext)
        except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
            print(f"warning: kanat's ahead-of-time kernels were not built ({type(error).__name__}: {error}); "
                  "runs will compile them with numba on first use", file=sys.stderr)


def extensions():
    """``kanat._kernels`` (:mod:`kanat.aot_build`), or none when it cannot be described here."""
    try:
        from kanat.aot_build import compiler

        return [compiler().distutils_extension()]      # named kanat._kernels after the module that made it
    except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
        print(f"warning: kanat's ahead-of-time kernels are skipped ({type(error).__name__}: {error})", file=sys.stderr)
        return []


setup(ext_modules=extensions(), cmdclass={"build_ext": BuildKernels})
