"""Builds kanat's kernels compiled ahead of time (``src/kanat/aot.py`` says why; ``kanat.aot_build`` what).

Everything else about the package is in ``pyproject.toml``. The extensions are optional: when
they cannot be built (no C compiler, say), or with ``KANAT_AOT=0`` in the environment, the
install goes on without them and runs compile their kernels with numba on first use. Compiled
once per machine: a later install with the same kernel sources, numba, NumPy and Python copies
them from a user cache directory (``kanat.aot_cache``; ``KANAT_KERNEL_CACHE`` names it, ``0``
turns it off). numba's own disk cache is read and written only in the folder of the current kernel
sources (``kanat.jit.cache_directory``: a reused ``NUMBA_CACHE_DIR`` could otherwise put callees as
they were before an upgrade into the modules; docs/kernels.md).
"""
import compileall
import multiprocessing
import os
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_ext import build_ext

sys.path.insert(0, str(Path(__file__).parent / "src"))

from kanat._private_api import compile_object_files, object_file  # noqa: E402 - from the source tree
from kanat.aot_cache import build_once  # noqa: E402


def _compile(extension, build_temp) -> bool:
    """Compile one module's kernels to its object file; whether it was done."""
    try:
        compile_object_files(extension._cc, build_temp)
        return True
    except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
        print(f"warning: {extension.name} was not compiled ({type(error).__name__}: {error})", file=sys.stderr)
        return False


def _compile_and_exit(extension, build_temp) -> None:
    """:func:`_compile` in a forked process, its answer the exit status."""
    os._exit(0 if _compile(extension, build_temp) else 1)


class BuildKernels(build_ext):
    """``build_ext`` that copies the kernel modules from the machine's cache when they were compiled
    before from the same sources by the same numba (:mod:`kanat.aot_cache`), and otherwise compiles
    numba's ``pycc`` modules side by side (numba compiles on one core), links them and caches them;
    a module that fails is skipped, not the install."""

    def run(self):
        super().run()
        if self.inplace:
            _compile_bytecode()

    def build_extensions(self):
        self.check_extensions_list(self.extensions)
        kernels = {Path(self.get_ext_fullpath(ext.name)): ext for ext in self.extensions if hasattr(ext, "_cc")}
        for other in [ext for ext in self.extensions if ext not in kernels.values()]:
            self.build_extension(other)
        if not kernels:
            return
        outcome = build_once(kernels, lambda missing: self._build_kernels([kernels[path] for path in missing]))
        made = outcome["copied"] + outcome["built"]
        for path, extension in kernels.items():
            if path not in made:
                self.extensions.remove(extension)          # not built: the runs compile with numba instead
        print(f"kanat kernels: {len(outcome['copied'])} copied from the cache {outcome['key']}, "
              f"{len(outcome['built'])} compiled, in {outcome['seconds']:.1f} s", file=sys.stderr)

    def _build_kernels(self, kernels) -> list:
        """Compile and link the kernel modules ``kernels``; the paths of those built."""
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
        built = []
        for extension, ok in zip(kernels, done):
            if ok:
                extension.extra_objects = [object_file(extension._cc, self.build_temp)]
                self.build_extension(extension)
                path = Path(self.get_ext_fullpath(extension.name))
                if path.is_file():
                    built.append(path)
        return built

    def build_extension(self, ext):
        try:
            super().build_extension(ext)
        except Exception as error:  # noqa: BLE001 - optional: the runs compile with numba instead
            print(f"warning: {ext.name} was not built ({type(error).__name__}: {error}); "
                  "runs will compile its kernels with numba on first use", file=sys.stderr)


def _compile_bytecode() -> None:
    """Write the package's bytecode beside its sources in an editable install, as pip does for a
    wheel's: where ``PYTHONDONTWRITEBYTECODE`` is set (container images often set it) Python would
    otherwise compile kanat's 200-odd modules on every run, 0.2-0.3 s of a 2.3 s run on a 2-core VM
    (docs/performance.md). Python recompiles a module whose source changed since, in memory."""
    try:
        compileall.compile_dir(str(Path(__file__).parent / "src" / "kanat"), quiet=1)
    except Exception as error:  # noqa: BLE001 - optional: Python compiles the sources as it imports them
        print(f"warning: kanat's bytecode was not written ({type(error).__name__}: {error})", file=sys.stderr)


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
