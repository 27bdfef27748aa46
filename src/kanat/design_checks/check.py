"""The design check: every condition x sea state (x seed) analysed, then the utilisation and fatigue tables.

1. Each condition (:mod:`.conditions`) is solved for its statics first; a condition whose
   statics fails (a body left with no restoring, say) is reported as failed, with the
   solver's message, and its lines' rows say ``ok = False`` with no tension.
2. Each sea state of each condition is analysed as ``design.analysis`` says:

   ``dynamic``
       run ``seeds`` times on the study engine (:mod:`.runs`: serially, on local workers or a
       Dask cluster), into ``DIR/runs/<condition>/<sea_state>_seed<k>.nc``; a run whose file is
       complete is read back, so an interrupted check resumes. The MPM of the fairlead tension
       over ``storm_duration`` comes from the seeds' records (:func:`kanat.analysis.extremes.mpm`).
   ``quasi-static``
       the statics with the vessel at its design offset (:mod:`.quasi_static`); that tension
       stands for the MPM.
   ``frequency``
       the tension spectra of a spectral analysis (:mod:`.spectral_check`); the MPM from their
       moments.
3. Utilisation: per line, ``safety_factor = MBL / MPM`` against the required one
   (:mod:`.factors`: API RP 2SK, or DNV-OS-E301's partial factors written in the same form).
4. Fatigue (API RP 2SK §7.4), intact condition only: at every node of every line, Miner's
   damage of each run's tension record on the T-N curve (:func:`kanat.analysis.fatigue.damage`),
   averaged over the seeds, scaled to a year by ``probability x YEAR / record length`` and
   summed over the sea states (dynamic); or Dirlik's damage rate of the tension spectrum times
   ``probability x YEAR`` (frequency); ``life_years = 1 / damage_per_year``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from kanat import api
from kanat.analysis.extremes import mpm
from kanat.analysis.fatigue import TN_CURVES, damage
from kanat.errors import KanatError
from kanat.model import Case

from . import records
from .conditions import Condition, condition_case, conditions, sea_state_case, wave_seed
from . import quasi_static, spectral_check
from .factors import check_standard, required_safety_factor
from .runs import Job, run_file, run_jobs
from .spectral_check import SpectralAnalysis

UTILISATION_COLUMNS = ("condition", "sea_state", "line", "mpm_tension", "mbl", "safety_factor",
                       "required_safety_factor", "ok")
FATIGUE_COLUMNS = ("line", "s", "damage_per_year", "life_years")
EXCURSION_COLUMNS = ("condition", "sea_state", "item", "quantity", "largest")
"""Rows of the offsets and uplifts table: ``item`` a body (``quantity`` ``offset`` [m]) or an
anchor (``uplift`` [N]); ``largest`` over the seeds' records (not an extreme-value estimate)."""

@dataclass
class DesignResult:
    """The tables of a design check and what they came from.

    Attributes
    ----------
    utilisation : pandas.DataFrame
        :data:`UTILISATION_COLUMNS`, one row per condition, sea state and line.
    fatigue : pandas.DataFrame
        :data:`FATIGUE_COLUMNS`, one row per node of every line (empty without ``fatigue``).
    excursions : pandas.DataFrame
        :data:`EXCURSION_COLUMNS`: each body's largest horizontal offset from its intact
        statics position, each anchor's largest uplift, per condition and sea state.
    failures : dict of str to str
        Conditions (or ``condition/sea state``) that could not be checked, and why.
    statics : dict of str to xarray.Dataset
        Each condition's statics.
    runs : dict of (str, str, int) to Path
        Each run's result file, by (condition, sea state, seed index) (empty when the runs went
        to a temporary folder).
    case : kanat.model.Case
    engine : str
        What ran the runs.
    offsets : dict of (str, str) to quasi_static.DesignOffset
        Quasi-static analysis: the vessel's design offset by (condition kind, sea state).
    """

    utilisation: object
    fatigue: object
    excursions: object = None
    failures: dict = field(default_factory=dict)
    statics: dict = field(default_factory=dict)
    runs: dict = field(default_factory=dict)
    case: Case | None = None
    engine: str = ""
    offsets: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """True when every line passes in every condition and no check failed."""
        life = self.case.design.fatigue.design_life if self.case.design.fatigue else 0.0
        return (not self.failures and bool(self.utilisation["ok"].all())
                and bool((self.fatigue["life_years"] >= life).all()))


def check_supported(case: Case, spectral_analysis: SpectralAnalysis | None = None) -> None:
    """Refuse what the design check does not do, before any run."""
    design = case.design
    if design is None:
        raise KanatError("the case has no 'design' block (standard, sea_states, conditions, ...); "
                         "see docs/design.md")
    check_standard(design.standard, design.analysis, design.consequence_class)
    if design.fatigue is not None and design.fatigue.curve not in TN_CURVES:
        raise KanatError(f"design.fatigue.curve: '{design.fatigue.curve}' is not a T-N curve; known: "
                         f"{', '.join(TN_CURVES)} (the S-N curves in stress are not used by the design check)")
    if design.analysis == "quasi-static" and design.fatigue is not None:
        raise KanatError("design.fatigue: a quasi-static analysis gives no tension cycles; check fatigue "
                         "with analysis: dynamic (or frequency), or remove 'fatigue'")
    if design.analysis == "frequency":
        spectral_check.spectral_method(design.extremes)
    if design.analysis == "dynamic" and case.model != "lumped":
        raise KanatError(f"model: {case.model}: a dynamic design check runs the lumped model "
                         "(model: lumped) of a mooring")


def _condition_statics(case: Case, condition: Condition, result: DesignResult) -> Case | None:
    """The condition's case once its statics is solved, or None (the failure recorded)."""
    try:
        variant = condition_case(case, condition)
        ds = api.solve_statics(variant)
    except KanatError as error:
        result.failures[condition.name] = f"no steady state: {error}"
        return None
    if ds.attrs.get("status", "ok") != "ok":
        result.failures[condition.name] = ds.attrs["status"]
        return None
    result.statics[condition.name] = ds
    return variant


def _row(variant: Case, condition: Condition, sea_state: str, cable: str, mean: float, largest: float) -> dict:
    """One utilisation row: the line's MPM tension ``largest`` (mean ``mean``) against its MBL."""
    design = variant.design
    required = required_safety_factor(design.standard, design.analysis, condition.kind, mean, largest,
                                      design.consequence_class)
    mbl = records.breaking_load(variant, cable)
    factor = mbl / largest
    return dict(condition=condition.name, sea_state=sea_state, line=cable, mpm_tension=largest, mbl=mbl,
                safety_factor=factor, required_safety_factor=required, ok=bool(factor >= required))


def _utilisation_rows(variant: Case, condition: Condition, sea_state: str, runs: list) -> list[dict]:
    design = variant.design
    rows = []
    for cable in variant.cables:
        series = np.array([records.fairlead_tension(ds, cable.name) for ds in runs])
        extreme = mpm(series, runs[0].time.values, design.storm_duration, design.extremes)
        rows.append(_row(variant, condition, sea_state, cable.name, float(series.mean()), extreme.value))
    return rows


def _excursion_rows(result: DesignResult, condition: str, sea_state: str, runs: list) -> list[dict]:
    intact = result.statics.get("intact")
    neutral = ({} if intact is None or "body_position" not in intact else
               {str(b): intact["body_position"].sel(body=b).values for b in intact["body"].values})
    rows = [dict(condition=condition, sea_state=sea_state, item=body, quantity="offset", largest=value)
            for body, value in records.largest_offsets(runs, neutral).items()]
    return rows + [dict(condition=condition, sea_state=sea_state, item=anchor, quantity="uplift", largest=value)
                   for anchor, value in records.largest_uplift(runs).items()]


def _failed_rows(case: Case, condition: Condition, sea_state: str) -> list[dict]:
    design = case.design
    required = (required_safety_factor(design.standard, design.analysis, condition.kind)
                if design.standard == "api-rp-2sk" else math.nan)    # DNV's depends on the tensions
    return [dict(condition=condition.name, sea_state=sea_state, line=c.name, mpm_tension=math.nan,
                 mbl=records.breaking_load(case, c.name), safety_factor=math.nan,
                 required_safety_factor=required, ok=False)
            for c in case.cables if c.name != condition.removed]


def annual_damage(variant: Case, sea_state, runs: list) -> dict[str, np.ndarray]:
    """Per cable, the damage per year at each node that one sea state causes, shape (n_nodes,).

    ``D_year = mean over seeds of D_record x probability x YEAR / record length``.
    """
    curve = variant.design.fatigue.curve
    found = {}
    for cable in variant.cables:
        nodes = records.cable_nodes(runs[0], cable.name)
        kinds = records.line_types_along(variant, cable.name, runs[0]["s"].values[nodes])
        strength = [records.reference_strength(variant, kind, curve) for kind in kinds]
        per_seed = [[damage(ds["tension"].isel(node=int(n)).values, ref, curve)
                     for n, ref in zip(nodes, strength)] for ds in runs]
        length = float(runs[0].time[-1] - runs[0].time[0])
        found[cable.name] = np.mean(per_seed, axis=0) * sea_state.probability * records.YEAR / length
    return found


def _fatigue_table(case: Case, intact_runs: dict, pd):
    """The fatigue rows from the intact runs of every sea state."""
    damages = []
    for sea_state, runs in intact_runs.values():
        s_of = {c.name: runs[0]["s"].values[records.cable_nodes(runs[0], c.name)] for c in case.cables}
        damages.append((annual_damage(case, sea_state, runs), s_of))
    return _fatigue_rows(case, damages, pd)


def _fatigue_rows(case: Case, damages: list, pd):
    """The fatigue table from each sea state's ``({cable: damage per year (n,)}, {cable: s (n,)})``."""
    rows = []
    if case.design.fatigue is None or not damages:
        return pd.DataFrame(columns=FATIGUE_COLUMNS)
    total: dict[str, np.ndarray] = {}
    s_of: dict[str, np.ndarray] = {}
    for per_cable, arclengths in damages:
        for cable, per_year in per_cable.items():
            total[cable] = total.get(cable, 0.0) + per_year
            s_of[cable] = arclengths[cable]
    for cable, per_year in total.items():
        for s, d in zip(s_of[cable], per_year):
            rows.append(dict(line=cable, s=float(s), damage_per_year=float(d),
                             life_years=1.0 / d if d > 0 else math.inf))
    return pd.DataFrame(rows, columns=FATIGUE_COLUMNS)


def _jobs(case: Case, folder: Path, result: DesignResult) -> tuple[list[Job], list[Condition]]:
    """Every run of the check, and the conditions whose statics failed (recorded in ``result``)."""
    jobs, failed = [], []
    for condition in conditions(case):
        variant = _condition_statics(case, condition, result)
        if variant is None:
            failed.append(condition)
            continue
        for sea_state in case.design.sea_state_rows:
            for k in range(case.design.seeds):
                jobs.append(Job(condition, sea_state, k, sea_state_case(variant, sea_state, wave_seed(case, k)),
                                run_file(folder, condition.name, sea_state.name, k)))
    return jobs, failed


def _tables(case: Case, jobs: list[Job], failed: list[Condition], failures: dict, result: DesignResult, pd):
    """The utilisation and fatigue tables from the runs' files."""
    rows, intact_runs, excursions = [], {}, []
    groups: dict[tuple[str, str], list[Job]] = {}
    for job in jobs:
        groups.setdefault((job.condition.name, job.sea_state.name), []).append(job)
    for condition in failed:
        for sea_state in case.design.sea_state_rows:
            rows += _failed_rows(case, condition, sea_state.name)
    for (name, sea_state_name), group in groups.items():
        condition, sea_state = group[0].condition, group[0].sea_state
        bad = [failures[job.label] for job in group if job.label in failures]
        if bad:
            result.failures[f"{name}/{sea_state_name}"] = bad[0]
            rows += _failed_rows(case, condition, sea_state_name)
            continue
        try:
            runs = [records.analysed(api.read_result(job.path).load(), job.case) for job in group]
        except KanatError as error:
            result.failures[f"{name}/{sea_state_name}"] = str(error)
            rows += _failed_rows(case, condition, sea_state_name)
            continue
        result.runs.update({(name, sea_state_name, job.seed): job.path for job in group})
        rows += _utilisation_rows(group[0].case, condition, sea_state_name, runs)
        excursions += _excursion_rows(result, name, sea_state_name, runs)
        if condition.kind == "intact":
            intact_runs[sea_state_name] = (sea_state, runs)
    result.utilisation = pd.DataFrame(rows, columns=UTILISATION_COLUMNS)
    result.fatigue = _fatigue_table(case, intact_runs, pd)
    result.excursions = pd.DataFrame(excursions, columns=EXCURSION_COLUMNS)


def _variants(case: Case, result: DesignResult) -> list[tuple[Condition, Case | None]]:
    """Each condition with its solved case (None: its statics failed, recorded in ``result``)."""
    return [(condition, _condition_statics(case, condition, result)) for condition in conditions(case)]


def _quasi_static_tables(case: Case, result: DesignResult, progress, pd) -> None:
    """The utilisation table from the statics at each sea state's design offset (:mod:`.quasi_static`)."""
    rows, excursions = [], []
    kinds = {condition.kind for condition in conditions(case)}
    offsets = {(kind, sea_state.name): quasi_static.design_offset(case, sea_state, kind)
               for kind in sorted(kinds) for sea_state in case.design.sea_state_rows}
    for condition, variant in _variants(case, result):
        for sea_state in case.design.sea_state_rows:
            if variant is None:
                rows += _failed_rows(case, condition, sea_state.name)
                continue
            offset = offsets[(condition.kind, sea_state.name)]
            try:
                tensions = quasi_static.line_tensions(variant, offset)
            except KanatError as error:
                result.failures[f"{condition.name}/{sea_state.name}"] = str(error)
                rows += _failed_rows(case, condition, sea_state.name)
                continue
            rows += [_row(variant, condition, sea_state.name, cable, math.nan, tension)
                     for cable, tension in tensions.items()]
            excursions.append(dict(condition=condition.name, sea_state=sea_state.name, item="vessel",
                                   quantity="offset", largest=offset.total))
            if progress is not None:
                progress(f"{condition.name}/{sea_state.name}: statics at an offset of {offset.total:.3g} m")
    result.offsets = offsets
    result.engine = "statics at the design offsets, in this process"
    result.utilisation = pd.DataFrame(rows, columns=UTILISATION_COLUMNS)
    result.fatigue = pd.DataFrame(columns=FATIGUE_COLUMNS)
    result.excursions = pd.DataFrame(excursions, columns=EXCURSION_COLUMNS)


def _spectral_tables(case: Case, result: DesignResult, analysis: SpectralAnalysis, progress, pd) -> None:
    """The tables from the tension spectra of ``analysis`` (:mod:`.spectral_check`)."""
    rows, damages = [], []
    design = case.design
    for condition, variant in _variants(case, result):
        for sea_state in design.sea_state_rows:
            if variant is None:
                rows += _failed_rows(case, condition, sea_state.name)
                continue
            try:
                spectra = analysis(sea_state_case(variant, sea_state, wave_seed(case, 0)))
            except KanatError as error:
                result.failures[f"{condition.name}/{sea_state.name}"] = str(error)
                rows += _failed_rows(case, condition, sea_state.name)
                continue
            missing = [c.name for c in variant.cables if c.name not in spectra]
            if missing:
                raise KanatError(f"the spectral analysis gave no tension spectra for cable '{missing[0]}' "
                                 f"({condition.name}, sea state {sea_state.name})")
            for cable in variant.cables:
                mean, largest = spectral_check.fairlead_extreme(spectra[cable.name], design.storm_duration,
                                                                design.extremes)
                rows.append(_row(variant, condition, sea_state.name, cable.name, mean, largest))
            if condition.kind == "intact" and design.fatigue is not None:
                damages.append(({c: spectral_check.annual_damage(variant, c, line, sea_state.probability)
                                 for c, line in spectra.items()}, {c: line.s for c, line in spectra.items()}))
            if progress is not None:
                progress(f"{condition.name}/{sea_state.name}: tension spectra")
    result.engine = "a spectral analysis, in this process"
    result.utilisation = pd.DataFrame(rows, columns=UTILISATION_COLUMNS)
    result.fatigue = _fatigue_rows(case, damages, pd)
    result.excursions = pd.DataFrame(columns=EXCURSION_COLUMNS)


def design(case: Case, output: str | Path | None = None, progress: Callable[[str], None] | None = None,
           scheduler=None, workers: int | None = None,
           spectral_analysis: SpectralAnalysis | None = None) -> DesignResult:
    """Check a mooring against its design block (module docstring).

    Parameters
    ----------
    case : kanat.model.Case
        A lumped-model mooring case with a ``design`` block.
    output : path-like, optional
        Folder for the runs' result files (``runs/``, :mod:`.runs`); None: a temporary folder,
        deleted once the tables are made.
    progress : callable, optional
        ``progress(message)`` after each run.
    scheduler : str or distributed.Client, optional
        Where the runs go: None or ``serial`` in this process, a Dask scheduler address or
        file, or a client (:func:`kanat.sweep.execution.execute`).
    workers : int, optional
        A local pool of this many worker processes.
    spectral_analysis : callable, optional
        ``analysis(case) -> {cable: LineSpectra}`` for ``analysis: frequency``
        (:mod:`.spectral_check`); needed by that analysis.

    Returns
    -------
    DesignResult
        ``utilisation`` and ``fatigue`` DataFrames, the failures, statics and run files.
    """
    import tempfile

    import pandas as pd

    check_supported(case, spectral_analysis)
    result = DesignResult(None, None, case=case)
    if case.design.analysis == "quasi-static":
        _quasi_static_tables(case, result, progress, pd)
        return result
    if case.design.analysis == "frequency":
        _spectral_tables(case, result, spectral_analysis or spectral_check.frequency_domain, progress, pd)
        return result
    with tempfile.TemporaryDirectory(prefix="kanat-design-") as scratch:
        folder = Path(output) if output is not None else Path(scratch)
        jobs, failed = _jobs(case, folder, result)
        failures, result.engine = run_jobs(jobs, scheduler, workers, progress)
        _tables(case, jobs, failed, failures, result, pd)
        if output is None:
            result.runs = {}
    return result


def write_tables(result: DesignResult, output: str | Path) -> list[Path]:
    """``utilisation.csv`` and ``fatigue.csv`` in the folder ``output``; their paths."""
    output = Path(output)
    output.mkdir(parents=True, exist_ok=True)
    paths = [output / "utilisation.csv", output / "fatigue.csv"]
    result.utilisation.to_csv(paths[0], index=False)
    result.fatigue.to_csv(paths[1], index=False)
    return paths
