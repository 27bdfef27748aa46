"""The open-loop stabilizer shape that minimises the steady pitch (beyond Gaisha).

The shape is piecewise linear over the active window (the paper's first half period),
``f(t) = M0 sum_k v_k h_k(t)`` with hat functions ``h_k`` on ``K + 1`` equally spaced nodes
and ``0 <= v_k <= 1``; the bounds on ``v`` are exactly ``0 <= f <= M0``. The steady pitch
is linear in ``v`` (Fourier steady state, :mod:`.pitch_fourier`),
``phi(t_j) = phi_wave(t_j) + sum_k v_k phi_k(t_j)``, so on a grid of times ``t_j``

* the amplitude ``(max phi - min phi) / 2`` is minimised by the linear programme
  ``min (u - l) / 2  s.t.  l <= phi(t_j) <= u,  0 <= v <= 1``;
* the largest ``|phi|`` by ``min m  s.t.  -m <= phi(t_j) <= m,  0 <= v <= 1``.

Both are solved to their global optimum over the family by
:func:`scipy.optimize.linprog` (HiGHS). The family holds the rectangular law
(all ``v_k = 1``), so the optimum is never worse than it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import linprog

from kanat.errors import SolverError

from .fourier import steady_state, wave_series
from .laws import Shaped
from .system import PitchSystem

OBJECTIVES = ("amplitude", "max_abs")
SAMPLES = 720      # time samples per period in the linear programme (every 0.5 deg of phase)
NODES = 16         # pieces of the default shape over the active window


@dataclass(frozen=True)
class OptimalShape:
    """The optimised law and what it achieves on the programme's grid.

    Attributes
    ----------
    law : Shaped
    objective : {"amplitude", "max_abs"}
    value : float
        The objective on the grid [rad].
    """

    law: Shaped
    objective: str
    value: float


def _basis(system: PitchSystem, max_moment: float, harmonics: int, nodes: int, active: float,
           times: np.ndarray) -> np.ndarray:
    """Steady pitch of each hat function times ``M0``, shape (len(times), nodes + 1) [rad]."""
    columns = []
    for k in range(nodes + 1):
        values = np.zeros(nodes + 1)
        values[k] = 1.0
        moment = Shaped(tuple(values), active).fourier(max_moment, system.wave_frequency, harmonics)
        columns.append(steady_state(system, moment)(times))
    return np.column_stack(columns)


def optimal_shape(system: PitchSystem, max_moment: float, harmonics: int, nodes: int = NODES,
                  objective: str = "amplitude", active: float = 0.5,
                  samples: int = SAMPLES) -> OptimalShape:
    """Find the shape in ``[0, M0]`` over the active window that minimises ``objective``.

    Parameters
    ----------
    system : PitchSystem
    max_moment : float
        ``M0`` [N m].
    harmonics : int
        ``N`` of the Fourier steady state used inside the programme.
    nodes : int
        Number of linear pieces ``K`` (``K + 1`` unknowns).
    objective : {"amplitude", "max_abs"}
        Half the peak-to-peak pitch, or the largest ``|phi|`` (which also counts the
        mean trim the one-sided stabilizer causes).
    active : float
        Fraction of the period the stabilizer may act in (0.5: the paper's half period).
    samples : int
        Grid points per period (the node times are added).

    Raises
    ------
    KanatError
        Unknown objective; :class:`~.pitch_system.ResonanceError` at undamped resonance;
        :class:`SolverError` if the programme fails.
    """
    if objective not in OBJECTIVES:
        raise SolverError(f"unknown objective '{objective}'; use one of: {', '.join(OBJECTIVES)}")
    period = 2.0 * math.pi / system.wave_frequency
    node_times = np.linspace(0.0, active * period, nodes + 1)
    times = np.union1d(np.linspace(0.0, period, samples, endpoint=False), node_times[:-1])
    scale = system.angle_scale
    wave = steady_state(system, wave_series(system, harmonics))(times) / scale
    basis = _basis(system, max_moment, harmonics, nodes, active, times) / scale
    m = nodes + 1
    if objective == "amplitude":   # x = (v, u, l)
        cost = np.r_[np.zeros(m), 0.5, -0.5]
        a_ub = np.block([[basis, -np.ones((len(times), 1)), np.zeros((len(times), 1))],
                         [-basis, np.zeros((len(times), 1)), np.ones((len(times), 1))]])
        bounds = [(0.0, 1.0)] * m + [(None, None)] * 2
    else:                          # x = (v, m)
        cost = np.r_[np.zeros(m), 1.0]
        a_ub = np.block([[basis, -np.ones((len(times), 1))], [-basis, -np.ones((len(times), 1))]])
        bounds = [(0.0, 1.0)] * m + [(0.0, None)]
    res = linprog(cost, A_ub=a_ub, b_ub=np.r_[-wave, wave], bounds=bounds, method="highs")
    if res.status != 0:
        raise SolverError(f"the linear programme of the optimal stabilizer shape failed: "
                          f"{res.message}; try fewer nodes or more samples")
    values = tuple(float(v) for v in np.clip(res.x[:m], 0.0, 1.0))
    return OptimalShape(Shaped(values, active), objective, float(res.fun) * scale)
