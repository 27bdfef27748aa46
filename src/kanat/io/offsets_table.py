"""The offset curve of a moored vessel (:mod:`kanat.statics.offsets`) as a :class:`ResultTable`.

Variables: ``offset`` [m] (the coordinate), ``restoring_force(offset, xyz)`` [N] and
``restoring_moment(offset, xyz)`` [N m] (the lines' force on the vessel and its moment about
the vessel's moved origin), ``end_tension(offset, cable, end)`` [N] at each cable's ``from``
and ``to`` ends; the attribute ``direction_deg``. A case with several coupled bodies adds each
body's own curve, that body moved alone (:func:`kanat.statics.offsets.body_offset_curves`), along
``body``: ``body_restoring_force(body, offset, xyz)`` [N], ``body_restoring_moment(body, offset,
xyz)`` [N m] about the body's moved reference point and ``body_end_tension(body, offset, cable,
end)`` [N]. ``kanat offsets -o FILE`` writes it to netCDF, or to CSV (one row per offset) for a
``.csv`` file.
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


def offsets_table(curve, case, wall_time_s: float = 0.0, bodies=None) -> ResultTable:
    """The table of an :class:`~kanat.statics.offsets.OffsetCurve` of ``case``, with each coupled
    body's own curve in ``bodies`` (dict of body name to ``OffsetCurve``, module docstring)."""
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
    labels = ("offset", "xyz", "cable", "end")
    if bodies:
        labels += ("body",)
        v["body"] = _label("body", list(bodies))
        v.update(_body_curves(list(bodies.values())))
    return ResultTable(v, labels, attrs)


def _body_curves(curves: list) -> dict:
    """The variables of each body's own curve, stacked along ``body``."""
    return {
        "body_restoring_force": (("body", "offset", "xyz"), np.array([c.force for c in curves], dtype=float),
                                 {"units": "N",
                                  "long_name": "force of the lines on each body, that body alone offset"}),
        "body_restoring_moment": (("body", "offset", "xyz"), np.array([c.moment for c in curves], dtype=float),
                                  {"units": "N m", "long_name": "moment of the lines' force about each body's moved "
                                   "reference point, that body alone offset"}),
        "body_end_tension": (("body", "offset", "cable", "end"), np.array([c.tension for c in curves], dtype=float),
                             {"units": "N", "long_name": "tension at each cable's from and to ends, each body alone "
                              "offset"}),
    }


def write_offsets_csv(curve, path, bodies=None) -> Path:
    """One row per offset: ``offset``, ``restoring_force_x/y/z``, ``restoring_moment_x/y/z`` and
    ``tension_<cable>_from``/``_to``, then for each body of ``bodies`` (as :func:`offsets_table`
    takes them) ``<body>_restoring_force_x/y/z`` and ``<body>_restoring_moment_x/y/z`` of that
    body alone offset (SI units)."""
    path = Path(path)
    bodies = bodies or {}
    head = ["offset", *(f"restoring_force_{c}" for c in XYZ), *(f"restoring_moment_{c}" for c in XYZ),
            *(f"tension_{cable}_{end}" for cable in curve.cables for end in ENDS),
            *(f"{body}_restoring_{what}_{c}" for body in bodies for what in ("force", "moment") for c in XYZ)]
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(head)
        for k, d in enumerate(curve.offset):
            own = [x for body in bodies.values() for x in (*body.force[k], *body.moment[k])]
            writer.writerow([repr(float(x)) for x in (d, *curve.force[k], *curve.moment[k],
                                                        *np.ravel(curve.tension[k]), *own)])
    return path
