"""Builds kanat's kernels compiled ahead of time (``src/kanat/aot.py`` says why; ``kanat.aot_build`` what).

Everything else about the package is in ``pyproject.toml``. The extensions are optional: when
they cannot be built (no C compiler, say), or with ``KANAT_AOT=0`` in the environment, the
install goes on without them and runs compile their kernels with numba on first use.
"""
import multiprocessing
import os
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_ext import build_ext

sys.path.insert(0, str(Path(__file__).parent / "src"))


def _compile(extension, build_temp) -> bool:
    """Compile one module's kernels to its object file; whether it was done."""
    try:
        extension._cc._compile_object_files(build_temp)
        return True
    except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
        print(f"warning: {extension.name} was not compiled ({type(error).__name__}: {error})", file=sys.stderr)
        return False


def _compile_and_exit(extension, build_temp) -> None:
    """:func:`_compile` in a forked process, its answer the exit status."""
    os._exit(0 if _compile(extension, build_temp) else 1)


def _object_file(extension, build_temp) -> str:
    """Where ``CC._compile_object_files`` writes ``extension``'s object file."""
    return os.path.join(build_temp, os.path.splitext(extension._cc.output_file)[0] + ".o")


class BuildKernels(build_ext):
    """``build_ext`` that compiles numba's ``pycc`` modules side by side (numba compiles on one core),
    then links them; a module that fails is skipped, not the install."""

    def build_extensions(self):
        kernels = [ext for ext in self.extensions if hasattr(ext, "_cc")]
        os.makedirs(self.build_temp, exist_ok=True)
        if "fork" in multiprocessing.get_all_start_methods():        # every module at once, forked: the
            fork = multiprocessing.get_context("fork")                # extensions hold functions, which do not pickle
            workers = [fork.Process(target=_compile_and_exit, args=(ext, self.build_temp)) for ext in kernels]
            for worker in workers:
                worker.start()
            for worker in workers:
                worker.join()
            done = [worker.exitcode == 0 for worker in workers]
        else:
            done = [_compile(extension, self.build_temp) for extension in kernels]
        for extension, ok in zip(kernels, done):
            if ok:
                extension.extra_objects = [_object_file(extension, self.build_temp)]
            else:
                self.extensions.remove(extension)
        super().build_extensions()

    def build_extension(self, ext):
        try:
            super().build_extension(ext)
        except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
            print(f"warning: {ext.name} was not built ({type(error).__name__}: {error}); "
                  "runs will compile its kernels with numba on first use", file=sys.stderr)


def extensions():
    """The modules of ``kanat.aot.MODULES`` (``kanat.aot_build``), or none when they cannot be described
    here or ``KANAT_AOT=0`` is set (an install that leaves the compiling to numba, at first use)."""
    if os.environ.get("KANAT_AOT") == "0":
        return []
    try:
        from kanat.aot_build import compilers

        return [cc.distutils_extension() for cc in compilers()]     # kanat.<module>: named after aot_build's package
    except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
        print(f"warning: kanat's ahead-of-time kernels are skipped ({type(error).__name__}: {error})", file=sys.stderr)
        return []


setup(ext_modules=extensions(), cmdclass={"build_ext": BuildKernels})
