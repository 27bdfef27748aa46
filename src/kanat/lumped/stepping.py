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

With seabed contact each node ``n`` of mass ``m_n`` and contact area ``A_n`` is an oscillator of
``omega = sqrt(k_b A_n / m_n)`` and ``sigma = c_b A_n / m_n`` (contact stiffness and damping, eq.
4), and the regularized friction at rest adds the real rate ``mu W_n / (v_s m_n)`` for the node's
weight ``W_n`` (:mod:`kanat.physics.contact`); they compete in the maximum of eq. (5).

Bending stiffness adds the highest frequency of the discrete fourth difference,
``omega = 4 sqrt(k / (m l^2))`` per interior node (:func:`kanat.lumped.bending.bending_frequency`).

``limit`` is the scheme's ``stability_limit`` (largest stable ``|lambda h|`` near the
imaginary axis; RK4's region reaches as far along the negative real axis, 2.79). The consistent mass matrix raises the highest frequency by ``sqrt(3)``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.lumped import entries
from kanat.lumped.bending import bending_frequency
from kanat.model.limits import EXPLICIT_SAFETY
from kanat.physics.contact import SLIP_VELOCITY

SAFETY = EXPLICIT_SAFETY     # margin below the stability limit (0.8)
CONSISTENT_FACTOR = math.sqrt(3.0)   # highest eigenvalue of [[2,1],[1,2]]/6 vs lumped 1/2: 3x in omega^2
STRAIN_REFERENCE = 0.02      # strain at which nonlinear laws' stiffness sets the step (or more if stretched)
IMPLICIT_COST = 9.0          # force evaluations of the fused RK4 path one fused Newton iteration (tangent,
                             # band LU) is worth: 8-10 on 20-100 element lines and Bezverkhyi's network,
                             # 3-4 on 400 (benchmarks/RESULTS.md, "lumped implicit cost")
STEPS_PER_PERIOD = 400.0     # implicit steps per period of the shortest excitation (default dt): MoorDyn's WD0050
                             # chain driven at 9 and 12 s (friction 0.5, a chain slapping the seabed) is as accurate
                             # at 0.1 s as at 0.025 s (fairlead tension within 0.5 % of MoorDyn) but costs 5.2 s of
                             # CPU there (9 Newton iterations a step, 9741 steps retaken by rk4), 4.4 at 0.05 s,
                             # 4.2 at 0.025 s
IMPLICIT_ITERATIONS = 3.0    # Newton iterations per implicit step: 2.2-2.6 measured on single lines at
                             # 0.05-0.1 s, 5.5 on Bezverkhyi's network in waves


@dataclass(frozen=True)
class StepInfo:
    """The explicit stability bound of a network state.

    Attributes
    ----------
    axial_period : float
        Shortest axial nodal period, eq. (3) [s].
    omega_max : float
        ``max |lambda_k|``, eq. (4) [1/s].
    element : int
        The element that sets it.
    """

    axial_period: float
    omega_max: float
    element: int

    def safe_step(self, scheme) -> float:
        """Eq. (5) for an explicit ``scheme`` [s]."""
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
    if seabed is not None:
        area = net.node_contact_area * (inv > 0)
        contact = (spectral_radius(np.sqrt(seabed.stiffness * area * inv), seabed.damping * area * inv)
                   + max(seabed.friction, seabed.lateral_friction) * net.node_weight / SLIP_VELOCITY * inv)
        top = max(top, float(np.max(contact, initial=0.0)))
    return StepInfo(2.0 * math.pi / max(float(np.max(omega, initial=0.0)), 1e-300), top, k)


def fit_step(h_max: float, output_dt: float) -> float:
    """The largest step ``<= h_max`` that divides ``output_dt`` exactly."""
    return output_dt / math.ceil(output_dt / h_max - 1e-9)


def choose_scheme(info: StepInfo, dt: float, schemes: dict, explicit_only: bool = False):
    """The cheapest safe scheme for a case that names none: RK4 at its safe step, or the
    implicit scheme at ``dt``, by force evaluations per simulated second (RK4 when
    ``explicit_only``: 6-DOF bodies)."""
    rk4, implicit = schemes["rk4"](), schemes["generalized-alpha-lumped"]()
    if explicit_only:
        return rk4
    explicit_cost = rk4.evaluations_per_step / min(info.safe_step(rk4), dt)
    implicit_cost = IMPLICIT_ITERATIONS * (1.0 + IMPLICIT_COST) / dt
    return rk4 if explicit_cost <= implicit_cost else implicit


def excitation_period(system) -> float | None:
    """The shortest period [s] of what drives the run: the prescribed motion's harmonics and the
    sea's components (those of at least a tenth of the largest amplitude); None without either."""
    from kanat.physics.motion import Harmonics

    periods = []
    if isinstance(system.motion, Harmonics):
        periods.extend(2.0 * math.pi / system.motion.omega[system.motion.amplitude > 0.0])
    sea = system.sea
    if sea is not None and len(sea.omega):
        amplitude = np.asarray(sea.amplitude, float)
        periods.extend(2.0 * math.pi / np.asarray(sea.omega, float)[amplitude >= 0.1 * amplitude.max()])
    return min(periods) if periods else None


def implicit_default(system, default: float) -> float:
    """The implicit scheme's step without ``dt``: ``default`` (``simulation.step_or_default``), or
    less where the run is driven: :data:`STEPS_PER_PERIOD` steps per :func:`excitation_period`."""
    period = excitation_period(system)
    return default if period is None else min(default, period / STEPS_PER_PERIOD)
