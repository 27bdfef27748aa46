"""Step sizes: the explicit schemes' safe step from the shortest axial nodal period, and the
automatic choice of scheme (theory/lumped.md).

For element ``k`` between nodes of masses ``m_i, m_j`` (lumped: half of each adjacent
element's mass plus bodies; a prescribed node counts as infinitely heavy), with tangent
axial stiffness ``k = f'(e)/L0`` and Kelvin–Voigt rate ``c/L0``::

    (1)  omega_k = sqrt(2 k (1/m_i + 1/m_j))      highest axial frequency of the element pair
                                                  (the chain's 2 sqrt(k/m) for equal masses)
    (2)  sigma_k = 2 (c/L0) (1/m_i + 1/m_j)       its viscous decay rate
    (3)  T_axial = 2 pi / max omega_k             shortest axial nodal period
    (4)  |lambda_k| = omega_k                     if sigma_k < 2 omega_k (underdamped: the eigenvalues
                    = sigma_k/2 + sqrt(sigma_k^2/4 - omega_k^2)   -sigma/2 +- i sqrt(omega^2 - sigma^2/4)
                                                  lie on the circle |lambda| = omega), else overdamped
    (5)  h_safe  = SAFETY * limit / max |lambda_k|

A fairlead of a 6-DOF body is no prescribed node here: it moves with its body, a node of inverse mass
``1/m_f = lambda_max(J_f M^-1 J_f^T)`` in eq. (1) (eq. 1b, :func:`kanat.lumped.rigid.fairlead_mobility`),
and each body's own modes on its hydrostatic stiffness and linear damping compete in eq. (4) (eq. 4b,
:func:`kanat.lumped.rigid.body_rates`): a body on a single element to an anchor, with no free line node,
gets its step from the body (``tests/lumped/test_body_single_element.py``). A network with nothing that
oscillates (every node prescribed) has no step limit: eq. (5) is infinite.

With seabed contact each node ``n`` of mass ``m_n`` and contact area ``A_n`` is an oscillator of
``omega = sqrt(k_b A_n / m_n)`` and ``sigma = c_b A_n / m_n`` (contact stiffness and damping, eq.
4), and the regularized friction at rest adds the real rate ``mu W_n / (v_s m_n)`` for the node's
weight ``W_n`` (:mod:`kanat.physics.contact`); they compete in the maximum of eq. (5).

Bending stiffness adds the highest frequency of the discrete fourth difference,
``omega = 4 sqrt(k / (m l^2))`` per interior node (:func:`kanat.lumped.bending.bending_frequency`).

``limit`` is the scheme's ``stability_limit`` (largest stable ``|lambda h|`` near the
imaginary axis; RK4's region reaches as far along the negative real axis, 2.79). The consistent mass matrix raises the highest frequency by ``sqrt(3)``.

A case that names no scheme gets the cheaper of RK4 at its safe step and the implicit scheme at its
step, by force evaluations per simulated second with the wave kinematics counted (eq. 6,
:func:`choose_scheme`; :func:`default_scheme` for a run and a coupling alike). The implicit step
without ``dt`` is :data:`STEPS_PER_PERIOD` steps per shortest period of what drives
the run, once the spectral tails under 1 % of the variance are left out (eq. 7, :func:`excitation_period`); the accuracy of a number
of steps per period is the period error and algorithmic damping of eq. (8), :func:`period_error`
(docs/lumped.md, "Default step of the implicit scheme").
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.lumped import entries
from kanat.lumped.bending import bending_frequency
from kanat.lumped.rigid import body_inertia, body_rates, fairlead_mobility
from kanat.model.limits import EXPLICIT_SAFETY
from kanat.physics.contact import SLIP_VELOCITY

SAFETY = EXPLICIT_SAFETY     # margin below the stability limit (0.8)
CONSISTENT_FACTOR = math.sqrt(3.0)   # highest eigenvalue of [[2,1],[1,2]]/6 vs lumped 1/2: 3x in omega^2
STRAIN_REFERENCE = 0.02      # strain at which nonlinear laws' stiffness sets the step (or more if stretched)
IMPLICIT_COST = 4.0          # force evaluations the tangent work of one implicit step is worth: its band factors
                             # are kept over steps and rebuilt every few (fast_implicit.newton_step), each
                             # iteration substitutes; measured (benchmarks/bench_scheme_cost.py): 1.4 on the
                             # three-leg chain, 1.5 on the lazy wave, 0.0 on Bezverkhyi's trawl in waves, 4.0 on
                             # MoorDyn's WD0050 chain with seabed friction, whose factors are rebuilt most steps:
                             # the largest, so that a close call goes to rk4
STEPS_PER_PERIOD = 400.0     # implicit steps per period of the shortest excitation (default dt): MoorDyn's WD0050
                             # chain driven at 9 and 12 s (friction 0.5, a chain slapping the seabed) is as accurate
                             # at 0.1 s as at 0.025 s (fairlead tension within 0.5 % of MoorDyn) but costs 5.2 s of
                             # CPU there (9 Newton iterations a step, 9741 steps retaken by rk4), 4.4 at 0.05 s,
                             # 4.2 at 0.025 s. In waves too: 80 a period (0.045 s) on the three-leg chain in a
                             # JONSWAP storm agreed with MoorDyn over 60 s but stopped at 1172 s of the 3 hours,
                             # a node through the seabed after 6017 snap loads, a step 2.3 times the axial nodal
                             # period (benchmarks/RESULTS.md, "3 hours asked")
IMPLICIT_ITERATIONS = 3.0    # force evaluations per implicit step (Newton iterations, line search included): 2.0-2.1
                             # on the three-leg chain, the lazy wave and the trawl, 4.3 on WD0050 (friction)
WAVE_COMPONENT_COST = 0.052  # a force evaluation's wave kinematics per sea component, relative to the rest of
                             # it: 0.73 ms for 200 components at 156 points against 0.07 ms (the three-leg
                             # storm, benchmarks/RESULTS.md, "wave kernel"); the cost of both grows with the points
NEGLIGIBLE_VARIANCE = 0.01   # a driving spectrum's high-frequency tail holding less than this share of its
                             # variance (rms under 10 % of the whole) does not set the implicit step (eq. 7)


@dataclass(frozen=True)
class StepInfo:
    """The explicit stability bound of a network state.

    Attributes
    ----------
    axial_period : float
        Shortest axial nodal period, eq. (3) [s]; infinite when no element has a moving end.
    omega_max : float
        ``max |lambda_k|``, eq. (4) [1/s].
    element : int
        The element that sets it.
    """

    axial_period: float
    omega_max: float
    element: int

    def safe_step(self, scheme) -> float:
        """Eq. (5) for an explicit ``scheme`` [s]; infinite when nothing in the network oscillates (no
        element with a moving end, no body on its own springs: every node prescribed)."""
        if self.omega_max <= 0.0:
            return math.inf
        return SAFETY * scheme.stability_limit / self.omega_max


def spectral_radius(omega, sigma):
    """``|lambda|`` of ``x'' + sigma x' + omega^2 x = 0``, eq. (4) (arrays)."""
    omega, sigma = np.asarray(omega, float), np.asarray(sigma, float)
    over = np.sqrt(np.maximum(0.25 * sigma**2 - omega**2, 0.0))
    return np.where(sigma < 2.0 * omega, omega, 0.5 * sigma + over)


def step_info(net, x, consistent: bool = False, seabed=None) -> StepInfo:
    """Stability bound of the network at positions ``x`` (n, 3), eqs. (1)-(4); ``seabed`` the
    case's ``environment.seabed`` block (None: no contact)."""
    inv = np.zeros(net.n_nodes)
    mass = net.node_mass.copy()
    np.add.at(mass, net.el_i, 0.5 * net.el_mass * net.el_length)
    np.add.at(mass, net.el_j, 0.5 * net.el_mass * net.el_length)
    heavy = net.free & (mass > 0)
    inv[heavy] = 1.0 / mass[heavy]
    rigid = net.rigid
    if rigid.count:
        inverse = np.linalg.inv(body_inertia(rigid, mass))
        inv[rigid.fairlead_node] = fairlead_mobility(rigid, inverse)    # eq. (1b): a fairlead rides on its body
    strain = np.linalg.norm(x[net.el_j] - x[net.el_i], axis=1) / net.el_length - 1.0
    slope = np.zeros(net.n_elements)
    for row in range(len(net.law_kind)):
        sel = net.el_law == row
        if not np.any(sel):
            continue
        top = max(STRAIN_REFERENCE, 2.0 * float(np.max(strain[sel])))
        slope[sel] = max(entries.elastic_row(net.law_kind, net.law_n, net.law_x, net.law_y, row, float(e))[1]
                         for e in np.linspace(0.0, top, 17))
    pair = inv[net.el_i] + inv[net.el_j]
    omega = np.sqrt(2.0 * slope / net.el_length * pair)
    if consistent:
        omega = omega * CONSISTENT_FACTOR
    rate = spectral_radius(omega, 2.0 * net.el_damping / net.el_length * pair)
    k = int(np.argmax(rate))
    top = float(rate[k]) if len(rate) else 0.0
    before, node, after, k, span = net.bend
    top = max(top, bending_frequency(node, k, span, np.where(inv > 0, 1.0 / np.maximum(inv, 1e-300), 0.0)))
    if rigid.count:
        top = max(top, float(np.max(spectral_radius(*body_rates(rigid, inverse)))))   # eq. (4b)
    if seabed is not None:
        area = net.node_contact_area * (inv > 0)
        contact = (spectral_radius(np.sqrt(seabed.stiffness * area * inv), seabed.damping * area * inv)
                   + max(seabed.friction, seabed.lateral_friction) * net.node_weight / SLIP_VELOCITY * inv)
        top = max(top, float(np.max(contact, initial=0.0)))
    highest = float(np.max(omega, initial=0.0))
    return StepInfo(2.0 * math.pi / highest if highest > 0.0 else math.inf, top, k)


def fit_step(h_max: float, output_dt: float) -> float:
    """The largest step ``<= h_max`` that divides ``output_dt`` exactly (``output_dt`` itself for an
    infinite ``h_max``)."""
    return output_dt / max(math.ceil(output_dt / h_max - 1e-9), 1)


def choose_scheme(info: StepInfo, dt: float, schemes: dict, explicit_only: bool = False,
                  wave_load: float = 0.0):
    """The cheapest safe scheme for a case that names none: RK4 at its safe step, or the
    implicit scheme at ``dt``, by cost per simulated second (RK4 when ``explicit_only``: 6-DOF bodies).

    In units of a force evaluation without waves, eq. (6)::

        (6)  E = 1 + wave_load                                       a force evaluation
             C_rk4      = 4 E / h_rk4
             C_implicit = (IMPLICIT_ITERATIONS E + IMPLICIT_COST) / dt

    An implicit step is a few force evaluations (waves included) and the tangent's work
    (:data:`IMPLICIT_COST`: its band factors, kept over steps and rebuilt every few, and a
    substitution per iteration; no wave kinematics), so waves weigh on RK4's many steps more than
    on the implicit scheme's few. ``wave_load`` is :func:`wave_load`.
    """
    rk4, implicit = schemes["rk4"](), schemes["generalized-alpha-lumped"]()
    if explicit_only:
        return rk4
    evaluation = 1.0 + wave_load
    explicit_cost = rk4.evaluations_per_step * evaluation / min(info.safe_step(rk4), dt)
    implicit_cost = (IMPLICIT_ITERATIONS * evaluation + IMPLICIT_COST) / dt
    return rk4 if explicit_cost <= implicit_cost else implicit


def wave_load(system) -> float:
    """The wave kinematics' share of a force evaluation, relative to the rest (eq. 6):
    :data:`WAVE_COMPONENT_COST` per component of the sea, 0 without waves."""
    sea = system.sea
    return 0.0 if sea is None else WAVE_COMPONENT_COST * len(sea.omega)


def shortest_period(omega, amplitude, tail: float = NEGLIGIBLE_VARIANCE) -> float | None:
    """The shortest period [s] of a sum of harmonics ``a_i sin(omega_i t + phi_i)`` once its
    high-frequency tail holding less than ``tail`` of the variance is left out, eq. (7)::

        (7)  T = 2 pi / omega_c,   omega_c = max { omega_j : sum_{omega_i >= omega_j} a_i^2 >= tail sum_i a_i^2 }

    (the variance of a harmonic is ``a^2 / 2``). None when every amplitude is zero.
    """
    omega, amplitude = np.asarray(omega, float), np.abs(np.asarray(amplitude, float))
    variance = amplitude**2
    total = float(np.sum(variance))
    if total <= 0.0:
        return None
    order = np.argsort(omega)[::-1]
    above = np.cumsum(variance[order])
    cut = int(np.searchsorted(above, tail * total * (1.0 - 1e-12)))
    return 2.0 * math.pi / float(omega[order][cut])


def excitation_period(system) -> float | None:
    """The shortest period [s] of what drives the run, eq. (7): each degree of freedom of the
    prescribed harmonic motion and the sea's elevation without their high-frequency tails holding
    less than :data:`NEGLIGIBLE_VARIANCE` of their variance; None without either."""
    from kanat.physics.motion import Harmonics

    periods = []
    motion = system.motion
    if isinstance(motion, Harmonics):
        for dof in set(motion.dof.tolist()):                 # np.unique would import numpy.ma (40-70 ms)
            on = motion.dof == dof
            periods.append(shortest_period(motion.omega[on], motion.amplitude[on]))
    sea = system.sea
    if sea is not None and len(sea.omega):
        periods.append(shortest_period(sea.omega, sea.amplitude))
    periods = [p for p in periods if p is not None]
    return min(periods) if periods else None


def implicit_default(system, default: float) -> float:
    """The implicit scheme's step without ``dt``: ``default`` (``simulation.step_or_default``), or
    less where the run is driven: :data:`STEPS_PER_PERIOD` steps per :func:`excitation_period`."""
    period = excitation_period(system)
    return default if period is None else min(default, period / STEPS_PER_PERIOD)


def implicit_step(system, simulation) -> float:
    """The implicit scheme's largest step [s]: ``simulation.dt``, else :func:`implicit_default`."""
    return simulation.dt if simulation.dt is not None else implicit_default(system, simulation.step_or_default)


def default_scheme(system, info: StepInfo, simulation, schemes: dict, explicit_only: bool = False):
    """The scheme of a case that names none, for a run and a coupling alike: :func:`choose_scheme`
    at the :func:`implicit_step` with the :func:`wave_load` of ``system`` (a
    :class:`kanat.lumped.system.LumpedSystem`), eq. (6)."""
    return choose_scheme(info, implicit_step(system, simulation), schemes, explicit_only=explicit_only,
                         wave_load=wave_load(system))


def period_error(steps: float, rho_inf: float = 0.5) -> tuple[float, float]:
    """Relative period elongation ``(T_h - T) / T`` and algorithmic damping ratio of the lumped
    generalized-alpha scheme (WBZ-alpha, ``alpha_f = 0``) on ``x'' + omega^2 x = 0`` at
    ``steps`` steps a period, from its amplification matrix (Chung & Hulbert 1993, eqs.
    2-4 and section 4)::

        (8)  [1, 0, -beta h^2; 0, 1, -gamma h; omega^2, 0, 1 - alpha_m] X_n+1
                 = [1, h, (1/2 - beta) h^2; 0, 1, (1 - gamma) h; 0, 0, -alpha_m] X_n,   X = (x, v, a)

    with ``alpha_m = (rho_inf - 1)/(rho_inf + 1)``, ``gamma = 1/2 - alpha_m``, ``beta = (1 - alpha_m)^2/4``.
    Its principal roots ``lambda = exp(h omega_h (-xi +- i sqrt(1 - xi^2)))`` give ``omega_h h =
    |ln lambda|``, ``xi = -ln|lambda| / |ln lambda|`` and ``T_h / T = omega / omega_h``.
    """
    am = (rho_inf - 1.0) / (rho_inf + 1.0)
    gamma, beta = 0.5 - am, 0.25 * (1.0 - am) ** 2
    big_omega = 2.0 * math.pi / steps          # omega h, with h = 1 / omega
    left = np.array([[1.0, 0.0, -beta], [0.0, 1.0, -gamma], [big_omega**2, 0.0, 1.0 - am]])
    right = np.array([[1.0, 1.0, 0.5 - beta], [0.0, 1.0, 1.0 - gamma], [0.0, 0.0, -am]])
    roots = np.linalg.eigvals(np.linalg.solve(left, right))
    root = roots[np.argmax(np.abs(roots.imag))]
    log = np.log(complex(root))
    discrete = abs(log)
    return big_omega / discrete - 1.0, -log.real / discrete
