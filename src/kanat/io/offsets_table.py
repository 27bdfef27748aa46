"""The offset curve of a moored vessel (:mod:`kanat.statics.offsets`) as a :class:`ResultTable`.

Variables: ``offset`` [m] (the coordinate), ``restoring_force(offset, xyz)`` [N] and
``restoring_moment(offset, xyz)`` [N m] (the lines' force on the vessel and its moment about
the vessel's moved origin), ``end_tension(offset, cable, end)`` [N] at each cable's ``from``
and ``to`` ends; the attribute ``direction_deg``. ``kanat offsets -o FILE`` writes it to
netCDF, or to CSV (one row per offset) for a ``.csv`` file.
"""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from kanat.io.provenance import provenance
from kanat.io.result_table import ResultTable
from kanat.io.statics_table import XYZ, _label

__all__ = ["offsets_table", "write_offsets_csv"]

ENDS = ("from", "to")


def offsets_table(curve, case, wall_time_s: float = 0.0) -> ResultTable:
    """The table of an :class:`~kanat.statics.offsets.OffsetCurve` of ``case``."""
    attrs = provenance(case, model="statics", scheme="offsets", wall_time_s=wall_time_s, status="ok",
                       direction_deg=float(curve.direction_deg))
    v = {
        "offset": (("offset",), np.asarray(curve.offset, dtype=float),
                   {"units": "m", "long_name": f"horizontal offset of the vessel along {curve.direction_deg:g} deg"}),
        "xyz": _label("xyz", XYZ),
        "cable": _label("cable", curve.cables),
        "end": _label("end", ENDS),
        "restoring_force": (("offset", "xyz"), np.asarray(curve.force, dtype=float),
                            {"units": "N", "long_name": "force of the lines on the vessel"}),
        "restoring_moment": (("offset", "xyz"), np.asarray(curve.moment, dtype=float),
                             {"units": "N m", "long_name": "moment of the lines' force about the vessel's origin"}),
        "end_tension": (("offset", "cable", "end"), np.asarray(curve.tension, dtype=float),
                        {"units": "N", "long_name": "tension at each cable's from and to ends"}),
    }
    return ResultTable(v, ("offset", "xyz", "cable", "end"), attrs)


def write_offsets_csv(curve, path) -> Path:
    """One row per offset: ``offset``, ``restoring_force_x/y/z``, ``restoring_moment_x/y/z`` and
    ``tension_<cable>_from``/``_to`` (SI units)."""
    path = Path(path)
    head = ["offset", *(f"restoring_force_{c}" for c in XYZ), *(f"restoring_moment_{c}" for c in XYZ),
            *(f"tension_{cable}_{end}" for cable in curve.cables for end in ENDS)]
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(head)
        for k, d in enumerate(curve.offset):
            writer.writerow([repr(float(x)) for x in (d, *curve.force[k], *curve.moment[k],
                                                        *np.ravel(curve.tension[k]))])
    return path
