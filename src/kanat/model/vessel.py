"""The towing vessel: tow point and track (case section ``vessel``).

A track is a list of segments executed in order, each written as a one-key mapping
(``{straight: {speed: 3.0, duration: 100}}``). Speeds may be given in m/s (``speed``,
``to_speed``) or in knots (``speed_kn``, ``to_speed_kn``), never both. Angles are in
degrees, positive to port (counter-clockwise seen from above).
"""
from __future__ import annotations

import math
from typing import Annotated, Any, ClassVar, Union

from pydantic import Discriminator, Field, Tag, computed_field, model_validator

from ._base import ZERO3, KanatModel, Vector3, fmt, quantity
from .operations import VesselMotion
from .problems import PitchModel

KNOT = 1852.0 / 3600.0
"""One knot in m/s: the international nautical mile (1852 m) per hour, exactly
``scipy.constants.knot`` (a test checks it), written out because importing
``scipy.constants`` costs 0.2 s of every ``kanat validate``."""


def _one_speed(speed: float | None, speed_kn: float | None, key: str) -> float | None:
    """Speed in m/s from the m/s or the knots key; error when both are given."""
    if speed is not None and speed_kn is not None:
        raise ValueError(f"give either '{key}' (m/s) or '{key}_kn' (knots), not both")
    return speed if speed_kn is None else speed_kn * KNOT


class TrackSegment(KanatModel):
    """Base of the track segments; ``KEY`` is the segment's name in the case file."""

    KEY: ClassVar[str] = ""

    @model_validator(mode="before")
    @classmethod
    def _unwrap(cls, value: Any) -> Any:
        if isinstance(value, dict) and len(value) == 1 and cls.KEY in value:
            inner = value[cls.KEY]
            return {} if inner is None else inner
        if isinstance(value, dict) and "kind" in value:
            return {k: v for k, v in value.items() if k != "kind"}
        return value

    @computed_field
    @property
    def kind(self) -> str:
        """Segment name as written in the case file (``straight``, ``turn``, ...)."""
        return self.KEY


class Straight(TrackSegment):
    """Straight run at constant speed; without a speed, the previous speed is kept."""

    KEY: ClassVar[str] = "straight"
    speed: float | None = quantity(None, unit="m/s", ge=0)
    speed_kn: float | None = quantity(None, unit="kn", ge=0)
    duration: float = quantity(unit="s", gt=0)

    @model_validator(mode="after")
    def _check(self) -> Straight:
        _one_speed(self.speed, self.speed_kn, "speed")
        return self

    @property
    def speed_ms(self) -> float | None:
        """Speed [m/s], or None to keep the previous one."""
        return _one_speed(self.speed, self.speed_kn, "speed")


class _ToSpeed(TrackSegment):
    """A segment that ends at a target speed given in m/s or knots."""

    to_speed: float | None = quantity(None, unit="m/s", ge=0)
    to_speed_kn: float | None = quantity(None, unit="kn", ge=0)

    @model_validator(mode="after")
    def _check_target(self) -> _ToSpeed:
        if _one_speed(self.to_speed, self.to_speed_kn, "to_speed") is None:
            raise ValueError("needs a target speed: 'to_speed' (m/s) or 'to_speed_kn' (knots)")
        return self

    @property
    def to_speed_ms(self) -> float:
        """Target speed [m/s]."""
        return _one_speed(self.to_speed, self.to_speed_kn, "to_speed")


class Accelerate(_ToSpeed):
    """Speed ramp at a constant rate toward ``to_speed``.

    ``acceleration`` is a magnitude; the speed rises or falls toward the target.
    With ``duration``, the segment lasts that long (holding the target speed once
    reached); without it, the segment ends when the target is reached.
    """

    KEY: ClassVar[str] = "accelerate"
    acceleration: float = quantity(unit="m/s^2", gt=0)
    duration: float | None = quantity(None, unit="s", gt=0)


class SpeedStep(_ToSpeed):
    """Instant change of speed to ``to_speed`` (zero duration)."""

    KEY: ClassVar[str] = "speed_step"


class Turn(TrackSegment):
    """Turn on a circle.

    Curvature from ``radius`` [m] or ``rate_deg_s`` (signed turn rate); extent from
    ``angle_deg`` (signed, positive to port) or ``duration``. With ``radius`` the
    direction comes from the sign of ``angle_deg``, so ``radius`` needs ``angle_deg``.
    ``speed``/``speed_kn`` optional (default: keep the previous speed).
    """

    KEY: ClassVar[str] = "turn"
    radius: float | None = quantity(None, unit="m", gt=0)
    rate_deg_s: float | None = quantity(None, unit="deg/s")
    angle_deg: float | None = quantity(None, unit="deg")
    duration: float | None = quantity(None, unit="s", gt=0)
    speed: float | None = quantity(None, unit="m/s", ge=0)
    speed_kn: float | None = quantity(None, unit="kn", ge=0)

    @model_validator(mode="after")
    def _check(self) -> Turn:
        _one_speed(self.speed, self.speed_kn, "speed")
        if (self.radius is None) == (self.rate_deg_s is None):
            raise ValueError("give exactly one of 'radius' (m) or 'rate_deg_s' (deg/s)")
        if (self.angle_deg is None) == (self.duration is None):
            raise ValueError("give exactly one of 'angle_deg' (signed, + to port) or "
                             "'duration' (s)")
        if self.radius is not None and self.angle_deg is None:
            raise ValueError("with 'radius', give 'angle_deg' (its sign sets the direction, "
                             "+ to port); or give 'rate_deg_s' with 'duration'")
        if self.angle_deg == 0 or self.rate_deg_s == 0:
            raise ValueError("a turn needs a non-zero angle_deg and rate_deg_s")
        if (self.rate_deg_s is not None and self.angle_deg is not None
                and self.rate_deg_s * self.angle_deg < 0):
            raise ValueError(f"rate_deg_s {fmt(self.rate_deg_s)} deg/s and angle_deg "
                             f"{fmt(self.angle_deg)} deg turn opposite ways; use the same sign")
        return self

    @property
    def speed_ms(self) -> float | None:
        """Speed [m/s], or None to keep the previous one."""
        return _one_speed(self.speed, self.speed_kn, "speed")


class Heading(TrackSegment):
    """Change of heading at a turn rate, to ``to_deg`` or by ``change_deg`` (signed)."""

    KEY: ClassVar[str] = "heading"
    to_deg: float | None = quantity(None, unit="deg")
    change_deg: float | None = quantity(None, unit="deg")
    rate_deg_s: float = quantity(unit="deg/s", gt=0)

    @model_validator(mode="after")
    def _check(self) -> Heading:
        if (self.to_deg is None) == (self.change_deg is None):
            raise ValueError("give exactly one of 'to_deg' (absolute heading) or "
                             "'change_deg' (signed, + to port)")
        return self


SEGMENT_TYPES: dict[str, type[TrackSegment]] = {
    cls.KEY: cls for cls in (Straight, Accelerate, SpeedStep, Turn, Heading)}


def _segment_key(value: Any) -> str | None:
    """Discriminator: the segment's name (the single key of its mapping)."""
    if isinstance(value, TrackSegment):
        return value.KEY
    if isinstance(value, dict):
        if "kind" in value:
            return value["kind"]
        if len(value) == 1:
            key = next(iter(value))
            return key if isinstance(key, str) else None
    return None


AnySegment = Annotated[
    Union[tuple(Annotated[cls, Tag(key)] for key, cls in SEGMENT_TYPES.items())],
    Discriminator(_segment_key)]


def start_speeds(track) -> list[float]:
    """The speed [m/s] at which each segment of ``track`` runs from its start.

    A segment's own ``speed`` (straight, turn) if it gives one, else the speed the segment
    before it ended at (0 before the first: from rest). A speed step ends at its target; a ramp
    at its target, or where its ``duration`` cut it short (``v + a t``). The one source of these
    speeds: :func:`kanat.vessel.track.compile_phases` builds the run's phases on them, so the
    case checks see the speeds the run will.

    Parameters
    ----------
    track : sequence of TrackSegment

    Returns
    -------
    list of float, one per segment
    """
    speeds, v = [], 0.0
    for segment in track:
        own = getattr(segment, "speed_ms", None)
        v = v if own is None else own
        speeds.append(v)
        if isinstance(segment, SpeedStep):
            v = segment.to_speed_ms
        elif isinstance(segment, Accelerate):
            change = segment.to_speed_ms - v
            ramp = abs(change) / segment.acceleration
            if segment.duration is not None:
                ramp = min(ramp, segment.duration)
            v = v + (math.copysign(segment.acceleration, change) if change else 0.0) * ramp
    return speeds


class VesselPitch(PitchModel):
    """The tow vessel's pitch in regular head seas (theory/vessel.md §2), coupled to the tow.

    The fields of :class:`~kanat.model.PitchModel` (``inertia``, ``natural_frequency`` or
    ``restoring``, ``wave_moment_amplitude``, ``wave_period``, ``damping_ratio``,
    ``stabilizer``, ``harmonics``, ``time_points``), with one mode, ``stabilizer.mode``,
    and the wave phase at the run's ``t = 0``: the pitch at time ``t`` is the steady pitch
    at ``t + phase_deg / 360 * wave_period`` of the period that :func:`kanat.vessel.solve_pitch`
    solves (whose ``t = 0`` has the wave moment ``-M_m sin(omega t)`` at zero, falling).
    ``modes`` is refused: a tow runs one mode (compare them with
    :func:`kanat.studies.pitch_tow.compare_modes`).
    """

    phase_deg: float = quantity(0.0, unit="deg", description="wave phase at t = 0 of the run")

    @model_validator(mode="after")
    def _one_mode(self) -> VesselPitch:
        if self.modes is not None:
            raise ValueError("'modes' is for model: pitch; the vessel pitches with one mode, "
                             "'stabilizer.mode' (to compare the modes on a tow, use "
                             "kanat study pitch-tow CASE -o DIR)")
        return self


class Vessel(KanatModel):
    """The towing vessel.

    Attributes
    ----------
    tow_point : tuple of 3 float
        Tow point in vessel axes (x forward, y port, z up) [m]. At t = 0 the vessel
        is at the origin with heading 0, so this is also the tow point's global
        initial position.
    track : tuple of TrackSegment
        Segments in execution order.
    pitch : VesselPitch or None
        The vessel's own pitch (theory/vessel.md §2): the steady periodic pitch of its stabilizer
        mode turns the tow point's lever arm about the pitch centre
        (:func:`kanat.vessel.pitch.motion.pitch_motion`). ``None``: no pitch.
    motion : VesselMotion
        Prescribed motion about the track (:mod:`kanat.model.operations`).
    """

    tow_point: Vector3 = quantity(ZERO3, unit="m")
    track: tuple[AnySegment, ...] = ()
    pitch: VesselPitch | None = None
    motion: VesselMotion = Field(
        default_factory=VesselMotion,
        description="prescribed motion about the track, in vessel axes: a list of harmonics "
                    "[{dof, amplitude, period, phase_deg}], {table: FILE} or {rao: FILE} (see "
                    "kanat.model.operations)")

    @model_validator(mode="after")
    def _raos_at_rest(self) -> Vessel:
        """RAOs move a vessel at zero forward speed: a track that sets a speed is refused."""
        if self.motion.rao_rows is None:
            return self
        for segment in self.track:
            speeds = [getattr(segment, key, None) for key in ("speed_ms", "to_speed_ms")]
            if any(speed for speed in speeds if speed is not None):
                raise ValueError("vessel.motion.rao: RAOs give the motion at zero forward speed, and the "
                                 "track moves the vessel (no encounter frequency is modelled); keep the "
                                 "vessel on station or give the motion as harmonics or a table")
        return self

    @property
    def initial_speed(self) -> float:
        """Speed at t = 0 [m/s]: the first segment's own speed, else 0 (from rest)."""
        if not self.track:
            return 0.0
        first = self.track[0]
        speed = getattr(first, "speed_ms", None)
        return float(speed) if speed is not None else 0.0

    @property
    def speed_unit(self) -> str:
        """The unit the case gives its speeds in: ``"kn"`` when the first segment that sets a speed
        uses a knots key (``speed_kn``, ``to_speed_kn``), else ``"m/s"`` (what messages and
        pictures show speeds in)."""
        for segment in self.track:
            for key in ("speed", "to_speed"):
                if getattr(segment, f"{key}_kn", None) is not None:
                    return "kn"
                if getattr(segment, key, None) is not None:
                    return "m/s"
        return "m/s"

    def speed_as_given(self, speed: float) -> tuple[float, str]:
        """A speed [m/s] as ``(value, unit)`` in the unit of the case (:attr:`speed_unit`):
        ``(6.0, "kn")`` for 3.0867 m/s in a case written in knots."""
        unit = self.speed_unit
        return (speed / KNOT if unit == "kn" else speed), unit
