"""Compiled kernels of the spatial continuum cable (theory/continuum.md §2–3, theory/time-schemes.md §1, theory/moorings.md): loads and end rows.

Unknowns per node ``Y = (T, u, v, w, phi, theta)``; ``V = u t + v n + w b`` with the frame of
theory/continuum.md §2 about the pole ``p`` of the current chart, and every vector (weight direction,
current, prescribed velocities) given in chart coordinates ``(e1, e2, p)``. Projecting
momentum and compatibility on ``(t, n, b)`` gives ``M(Y) Y_t + K(Y) Y_s = F(Y)`` with

    row 0  m (u_t - v phi_t + w cos(phi) theta_t)            - T_s                 = f_t
    row 1  mn (v_t + u phi_t - w sin(phi) theta_t)           - T phi_s             = f_n
    row 2  mn (w_t - u cos(phi) theta_t + v sin(phi) theta_t) + T cos(phi) theta_s  = f_b
    row 3  T_t / EA       - u_s + v phi_s - w cos(phi) theta_s                     = 0
    row 4  (1 + e) phi_t  - v_s - u phi_s + w sin(phi) theta_s                     = 0
    row 5  -(1 + e) cos(phi) theta_t - w_s + u cos(phi) theta_s - v sin(phi) theta_s = 0

(``mn = m + m_a``; frame identities ``t_phi = n``, ``t_theta = -cos(phi) b``, ``n_phi = -t``,
``n_theta = sin(phi) b``, ``b_theta = cos(phi) t - sin(phi) n``). For ``w = 0`` and constant
``theta`` rows 0, 1, 3, 4 are the planar equations of theory/continuum.md §1; :mod:`.oracle_sympy3d` derives
the same system symbolically and the tests compare. ``M`` is singular where ``cos(phi) = 0``
(the tangent along the pole): the driver re-charts the pole before that happens.

Loads as in the plane (:mod:`kernels2d`): weight and drag (:func:`node_load3`), and
(:func:`extra_load3`) the waves' fluid inertia ``(m - w0/g) a_w + m_a (a_w)_normal`` and seabed
contact with Coulomb friction along the line and across it: with ``a`` the line's direction on
the seabed (from the previous step, in the nodal data) and ``l = n_b x a``,
``F = N n_b - mu_a N tanh(V.a / v_s) a - mu_l N tanh(V.l / v_s) l``. Inline bodies, the winch and
the parameter rows per interval are :mod:`kanat.continuum.rows3d`'s; the ends add a surface
buoy's waterplane, the body's wave inertia and the winch's pay-out as in the plane. Bending
stiffness adds four unknowns per node and its own kernel, :mod:`kanat.continuum.bending3d`, which
only a case with bending stiffness compiles.

Box method and generalized-α exactly as the planar kernels, with the two-node averages of
``M``, ``K`` and ``F``; rows are ``[start (3); interval 0 (6); ...; far end (3)]``, a band of 8
sub- and super-diagonals. All derivatives are written out -- ``M(m) r`` and ``K(k) g``
(:func:`d_mass_times`, :func:`d_stiffness_times`), the nodal loads (:func:`node_load3_jacobian`,
:func:`extra_load3_jacobian`) and the ends (:func:`end_jacobian3`) -- so a run compiles real
kernels only; the complex-step oracle (:mod:`kanat.continuum.oracle_complex_step3d`) is compiled by the tests.
As in :mod:`kernels2d`, scalar loops only (no array expressions, slice copies or ``@``).

The code is in :mod:`.layout3d` (data layout), :mod:`.loads3d` (frame, matrices, loads, ends),
:mod:`.rows3d` (interval rows, :func:`assemble3`) and :mod:`.bending3d` (with bending stiffness,
:func:`assemble3_bending`), all below this module: import the kernels from here. As in
:mod:`.kernels2d`, the layout is plain constants, and the
two kernels a run calls are entry points: the extension compiled at install (:mod:`kanat.aot`) when
it is current, else numba's kernels.
"""
from __future__ import annotations

from kanat import aot
from kanat.continuum.layout3d import (  # noqa: F401  re-exported: this module is the kernels' one import
    LOWER, UPPER, B3_KIND, B3_V0, B3_V1, B3_V2, B3_MASS, B3_BUOY, B3_DRAG, B3_F0, B3_F1, B3_F2, B3_WAVE, B3_WPA,
    B3_HEIGHT, B3_ETA, B3_PAYOUT, NBPAR3, UX3, AX3, RX3, DX3, NENV3, NV_BENDING, WIDTH_BENDING, B3_CLAMP, B3_PHI0,
    B3_THETA0, NBPAR3_BENDING)

from kanat.continuum.loads3d import (  # noqa: F401  re-exported: numba's kernels (no numba imported)
    frame, node_load3, node_load3_jacobian, mass_times, stiffness_times, mass_matrix, stiffness_matrix,
    d_mass_times, d_stiffness_times, seabed_force3, seabed_force3_jacobian, extra_load3, extra_load3_jacobian,
    surface_buoyancy3, end_jacobian3)

SpatialStep = aot.record(
    "SpatialStep", "kanat.continuum.kernels3d",
    previous=aot.F2,                        # y: the nodal states at the start of the step (N+1, nv)
    rate=aot.F2,                            # d: their time derivative (N+1, nv)
    water=aot.F2,                           # env: nodal data in chart coordinates (N+1, NENV3), layout3d
    vertical=aot.F1,                        # up: the chart components of the vertical z (3,)
    intervals=aot.F2,                       # P: every interval's parameter row (N, n_par), layout2d
    start=aot.F1, end=aot.F1,               # b0, b1: the end conditions (NBPAR3, NBPAR3_BENDING with bending)
    extras=aot.F1,                          # None for a plain cable (rows3d docstring), else a marker (1,)
)
"""What one step of the spatial box scheme knows before its Newton iteration, as :func:`assemble3`
and :func:`assemble3_bending` read it: one field per input, built by
:func:`kanat.continuum.spatial.step_data` and nowhere else (as :class:`kernels2d.PlanarStep`)."""

# the compiled entries' arguments: x, step, res, band; the plain cable's version (extras None) first
_VERSIONS = tuple((aot.F2, step, aot.F1, aot.F2) for step in (SpatialStep.narrowed(extras=None), SpatialStep))
assemble3 = aot.register("assemble3", "kanat.continuum.rows3d", *_VERSIONS)
assemble3_bending = aot.register("assemble3_bending", "kanat.continuum.bending3d", *_VERSIONS)
