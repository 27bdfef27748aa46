"""Ship pitch with a reactive stabilizer (Gaisha, theory/vessel.md §2): modes, both solution
paths and the comparison table.

``I_y phi'' + c phi' + k phi = M_m sin(omega t + pi) + f(t)``, ``0 <= f <= M0``.

Two paths to the periodic steady state, which must agree:

* ``"fourier"``: the series of paper eqs. 7, 10, 11, 12 (theory/vessel.md §2) with ``N`` harmonics,
  each answered by ``A / (I_y (omega_0^2 - (n omega)^2))`` or, damped, the complex transfer
  function (:mod:`.fourier`); open-loop modes only;
* ``"shooting"``: DOP853 time integration with Newton shooting on the initial state for
  the periodic orbit (:mod:`.periodic`), for every mode. The feedback mode has no
  open-loop Fourier form and is solved this way only.

``solve_pitch`` solves each mode by its primary path (Fourier when it has one) and, with
``cross_check``, by shooting too, recording ``max_t |phi_F - phi_T| / amplitude``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kanat.errors import KanatError
from kanat.model.problems import STABILIZER_MODES

from .fourier import fourier_pitch
from .laws import OPEN_LOOP, Feedback
from .optimal import optimal_shape
from .system import PitchSystem
from .periodic import periodic_orbit

MODES = STABILIZER_MODES     # off, sinusoidal, rectangular, feedback, optimal
PAPER_MODES = ("off", "sinusoidal", "rectangular")
METHODS = ("auto", "fourier", "shooting")


@dataclass(frozen=True)
class PitchResponse:
    """The steady pitch of one stabilizer mode over one period.

    Attributes
    ----------
    mode : str
    method : {"fourier", "shooting"}
        The path that produced ``pitch``.
    time : ndarray, shape (n,)
        ``[0, T]``, both ends included [s].
    pitch : ndarray, shape (n,)
        ``phi`` [rad].
    moment : ndarray, shape (n,)
        Stabilizer moment ``f`` [N m].
    harmonics : int or None
        ``N`` of the Fourier path.
    """

    mode: str
    method: str
    time: np.ndarray
    pitch: np.ndarray
    moment: np.ndarray
    harmonics: int | None = None

    @property
    def amplitude(self) -> float:
        """Half the peak-to-peak pitch [rad]."""
        return 0.5 * float(np.ptp(self.pitch))

    @property
    def max_abs(self) -> float:
        """Largest ``|phi|`` [rad]."""
        return float(np.max(np.abs(self.pitch)))

    @property
    def mean(self) -> float:
        """Period mean of ``phi`` (the trim the one-sided stabilizer causes) [rad]."""
        return float(np.mean(self.pitch[:-1]))


@dataclass(frozen=True)
class PitchResult:
    """Steady pitch of several modes with the same ship, sea and ``M0``.

    Attributes
    ----------
    system : PitchSystem
    max_moment : float
        ``M0`` [N m].
    harmonics : int
        ``N`` of the Fourier path.
    responses : dict of str to PitchResponse
    agreement : dict of str to float
        ``max_t |phi_fourier - phi_shooting| / amplitude`` per open-loop mode.
    laws : dict of str to object
        The law of each mode (for ``optimal``, the shape found).
    name : str
    """

    system: PitchSystem
    max_moment: float
    harmonics: int
    responses: dict[str, PitchResponse]
    agreement: dict[str, float] = field(default_factory=dict)
    laws: dict[str, object] = field(default_factory=dict)
    name: str = ""

    def reduction(self, mode: str, metric: str = "amplitude") -> float:
        """``metric(off) / metric(mode)``: how many times the stabilizer reduces the pitch."""
        off = self.responses.get("off")
        if off is None:
            raise KanatError("the reduction needs the 'off' mode among the modes solved")
        return getattr(off, metric) / getattr(self.responses[mode], metric)

    def table(self) -> str:
        """Plain-text table of amplitude, largest |pitch| and reduction per mode."""
        return summary_table(self)


def stabilizer_law(mode: str, system: PitchSystem, stabilizer=None, harmonics: int = 50):
    """The law of a mode name.

    Parameters
    ----------
    mode : {"off", "sinusoidal", "rectangular", "feedback", "optimal"}
    system : PitchSystem
    stabilizer : kanat.model.Stabilizer, optional
        ``max_moment``, ``feedback_gain``, ``shape_nodes`` and ``objective``.
    harmonics : int
        ``N`` used to optimise the ``optimal`` shape.
    """
    if mode in OPEN_LOOP:
        return OPEN_LOOP[mode]()
    if mode == "feedback":
        return Feedback(getattr(stabilizer, "feedback_gain", None))
    if mode == "optimal":
        max_moment = getattr(stabilizer, "max_moment", 0.0)
        return optimal_shape(system, max_moment, harmonics, nodes=getattr(stabilizer, "shape_nodes", 16),
                             objective=getattr(stabilizer, "objective", "amplitude")).law
    raise KanatError(f"unknown stabilizer mode '{mode}'; known: {', '.join(MODES)}")


def solve_mode(system: PitchSystem, law, max_moment: float, times, harmonics: int = 50,
               method: str = "auto") -> PitchResponse:
    """Steady pitch of one law over one period.

    Parameters
    ----------
    system : PitchSystem
    law : OpenLoopLaw or Feedback
    max_moment : float
        ``M0`` [N m].
    times : ndarray, shape (n,)
        Output times in ``[0, T]`` [s].
    harmonics : int
        ``N`` of the Fourier path.
    method : {"auto", "fourier", "shooting"}
        ``auto``: Fourier for open-loop laws, shooting for feedback.

    Raises
    ------
    KanatError
        Fourier asked for the feedback law, or an unknown method;
        :class:`~.pitch_system.ResonanceError` at undamped resonance.
    """
    if method not in METHODS:
        raise KanatError(f"unknown method '{method}'; use one of: {', '.join(METHODS)}")
    closed = getattr(law, "closed_loop", False)
    if method == "fourier" and closed:
        raise KanatError(f"mode '{law.name}' is closed-loop (its moment depends on the pitch rate) "
                         "and has no open-loop Fourier form; use method 'shooting'")
    times = np.asarray(times, dtype=float)
    if method == "shooting" or closed:
        if closed:
            pieces = law.pieces(max_moment, system.wave_frequency, law.gain_for(system))
        else:
            system.check_resonance()
            pieces = law.pieces(max_moment, system.wave_frequency)
        sol = periodic_orbit(system, pieces, times)
        return PitchResponse(law.name, "shooting", times, sol.pitch, sol.moment)
    pitch, _ = fourier_pitch(system, law, max_moment, harmonics)
    return PitchResponse(law.name, "fourier", times, pitch(times), law.moment(times, max_moment,
                                                                               system.wave_frequency),
                         harmonics)


def agreement(a: PitchResponse, b: PitchResponse) -> float:
    """``max_t |phi_a - phi_b| / amplitude_b``: the relative difference of two paths."""
    return float(np.max(np.abs(a.pitch - b.pitch)) / b.amplitude)


def modes_of(model) -> tuple[str, ...]:
    """Modes a pitch block asks for: ``model.modes``, else the paper's three and its own."""
    if model.modes:
        return tuple(dict.fromkeys(model.modes))
    return tuple(dict.fromkeys((*PAPER_MODES, model.stabilizer.mode)))


def solve_pitch(model, modes=None, *, harmonics: int | None = None, time_points: int | None = None,
                cross_check: bool = True, name: str = "") -> PitchResult:
    """Solve a :class:`kanat.model.PitchModel` for several stabilizer modes.

    Parameters
    ----------
    model : kanat.model.PitchModel
    modes : sequence of str, optional
        Default :func:`modes_of` ``(model)``.
    harmonics, time_points : int, optional
        Override the block's ``harmonics`` (N) and ``time_points``.
    cross_check : bool
        Also solve the open-loop modes by shooting and record the agreement.
    name : str
        Case name for the table.
    """
    system = PitchSystem.from_model(model)
    system.check_resonance()
    harmonics = harmonics or model.harmonics
    times = np.linspace(0.0, system.period, time_points or model.time_points)
    max_moment = model.stabilizer.max_moment
    responses, checks, laws = {}, {}, {}
    for mode in modes or modes_of(model):
        law = stabilizer_law(mode, system, model.stabilizer, harmonics)
        laws[mode] = law
        responses[mode] = solve_mode(system, law, max_moment, times, harmonics)
        if cross_check and responses[mode].method == "fourier":
            shot = solve_mode(system, law, max_moment, times, harmonics, method="shooting")
            checks[mode] = agreement(responses[mode], shot)
    return PitchResult(system, max_moment, harmonics, responses, checks, laws, name)


def summary_table(result: PitchResult) -> str:
    """The comparison table of a :class:`PitchResult` (plain text, fixed width)."""
    s = result.system
    lines = [(f"pitch steady state{' of ' + result.name if result.name else ''}: I_y = {s.inertia:.4g} "
              f"kg m^2, omega_0 = {s.natural_frequency:.4g} rad/s, omega = {s.wave_frequency:.4g} rad/s "
              f"(T = {s.period:.4g} s), zeta = {s.damping_ratio:.3g}, M_m = {s.wave_moment_amplitude:.4g} "
              f"N m, M0 = {result.max_moment:.4g} N m, N = {result.harmonics}"),
             (f"{'mode':<12} {'method':<9} {'amplitude':>10} {'[deg]':>6} {'max|pitch|':>10} {'[deg]':>6} "
              f"{'mean':>9} {'off/mode':>9} {'off/mode':>10} {'Fourier vs':>10}"),
             (f"{'':<12} {'':<9} {'[rad]':>10} {'':>6} {'[rad]':>10} {'':>6} {'[rad]':>9} "
              f"{'amplitude':>9} {'max|pitch|':>10} {'shooting':>10}")]
    for mode, r in result.responses.items():
        ratios = ((f"{result.reduction(mode):9.3g}", f"{result.reduction(mode, 'max_abs'):10.3g}")
                  if "off" in result.responses else (f"{'-':>9}", f"{'-':>10}"))
        check = f"{result.agreement[mode]:10.1e}" if mode in result.agreement else f"{'-':>10}"
        lines.append(f"{mode:<12} {r.method:<9} {r.amplitude:10.5f} {np.degrees(r.amplitude):6.2f} "
                     f"{r.max_abs:10.5f} {np.degrees(r.max_abs):6.2f} {r.mean:9.5f} {ratios[0]} "
                     f"{ratios[1]} {check}")
    lines.append("off/mode: how many times the stabilizer reduces the pitch; Fourier vs shooting: "
                 "max_t |phi_F - phi_T| / amplitude")
    return "\n".join(lines)
