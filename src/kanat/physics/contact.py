"""Seabed contact of line nodes (theory/moorings.md §3 "Seabed contact"; MoorDyn's kbot/cbot convention).

Node ``n`` carries the contact area ``A_n = sum d L0 / 2`` of its elements, plus the
``seabed_area`` of a point body on it (its bearing area: an anchor or sinker that lands). With the seabed's
upward unit normal ``nu`` and the node's penetration ``delta = (h(x, y) - z) nu_z`` (the
normal distance below the seabed, :meth:`kanat.physics.seabed.PlaneSeabed.penetration`)::

    (1)  N = max(0, k_b delta - c_b r(delta) (v . nu)) A_n   if delta > 0, else 0   [N]
         r(delta) = min(1, delta / delta_r)                   damping ramp
    (2)  F_n = N nu                                         normal force
    (3)  F_a = -mu_a N tanh(v_a / v_s) a                    friction along the line
    (4)  F_l = -mu_l N tanh(|v_l| / v_s) v_l / |v_l|        friction across the line

``k_b`` [Pa/m], ``c_b`` [Pa s/m] (``environment.seabed.stiffness``, ``damping``), as MoorDyn,
but with the damping ramped in over the first ``delta_r`` = :data:`DAMPING_RAMP` (0.2 mm) of
penetration: MoorDyn's force jumps from 0 to ``c_b |v| A`` where a moving node strikes the
seabed, which an implicit scheme's Newton iteration cannot follow (it cycles between touching
and not); the ramp makes it continuous, and the tangent takes the ramp's slope where it
stiffens (a node moving in) and ``k_b`` elsewhere (a negative slope, lifting off, would make it
indefinite); ``a`` the
line's direction at the node (sum of its elements' unit tangents) projected on the seabed
plane; ``v_a = v . a`` and ``v_l = v - (v . nu) nu - v_a a``. Coulomb friction is
regularized by ``tanh`` with the velocity scale ``v_s`` = :data:`SLIP_VELOCITY`: smooth, so
the implicit scheme's Newton iteration sees a continuous tangent (its ``dF/dv``, ``mu N / v_s``
at rest, is taken at the node's slip in the tangent: :func:`contact_tangent`, eqs. 5-6), and a line loaded below its friction limit
creeps at ``v_s atanh(load / (mu N))`` at most (0.55 v_s at half the limit).

In a static equilibrium velocities are zero, and friction depends on how the line got
there. The equilibrium takes MoorPy's assumption (the line laid straight from its anchor,
then pulled towards the fairlead, so friction is mobilized towards the anchor wherever the
line has stretched): friction along the line is ``-mu_a N tanh(u / u_s) a`` with ``u`` the
node's displacement along ``a`` from where it lay, ``x_ref + s a`` (:data:`SLIP_DISPLACEMENT`
``= u_s``); nodes of a cable with no anchor on the seabed feel none, and none across.

The kernels take two named records, each built in one place: the seabed's geometry, a
:data:`Bed` (the plane ``z = -depth + x tan(slope)``, :func:`bed_of`), and the law of eqs. (1)-(4)
with its parameters, a :data:`ContactLaw` (:func:`contact_law`); a bathymetry grid would be
another record with the same ``height`` and ``normal`` role (:mod:`kanat.physics.seabed`).
"""
from __future__ import annotations

import math

from kanat import aot
from kanat.aot import BOOL, FLOAT
from kanat.jit import inner, kernel
from kanat.physics.seabed import (  # noqa: F401  re-exported: v_s of eqs. (3)-(4), the penetration allowed
    PENETRATION_FLOOR, PENETRATION_MARGIN, SLIP_VELOCITY, PlaneSeabed)

SLIP_DISPLACEMENT = 1.0e-4  # m, u_s of the equilibrium's friction
DAMPING_RAMP = 2.0e-4      # m, delta_r of eq. (1) (the continuum model ramps over 1 mm: kernels2d.CONTACT_RAMP)

Bed = aot.record(
    "Bed", "kanat.physics.contact",
    depth=FLOAT,                            # the seabed's depth below the surface at x = 0 [m]
    tan_slope=FLOAT, cos_slope=FLOAT,       # tan, cos and sin of its slope, rising towards +x
    sin_slope=FLOAT,
)
"""The plane seabed ``z = -depth + x tan(slope)`` as the kernels read it (:func:`penetration_at`),
built by :func:`bed_of`."""
ContactLaw = aot.record(
    "ContactLaw", "kanat.physics.contact",
    stiffness=FLOAT, damping=FLOAT,         # k_b [Pa/m], c_b [Pa s/m] of eq. (1)
    friction_axial=FLOAT,                   # mu_a of eq. (3), 0: none
    friction_lateral=FLOAT,                 # mu_l of eq. (4), 0: none
    slip_velocity=FLOAT,                    # v_s of eqs. (3)-(4) [m/s]
    equilibrium=BOOL,                       # True: the equilibrium's friction in displacement, u_s
    slip_displacement=FLOAT,                # u_s of the equilibrium's friction [m]
)
"""The contact law of eqs. (1)-(4) and its parameters as the kernels read them
(:func:`contact_forces`, :func:`contact_tangent`), built by :func:`contact_law`."""


def bed_of(seabed) -> Bed:
    """The kernel form of a seabed geometry, a :data:`Bed`.

    Raises
    ------
    TypeError
        For a geometry this kernel does not know yet (only :class:`PlaneSeabed`).
    """
    if isinstance(seabed, PlaneSeabed):
        angle = math.radians(seabed.slope_deg)
        return Bed(depth=float(seabed.depth), tan_slope=math.tan(angle), cos_slope=math.cos(angle),
                   sin_slope=math.sin(angle))
    raise TypeError(f"no contact kernel for the seabed {type(seabed).__name__}")


def contact_law(seabed_block, equilibrium: bool = False, friction: bool = True) -> ContactLaw:
    """The :data:`ContactLaw` of ``environment.seabed`` (``stiffness``, ``damping``, ``friction``,
    ``lateral_friction``): its friction in velocity (eqs. 3-4, a run) or, with ``equilibrium``, in
    displacement (a static equilibrium); without ``friction``, none (``mu_a = mu_l = 0``)."""
    return ContactLaw(
        stiffness=float(seabed_block.stiffness), damping=float(seabed_block.damping),
        friction_axial=float(seabed_block.friction) if friction else 0.0,
        friction_lateral=float(seabed_block.lateral_friction) if friction else 0.0,
        slip_velocity=SLIP_VELOCITY, equilibrium=bool(equilibrium), slip_displacement=SLIP_DISPLACEMENT)


@inner
def penetration_at(x, y, z, bed):
    """Normal depth below the seabed :data:`Bed` ``bed`` (eq. 1's ``delta``; < 0 above) and the
    normal ``(nx, nz)``."""
    height = -bed.depth + bed.tan_slope * x
    return (height - z) * bed.cos_slope, -bed.sin_slope, bed.cos_slope


@kernel
def contact_forces(x, v, el_i, el_j, area, bed, law, laid, tangent, F, normal_force):
    """Add the seabed contact forces, eqs. (1)-(4), to ``F`` (n, 3) for every node with a contact
    area; ``normal_force`` (n,) gets ``N``.

    Parameters
    ----------
    x, v : ndarray, shape (n, 3)
    el_i, el_j : ndarray of int, shape (m,)
    area : ndarray, shape (n,)
        Contact area ``A_n`` [m^2].
    bed : Bed
        The seabed (:func:`bed_of`).
    law : ContactLaw
        The law's parameters (:func:`contact_law`).
    laid : record of ``origin`` (n, 3), ``direction`` (n, 3), ``distance`` (n,)
        Where each node lay (equilibrium friction): ``x_ref + s a`` (origin, direction, distance);
        a zero direction: none (the lumped model's :class:`kanat.lumped.entries.Laid`).
    tangent : ndarray, shape (n, 3)
        Work array.
    """
    kb, cb, vs = law.stiffness, law.damping, law.slip_velocity
    mu_a, mu_l = law.friction_axial, law.friction_lateral
    n = x.shape[0]
    any_contact = False
    for a in range(n):
        normal_force[a] = 0.0
        if area[a] > 0.0 and penetration_at(x[a, 0], x[a, 1], x[a, 2], bed)[0] > 0.0:
            any_contact = True
    if not any_contact:
        return
    friction = mu_a > 0.0 or mu_l > 0.0
    if friction:
        tangent[:, :] = 0.0
        for k in range(el_i.shape[0]):
            i, j = el_i[k], el_j[k]
            d0, d1, d2 = x[j, 0] - x[i, 0], x[j, 1] - x[i, 1], x[j, 2] - x[i, 2]
            inv = 1.0 / max(math.sqrt(d0 * d0 + d1 * d1 + d2 * d2), 1e-300)
            for node in (i, j):
                tangent[node, 0] += d0 * inv
                tangent[node, 1] += d1 * inv
                tangent[node, 2] += d2 * inv
    for a in range(n):
        if area[a] <= 0.0:
            continue
        delta, nx, nz = penetration_at(x[a, 0], x[a, 1], x[a, 2], bed)
        if delta <= 0.0:
            continue
        vn = v[a, 0] * nx + v[a, 2] * nz
        N = max(0.0, kb * delta - cb * min(delta / DAMPING_RAMP, 1.0) * vn) * area[a]
        normal_force[a] = N
        F[a, 0] += N * nx
        F[a, 2] += N * nz
        if friction and N > 0.0:
            if law.equilibrium:
                f0, f1, f2 = laid_friction(x[a, 0] - laid.origin[a, 0], x[a, 1] - laid.origin[a, 1],
                                           x[a, 2] - laid.origin[a, 2], laid.direction[a, 0], laid.direction[a, 1],
                                           laid.direction[a, 2], laid.distance[a], mu_a * N, law.slip_displacement)
            else:
                t0, t1, t2 = plane_tangent(tangent[a, 0], tangent[a, 1], tangent[a, 2], nx, nz)
                f0, f1, f2 = slip_friction(v[a, 0], v[a, 1], v[a, 2], N, nx, nz, t0, t1, t2, mu_a, mu_l, vs)
            F[a, 0] -= f0
            F[a, 1] -= f1
            F[a, 2] -= f2


@inner
def plane_tangent(t0, t1, t2, nx, nz):
    """The line's direction at a node ``(t0, t1, t2)`` (a sum of unit vectors) projected on the seabed
    plane of normal ``(nx, 0, nz)`` and normalized (zero where it is normal to the plane): eq. (3)'s ``a``.

    The friction helpers take and return scalars: a compiled call that passes arrays, once per node in
    contact, cost more than the friction itself (docs/performance.md, "Calls in the element loops")."""
    tn = t0 * nx + t2 * nz
    t0, t2 = t0 - tn * nx, t2 - tn * nz
    size = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
    if size > 0.0:
        t0, t1, t2 = t0 / size, t1 / size, t2 / size
    return t0, t1, t2


@inner
def slip(v0, v1, v2, nx, nz, t0, t1, t2):
    """A node's velocity ``v`` in the seabed plane of normal ``(nx, 0, nz)``, split along the line's
    direction ``a = (t0, t1, t2)`` and across it: ``v_a`` and ``v_l`` of eqs. (3)-(4)."""
    vn = v0 * nx + v2 * nz
    s0, s1, s2 = v0 - vn * nx, v1, v2 - vn * nz
    va = s0 * t0 + s1 * t1 + s2 * t2
    return va, s0 - va * t0, s1 - va * t1, s2 - va * t2


@inner
def slip_friction(v0, v1, v2, N, nx, nz, t0, t1, t2, mu_a, mu_l, vs):
    """Eqs. (3)-(4): the friction ``-(F_a + F_l)`` of a node moving at ``v`` under the normal force ``N``,
    ``a = (t0, t1, t2)`` (:func:`plane_tangent`); the caller subtracts it."""
    va, l0, l1, l2 = slip(v0, v1, v2, nx, nz, t0, t1, t2)
    fa = mu_a * N * math.tanh(va / vs)
    speed = math.sqrt(l0 * l0 + l1 * l1 + l2 * l2)
    fl = mu_l * N * math.tanh(speed / vs) / speed if speed > 0.0 else 0.0
    return fa * t0 + fl * l0, fa * t1 + fl * l1, fa * t2 + fl * l2


@inner
def laid_friction(r0, r1, r2, d0, d1, d2, s, limit, slip_displacement):
    """The equilibrium's friction (module docstring) of a node ``r`` from where its line was laid, along the
    laid direction ``d`` at distance ``s``, ``limit = mu_a N``; none where ``d`` is zero. The caller subtracts it."""
    if d0 == 0.0 and d1 == 0.0 and d2 == 0.0:
        return 0.0, 0.0, 0.0
    f = limit * math.tanh((r0 * d0 + r1 * d1 + r2 * d2 - s) / slip_displacement)
    return f * d0, f * d1, f * d2


@kernel
def contact_tangent(x, v, area, bed, law, normal_force, line_tangent, K, C):
    """Node blocks of ``-dF/dx`` (``K``) and ``-dF/dv`` (``C``) of eqs. (1)-(4), shape (n, 3, 3), at
    nodes the seabed pushes: ``max(k_b, dN/d delta) A nu nu^T`` and ``c_b r A nu nu^T``, and the
    friction's derivative in velocity at the node's own slip (``dN/dv`` and the turn of the line's
    direction left out)::

        (5)  dF_a/dv = -mu_a N sech^2(v_a / v_s) / v_s  a a^T
        (6)  dF_l/dv = -mu_l N [sech^2(|v_l| / v_s) / v_s  e e^T + tanh(|v_l| / v_s) / |v_l|  (P - a a^T - e e^T)]

    with ``e = v_l / |v_l|`` and ``P = I - nu nu^T`` (both ``mu N / v_s`` across the seabed plane at
    rest). The derivative at the slip, not at rest: a node sliding at a few ``v_s`` has a friction
    force almost independent of its speed, and the slope at rest (``mu N / v_s``, 10^2-10^4 times
    larger there) made Newton's iteration contract by only 0.6 per iteration on a chain sliding at
    3-9 mm/s (MoorDyn's WD0050 chain, friction 0.5, at the start of a driven run).
    ``bed`` is a :data:`Bed`, ``law`` a :data:`ContactLaw`; ``line_tangent`` holds the line's
    direction at each node, as :func:`contact_forces` left it."""
    kb, cb, vs = law.stiffness, law.damping, law.slip_velocity
    mu_a, mu_l = law.friction_axial, law.friction_lateral
    friction = mu_a > 0.0 or mu_l > 0.0
    for a in range(x.shape[0]):
        for r in range(3):
            for q in range(3):
                K[a, r, q] = 0.0
                C[a, r, q] = 0.0
        if normal_force[a] <= 0.0:
            continue
        delta, nx, nz = penetration_at(x[a, 0], x[a, 1], x[a, 2], bed)
        nrm = (nx, 0.0, nz)
        ramp, stiff = 1.0, kb
        if delta < DAMPING_RAMP:      # the ramp's slope where it stiffens (a node moving in), else kb
            ramp = delta / DAMPING_RAMP
            stiff = max(kb, kb - cb * (v[a, 0] * nx + v[a, 2] * nz) / DAMPING_RAMP)
        for r in range(3):
            for q in range(3):
                K[a, r, q] = stiff * area[a] * nrm[r] * nrm[q]
                C[a, r, q] = cb * ramp * area[a] * nrm[r] * nrm[q]
        if friction:
            t0, t1, t2 = plane_tangent(line_tangent[a, 0], line_tangent[a, 1], line_tangent[a, 2], nx, nz)
            along, slip, turn, e0, e1, e2 = friction_slopes(v[a, 0], v[a, 1], v[a, 2], normal_force[a], nx, nz,
                                                            t0, t1, t2, mu_a, mu_l, vs)
            nrm, tan, lat = (nx, 0.0, nz), (t0, t1, t2), (e0, e1, e2)
            for r in range(3):
                for q in range(3):
                    plane = (1.0 if r == q else 0.0) - nrm[r] * nrm[q] - tan[r] * tan[q]
                    C[a, r, q] += (along * tan[r] * tan[q] + slip * lat[r] * lat[q]
                                   + turn * (plane - lat[r] * lat[q]))


@inner
def friction_slopes(v0, v1, v2, N, nx, nz, t0, t1, t2, mu_a, mu_l, vs):
    """The coefficients of eqs. (5)-(6) of a node moving at ``v`` along ``a = (t0, t1, t2)``
    (:func:`plane_tangent`): ``mu_a N sech^2(v_a / v_s) / v_s``, ``mu_l N sech^2(|v_l| / v_s) / v_s``,
    ``mu_l N tanh(|v_l| / v_s) / |v_l|`` and ``e`` (zero, and both lateral ones ``mu_l N / v_s``, at rest
    across the line)."""
    va, l0, l1, l2 = slip(v0, v1, v2, nx, nz, t0, t1, t2)
    speed = math.sqrt(l0 * l0 + l1 * l1 + l2 * l2)
    along = mu_a * N / vs / math.cosh(va / vs) ** 2
    if speed > 1e-9 * vs:
        return (along, mu_l * N / vs / math.cosh(speed / vs) ** 2, mu_l * N * math.tanh(speed / vs) / speed,
                l0 / speed, l1 / speed, l2 / speed)
    return along, mu_l * N / vs, mu_l * N / vs, 0.0, 0.0, 0.0
