"""The lumped Lagrangian network model (theory/lumped.md, Bezverkhyi 2006).

Public API
----------
LumpedModel(case, scheme=None)
    A ``model: lumped`` case ready for the run loop of :mod:`kanat.dynamics` (:mod:`.adapter`);
    the steps between outputs go through :func:`.advance.advance` (compiled paths :mod:`.fast`,
    :mod:`.fast_implicit`).
build_network(case) -> Network
    The case as nodes, elements and bodies (:mod:`.network`).
equilibrium(net, case) -> (x, info)
    The initial static state (:mod:`.equilibrium`).
LumpedSystem
    The equations of motion (:mod:`.system`); schemes in :mod:`.integrators`.

A test-only oracle (an independent twin of compiled kernels that only the tests import) is a
module ``oracle_<method><dim>.py`` in the package whose kernels it checks, ``<method>`` saying how
it is written (``complex_step``, ``numpy``, ``sympy``) and ``<dim>`` the ``2d``/``3d`` of those
kernels where the package has both: here :mod:`.oracle_numpy`.
"""
_API = {"LumpedModel": "adapter", "equilibrium": "equilibrium", "Network": "network", "build_network": "network",
        "LumpedSystem": "system"}


def __getattr__(name):
    """The public names, imported on first use: the compiled kernels' modules import this package
    without the model's case and run machinery (the install's kernel build has only numba)."""
    if name not in _API:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from importlib import import_module

    return getattr(import_module(f"kanat.lumped.{_API[name]}"), name)


__all__ = ["LumpedModel", "LumpedSystem", "Network", "build_network", "equilibrium"]
