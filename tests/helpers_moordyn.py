"""MoorDyn side by side: the one coupling loop the tests run MoorDyn-C through (its Python API,
``moordyn`` on PyPI, MoorDyn v2).

:func:`run_moordyn` creates a system from an input file, optionally sets MoorDyn's own time scheme
and step, initialises it with the coupled degrees of freedom at their place at t = 0 (at rest),
and steps it every ``coupling`` seconds to ``duration``:

* driven (``point``): the coupled points' or bodies' coordinates at ``point(t)`` at the step's
  start, moved at ``velocity(t)`` over the step (default the secant ``(point(t + c) - point(t)) / c``,
  the mean velocity over the step, which MoorDyn integrates to ``point(t + c)`` exactly);
* in waves (``sea``): the file's wave kinematics given externally (``WaveKin 1``), the sea's
  velocity and acceleration at MoorDyn's nodes set at mid-step ``t + c / 2`` every step (MoorDyn
  holds them over the step);
* recorded: ``record(system)`` every ``every`` coupling steps, a row ``(t, *record(system))`` at the
  step's end; ``at_start(system)`` once after the initialisation (a still-water tension, MoorDyn's
  own initial state, or a state written into MoorDyn's).

Its console output is silenced (:class:`helpers.quiet`).
"""
import numpy as np

from helpers import quiet


def secant(point, coupling: float):
    """The mean velocity of ``point`` over each coupling step: ``(point(t + c) - point(t)) / c``."""
    return lambda t: (point(t + coupling) - point(t)) / coupling


def run_moordyn(moordyn, path, duration: float, coupling: float, record, every: int = 1, *, point=None,
                velocity=None, sea=None, scheme: str | None = None, dt: float | None = None, at_start=None):
    """MoorDyn on the input file ``path`` coupled every ``coupling`` s to ``duration`` (module docstring).

    Parameters
    ----------
    moordyn : module
        The ``moordyn`` package (the ``moordyn`` fixture).
    path : path-like
        MoorDyn input file (MoorDyn writes its outputs beside it).
    duration, coupling : float
        [s].
    record : callable
        ``record(system) -> sequence of float``, the row's values after each ``every``-th step.
    every : int
        Coupling steps between rows.
    point, velocity : callable, optional
        ``point(t) -> array_like (n,)``: every coupled coordinate [m, rad]; ``velocity(t)`` over the
        step from t (default :func:`secant`). None: no coupled degree of freedom.
    sea : object, optional
        ``sea.velocity(points, t)``, ``sea.acceleration(points, t)`` (n, 3) at MoorDyn's nodes.
    scheme, dt : optional
        MoorDyn's time scheme (``"RK2"``) and step [s]; None: the file's.
    at_start : callable, optional
        ``at_start(system)`` after the initialisation; its value is returned.

    Returns
    -------
    start : object
        ``at_start(system)`` (None without it).
    rows : ndarray, shape (duration / (coupling every), 1 + len(record(system)))
        ``(t, *record(system))``.
    """
    velocity = velocity or (secant(point, coupling) if point is not None else None)
    rows, start = [], None
    with quiet():
        system = moordyn.Create(str(path))
        if scheme is not None:
            moordyn.SetTimeScheme(system, scheme)
        if dt is not None:
            moordyn.SetDt(system, dt)
        place = [] if point is None else list(point(0.0))
        moordyn.Init(system, place, [0.0] * len(place))
        if sea is not None:
            moordyn.ExternalWaveKinInit(system)
        if at_start is not None:
            start = at_start(system)
        for k in range(int(round(duration / coupling))):
            t = k * coupling
            if sea is not None:
                _set_waves(moordyn, system, sea, t, coupling)
            moordyn.Step(system, [] if point is None else list(point(t)),
                         [] if point is None else list(velocity(t)), t, coupling)
            if (k + 1) % every == 0:
                rows.append([(k + 1) * coupling, *record(system)])
        moordyn.Close(system)
    return start, np.array(rows)


def _set_waves(moordyn, system, sea, t: float, coupling: float) -> None:
    """The sea's kinematics at MoorDyn's wave points at mid-step, held over the step from ``t``."""
    points = np.array(moordyn.ExternalWaveKinGetCoordinates(system))
    middle = t + coupling / 2
    moordyn.ExternalWaveKinSet(system, sea.velocity(points, middle).tolist(),
                               sea.acceleration(points, middle).tolist(), t)


def fairlead_tension(moordyn, number: int = 1, node: int | None = None):
    """A ``record`` of line ``number``'s fairlead tension [N], then node ``node``'s position [m] if given."""
    def record(system):
        line = moordyn.GetLine(system, number)
        return [moordyn.GetLineFairTen(line), *(() if node is None else moordyn.GetLineNodePos(line, node))]
    return record
