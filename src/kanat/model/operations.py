"""Prescribed operations: the vessel's motion about its track (``vessel.motion``) and the
winch on the first cable (``winch``).

``vessel.motion`` is written either as a list of harmonics
(``[{dof: surge, amplitude: 10.0, period: 27.0, phase_deg: 0}, ...]``) or as a table
(``{table: motion.csv}``, columns ``time, surge, sway, heave, roll, pitch, yaw``). To ramp it
up, write the harmonics as a mapping: ``{harmonics: [...], ramp: 20.0}`` (or ``{table:
motion.csv, ramp: 20.0}``): the displacement is multiplied by the half cosine of
:mod:`kanat.physics.ramp` and its velocity follows (``r q_dot + r' q``). The
table's file is read when the case is loaded (:mod:`kanat.io.tables`), so the model holds
its numbers (``rows``), never a file for a solver to open; rows may also be written inline.
:func:`kanat.physics.motion.vessel_motion` turns either form into the 6-DOF displacement
and velocity at a time.

Degrees of freedom are in vessel axes (x forward, y port, z up): surge, sway, heave [m]
along x, y, z; roll, pitch, yaw [deg] turning right-handed about x, y, z (roll: starboard
down; pitch: bow down; yaw: bow to port). A harmonic is
``amplitude * sin(2 pi t / period + phase)``.
"""
from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Field, field_validator, model_validator

from ._base import KanatModel, fmt, quantity

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
"""The six degrees of freedom, in this order everywhere (tables, arrays)."""
TABLE_COLUMNS = ("time", *DOFS)
"""Columns of a motion table: time [s], surge, sway, heave [m], roll, pitch, yaw [deg]."""

Dof = Literal["surge", "sway", "heave", "roll", "pitch", "yaw"]


class HarmonicMotion(KanatModel):
    """One harmonic of the vessel's motion, ``amplitude * sin(2 pi t / period + phase)``."""

    dof: Dof = Field(description="degree of freedom in vessel axes: surge, sway, heave (along "
                                 "x forward, y port, z up) or roll, pitch, yaw (right-handed "
                                 "about x, y, z)")
    amplitude: float = quantity(unit="m or deg", ge=0,
                                description="amplitude: m for surge, sway, heave; deg for roll, "
                                            "pitch, yaw")
    period: float = quantity(unit="s", gt=0, description="period of the harmonic")
    phase_deg: float = quantity(0.0, unit="deg", description="phase at t = 0 (0: the motion "
                                                             "starts at zero, rising)")


def _as_table_row(value: Any) -> Any:
    if not isinstance(value, (list, tuple)) or len(value) != len(TABLE_COLUMNS):
        got = f"{len(value)} values" if isinstance(value, (list, tuple)) else repr(value)
        raise ValueError(f"each motion row must be {len(TABLE_COLUMNS)} numbers "
                         f"[{', '.join(TABLE_COLUMNS)}] (got {got})")
    return tuple(value)


TableRow = Annotated[tuple[float, float, float, float, float, float, float],
                     BeforeValidator(_as_table_row)]
RaoRow = tuple[float, float, Dof, float, float]
"""A displacement RAO: ``(omega [rad/s], heading_deg, dof, amplitude [m/m or deg/m], phase_deg)``."""


def _written_form(value: Any) -> Any:
    """``[harmonic, ...]`` -> ``{harmonics: [...]}``; mappings and models pass."""
    if isinstance(value, (list, tuple)):
        return {"harmonics": list(value)}
    return value


class VesselMotion(KanatModel):
    """Prescribed motion of the vessel about its track: harmonics, a table or RAOs (one of them).

    Attributes
    ----------
    harmonics : tuple of HarmonicMotion
        Written as the list itself (``motion: [{dof: surge, ...}]``).
    table : str or None
        File the rows were read from (for messages; solvers never open it).
    rows : tuple of (time, surge, sway, heave, roll, pitch, yaw) or None
        [s, m, m, m, deg, deg, deg], time strictly increasing. Before the first and after
        the last row the motion holds the end values.
    rao : str or None
        File of displacement RAOs (:mod:`kanat.io.raos`; for messages: solvers never open it).
    rao_rows : tuple of RaoRow or None
        The RAOs, read from ``rao`` when the case is loaded.
    ulen : float
        WAMIT's length scale of a ``.4`` file's rotations [m].
    ramp : float
        Start-up ramp [s] (0: none).
    """

    harmonics: tuple[HarmonicMotion, ...] = Field(
        (), description="harmonics, written as the list itself: motion: [{dof, amplitude, "
                        "period, phase_deg}, ...]")
    table: str | None = Field(
        None, description="CSV file with columns time, surge, sway, heave, roll, pitch, yaw "
                          "(s, m, deg), relative to the case file; read when the case is "
                          "loaded")
    rows: tuple[TableRow, ...] | None = quantity(
        None, unit="s, m, deg", description="the table's rows [time, surge, sway, heave, roll, "
                                            "pitch, yaw] (read from 'table', or written inline)")
    rao: str | None = Field(
        None, description="file of displacement RAOs applied to the case's sea (first-order motion at "
                          "zero forward speed): a CSV table with columns omega [rad/s], heading_deg, dof, "
                          "amplitude [m/m or deg/m], phase_deg (motion = amplitude x wave amplitude x "
                          "cos(omega t - phase) for the wave crest at the vessel origin at t = 0), a WAMIT "
                          ".4 file or a Capytaine .nc dataset; relative to the case file")
    rao_rows: tuple[RaoRow, ...] | None = Field(
        None, description="the RAOs' rows (omega, heading_deg, dof, amplitude, phase_deg), read from 'rao'")
    ulen: float = quantity(1.0, unit="m", gt=0,
                           description="WAMIT's length scale ULEN of a .4 RAO file (its rotations are "
                                       "xi ULEN / A)")
    ramp: float = quantity(0.0, unit="s", ge=0,
                           description="start-up ramp [s] (needs the mapping form: {harmonics: [...], ramp: T} "
                                       "or {table: F, ramp: T}): the half cosine r(t) = (1 - cos(pi t / ramp)) "
                                       "/ 2 for t < ramp, 1 after, multiplies the displacement (the velocity "
                                       "is its derivative, r v + r' q); 0: none")

    @model_validator(mode="before")
    @classmethod
    def _form(cls, value: Any) -> Any:
        return _written_form(value)

    @field_validator("rows")
    @classmethod
    def _increasing(cls, rows: tuple | None) -> tuple | None:
        if rows is None:
            return None
        if len(rows) < 2:
            raise ValueError("a motion table needs at least 2 rows")
        times = [r[0] for r in rows]
        bad = next((i for i in range(1, len(times)) if times[i] <= times[i - 1]), None)
        if bad is not None:
            raise ValueError(f"time must increase from row to row (row {bad + 1}: "
                             f"{fmt(times[bad])} s after {fmt(times[bad - 1])} s)")
        return rows

    @model_validator(mode="after")
    def _one_form(self) -> VesselMotion:
        given = [name for name, used in (("harmonics", bool(self.harmonics)), ("a table", self.rows is not None),
                                          ("RAOs", self.rao_rows is not None)) if used]
        if len(given) > 1:
            raise ValueError(f"give either harmonics (a list), a table or RAOs, not {' and '.join(given)}")
        if self.rao is not None and self.rao_rows is None:
            raise ValueError(f"the RAO file '{self.rao}' was not read; load the case with "
                             "kanat.io.load_case, which reads it next to the case file")
        if self.table is not None and self.rows is None:
            raise ValueError(f"the table '{self.table}' was not read; load the case with "
                             "kanat.io.load_case, which reads it next to the case file")
        return self

    @property
    def is_used(self) -> bool:
        """True when the vessel moves about its track."""
        return bool(self.harmonics) or self.rows is not None or self.rao_rows is not None


class WinchStep(KanatModel):
    """Pay-out (positive ``rate``) or haul-in (negative) of the first cable at its ``from``
    end, at a constant rate of unstretched length over ``[start, start + duration]``."""

    start: float = quantity(unit="s", ge=0, description="time the step starts")
    duration: float = quantity(unit="s", gt=0, description="how long it lasts")
    rate: float = quantity(unit="m/s", description="unstretched length paid out per second at "
                                                  "the first cable's 'from' end (negative: "
                                                  "hauled in)")

    @property
    def end(self) -> float:
        """``start + duration`` [s]."""
        return self.start + self.duration

    @property
    def change(self) -> float:
        """Length paid out over the step [m] (negative: hauled in)."""
        return self.rate * self.duration
