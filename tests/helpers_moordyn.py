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
  step's end, or with ``forces`` ``(t, *forces, *record(system))``, ``forces`` being MoorDyn's loads
  on the coupled degrees of freedom that ``Step`` returns (what a coupled code receives);
  ``at_start(system)`` once after the initialisation (a still-water tension, MoorDyn's own initial
  state, or a state written into MoorDyn's).

Its console output is silenced (:class:`helpers.quiet`).
"""
import numpy as np

from helpers import quiet


def secant(point, coupling: float):
    """The mean velocity of ``point`` over each coupling step: ``(point(t + c) - point(t)) / c``."""
    return lambda t: (point(t + coupling) - point(t)) / coupling


def run_moordyn(moordyn, path, duration: float, coupling: float, record=None, every: int = 1, *, point=None,
                velocity=None, sea=None, scheme: str | None = None, dt: float | None = None, at_start=None,
                forces: bool = False):
    """MoorDyn on the input file ``path`` coupled every ``coupling`` s to ``duration`` (module docstring).

    Parameters
    ----------
    moordyn : module
        The ``moordyn`` package (the ``moordyn`` fixture).
    path : path-like
        MoorDyn input file (MoorDyn writes its outputs beside it).
    duration, coupling : float
        [s].
    record : callable, optional
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
    forces : bool
        Rows start with the loads ``Step`` returns on the coupled degrees of freedom [N, N m].

    Returns
    -------
    start : object
        ``at_start(system)`` (None without it).
    rows : ndarray, shape (duration / (coupling every), 1 + (n if forces) + len(record(system)))
        ``(t, *record(system))`` or ``(t, *forces, *record(system))``.
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
            loads = moordyn.Step(system, [] if point is None else list(point(t)),
                                 [] if point is None else list(velocity(t)), t, coupling)
            if (k + 1) % every == 0:
                rows.append([(k + 1) * coupling, *(loads if forces else ()), *(record(system) if record else ())])
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


def node_tensions(moordyn, number: int = 1):
    """A ``record`` of the tension [N] at every node of line ``number``, anchor to fairlead."""
    def record(system):
        line = moordyn.GetLine(system, number)
        return [np.linalg.norm(moordyn.GetLineNodeTen(line, i)) for i in range(moordyn.GetLineN(line) + 1)]
    return record


JUMPER_FILE = """--------------------- MoorDyn Input File ------------------------------------
A steep flexible jumper: 170 m from an anchor 100 m away at 55 m depth to a fairlead 5 m down
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
flex       0.396   165        5.0e8      -0.8        {bending_stiffness:<10g} 1.0    1.0    0.0     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     100.0   0.0     -55.0   0      0       0      0
2     Vessel    0.0     0.0     -5.0    0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     flex       1        2         170       {segments:<8d}-
---------------------- OPTIONS -----------------------------------------
0.0005        dtM                  time step to use in mooring integration (s)
3.0e6         kBot                 bottom stiffness (Pa/m)
3.0e5         cBot                 bottom damping (Pa-s/m)
1025.0        WtrDnsty             water density (kg/m^3)
100           WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"""


def jumper_file(bending_stiffness: float = 0.0, segments: int = 34) -> str:
    """The MoorDyn input file of a steep flexible jumper: 170 m, d 0.396 m, 165 kg/m, EA 5e8 N, damping
    ratio 0.8, Cd 1, Ca 1, from an anchor 100 m away at 55 m depth to a coupled fairlead 5 m down, in
    100 m of water, with ``bending_stiffness`` (EI) [N m^2] and ``segments`` segments."""
    return JUMPER_FILE.format(bending_stiffness=bending_stiffness, segments=segments)
