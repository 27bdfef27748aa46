"""What ``setup.py`` compiles ahead of time into the modules of :data:`kanat.aot.MODULES` (numba's ``pycc``).

Every entry of :data:`kanat.aot.ENTRIES` (the kernels runs call from Python, declared by the
modules of :data:`DECLARING`) goes into its module, each version exported as ``<name>__<i>`` with
the signature its argument specifications give; every module also exports ``fingerprint()``,
the digest of the sources it was compiled from. The kernels are the same Python functions numba
compiles just in time.

The build compiles through the same numba dispatchers a run makes, so it reads and writes numba's
disk cache in the folder of the current kernel sources (:func:`kanat.jit.cache_directory`): a cache
filled by an earlier build or run over other sources is never read (it would answer a kernel whose
own file is unchanged with machine code holding its callees as they were then, and the extension
would carry that stale code: docs/kernels.md, "numba's disk cache"), and numba's kernels run after
the install find the build's cache warm.

Imported by the build and the tests only (it needs numba and a C compiler).
"""
from __future__ import annotations

import importlib

from kanat import aot, jit
from kanat._private_api import named_tuple_type

DECLARING = ("kanat.continuum.kernels2d", "kanat.continuum.kernels3d", "kanat.lumped.entries",
             "kanat.continuum.factorized.sweeps_compiled", "kanat.continuum.factorized.waves_compiled")
"""The modules that declare entries (:func:`kanat.aot.register`)."""


def numba_type(spec):
    """The numba type of an argument specification of :mod:`kanat.aot`."""
    from numba import types

    if spec is None:
        return types.none
    if aot.is_record(spec):                 # a named tuple of the record's class, as numba types its instances
        spec = aot.as_record(spec)
        return named_tuple_type([numba_type(item) for item in spec.specification], spec.kind)
    if isinstance(spec, tuple):
        return types.Tuple(tuple(numba_type(item) for item in spec))
    if isinstance(spec, aot.Array):
        return types.Array(numba_type(spec.dtype), spec.ndim, "C")
    return types.boolean if spec == aot.BOOL else getattr(types, spec)


def compilers(output_dir=None) -> list:
    """numba's ``CC`` of every module of :data:`kanat.aot.MODULES` (:func:`compiler`)."""
    return [compiler(module, output_dir) for module in aot.MODULES]


def compiler(module: str, output_dir=None):
    """numba's ``CC`` for ``kanat.<module>``, with its entry points exported.

    Parameters
    ----------
    module : str
        One of :data:`kanat.aot.MODULES`.
    output_dir : path-like, optional
        Where ``CC.compile()`` writes the module (default: beside this file, as ``setup.py``'s
        in-place build does).
    """
    from numba import types
    from numba.pycc import CC

    cc = CC(module)
    cc.verbose = False
    if output_dir is not None:
        cc.output_dir = str(output_dir)
    stamp = aot.fingerprint()

    @cc.export("fingerprint", "i8()")
    def fingerprint():
        return stamp

    for declaring in DECLARING:
        importlib.import_module(declaring)
    for name, entry in aot.ENTRIES.items():
        if entry.module != module:
            continue
        kernel = jit.dispatcher_of(getattr(importlib.import_module(entry.home), entry.function))
        returns = types.void if entry.returns is None else numba_type(entry.returns)
        for i, spec in enumerate(entry.versions):
            cc.export(f"{name}__{i}", returns(*map(numba_type, spec)))(_calling(kernel, len(spec)))
    return cc


def _calling(kernel, arity: int):
    """A function of ``arity`` arguments that calls numba's ``kernel`` with them: exported, it
    compiles ``kernel`` with the kernel's own options (:mod:`kanat.jit`: numpy's error model),
    which pycc would not give the exported function's own body."""
    names = ", ".join(f"a{i}" for i in range(arity))
    namespace = {"kernel": kernel}
    exec(f"def entry({names}):\n    return kernel({names})\n", namespace)      # noqa: S102 - a fixed template
    return namespace["entry"]


if __name__ == "__main__":          # python -m kanat.aot_build: rebuild in place after editing a kernel
    for cc in compilers():
        cc.compile()
