"""Compiled kernels of the planar continuum cable (theory/continuum.md §1, §3, theory/time-schemes.md §1, theory/moorings.md): loads and end rows.

The unknowns of a step are the nodal states ``X = Y^{n+1}``: ``Y = (T, u, v, phi)`` for a
perfectly flexible cable, ``Y = (T, u, v, phi, S, Mb)`` (shear and bending moment) when a line
type has bending stiffness (:mod:`kanat.continuum.rows2d` writes the interval rows of both).
The residual rows are ordered ``[start end (nv/2); interval 0 (nv); ...; interval N-1 (nv); far
end (nv/2)]``, so the Jacobian is banded (5 sub- and super-diagonals for nv = 4, 8 for nv = 6)
and one Newton iteration costs O(N).

Each interval has its own parameter row (``P[j]``, layout below): a cable of several sections
changes properties at the node between two intervals and nothing is averaged across it (the
nodal loads of an interval's two nodes are evaluated with that interval's row). An interval of
kind ``JUNCTION`` joins two nodes at the same arclength and carries an inline body (an
attachment): its rows are the body's equations, not the cable's. A spherical float's row holds
its diameter, its buoyancy fully submerged and the wave elevation over it (filled per step,
:func:`kanat.continuum.water.float_elevations`): its lift is the immersed share at its predicted
height (:func:`float_immersion`, :mod:`kanat.physics.immersion`).

Nodal loads per unstretched length (f_t, f_n), at the ``[ak]``-weighted state:

* :func:`node_load` -- weight in water and quadratic drag of the velocity relative to the water
  (current plus wave orbital velocity), with the ``sqrt(1 + e)`` factor (theory/continuum.md §1);
* :func:`extra_load` -- the fluid inertia of waves (Morison): Froude–Krylov ``rho A a_w`` on the
  whole water acceleration plus ``m_a (a_w . n)`` on its normal part, ``rho A = m - w0/g`` the
  displaced mass; and seabed contact, the lumped model's law (:mod:`kanat.physics.contact`,
  MoorDyn's convention): with the penetration ``delta = c0 - n_b . r`` below the plane
  ``n_b . r = c0``, a normal force per unstretched length ``N = d (k_b delta + c_b r(delta)
  delta_dot)`` (``N >= 0``, only where ``delta >= 0``; the damping ramps in as ``r = min(1,
  delta / delta_r)`` so the force is continuous where a node strikes) and Coulomb friction
  ``-mu N tanh(V . s_b / v_s) s_b`` along the seabed (``s_b`` the seabed's slope direction in the
  x–z plane, ``v_s`` = :data:`FRICTION_SPEED`).

Positions are not unknowns; a node's position at the ``[ak]`` level is predicted from its own
velocity: ``r^[ak] = r^n + dt ((1 - ak)(1 - gamma) - gamma ak) V^n + dt gamma V^[ak]`` (exact
for a velocity following the scheme's own update), written ``r = R + PRED V`` with ``R`` in the
nodal data and ``PRED = gamma dt``. So contact is implicit and the Jacobian keeps its band.

Ends (theory/continuum.md §3), ``side`` = -1 at ``s = 0`` and +1 at ``s = L``:

* prescribed velocity (tow point, anchor): ``u = V.t + c_w``, ``v = V.n`` (``c_w`` a winch's
  pay-out speed); with bending, ``Mb = 0`` (pinned) or ``phi = phi0`` (clamped);
* body: ``(M_b + M_a) dV/dt = -side (T t + S n) + B z + D + F + (M_a + rho Vol) a_w`` with the
  drag ``D = 0.5 rho C_D S |U_r| U_r`` of the water relative to the body, and for a surface buoy
  the buoyancy ``rho g A_w clip(eta - z, 0, h)`` added to ``B`` (``z`` predicted as above);
  with bending, ``Mb = 0``;
* free: ``T = 0`` and the end node's normal momentum; with bending ``T = S = Mb = 0``.

Every function here has its exact derivative beside it (``*_jacobian``); the complex-capable
residuals (``|x| x`` written ``x sqrt(x x)``) and the all-complex-step oracle live in
:mod:`kanat.continuum.oracle_complex_step2d`, compiled by the tests only. Scalar loops only -- no array
expressions, slice copies or ``@`` -- which keeps numba's compile short (:mod:`kanat.jit`).

The code is in :mod:`.layout2d` (data layout), :mod:`.loads2d` (loads, ends) and :mod:`.rows2d`
(interval rows, :func:`assemble`), all below this module: import the kernels from here. The
layout is plain constants; :func:`assemble`, the one kernel a run calls, is an entry point
(:class:`kanat.aot.EntryPoint`): the extension compiled at install (:mod:`kanat.aot`) when it is
current, so such a run never imports numba, else numba's kernel.
"""
from __future__ import annotations

from kanat import aot
from kanat.continuum.layout2d import (  # noqa: F401  re-exported: this module is the kernels' one import
    M, MA, W0, EA, DIAM, CN, CT, RHO, DS, AM, AK, GAMMA, DT, INERTIA, GRAV, EI, CONV, PRED, KIND, SECTION, SB_ON,
    SB_K, SB_C, SB_MUA, SB_MUL, SB_C0, SB_N0, SB_N1, SB_N2, JB_MASS, JB_BUOY, JB_DRAG, JB_F0, JB_F1, JB_F2, JB_WAVE,
    TFLOOR, JB_DIAMETER, JB_FULL, JB_ETA,
    NPAR, LAW, CABLE, JUNCTION, UX, UZ, AX, AZ, RX, RZ, NENV, VELOCITY, BODY, FREE, B_KIND, B_V0, B_V1, B_MASS,
    B_BUOY, B_DRAG, B_F0, B_F1, B_WAVE, B_WPA, B_HEIGHT, B_ETA, B_PAYOUT, B_CLAMP, B_PHI0, NBPAR, FRICTION_SPEED,
    CONTACT_RAMP, STEP, LOWER, UPPER, bandwidth)

PlanarStep = aot.record(
    "PlanarStep", "kanat.continuum.kernels2d",
    previous=aot.F2,                        # y: the nodal states at the start of the step (N+1, nv)
    rate=aot.F2,                            # d: their time derivative (N+1, nv)
    water=aot.F2,                           # env: nodal water velocity, acceleration and position (N+1, NENV)
    intervals=aot.F2,                       # P: every interval's parameter row (N, n_par), layout2d
    start=aot.F1, end=aot.F1,               # b0, b1: the end conditions at s = 0 and s = L (NBPAR)
    extras=aot.F1,                          # None for a plain cable (rows2d docstring), else a marker (1,)
)
"""What one step of the planar box scheme knows before its Newton iteration, as :func:`assemble`
reads it (``step.intervals[j, DS]``): one field per input, built by
:func:`kanat.continuum.stepper.step_data` and nowhere else (docs/contributing.md, adding a line
property). The unknowns ``x`` and the outputs ``res``, ``band`` stay arguments of their own: they
change at every iteration, the record only from step to step."""

# the compiled entry's arguments: x, step, res, band; the plain cable's version (extras None) first
assemble = aot.register("assemble", "kanat.continuum.rows2d", *(
    (aot.F2, step, aot.F1, aot.F2) for step in (PlanarStep.narrowed(extras=None), PlanarStep)))

from kanat.continuum.loads2d import (  # noqa: E402, F401  re-exported: numba's kernels (no numba imported)
    strain, compliance, transverse_tension, node_load, node_load_jacobian, smooth_sign, seabed_force,
    seabed_force_jacobian, extra_load, extra_load_jacobian, weighted, surface_buoyancy, float_immersion, end_jacobian)
