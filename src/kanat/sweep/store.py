"""A study on disk: its manifest, case files, results, per-case records and the summary.

Layout of a study directory::

    study.json            base case, varied keys and values, the case table
    cases/NAME.yaml       each variant's case file (run it alone with kanat run)
    results/NAME.nc       each case's result file (case-format.md)
    records/NAME.json     written when a case is finished (ok or failed): its status,
                          message, wall time and summary statistics
    summary.nc            one row per finished case (dimension ``case``): the varied
                          parameters (variables named by their key paths), ``name``,
                          ``status``, ``message`` and every summary statistic
                          (:func:`kanat.analysis.summary_statistics`)
    summary.csv           the same table for spreadsheets

A case is finished when its record exists; the summary is rewritten (atomically) from
the records each time one is added, so a killed study leaves a consistent summary of
what it finished, and resuming runs only the cases without a record.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from kanat.analysis.summary import statistic_units
from kanat.errors import KanatError
from kanat.io.results import write_result

MANIFEST = "study.json"
SUMMARY = "summary.nc"


def _atomic_text(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".part")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


class StudyStore:
    """The files of one study directory (module docstring)."""

    def __init__(self, root):
        self.root = Path(root).resolve()

    def case_file(self, name: str) -> Path:
        return self.root / "cases" / f"{name}.yaml"

    def result_file(self, name: str) -> Path:
        return self.root / "results" / f"{name}.nc"

    def checkpoint_file(self, name: str) -> Path:
        return self.root / "results" / f"{name}.nc.ckpt.npz"

    def record_file(self, name: str) -> Path:
        return self.root / "records" / f"{name}.json"

    def prepare(self, plan) -> None:
        """Create the directory for ``plan``, or check that it holds the same study.

        Raises
        ------
        KanatError
            When the directory holds a different study (another base case or other values).
        """
        manifest = plan.manifest()
        path = self.root / MANIFEST
        if path.exists():
            old = json.loads(path.read_text(encoding="utf-8"))
            if old.get("base_sha256") != manifest["base_sha256"] or old.get("vary") != _jsonable(manifest["vary"]):
                raise KanatError(f"{self.root} holds another study (base case {old.get('base_case')}, varying "
                                 f"{', '.join(old.get('vary', {}))}); give a new output directory or delete that one")
        for sub in ("cases", "results", "records"):
            (self.root / sub).mkdir(parents=True, exist_ok=True)
        _atomic_text(path, json.dumps(_jsonable(manifest), indent=1))
        for case in plan.cases:
            target = self.case_file(case.name)
            if not target.exists():
                _atomic_text(target, case.text)

    def finished(self) -> dict:
        """Records of the finished cases by name."""
        out = {}
        for path in sorted((self.root / "records").glob("*.json")):
            try:
                out[path.stem] = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                continue                                   # never written whole: not finished
        return out

    def record(self, record: dict) -> None:
        """Write one finished case's record."""
        _atomic_text(self.record_file(record["name"]), json.dumps(_jsonable(record), indent=1))

    def write_summary(self, plan) -> xr.Dataset:
        """Rewrite ``summary.nc`` and ``summary.csv`` from the records (case order)."""
        records = self.finished()
        rows = [records[c.name] for c in plan.cases if c.name in records]
        ds = summary_dataset(rows, plan.keys, plan.base)
        write_result(ds, self.root / SUMMARY)
        frame = ds.to_dataframe()
        _atomic_text(self.root / "summary.csv", frame.to_csv())
        return ds


def _jsonable(value):
    """JSON-safe copy (NumPy scalars to Python, NaN to None)."""
    if isinstance(value, dict):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not np.isfinite(value):
        return None
    return value


def _column(values: list):
    """A summary column: floats where every value is a number, else text."""
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) or v is None for v in values):
        return np.array([np.nan if v is None else float(v) for v in values])
    return np.array(["" if v is None else str(v) for v in values], dtype=object)


def summary_dataset(rows: list, keys: list, base: str = "") -> xr.Dataset:
    """The summary table of finished case records.

    Parameters
    ----------
    rows : list of dict
        Records (``index``, ``name``, ``parameters``, ``status``, ``message``,
        ``statistics``), in case order.
    keys : list of str
        The varied key paths.
    base : str
        Base case, kept as an attribute.

    Returns
    -------
    xarray.Dataset
        Dimension ``case`` (coordinate: the case index).
    """
    stats = list(dict.fromkeys(name for r in rows for name in r.get("statistics", {})))
    data = {"name": ("case", np.array([r["name"] for r in rows], dtype=object))}
    for key in keys:
        data[key] = ("case", _column([r["parameters"].get(key) for r in rows]), {"long_name": f"varied: {key}"})
    data["status"] = ("case", np.array([r["status"] for r in rows], dtype=object))
    data["message"] = ("case", np.array([r.get("message", "") for r in rows], dtype=object))
    for name in stats:
        data[name] = ("case", _column([r.get("statistics", {}).get(name) for r in rows]),
                      {"units": statistic_units(name)})
    ds = xr.Dataset(data, coords={"case": ("case", np.array([r["index"] for r in rows], dtype=int))},
                    attrs={"base_case": base, "parameters": json.dumps(keys), "statistics": json.dumps(stats),
                           "cases_ok": sum(r["status"] == "ok" for r in rows),
                           "cases_failed": sum(r["status"] != "ok" for r in rows)})
    return ds


def read_summary(path) -> tuple[xr.Dataset, list, list]:
    """Read a study's summary: the dataset, its varied keys and its statistic names.

    Parameters
    ----------
    path : path-like
        The study directory or its ``summary.nc``.
    """
    path = Path(path)
    if path.is_dir():
        path = path / SUMMARY
    if not path.exists():
        raise KanatError(f"{path} does not exist: not a study directory (run kanat sweep first)")
    from kanat.io.results import read_result

    ds = read_result(path)
    return ds, json.loads(ds.attrs.get("parameters", "[]")), json.loads(ds.attrs.get("statistics", "[]"))


def summary_frame(ds: xr.Dataset) -> pd.DataFrame:
    """The summary as a pandas table indexed by case."""
    return ds.to_dataframe()
