"""What the study benchmarks share: a study case written from an example with its sea-state table
beside it, the ``kanat`` command as a user types it, and one fresh process timed as a whole.

Used by ``bench_design_study.py``, ``bench_fatigue_frequency.py`` and ``bench_sweep.py``.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import yaml

from fatigue_scatter import SeaStateCell, sea_state_table

SEA_STATES = "sea_states.csv"     # the ``design.sea_states`` table, beside the case


def kanat_command() -> list[str]:
    """The installed ``kanat`` script (as a user runs it), else ``python -m kanat``."""
    script = shutil.which("kanat") or str(Path(sys.executable).with_name("kanat"))
    return [script] if Path(script).exists() else [sys.executable, "-m", "kanat"]


def timed_process(command: list[str], accepted: tuple[int, ...] = (0,)) -> dict:
    """Run ``command`` as a fresh process and time it whole.

    Returns
    -------
    dict
        ``wall`` [s]; ``cpu`` [s], user and system time of the process tree (its children included);
        ``load``, the 1-minute load average before it; ``stdout`` and ``stderr``.

    Raises
    ------
    RuntimeError
        The process exited with a code not in ``accepted``; the message holds its output.
    """
    load = os.getloadavg()[0]
    before = os.times()
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = os.times()
    if done.returncode not in accepted:
        raise RuntimeError(f"{' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return {"wall": wall, "cpu": cpu, "load": load, "stdout": done.stdout, "stderr": done.stderr}


def write_study(folder: Path, data: dict, cells: list[SeaStateCell], duration: float,
                name: str = "case.yaml") -> Path:
    """The case ``data`` (its ``design.sea_states`` naming ``SEA_STATES``) written as ``folder / name``,
    beside it ``cells`` as its sea states of ``duration`` s each."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / SEA_STATES).write_text(sea_state_table(cells, duration))
    path = folder / name
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path
