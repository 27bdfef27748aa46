"""What ``setup.py`` compiles ahead of time into ``kanat._kernels`` (numba's ``pycc``; :mod:`kanat.aot`).

The continuum model's step kernels, the only ones its runs call from Python:
:func:`kanat.continuum.rows2d.assemble` (planar), :func:`kanat.continuum.rows3d.assemble3`
(spatial) and :func:`kanat.continuum.bending3d.assemble3_bending` (spatial, bending stiffness),
each in the two versions a run uses (``<name>_plain``: a plain cable, ``extras`` None;
``<name>_extras``: with seabed, waves, inline bodies, bending or a surface buoy, ``extras`` an
array), for C-ordered float64 arrays; and ``fingerprint()``, the digest of the sources it was
compiled from. The kernels are the same Python functions numba
compiles just in time; only their entry points are written here, with explicit signatures.

Imported by the build and the tests only (it needs numba and a C compiler).
"""
from __future__ import annotations

from pathlib import Path

from kanat import aot

MODULE = "_kernels"
A1, A2 = "f8[::1]", "f8[:,::1]"
ASSEMBLE = f"{A2},{A2},{A2},{A2},{A2},{A1},{A1},{A1},{A2}"
"""``assemble``'s arguments ``x, y, d, env, P, b0, b1, res, band`` (:mod:`kanat.continuum.rows2d`)."""
ASSEMBLE3 = f"{A2},{A2},{A2},{A2},{A1},{A2},{A1},{A1},{A1},{A2}"
"""``assemble3``'s and ``assemble3_bending``'s ``x, y, d, env, up, P, b0, b1, res, band`` (:mod:`.rows3d`)."""


def compiler(output_dir: str | Path | None = None):
    """numba's ``CC`` for ``kanat._kernels``, with every entry point exported.

    Parameters
    ----------
    output_dir : path-like, optional
        Where ``CC.compile()`` writes the module (for a build outside setuptools, e.g. a test).
    """
    from numba.pycc import CC

    from kanat.continuum.bending3d import assemble3_bending
    from kanat.continuum.rows2d import assemble
    from kanat.continuum.rows3d import assemble3

    cc = CC(MODULE)
    cc.verbose = False
    if output_dir is not None:
        cc.output_dir = str(output_dir)
    stamp = aot.fingerprint()

    @cc.export("fingerprint", "i8()")
    def fingerprint():
        return stamp

    @cc.export("assemble_plain", f"void({ASSEMBLE})")
    def assemble_plain(x, y, d, env, P, b0, b1, res, band):
        assemble(x, y, d, env, P, b0, b1, res, band, None)

    @cc.export("assemble_extras", f"void({ASSEMBLE},{A1})")
    def assemble_extras(x, y, d, env, P, b0, b1, res, band, extras):
        assemble(x, y, d, env, P, b0, b1, res, band, extras)

    @cc.export("assemble3_plain", f"void({ASSEMBLE3})")
    def assemble3_plain(x, y, d, env, up, P, b0, b1, res, band):
        assemble3(x, y, d, env, up, P, b0, b1, res, band, None)

    @cc.export("assemble3_extras", f"void({ASSEMBLE3},{A1})")
    def assemble3_extras(x, y, d, env, up, P, b0, b1, res, band, extras):
        assemble3(x, y, d, env, up, P, b0, b1, res, band, extras)

    @cc.export("assemble3_bending_plain", f"void({ASSEMBLE3})")
    def assemble3_bending_plain(x, y, d, env, up, P, b0, b1, res, band):
        assemble3_bending(x, y, d, env, up, P, b0, b1, res, band, None)

    @cc.export("assemble3_bending_extras", f"void({ASSEMBLE3},{A1})")
    def assemble3_bending_extras(x, y, d, env, up, P, b0, b1, res, band, extras):
        assemble3_bending(x, y, d, env, up, P, b0, b1, res, band, extras)

    return cc


if __name__ == "__main__":          # python -m kanat.aot_build: rebuild in place after editing a kernel
    compiler().compile()
