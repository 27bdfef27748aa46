"""What the pictures of a result share: cables, frames, fixed points and honest axis limits.

Every picture of :mod:`kanat.report.run_plot`, :mod:`kanat.report.statics_plot` and
:mod:`kanat.report.overview` draws from a result dataset (the names of
:mod:`kanat.io.schema`), never from a solver's objects, so a picture of a file read back
is the picture of the run. Geometry is projected on the coordinate planes only (x–z
elevation, x–y plan): a projection never mixes axes, so nothing is drawn where it is not.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MIN_HEIGHT_SPAN = 2.0
"""Least span of a height axis [m]: a body that moves by round-off stays a flat line."""
MIN_RELATIVE_SPAN = 0.05
"""Least span of a value axis as a fraction of the largest value drawn (tension, ...)."""
STILL = 1e-6
"""Relative motion of the tow point [of the system's size] below which it is at rest."""
KN = 1e3
"""N per kN: forces are drawn in kN."""


def cable_nodes(ds) -> dict[str, np.ndarray]:
    """Node indices of every cable, in order of ``s``, by cable name (order of the file)."""
    cable = np.asarray(ds["cable"].values).astype(str)
    return {name: np.nonzero(cable == name)[0] for name in dict.fromkeys(cable.tolist())}


def snapshot_indices(count: int, snapshots: int) -> np.ndarray:
    """``snapshots`` output indices spread evenly over ``count`` outputs, first and last included."""
    return np.unique(np.linspace(0, count - 1, max(1, min(snapshots, count))).round().astype(int))


def is_planar(ds) -> bool:
    """True when every node and body stays on y = 0 (to round-off of the system's size)."""
    y = np.abs(ds["position"].values[..., 1])
    size = max(float(np.ptp(ds["position"].values[..., [0, 2]])), 1.0)
    bodies = np.abs(ds["body_position"].values[..., 1]) if "body_position" in ds else np.zeros(1)
    return float(max(y.max(initial=0.0), bodies.max(initial=0.0))) <= 1e-9 * size


@dataclass(frozen=True)
class Frame:
    """The horizontal frame geometry is drawn in.

    Attributes
    ----------
    shift : ndarray, shape (k, 3)
        Subtracted from every position at each output: the tow point's horizontal position
        when it moves (a frame translating with it), else zero (the global frame).
    moving : bool
    """

    shift: np.ndarray
    moving: bool

    def label(self, axis: str) -> str:
        return f"{axis} − {axis}_tow [m]" if self.moving else f"{axis} [m]"


def tow_frame(ds) -> Frame:
    """A frame translating with the tow point when it moves, else the global frame."""
    count = ds.sizes.get("time", 1)
    vessel = ds["vessel_position"].values.reshape(count, 3) if "vessel_position" in ds else np.zeros((count, 3))
    size = max(float(np.ptp(ds["position"].values)), 1.0)
    moved = float(np.max(np.abs(vessel[:, :2] - vessel[0, :2]))) > STILL * size
    shift = np.zeros((count, 3))
    if moved:
        shift[:, :2] = vessel[:, :2]
    return Frame(shift, moved)


def embedded_case(ds):
    """The case embedded in the result (``case_yaml``), or None when it carries none or it
    does not load (a picture with less on it rather than none)."""
    text = ds.attrs.get("case_yaml")
    if not text:
        return None
    import warnings

    from kanat.api import load_case

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return load_case(str(text))
    except Exception:  # noqa: BLE001 - see the docstring
        return None


def speed_text(ds, speed: float) -> str:
    """A speed [m/s] written in the unit its case used (``6 kn`` for a case in knots, else m/s)."""
    case = embedded_case(ds)
    value, unit = case.vessel.speed_as_given(speed) if case is not None else (speed, "m/s")
    return f"{value:.3g} {unit}"


def fixed_points(ds) -> dict[str, np.ndarray]:
    """Anchors and the tow point of the case embedded in the result (``case_yaml``).

    Returns
    -------
    dict
        ``"anchor"``: positions, shape (a, 3); ``"depth"``: the seabed depth or NaN;
        ``"towed"``: whether a cable ends at the vessel. No anchors, no depth and towed when
        the result carries no case.
    """
    found = {"anchor": np.zeros((0, 3)), "depth": np.nan, "towed": True}
    case = embedded_case(ds)
    if case is None:
        return found
    anchors = [end.position for cable in case.cables for end in cable.ends if end.kind == "anchor"]
    found["anchor"] = np.array(anchors, dtype=float).reshape(-1, 3)
    found["depth"] = case.environment.depth if case.environment.depth is not None else np.nan
    found["towed"] = any(end.kind == "vessel" and end.offset is None for cable in case.cables for end in cable.ends)
    return found


def at_least(ax, axis: str, values, minimum: float = 0.0, relative: float = 0.0, pad: float = 0.05) -> None:
    """Set the ``axis`` ("x" or "y") limits of ``ax`` around ``values`` with a least span.

    The span is the data's range plus ``pad`` of it on each side, but at least ``minimum``
    and ``relative`` times the largest absolute value, centred on the data: a quantity that
    does not change is drawn as a flat line, not as noise blown up to fill the axis.
    """
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    if values.size == 0:
        return
    low, high = float(values.min()), float(values.max())
    span = max((high - low) * (1 + 2 * pad), minimum, relative * float(np.abs(values).max()))
    if span <= 0:
        span = 1.0
    centre = 0.5 * (low + high)
    getattr(ax, f"set_{axis}lim")(centre - span / 2, centre + span / 2)


def surface_and_seabed(ax, depth: float, z_low: float, z_span: float) -> None:
    """The mean free surface (z = 0) and, when the system comes near it, the seabed."""
    ax.axhline(0.0, color="tab:blue", lw=0.8, ls=":", zorder=0)
    if np.isfinite(depth) and -depth > z_low - 0.3 * max(z_span, 1.0):
        ax.axhline(-depth, color="saddlebrown", lw=2, label="seabed", zorder=0)
