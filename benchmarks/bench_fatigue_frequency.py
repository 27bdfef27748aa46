"""Fatigue assessment over a scatter diagram: frequency domain against time domain (issue 26).

The mooring is ``examples/design/quasi_static.yaml`` (a vessel on three 620 m legs of 76 mm
studless R3 chain in 120 m of water, fairleads moved by the displacement RAOs of ``raos.csv``),
checked intact with fatigue on API's studless chain T-N curve. The sea states are a scatter
diagram of ``--sea-states`` cells written from the DNV-RP-C205 Weibull-lognormal Hs-Tp model
(``fatigue_scatter.py``: Hs x Tp x heading classes with their probabilities, summing to 1).

Each analysis runs as a user runs it, ``kanat design CASE -o DIR --scheduler serial`` in a fresh
process (whole-process wall and CPU time, the load average before it):

1. ``design.analysis: frequency`` over all ``--sea-states`` cells (the assessment);
2. ``design.analysis: frequency`` over the ``--time-sea-states`` cells the time domain runs
   (evenly spread through the diagram), to put the two domains' lives side by side;
3. ``design.analysis: dynamic`` over the same cells, ``--seeds`` seeds of ``--duration`` s each
   (a signed assessment runs 3-hour storms, 10,800 s), rainflow-counted.

The time domain's cost per sea state (per simulated second) is measured on the subset and
extrapolated, **as an extrapolation**, to ``--sea-states`` x 10,800 s x ``--seeds`` (the cost counts
the simulated time the run files cover: a run that fails stops early, and it is listed, since
``kanat design`` leaves it out of the time domain's fatigue table); the ratio
is that extrapolation over the frequency domain's measured wall time. Fatigue lives per line
(the shortest along the line) are printed side by side for the subset, and with several seeds
the time domain's own spread over seeds (each seed's record alone, same weights).

Run small on a loaded machine, e.g. ``--sea-states 10 --time-sea-states 3 --duration 1800``;
the full one is ``--sea-states 100 --time-sea-states 100 --duration 10800 --seeds 3`` (hours).
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fatigue_scatter import scatter_diagram  # noqa: E402
from studies import SEA_STATES, kanat_command, timed_process, write_study  # noqa: E402

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "design" / "quasi_static.yaml"
STORM = 10800.0     # s: a signed assessment's storm length


def write_case(folder: Path, analysis: str, cells, duration: float, seeds: int, ramp: float) -> Path:
    """The example, intact only with fatigue, in ``analysis``, over ``cells``, in ``folder``."""
    data = yaml.safe_load(EXAMPLE.read_text())
    data["design"] = {"standard": "api-rp-2sk", "analysis": analysis, "sea_states": SEA_STATES,
                      "storm_duration": STORM, "conditions": ["intact"], "extremes": "rayleigh",
                      "fatigue": {"curve": "api-chain-studless", "design_life": 25}}
    if analysis == "dynamic":
        data["design"]["seeds"] = seeds
        data["environment"]["waves"].update(seed=1, ramp=ramp)
    path = write_study(folder, data, cells, duration)
    shutil.copy(EXAMPLE.parent / "raos.csv", folder / "raos.csv")
    return path


def run_design(case: Path, out: Path) -> dict:
    """One ``kanat design`` process: wall and CPU time, load before, its fatigue table."""
    command = kanat_command() + ["design", str(case), "-o", str(out), "--scheduler", "serial"]
    timed = timed_process(command, accepted=(0, 3, 4))      # 3: a check fails, 4: a run failed (listed below)
    if not (out / "fatigue.csv").exists():
        raise RuntimeError(f"{' '.join(command)} wrote no fatigue table:\n{timed['stdout']}\n{timed['stderr']}")
    return {**timed, "fatigue": pd.read_csv(out / "fatigue.csv")}


def simulated(out: Path) -> tuple[float, list[str]]:
    """The simulated time the time domain's run files under ``out`` cover [s], and the runs that
    did not end ``ok`` (name: status): ``kanat design`` leaves those out of its fatigue table."""
    import kanat

    total, failed = 0.0, []
    for path in sorted((out / "runs").rglob("*.nc")):
        with kanat.read_result(path) as ds:
            total += float(ds.time.values[-1]) if ds.sizes.get("time") else 0.0
            if ds.attrs["status"] != "ok":
                failed.append(f"{path.parent.name}/{path.stem}: {ds.attrs['status']}")
    return total, failed


def line_lives(fatigue: pd.DataFrame) -> pd.Series:
    """Shortest fatigue life along each line [years]."""
    return fatigue.groupby("line")["life_years"].min()


def kept_run(out: Path, loaded, sea_state, k: int):
    """Seed ``k``'s run of ``sea_state`` under ``out``, analysed as the design analyses it (its
    attributes, ``status`` among them, kept)."""
    import kanat
    from kanat.design_checks import records
    from kanat.design_checks.conditions import sea_state_case, wave_seed

    run = kanat.read_result(out / "runs" / "intact" / f"{sea_state.name}_seed{k}.nc").load()
    return records.analysed(run, sea_state_case(loaded, sea_state, wave_seed(loaded, k)))


def seed_lives(out: Path, case: Path, seeds: int) -> pd.DataFrame:
    """Each seed's lives per line, from the kept runs, as the design weights them."""
    import kanat
    from kanat.design_checks.check import annual_damage

    loaded = kanat.load_case(case)
    found = {}
    for k in range(seeds):
        total: dict[str, float] = {}
        for sea_state in loaded.design.sea_state_rows:
            for line, damage in annual_damage(loaded, sea_state, [kept_run(out, loaded, sea_state, k)]).items():
                total[line] = total.get(line, np.zeros_like(damage)) + damage
        found[f"seed {k}"] = {line: 1.0 / float(np.max(d)) for line, d in total.items()}
    return pd.DataFrame(found)


def cell_damage(args: argparse.Namespace, subset: list, dyn_case: Path, scratch: Path) -> pd.DataFrame:
    """Per cell of ``subset`` and line, the largest annual damage along the line in each domain
    [1/year]: the frequency domain's from a one-cell ``kanat design`` of that cell (not timed), the
    time domain's from its kept runs over all seeds, weighted as the design weights them."""
    import kanat
    from kanat.design_checks.check import annual_damage

    loaded = kanat.load_case(dyn_case)
    rows = []
    for cell, sea_state in zip(subset, loaded.design.sea_state_rows):
        folder = scratch / f"frequency_{sea_state.name}"
        frequency = run_design(write_case(folder, "frequency", [cell], STORM, 1, args.ramp), folder / "out")
        fd = frequency["fatigue"].groupby("line")["damage_per_year"].max()
        runs = [kept_run(scratch / "dynamic" / "out", loaded, sea_state, k) for k in range(args.seeds)]
        runs = [run for run in runs if run.attrs["status"] == "ok"]
        td = {line: float(np.max(d)) for line, d in annual_damage(loaded, sea_state, runs).items()} if runs else {}
        for line in fd.index:
            rows.append({"cell": f"{sea_state.name} Hs {cell.hs:.3g} m Tp {cell.tp:.4g} s {cell.heading_deg:g} deg",
                         "line": line, "frequency": fd[line], "time": td.get(line, np.nan),
                         "seeds ok": len(runs)})
    table = pd.DataFrame(rows)
    table["time / frequency"] = table["time"] / table["frequency"]
    return table


def markdown(table: pd.DataFrame) -> str:
    """``table`` as a markdown table, numbers to 4 significant digits."""
    rows = ["| line | " + " | ".join(table.columns) + " |", "|---" * (len(table.columns) + 1) + "|"]
    rows += [f"| {index} | " + " | ".join(f"{v:.4g}" for v in row) + " |" for index, row in table.iterrows()]
    return "\n".join(rows)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sea-states", type=int, default=100, help="cells of the scatter diagram")
    parser.add_argument("--time-sea-states", type=int, default=3, help="cells the time domain runs")
    parser.add_argument("--duration", type=float, default=1800.0, help="simulated s per time-domain run")
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--ramp", type=float, default=60.0, help="s: waves ramped in (time domain)")
    parser.add_argument("--keep", type=Path, help="keep the cases and outputs in this folder")
    args = parser.parse_args()
    cells = scatter_diagram(args.sea_states)
    picked = np.unique(np.linspace(0, len(cells) - 1, args.time_sea_states).round().astype(int))
    if args.keep is not None:
        assess(args, cells, picked, args.keep)
        return
    with tempfile.TemporaryDirectory(prefix="kanat-bench-fatigue-") as scratch:
        assess(args, cells, picked, Path(scratch))


def assess(args: argparse.Namespace, cells: list, picked: np.ndarray, scratch: Path) -> None:
    """Run the three design processes in ``scratch`` and print the tables."""
    subset = [cells[k] for k in picked]
    full = run_design(write_case(scratch / "frequency", "frequency", cells, STORM, 1, args.ramp),
                      scratch / "frequency" / "out")
    part = run_design(write_case(scratch / "frequency_subset", "frequency", subset, STORM, 1, args.ramp),
                      scratch / "frequency_subset" / "out")
    dyn_case = write_case(scratch / "dynamic", "dynamic", subset, args.duration, args.seeds, args.ramp)
    dyn = run_design(dyn_case, scratch / "dynamic" / "out")
    covered, failed = simulated(scratch / "dynamic" / "out")
    per_second = dyn["wall"] / covered
    extrapolated = per_second * args.sea_states * STORM * args.seeds
    print(f"scatter diagram: {args.sea_states} cells (DNV-RP-C205 Weibull-lognormal), probability sum "
          f"{sum(c.probability for c in cells):.12f}; time domain on cells {picked.tolist()}, "
          f"{args.seeds} seed(s) x {args.duration:g} s; {os.cpu_count()} cores\n")
    print("| analysis, whole process | sea states | wall [s] | CPU [s] | per sea state [s] | load before |"
          "\n|---|---|---|---|---|---|")
    for name, r, n in (("frequency, all cells", full, args.sea_states), ("frequency, subset", part, len(subset)),
                       (f"dynamic, {args.seeds} seed(s) x {args.duration:g} s", dyn, len(subset))):
        print(f"| {name} | {n} | {r['wall']:.1f} | {r['cpu']:.1f} | {r['wall'] / n:.2f} | {r['load']:.2f} |")
    if failed:
        print("\nTIME-DOMAIN RUNS THAT FAILED (left out of the time domain's lives below, which then do not "
              "compare with the frequency domain's):\n" + "\n".join(f"- {line}" for line in failed))
    print(f"\ntime domain: {covered:g} s simulated, {per_second * 3600:.0f} s wall per simulated hour "
          f"(measured); "
          f"EXTRAPOLATED full assessment ({args.sea_states} x {STORM:g} s x {args.seeds} seed(s)): "
          f"{extrapolated:.0f} s = {extrapolated / 3600:.1f} h; ratio to the frequency domain's "
          f"{full['wall']:.1f} s: {extrapolated / full['wall']:.0f}x (extrapolated)\n")
    lives = pd.DataFrame({"frequency (Dirlik)": line_lives(part["fatigue"]),
                          "time domain (rainflow)": line_lives(dyn["fatigue"])})
    lives["time / frequency"] = lives.iloc[:, 1] / lives.iloc[:, 0]
    if args.seeds > 1:
        lives = lives.join(seed_lives(scratch / "dynamic" / "out", dyn_case, args.seeds))
    print(f"fatigue lives [years] on the {len(subset)}-cell subset (weights as in the diagram):\n")
    print(markdown(lives))
    damage = cell_damage(args, subset, dyn_case, scratch)
    print("\nlargest annual damage along each line, per cell (frequency: the cell's own frequency-domain "
          "design; time: its runs' rainflow, seeds averaged):\n")
    print("| cell | line | frequency [1/y] | time [1/y] | time / frequency | seeds ok |\n|---|---|---|---|---|---|")
    for _, r in damage.iterrows():
        print(f"| {r['cell']} | {r['line']} | {r['frequency']:.4g} | {r['time']:.4g} | {r['time / frequency']:.3g} "
              f"| {r['seeds ok']} |")
    print(f"\nfrequency domain, all {args.sea_states} cells: "
          + ", ".join(f"{k} {v:.4g} y" for k, v in line_lives(full["fatigue"]).items()))
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
