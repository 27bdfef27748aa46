"""The lumped Lagrangian network model (SPEC §5, seed 004).

Public API
----------
run(case, output_path, *, scheme=None, resume=False, progress=None, checkpoint_every=None,
    stop_after=None) -> RunSummary
    Run a ``model: lumped`` case, streaming results and checkpoints (:mod:`.driver`); the steps
    between outputs go through :func:`.advance.advance` (compiled paths :mod:`.fast`,
    :mod:`.fast_implicit`).
build_network(case) -> Network
    The case as nodes, elements and bodies (:mod:`.network`).
equilibrium(net, case) -> (x, info)
    The initial static state (:mod:`.equilibrium`).
LumpedSystem
    The equations of motion (:mod:`.system`); schemes in :mod:`.integrators`.

Seed 004's example: :mod:`.seed004` (statistics, findings, ``python -m kanat.lumped.seed004``).
"""
from kanat.lumped.driver import RunSummary, run
from kanat.lumped.equilibrium import equilibrium
from kanat.lumped.network import Network, build_network
from kanat.lumped.system import LumpedSystem

__all__ = ["LumpedSystem", "Network", "RunSummary", "build_network", "equilibrium", "run"]
