"""The coupled bodies of the MoorDyn file a case was read from, each with its points.

The importer (:mod:`kanat.io.moordyn`) makes every ``Coupled`` body's points fairleads of the
one kanat vessel (``{vessel: [x, y, z]}`` at their places at t = 0). Statics and the coupling
API, which treat each coupled body as its own, read back here which fairlead is on which body:
a point at ``o`` in the axes of body ``b`` (reference point ``X_b``, angles ``theta_b``) is at::

    (1)  r = X_b + R(theta_b) o,    R = Rz(yaw) Ry(pitch) Rx(roll)

(MoorDyn's body orientation, :func:`kanat.io.moordyn_map.rotation`).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["CoupledBody", "coupled_bodies", "coupled_points", "moordyn_items"]


@dataclass(frozen=True, eq=False)
class CoupledBody:
    """A MoorDyn ``Coupled`` body.

    Attributes
    ----------
    name : str
        ``bodyN``, N its number in the file.
    position : ndarray, shape (3,)
        Its reference point at t = 0 [m].
    angles : ndarray, shape (3,)
        Roll, pitch, yaw at t = 0 [rad].
    offsets : ndarray, shape (p, 3)
        Its points in its own axes [m], in file order.
    points : ndarray, shape (p, 3)
        The same points in global axes at t = 0, eq. (1) [m].
    """

    name: str
    position: np.ndarray
    angles: np.ndarray
    offsets: np.ndarray
    points: np.ndarray


def moordyn_items(case):
    """The points and bodies by number of the MoorDyn file ``case`` was read from
    (:mod:`kanat.io.moordyn_map`), or None when it was not read from one."""
    source = getattr(case, "source", None)
    if not source or not Path(source).is_file():
        return None
    from kanat.io.moordyn_map import Reader, file_version, read_bodies, read_points
    from kanat.io.moordyn_text import looks_like_moordyn, split

    text = Path(source).read_text(errors="replace")
    if not looks_like_moordyn(text):
        return None
    reader = Reader(split(text), str(source), Path(source).parent)
    reader.version = file_version(reader)
    bodies = read_bodies(reader)
    return read_points(reader, bodies), bodies


def coupled_bodies(case) -> list[CoupledBody]:
    """The ``Coupled`` bodies of the MoorDyn file ``case`` was read from, in file order, each with
    its points (module docstring); empty for any other case."""
    from kanat.io.moordyn_map import rotation

    read = moordyn_items(case)
    if read is None:
        return []
    points, bodies = read
    out = []
    for number, body in bodies.items():
        if body.kind != "coupled":
            continue
        offsets = np.array([p.xyz for p in points.values() if p.kind == "body" and p.body == number],
                           float).reshape(-1, 3)
        X = np.asarray(body.xyz, float)
        out.append(CoupledBody(f"body{number}", X, np.radians(body.angles_deg), offsets,
                               X + offsets @ np.asarray(rotation(body.angles_deg)).T))
    return out


def coupled_points(case) -> list[tuple[str, np.ndarray]]:
    """``(pointN, xyz)`` of the ``Coupled``/``Vessel`` points of the MoorDyn file ``case`` was read from,
    in file order; empty for any other case."""
    read = moordyn_items(case)
    if read is None:
        return []
    points, _ = read
    return [(f"point{number}", np.asarray(p.xyz, float)) for number, p in points.items() if p.kind == "vessel"]
