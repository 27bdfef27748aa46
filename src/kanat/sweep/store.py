"""A study on disk: its manifest, case files, results, per-case records and the summary.

Layout of a study directory::

    study.json            base case, varied keys and values, the case table
    cases/NAME.yaml       each variant's case file (run it alone with kanat run)
    results/NAME.nc       each case's result file (case-format.md)
    records/NAME.json     written when a case is finished (ok or failed): its status,
                          message, wall and CPU time and summary statistics
    summary.nc            one row per finished case (dimension ``case``): the varied
                          parameters (variables named by their key paths), ``name``,
                          ``status``, ``message`` and every summary statistic
                          (:func:`kanat.analysis.summary_statistics`)
    summary.csv           the same table for spreadsheets

NAME is made by :func:`kanat.sweep.plan.case_name`: ``case`` and the case's index, then
a label of its values reduced to ``[A-Za-z0-9._=+-]`` and cut at
:data:`~kanat.sweep.plan.MAX_LABEL` characters, so no varied value can reach another
directory or clash with another case; :meth:`StudyStore.result_file` refuses any other
name. Readers find a case's files through the study's own table (``study.json``, by
index), never through a value from the summary.

A varied key that would take the name of a summary column (``name``, ``status``,
``message``, ``case``, a statistic) or holds a ``/`` is stored as ``vary:KEY`` (``/``
replaced by ``_``); ``parameters`` (variable names) and ``varied_keys`` (key paths), two
JSON lists in the summary's attributes, say which variable is which key.

A case is finished when its record exists; the summary is rewritten (atomically) from
the records each time one is added, so a killed study leaves a consistent summary of
what it finished, and resuming runs only the cases without a record. Every file is
written to a temporary name in its directory and renamed (:mod:`kanat.io.outputs`).
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import xarray as xr

from kanat.analysis.summary import statistic_units
from kanat.errors import KanatError
from kanat.io.outputs import atomic_path, remove_temporaries, write_text_atomic
from kanat.io.results import write_result

MANIFEST = "study.json"
SUMMARY = "summary.nc"
COLUMNS = ("case", "name", "status", "message")
"""The summary's own columns; a varied key never takes one of these names."""

SAFE_NAME = re.compile(r"case\d+(_[A-Za-z0-9._=+-]*)?")
"""Every case name (:func:`kanat.sweep.plan.case_name`); nothing else names a study file."""


def _atomic_text(path: Path, text: str) -> None:
    write_text_atomic(path, text)


def checked_name(name: str) -> str:
    """``name`` when it is a study case name (:data:`SAFE_NAME`), else a KanatError.

    A case name is one path component that cannot leave its directory (no ``/``, not
    ``.`` or ``..``), whatever a study file on disk says.
    """
    if not isinstance(name, str) or not SAFE_NAME.fullmatch(name) or len(name) > 200:
        raise KanatError(f"{name!r} is not the name of a study case (caseNNN_...); the study directory has been "
                         "edited or is not a kanat study")
    return name


class StudyStore:
    """The files of one study directory (module docstring)."""

    def __init__(self, root):
        self.root = Path(root).resolve()

    def case_file(self, name: str) -> Path:
        return self.root / "cases" / f"{checked_name(name)}.yaml"

    def result_file(self, name: str) -> Path:
        return self.root / "results" / f"{checked_name(name)}.nc"

    def checkpoint_file(self, name: str) -> Path:
        return self.root / "results" / f"{checked_name(name)}.nc.ckpt.npz"

    def record_file(self, name: str) -> Path:
        return self.root / "records" / f"{checked_name(name)}.json"

    def case_table(self) -> dict[int, str]:
        """Case index -> case name, from the study's own table (``study.json``).

        Raises
        ------
        KanatError
            When the table is missing or names a file outside the study's layout.
        """
        path = self.root / MANIFEST
        try:
            cases = json.loads(path.read_text(encoding="utf-8"))["cases"]
            return {int(c["index"]): checked_name(c["name"]) for c in cases}
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise KanatError(f"cannot read the case table of the study {self.root} ({path.name}): {error}") from None

    def prepare(self, plan) -> None:
        """Create the directory for ``plan``, or check that it holds the same study.

        Call it holding the study's :class:`~kanat.io.outputs.OutputLock`: it removes the
        temporary files a killed study left.

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
        for folder in (self.root, *(self.root / sub for sub in ("cases", "results", "records"))):
            remove_temporaries(folder)                    # a killed study's half-written files (we hold the lock)
        _atomic_text(path, json.dumps(_jsonable(manifest), indent=1))
        for case in plan.cases:
            target = self.case_file(case.name)
            if not target.exists():
                _atomic_text(target, case.text)

    def finished(self) -> dict:
        """Records of the finished cases by name (only files named like a case, holding their own name)."""
        out = {}
        for path in sorted((self.root / "records").glob("case*.json")):
            try:
                record = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                continue                                   # never written whole: not finished
            if isinstance(record, dict) and record.get("name") == path.stem and SAFE_NAME.fullmatch(path.stem):
                out[path.stem] = record
        return out

    def record(self, record: dict) -> None:
        """Write one finished case's record."""
        _atomic_text(self.record_file(record["name"]), json.dumps(_jsonable(record), indent=1))

    def write_summary(self, plan) -> xr.Dataset:
        """Rewrite ``summary.nc`` and ``summary.csv`` from the records (case order)."""
        records = self.finished()
        rows = [records[c.name] for c in plan.cases if c.name in records]
        ds = summary_dataset(rows, plan.keys, plan.base)
        with atomic_path(self.root / SUMMARY) as tmp:
            write_result(ds, tmp)
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


def parameter_variables(keys: list, reserved=()) -> dict[str, str]:
    """The summary variable of each varied key: the key path itself, or ``vary:KEY``.

    A key takes the ``vary:`` form (``/`` written ``_``) when its path is one of the
    summary's columns (:data:`COLUMNS`), one of ``reserved`` (the statistics), holds a
    ``/`` (not allowed in a netCDF name), or would repeat another key's variable.
    """
    taken = set(COLUMNS) | set(reserved)
    out = {}
    for key in keys:
        name = key if key not in taken and "/" not in key else "vary:" + key.replace("/", "_")
        while name in taken or name in out.values():
            name += "'"
        out[key] = name
        taken.add(name)
    return out


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
        Dimension ``case`` (coordinate: the case index); a varied key's variable is named
        by :func:`parameter_variables`.
    """
    names = list(dict.fromkeys(name for r in rows for name in r.get("statistics", {})))
    stat_names = {name: name.replace("/", "_") for name in names if name not in COLUMNS}   # a body named a/b
    stats = list(dict.fromkeys(stat_names.values()))
    variables = parameter_variables(keys, stats)
    data = {"name": ("case", np.array([r["name"] for r in rows], dtype=object))}
    for key in keys:
        data[variables[key]] = ("case", _column([r["parameters"].get(key) for r in rows]),
                                {"long_name": f"varied: {key}"})
    data["status"] = ("case", np.array([r["status"] for r in rows], dtype=object))
    data["message"] = ("case", np.array([r.get("message", "") for r in rows], dtype=object))
    for name, variable in stat_names.items():
        data[variable] = ("case", _column([r.get("statistics", {}).get(name) for r in rows]),
                          {"units": statistic_units(name)})
    ds = xr.Dataset(data, coords={"case": ("case", np.array([r["index"] for r in rows], dtype=int))},
                    attrs={"base_case": base, "parameters": json.dumps([variables[k] for k in keys]),
                           "varied_keys": json.dumps(keys), "statistics": json.dumps(stats),
                           "cases_ok": sum(r["status"] == "ok" for r in rows),
                           "cases_failed": sum(r["status"] != "ok" for r in rows)})
    return ds


def read_summary(path) -> tuple[xr.Dataset, list, list]:
    """Read a study's summary: the dataset, its varied parameters' variables and its statistic names.

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
