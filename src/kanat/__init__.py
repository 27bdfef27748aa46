"""kanat: statics and dynamics of marine cable systems.

Public API (:mod:`kanat.api`)
-----------------------------
load_case(path | yaml_text | mapping) -> Case
    Read and validate a case; ``case.replace({...})`` gives a validated variant.
solve_statics(case, method="auto") -> xarray.Dataset
    The steady state.
simulate(case, scheme=None, output=None, resume=False, progress=None) -> xarray.Dataset
    Run any case with its model: in memory, or streamed to a netCDF file.
run(case, ...) -> Outcome
    The same, with the run summary and its text (what ``kanat run`` prints).
offsets(case, direction, to, steps=20) -> xarray.Dataset
    Restoring force and line tensions of a moored vessel against its offset.
read_result(path) -> xarray.Dataset
    A result file.
report(result | path | study_dir, html_path) -> Path
    One self-contained HTML page (:func:`kanat.report.report`).
design(case, output=None) -> DesignResult
    The design checks of a mooring: ``utilisation`` and ``fatigue`` tables (pandas), intact and
    damaged, under API RP 2SK (:mod:`kanat.design_checks`).
Coupling(case)
    The lines driven by another program's time loop: ``initialize(positions)``,
    ``step(t, dt, positions, velocities) -> forces`` (:mod:`kanat.coupling`).
linearize(case) -> Linearization
    Mass, damping and stiffness (sparse) of the lumped system about its equilibrium.
modes(case, n=10) -> xarray.Dataset
    Natural frequencies and mode shapes (:mod:`kanat.frequency`).
solve_frequency(case) -> xarray.Dataset
    The linear response to the sea and the vessel's motion: tension and motion RAOs, spectra and
    standard deviations (``simulation.method: frequency``).

The names are loaded on first use, so ``import kanat`` stays light.
"""
from kanat.version import __version__

_API = ("load_case", "solve_statics", "offsets", "simulate", "run", "read_result", "Outcome", "RunFailedWarning", "MODELS")
__all__ = ["__version__", *_API, "report", "Coupling", "design"]
_FREQUENCY = ("linearize", "modes", "solve_frequency")     # the lumped system about its equilibrium (kanat.frequency)
__all__ += list(_FREQUENCY)


import kanat.report as _report_package  # noqa: E402 - binds the package first (it imports nothing) ...

report = _report_package.report          # ... then the name to the plain function, for good


def __getattr__(name):
    if name in _API:
        from kanat import api

        return getattr(api, name)
    if name in _FREQUENCY:
        import kanat.frequency

        return getattr(kanat.frequency, name)
    if name == "Coupling":
        from kanat.coupling import Coupling

        return Coupling
    if name == "catalog":
        import kanat.catalog  # noqa: F401 - binds the module kanat.catalog

        return globals()["catalog"]
    if name == "design":
        from kanat.design_checks import design

        return design
    raise AttributeError(f"module 'kanat' has no attribute {name!r}")
