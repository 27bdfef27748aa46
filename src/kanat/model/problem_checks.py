"""Checks of the special problems of a case (part of :data:`kanat.model.checks.CHECKS`): the
sphere on two cables (Naumov & Agievich), pitch resonance and stabilizer, and sections a model ignores."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ._base import fmt
from .findings import Findings
from .paths import Path

if TYPE_CHECKING:                 # a check takes a case, and the case's edit runs the checks (edit.py)
    from .case import Case

RESONANCE_GAIN = 10.0       # dynamic amplification of a pitch harmonic worth a warning


def check_sphere(case: Case, out: Findings) -> None:
    """The sphere problem's groups must admit an equilibrium (the solver's own conditions).

    The line (``LoL`` cable lengths) and the cable (1) meet at the sphere, so the anchors
    must lie between ``|LoL - 1|`` and ``LoL + 1`` cable lengths apart; ``chi`` below 1;
    ``QkL`` and ``RkL`` not both zero.
    """
    sphere = case.sphere_two_cables
    if sphere is None:
        return
    if sphere.dimensionless is not None:
        groups = sphere.dimensionless
        where = ("sphere_two_cables", "dimensionless")
        _check_sphere_span(out, (*where, "x_C"), abs(groups.x_C), groups.LoL, 1.0,
                           f"|x_C| = {fmt(abs(groups.x_C))} cable lengths",
                           f"line (LoL = {fmt(groups.LoL)}) and the cable (1)", " cable lengths")
        if groups.chi >= 1:
            out.error((*where, "chi"), f"chi = C_0/C_90 = {fmt(groups.chi)} must be below 1 "
                      "(the tangential drag of a cable is a fraction of its normal drag)")
        if groups.QkL == 0 and groups.RkL == 0:
            out.error((*where, "QkL"), "QkL and RkL are both 0: the sphere has neither net "
                      "buoyancy nor drag, and its cable's tension no scale; give either")
    else:
        dims = sphere.dimensional
        _check_sphere_span(out, ("sphere_two_cables", "dimensional", "anchor_x"),
                           abs(dims.anchor_x), dims.line_length, dims.cable_length,
                           f"{fmt(abs(dims.anchor_x))} m", f"line ({fmt(dims.line_length)} m) "
                           f"and the cable ({fmt(dims.cable_length)} m)", " m")


def _check_sphere_span(out: Findings, path: Path, span: float, line: float, cable: float,
                       apart: str, lengths: str, unit: str) -> None:
    """The anchors ``span`` apart must be reached by ``line`` and ``cable`` meeting at A."""
    if span >= line + cable:
        out.error(path, f"the anchors are {apart} apart but the {lengths} reach only "
                  f"{fmt(line + cable)}{unit}: no equilibrium; bring the anchors closer than that")
    elif span <= abs(line - cable):
        out.error(path, f"the anchors are {apart} apart but the {lengths} differ by "
                  f"{fmt(abs(line - cable))}{unit}: they cannot meet at the sphere with both "
                  f"taut; set the anchors between {fmt(abs(line - cable))}{unit} and "
                  f"{fmt(line + cable)}{unit} apart")


def check_pitch(case: Case, out: Findings) -> None:
    """No harmonic of the wave frequency should sit on the pitch natural frequency.

    Applies to the ``pitch`` block of a pitch case and to ``vessel.pitch`` of a tow.
    """
    for where, pitch in ((("pitch",), case.pitch), (("vessel", "pitch"), case.vessel.pitch)):
        if pitch is not None:
            _check_one_pitch(where, pitch, out)


def _check_one_pitch(where: tuple, pitch, out: Findings) -> None:
    from .problems import RESONANCE_RTOL      # the solver's own guard

    key = "natural_frequency" if pitch.natural_frequency is not None else "restoring"
    omega, omega0, zeta = pitch.wave_frequency, pitch.omega0, pitch.damping_ratio
    n = range(1, pitch.harmonics + 1)
    denominator = [math.hypot(1 - (k * omega / omega0) ** 2, 2 * zeta * k * omega / omega0) for k in n]
    worst = min(range(len(denominator)), key=denominator.__getitem__)
    nearest = max(1, round(omega0 / omega))  # every harmonic counts, also beyond the truncation
    text = (f"harmonic n = {n[worst]} of the wave frequency ({n[worst]} × {omega:.4g} = "
            f"{n[worst] * omega:.4g} rad/s) ")
    if zeta == 0 and abs(nearest * omega - omega0) / omega0 <= RESONANCE_RTOL:  # the solver's test
        beyond = f" (beyond the {pitch.harmonics} harmonics computed)" if nearest > pitch.harmonics else ""
        out.error((*where, key), f"harmonic n = {nearest} of the wave frequency ({nearest} × {omega:.4g} = "
                  f"{nearest * omega:.4g} rad/s){beyond} is within {100 * RESONANCE_RTOL:g} % of the natural "
                  f"frequency {omega0:.4g} rad/s and there is no damping: the steady state is unbounded; "
                  f"change {key} or give damping_ratio > 0")
    elif 1 / denominator[worst] > RESONANCE_GAIN:
        out.warning((*where, key), text + f"is close to the natural frequency {omega0:.4g} "
                    f"rad/s: its response is amplified {1 / denominator[worst]:.3g} times")
    stabilizer = pitch.stabilizer
    if stabilizer.mode != "off" and stabilizer.max_moment == 0:
        out.warning((*where, "stabilizer", "max_moment"), f"stabilizer mode "
                    f"'{stabilizer.mode}' with max_moment 0 N m has no effect")


def check_ignored_sections(case: Case, out: Findings) -> None:
    """Sections that the chosen model does not use."""
    if case.sphere_two_cables is not None and case.model != "statics":
        out.warning(("sphere_two_cables",), f"ignored by model '{case.model}' (it is solved "
                    "by model: statics)")
    if case.pitch is not None and case.model != "pitch":
        out.warning(("pitch",), f"ignored by model '{case.model}' (it is solved by model: "
                    "pitch; a vessel's own pitch goes in vessel.pitch)")
    if case.cables and case.model == "pitch":
        out.warning(("cables",), "ignored by model 'pitch'")
