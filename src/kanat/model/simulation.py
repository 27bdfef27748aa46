"""Time integration settings (case section ``simulation``)."""
from __future__ import annotations

from typing import Literal

from ._base import KanatModel, quantity


DEFAULT_OUTPUT_DT = 1.0
"""Stored interval [s] when neither ``output_dt`` nor ``dt`` is given."""
DEFAULT_IMPLICIT_DT = 0.1
"""Step [s] of the lumped implicit scheme when the case gives no ``dt`` (at most the output interval)."""


class Simulation(KanatModel):
    """How long and how finely to integrate, and with which scheme.

    Attributes
    ----------
    method : {"time", "frequency"}
        ``time``: integrate the model in time. ``frequency``: the lumped model linearised about its
        equilibrium, solved per frequency of the sea and the vessel's harmonic or RAO motion, drag by
        equivalent linearisation (docs/frequency.md); ``duration`` is then the exposure of the
        spectral extreme in the slack check.
    scheme : str or None
        Scheme name from the model's scheme registry (theory/time-schemes.md §1–3, theory/lumped.md; checked against
        :data:`kanat.schemes.SCHEME_NAMES`); None: the model's default.
    lambda_inf : float
        Spectral radius at infinite frequency of the generalized-alpha family, in [-1, 0].
    gamma : float or None
        Weight of the generalized trapezoidal scheme, in [1/2, 1].
    duration : float
        Simulated time [s].
    dt : float or None
        Time step [s]. The continuum model needs it. The lumped model may go without: its
        explicit schemes then step at their safe step, its implicit scheme at
        :data:`DEFAULT_IMPLICIT_DT` (at most the output interval).
    output_dt : float or None
        Interval between stored results [s]; None: every step, or :data:`DEFAULT_OUTPUT_DT`
        when ``dt`` is not given either.
    dimensions : {2, 3, "auto"}
        Planar (x-z) or spatial model; ``auto`` picks 2 when everything stays in the
        x-z plane.
    frame_pole : str
        Where the 3-D continuum model puts the pole of its angle frame (``auto``).
    mass_matrix : {"lumped", "consistent"}
        Lumped model: element mass ``mL/2`` at each node or consistent ``mL/6 [[2,1],[1,2]]``.
    initial_state : {"equilibrium", "as_given"}
        Lumped model: start from the network's equilibrium at the initial tow speed
        (theory/moorings.md §1), or at rest from the given positions of ends, bodies and points with
        each cable laid unstretched between its ends (no tension): straight when its ends are as far
        apart as it is long, or one above the other at least half its length apart; else sagging in a
        parabola of its length (downward, or sideways in x between ends one above the other), lying on
        the seabed where the sag would dip below it.
    slack : {"continue", "stop"}
        Continuum model: what a run does when the cable goes slack (compression beyond what
        its bending stiffness carries): ``continue`` carries the small compression the box
        equations give (the planar model with a tension floor in its normal rows), records
        each slack event (times, node, lowest tension) in the result and its notes, and goes
        on; ``stop`` ends the run there with ``status: failed``.
    tension_floor : float or None
        Continuum model, ``slack: continue``: the least tension the normal momentum rows of the
        planar model carry [N] (a slack interval keeps a string's small stiffness, the other
        rows the true tension); None: 1 % of the cable's weight in water, at least 1 N; 0: none.
    """

    method: Literal["time", "frequency"] = "time"
    scheme: str | None = None
    lambda_inf: float = quantity(-0.5, unit="-", ge=-1, le=0)
    gamma: float | None = quantity(None, unit="-", ge=0.5, le=1)
    duration: float = quantity(unit="s", gt=0)
    dt: float | None = quantity(None, unit="s", gt=0)
    output_dt: float | None = quantity(None, unit="s", gt=0)
    dimensions: Literal[2, 3, "auto"] = "auto"
    frame_pole: str = "auto"
    mass_matrix: Literal["lumped", "consistent"] = "lumped"
    initial_state: Literal["equilibrium", "as_given"] = "equilibrium"
    slack: Literal["continue", "stop"] = "continue"
    tension_floor: float | None = quantity(None, unit="N", ge=0)

    @property
    def output_interval(self) -> float:
        """``output_dt`` if given, else ``dt``, else :data:`DEFAULT_OUTPUT_DT` [s]."""
        if self.output_dt is not None:
            return self.output_dt
        return self.dt if self.dt is not None else DEFAULT_OUTPUT_DT

    @property
    def step_or_default(self) -> float:
        """``dt`` if given, else the default step of implicit lumped runs [s]."""
        return self.dt if self.dt is not None else min(self.output_interval, DEFAULT_IMPLICIT_DT)
