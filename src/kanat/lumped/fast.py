"""Fused explicit stepping: many RK4 or ABM4 steps of a lumped network in one compiled call.

The Python path (:class:`kanat.lumped.system.LumpedSystem` ``rhs`` driven step by step by
:mod:`kanat.lumped.integrators`) costs some 50-200 us of interpreter and NumPy overhead per
force evaluation; explicit schemes take thousands of small steps per simulated second, so
that overhead dominates. Here the whole right-hand side — prescribed nodes, current
profile, wave kinematics, element forces (:func:`kernels.element_forces`), body loads, surface
buoys, the lumped-mass solve — and the per-step tension and snap-event bookkeeping run
inside numba. The equations are those of :mod:`kanat.lumped.system` (eqs. 1-2) and
:mod:`kanat.physics.waves` (eqs. 2-5); the Python path is this module's twin, and the
tests compare them.

It applies to the lumped mass matrix and the built-in ``rk4`` and ``abm4`` schemes
(:func:`supports`); the driver falls back to the Python path otherwise. The vessel's
tow point is sampled on the half-step grid of each call (an :class:`kanat.lumped.entries.Track`,
built by :func:`kanat.lumped.advance.track_samples`).
"""
from __future__ import annotations

import math

import numpy as np
from kanat.jit import inner, kernel

from kanat.lumped import kernels, rigid
from kanat.lumped.bending import bending_forces
from kanat.physics.contact import contact_forces

EVENT_BUFFER_MIN = 1024     # closed snap events held before the kernel hands them back


# --- environment --------------------------------------------------------------------------
@inner
def ramp_at(t, duration):
    """The half-cosine ramp of :func:`kanat.physics.ramp.ramp_factor` (its twin)."""
    if duration <= 0.0 or t >= duration:
        return 1.0
    if t <= 0.0:
        return 0.0
    return 0.5 * (1.0 - math.cos(math.pi * t / duration))


@inner
def current_at(points, cz, cu, scale, u):
    """Set ``u`` (k, 3) to ``scale`` times the current at the heights ``points[:, 2]`` from a
    piecewise-linear profile (``cz`` ascending, ``cu`` (k, 3)); constant beyond the ends (as
    ``np.interp``).

    This and :func:`sea_add` loop over the points themselves: a compiled call that passes arrays,
    made once per point, cost 70 times the interpolation (docs/performance.md, "Calls in the
    element loops")."""
    n = cz.shape[0]
    for p in range(points.shape[0]):
        z = points[p, 2]
        i, w = 0, 0.0
        if n > 1 and z >= cz[n - 1]:
            i = n - 1
        elif n > 1 and z > cz[0]:
            while cz[i + 1] < z:
                i += 1
            w = (z - cz[i]) / (cz[i + 1] - cz[i])
        for r in range(3):
            u[p, r] = scale * (cu[i, r] + (w * (cu[i + 1, r] - cu[i, r]) if w > 0.0 else 0.0))


QUARTER_TURN = (1.5707963267341256, 6.077100506303966e-11, 2.0222662487959506e-21)
"""``pi / 2`` split in three (the first two of 33 bits: ``n`` times them is exact for ``|n| < 2^20``);
fdlibm's ``pio2_1``, ``pio2_2``, ``pio2_2t`` (e_rem_pio2.c)."""
TWO_OVER_PI = 0.6366197723675814
SINCOS_REACH = 1.0e6           # |theta| [rad] below which sincos's reduction is exact (n < 2^20 quarter turns)
SIN_TAYLOR = (-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0, -1.0 / 39916800.0, 1.0 / 6227020800.0,
              -1.0 / 1307674368000.0, 1.0 / 355687428096000.0)    # x^3 ... x^17: truncation < 1e-19 at pi/4
COS_TAYLOR = (-0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0, -1.0 / 3628800.0, 1.0 / 479001600.0,
              -1.0 / 87178291200.0, 1.0 / 20922789888000.0, -1.0 / 6402373705728000.0)   # x^2 ... x^18


@inner
def sincos(theta):
    """``(cos theta, sin theta)`` from one reduction: ``theta = n pi / 2 + r`` with ``|r| <= pi / 4``
    (Cody & Waite 1980, *Software Manual for the Elementary Functions*, ch. 8: ``pi / 2`` in three
    parts, :data:`QUARTER_TURN`), the Taylor series of ``sin r`` and ``cos r`` to ``r^17`` and ``r^18``,
    and the quadrant ``n mod 4``, for ``|theta| <= SINCOS_REACH``. Within an ulp or two of ``math.cos``
    and ``math.sin``; one reduction instead of two, and no library call (a loop of them vectorizes)."""
    n = math.floor(theta * TWO_OVER_PI + 0.5)
    r = ((theta - n * QUARTER_TURN[0]) - n * QUARTER_TURN[1]) - n * QUARTER_TURN[2]
    r2 = r * r
    ps = SIN_TAYLOR[7]
    for i in range(6, -1, -1):
        ps = SIN_TAYLOR[i] + r2 * ps
    pc = COS_TAYLOR[8]
    for i in range(7, -1, -1):
        pc = COS_TAYLOR[i] + r2 * pc
    s, c = r + r * r2 * ps, 1.0 + r2 * pc
    quadrant = np.int64(n) & 3
    odd = (quadrant & 1) == 1
    cos_sign = -1.0 if ((quadrant + 1) & 2) == 2 else 1.0
    sin_sign = -1.0 if (quadrant & 2) == 2 else 1.0
    return cos_sign * (s if odd else c), sin_sign * (c if odd else s)


@inner
def stretched(z, eta, depth, wheeler):
    """The height whose kinematics a point at height ``z`` under the surface ``eta`` takes (waves
    eq. 7; ``z`` itself without stretching)."""
    if wheeler <= 0.0:
        return z
    if z > eta:
        return 0.0
    if depth <= 0.0:
        return z - eta
    return depth * (z + depth) / (depth + eta) - depth


@inner
def sea_add(points, t, sea, spare, reach, u, a):
    """Add the wave velocity and acceleration at ``points`` (k, 3) to ``u``, ``a`` (k, 3) (waves eqs. 3-5,
    stretched by eq. 7 and ramped by eq. 8) of the linear ``sea`` (:class:`kanat.lumped.entries.Sea`).

    ``spare`` (4, n) holds the point-independent factors of the ``n`` components at ``t``
    (:func:`sea_factors`) and, in its last two rows, room for ``cos theta_j`` and ``sin theta_j``:
    each phase's cosine and sine are taken once, for the elevation of eq. (7) and for eqs. (3)-(4), by
    :func:`sincos` where every phase is within its reach (``reach``: a bound on ``|theta_j| - k_j |x, y|``
    from :func:`sea_factors`), by ``math`` beyond.
    In finite depth ``C`` and ``S`` of eq. (5) come from one exponential,
    ``C, S = (E +- e^{-2 k h} / E) / (1 - e^{-2 k h})`` with ``E = e^{k z}``.
    """
    amp, omega, k, cosd, sind = sea.amplitude, sea.omega, sea.wavenumber, sea.cos_direction, sea.sin_direction
    phase, depth, inv = sea.phase, sea.depth, sea.depth_factor
    ramp, n = ramp_at(t, sea.ramp), amp.shape[0]
    deep, wt, ct, st = spare[0], spare[1], spare[2], spare[3]
    for p in range(points.shape[0]):
        x, y, z = points[p, 0], points[p, 1], points[p, 2]
        eta = 0.0
        if reach[0] * (abs(x) + abs(y)) + reach[1] <= SINCOS_REACH:
            for j in range(n):
                ct[j], st[j] = sincos(k[j] * (x * cosd[j] + y * sind[j]) - wt[j] + phase[j])
                eta += amp[j] * ct[j]
        else:
            for j in range(n):
                theta = k[j] * (x * cosd[j] + y * sind[j]) - wt[j] + phase[j]
                ct[j], st[j] = math.cos(theta), math.sin(theta)
                eta += amp[j] * ct[j]
        if n > 0:
            z = stretched(z, ramp * eta, depth, sea.wheeler)
        zc = min(z, 0.0) if depth <= 0.0 else min(max(z, -depth), 0.0)
        for j in range(n):
            e = math.exp(k[j] * zc)
            if depth <= 0.0:
                c, s = e, e
            else:
                low = deep[j] / e if e > 0.0 else 0.0           # e^{-k (z + 2 h)}
                c, s = (e + low) * inv[j], (e - low) * inv[j]
            aw, aw2 = ramp * amp[j] * omega[j], ramp * amp[j] * omega[j] * omega[j]
            u[p, 0] += c * ct[j] * aw * cosd[j]
            u[p, 1] += c * ct[j] * aw * sind[j]
            u[p, 2] += s * st[j] * aw
            a[p, 0] += c * st[j] * aw2 * cosd[j]
            a[p, 1] += c * st[j] * aw2 * sind[j]
            a[p, 2] -= s * ct[j] * aw2


@inner
def sea_factors(t, sea, spare, reach):
    """Fill ``spare[0]`` with ``e^{-2 k_j h}`` (finite depth) and ``spare[1]`` with ``omega_j t``,
    the factors :func:`sea_add` shares between points at one instant, and ``reach`` with
    ``max k_j`` and ``max |omega_j t| + |phi_j|`` (``|theta_j|`` is at most the first times
    ``|x| + |y|`` plus the second)."""
    k, omega, phase, depth = sea.wavenumber, sea.omega, sea.phase, sea.depth
    reach[0], reach[1] = 0.0, 0.0
    for j in range(k.shape[0]):
        spare[0, j] = math.exp(-2.0 * k[j] * depth) if depth > 0.0 else 0.0
        spare[1, j] = omega[j] * t
        reach[0], reach[1] = max(reach[0], k[j]), max(reach[1], abs(spare[1, j]) + abs(phase[j]))


@inner
def sea_elevation(x, y, t, sea):
    """Surface elevation at ``(x, y)`` (waves eq. 2, ramped by eq. 8)."""
    amp, omega, k, cosd, sind = sea.amplitude, sea.omega, sea.wavenumber, sea.cos_direction, sea.sin_direction
    phase = sea.phase
    eta = 0.0
    for j in range(amp.shape[0]):
        eta += amp[j] * math.cos(k[j] * (x * cosd[j] + y * sind[j]) - omega[j] * t + phase[j])
    return ramp_at(t, sea.ramp) * eta


@inner
def water(points, t, cz, cu, current_ramp, sea, u, a):
    """Water velocity ``u`` and acceleration ``a`` (k, 3) at ``points`` (k, 3): current (ramped over
    ``current_ramp`` seconds) + waves."""
    current_at(points, cz, cu, ramp_at(t, current_ramp), u)
    a[:, :] = 0.0
    if sea.amplitude.shape[0] > 0:
        spare, reach = np.empty((4, sea.amplitude.shape[0])), np.empty(2)
        sea_factors(t, sea, spare, reach)
        sea_add(points, t, sea, spare, reach, u, a)


# --- vessel ----------------------------------------------------------------------------------
@kernel
def track_states(times, phases, arm, position, velocity, heading):
    """Tow point kinematics at ``times`` (ascending or not) from the track's phases (rows start,
    duration, x, y, heading, speed, acceleration, yaw rate; :mod:`kanat.vessel.track`): closed
    forms of a straight phase of constant acceleration or a turn at constant speed, straight on
    past the last phase; ``arm`` the tow point's lever arm in vessel axes."""
    n = phases.shape[0]
    for q in range(times.shape[0]):
        t = times[q]
        low, high = 0, n - 1                       # the last phase starting at or before t
        while low < high:
            mid = (low + high + 1) // 2
            if phases[mid, 0] <= t:
                low = mid
            else:
                high = mid - 1
        p = low
        start, duration, x0, y0, psi0, v0, a, r = phases[p]
        elapsed = t - start
        tau, over = min(elapsed, duration), max(elapsed - duration, 0.0)
        if r == 0.0:
            run = v0 * tau + 0.5 * a * tau * tau
            psi, v = psi0, v0 + a * tau
            x, y = x0 + run * math.cos(psi0), y0 + run * math.sin(psi0)
        else:
            psi, v = psi0 + r * tau, v0
            x = x0 + v0 / r * (math.sin(psi) - math.sin(psi0))
            y = y0 + v0 / r * (math.cos(psi0) - math.cos(psi))
        c, s = math.cos(psi), math.sin(psi)
        x, y = x + v * over * c, y + v * over * s
        rate = 0.0 if over > 0.0 else r
        rx, ry = c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]
        position[q, 0], position[q, 1], position[q, 2] = x + rx, y + ry, arm[2]
        velocity[q, 0], velocity[q, 1], velocity[q, 2] = v * c - rate * ry, v * s + rate * rx, 0.0
        heading[q] = psi


@kernel
def harmonic_points(times, dof, amplitude, omega, phase, ramp, arms, position, velocity):
    """Points ``arms`` (p, 3) of a vessel that moves by translational harmonics alone (no track, no
    rotation): positions and velocities (k, p, 3) at ``times`` (k,). The twin of
    :func:`kanat.physics.motion_samples.motion_series` with :func:`kanat.physics.motion_samples.point_series`
    at ``R = I``, ``w = 0``: ``q_d = sum_h a_h sin(omega_h t + phi_h)`` over the harmonics of degree of
    freedom ``d`` (``dof``: 0-2 surge, sway, heave), ramped by ``r q`` and ``r q_dot + r' q``
    (:mod:`kanat.physics.ramp` eqs. 1-2); a point at ``r + ((q + r) - r)`` moving at ``q_dot``."""
    for k in range(times.shape[0]):
        t = times[k]
        q0 = q1 = q2 = v0 = v1 = v2 = 0.0
        for h in range(dof.shape[0]):
            arg = t * omega[h] + phase[h]
            a = amplitude[h]
            d, rate = a * math.sin(arg), a * omega[h] * math.cos(arg)
            if dof[h] == 0:
                q0, v0 = q0 + d, v0 + rate
            elif dof[h] == 1:
                q1, v1 = q1 + d, v1 + rate
            else:
                q2, v2 = q2 + d, v2 + rate
        if ramp > 0.0:
            r, dr = ramp_at(t, ramp), 0.0
            if 0.0 < t < ramp:
                dr = 0.5 * math.pi / ramp * math.sin(math.pi * t / ramp)
            v0, v1, v2 = r * v0 + dr * q0, r * v1 + dr * q1, r * v2 + dr * q2
            q0, q1, q2 = r * q0, r * q1, r * q2
        for j in range(arms.shape[0]):
            x, y, z = arms[j, 0], arms[j, 1], arms[j, 2]
            position[k, j, 0], position[k, j, 1], position[k, j, 2] = x + ((q0 + x) - x), y + ((q1 + y) - y), \
                z + ((q2 + z) - z)
            velocity[k, j, 0], velocity[k, j, 1], velocity[k, j, 2] = v0, v1, v2


# --- right-hand side ------------------------------------------------------------------------
@inner
def place(y, vpos, vvel, nodes, x, v):
    """All nodes' positions and velocities from ``y = (q, q_dot)`` (flat, free nodes) and the
    prescribed motion (``vpos, vvel`` (k, 3): the vessel nodes')."""
    free_index, vessel_nodes, anchor_nodes, anchor_pos = nodes.free, nodes.vessel, nodes.anchor, nodes.anchor_position
    nf = free_index.shape[0]
    for k in range(nf):
        for r in range(3):
            x[free_index[k], r] = y[3 * k + r]
            v[free_index[k], r] = y[3 * nf + 3 * k + r]
    for k in range(vessel_nodes.shape[0]):
        for r in range(3):
            x[vessel_nodes[k], r] = vpos[k, r]
            v[vessel_nodes[k], r] = vvel[k, r]
    for k in range(anchor_nodes.shape[0]):
        for r in range(3):
            x[anchor_nodes[k], r] = anchor_pos[k, r]
            v[anchor_nodes[k], r] = 0.0


PACKED = kernels.PACKED      # packed symmetric 3 x 3 mass blocks: xx, yy, zz, xy, xz, yz


@inner
def wetted(x, el_i, el_j, diameter, t, sea, bound, wet):
    """Wetted fraction of every element (kernels.wetted_fraction); the surface elevation is only
    evaluated for elements that reach above ``-bound`` (``bound`` >= the largest elevation)."""
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        top = max(x[i, 2], x[j, 2]) + 0.5 * diameter[k]
        if top < -bound:
            wet[k] = 1.0
            continue
        eta = 0.0
        if bound > 0.0:
            eta = sea_elevation(0.5 * (x[i, 0] + x[j, 0]), 0.5 * (x[i, 1] + x[j, 1]), t, sea)
        wet[k] = kernels.wetted_fraction(x[i, 2], x[j, 2], diameter[k], eta)


@inner
def place_rigid(x, v, rig):
    """Fairleads on their 6-DOF bodies; nothing (and nothing compiled) when ``rig`` is None."""
    if rig is not None:
        rigid.place_fairleads(x, v, rig)


@inner
def seabed_loads(x, v, el_i, el_j, contact, work):
    """Seabed contact forces into ``work.force``; nothing (and nothing compiled) when ``contact`` is None."""
    if contact is not None:
        contact_forces(x, v, el_i, el_j, contact.area, contact.seabed, contact.law, contact.laid,
                       work.line_tangent, work.force, work.normal_force)


@inner
def rigid_loads(t, rig, env, work):
    """6-DOF body accelerations into ``work.body_acceleration`` (rigid.rigid_accelerations), water at their
    reference points; nothing (and nothing compiled) when ``rig`` is None."""
    if rig is not None:
        rigid_water_and_loads(t, rig, env, work)


@inner
def rigid_water_and_loads(t, rig, env, work):
    rho, cz, cu, sea = env.rho, env.current_depths, env.current_velocities, env.sea
    x, v, F, M, acc = work.x, work.v, work.force, work.mass, work.body_acceleration
    ru, ra, reta, rx = work.body_velocity, work.body_water_acceleration, work.body_elevation, work.body_position
    ref = rig.reference_node
    for b in range(ref.shape[0]):
        for r in range(3):
            rx[b, r] = x[ref[b], r]
        reta[b] = sea_elevation(rx[b, 0], rx[b, 1], t, sea) if env.elevation_bound > 0.0 else 0.0
    water(rx, t, cz, cu, env.current_ramp, sea, ru, ra)
    rigid.rigid_accelerations(x, v, F, M, ru, ra, reta, rho, rig, acc)


@inner
def sphere_share(z, eta, diameter):
    """Submerged volume fraction of a sphere of ``diameter`` centred at height ``z`` under the surface
    ``eta``: :func:`kanat.physics.immersion.sphere_fraction`, eq. (1) (its twin, real heights)."""
    u = min(max((eta - z) / diameter + 0.5, 0.0), 1.0)
    return u * u * (3.0 - 2.0 * u)


@inner
def float_loads(t, x, node, diameter, buoyancy, sea, F):
    """Take off ``F`` the buoyancy ``(1 - f) B`` that spherical inline floats lose out of the water
    (``f`` of :func:`sphere_share`; the nodal force holds ``net_buoyancy``, the fully submerged one)."""
    for b in range(node.shape[0]):
        n = node[b]
        share = sphere_share(x[n, 2], sea_elevation(x[n, 0], x[n, 1], t, sea), diameter[b])
        F[n, 2] -= (1.0 - share) * buoyancy[b]


@inner
def loads(t, y, vpos, vvel, heading, nodes, el, bodies, env, work):
    """Nodal forces ``F`` and packed mass blocks ``M`` into ``work`` at ``y = (q, q_dot)`` (flat)
    — system eqs. (1)-(2); seabed contact and 6-DOF bodies included (``bodies.rig``, ``bodies.contact``
    None when a network has neither: their code is then pruned from the compiled kernels)."""
    node_force, node_mass = nodes.force, nodes.mass
    x, v, F, M, T, strain = work.x, work.v, work.force, work.mass, work.tension, work.strain
    mid, uw, aw, wet = work.midpoint, work.water_velocity, work.water_acceleration, work.wet
    bx, bu, ba = work.load_position, work.load_velocity, work.load_acceleration
    rho, g, cz, cu, sea = env.rho, env.g, env.current_depths, env.current_velocities, env.sea
    still, bound, current_ramp = env.still, env.elevation_bound, env.current_ramp
    body_node, drag_area, spreading, fluid_inertia = bodies.load_node, bodies.drag_area, bodies.spreading, \
        bodies.fluid_inertia
    buoy_node, buoy_area, buoy_height = bodies.buoy_node, bodies.buoy_area, bodies.buoy_height
    rig, contact = bodies.rig, bodies.contact
    place(y, vpos, vvel, nodes, x, v)
    place_rigid(x, v, rig)
    el_i, el_j = el.first_node, el.second_node
    if not still:                        # else uw, aw hold the uniform current and zero (FusedArrays)
        for k in range(el_i.shape[0]):
            for r in range(3):
                mid[k, r] = 0.5 * (x[el_i[k], r] + x[el_j[k], r])
        water(mid, t, cz, cu, current_ramp, sea, uw, aw)
    wetted(x, el_i, el_j, el.diameter, t, sea, bound, wet)
    kernels.element_forces(x, v, uw, aw, wet, node_force, node_mass, el, F, M, T, strain)
    bending_forces(x, el.bend_before, el.bend_node, el.bend_after, el.bend_stiffness, F)
    seabed_loads(x, v, el_i, el_j, contact, work)
    if body_node.shape[0] > 0:
        if not still:
            for b in range(body_node.shape[0]):
                for r in range(3):
                    bx[b, r] = x[body_node[b], r]
            water(bx, t, cz, cu, current_ramp, sea, bu, ba)
        kernels.add_body_loads(x, v, bu, ba, body_node, drag_area, spreading, fluid_inertia, rho, heading, F)
    for b in range(buoy_node.shape[0]):
        keel = buoy_node[b]
        immersion = sea_elevation(x[keel, 0], x[keel, 1], t, sea) - x[keel, 2]
        immersion = min(max(immersion, 0.0), buoy_height[b])
        F[buoy_node[b], 2] += rho * g * buoy_area[b] * immersion
    float_loads(t, x, bodies.float_node, bodies.float_diameter, bodies.float_buoyancy, sea, F)
    rigid_loads(t, rig, env, work)


@inner
def derivative(t, y, s, samples, nodes, el, bodies, env, work, dy):
    """``dy/dt`` of ``y = (q, q_dot)`` (flat) with the vessel at sample ``s`` of ``samples`` (an
    :class:`kanat.lumped.entries.Track`) — system eq. (1), lumped mass; leaves the element tensions
    at ``y`` in ``work.tension``."""
    nf = nodes.free.shape[0]
    loads(t, y, samples.position[s], samples.velocity[s], samples.heading[s], nodes, el, bodies, env, work)
    for i in range(3 * nf):
        dy[i] = y[3 * nf + i]
    M, F, free_index = work.mass, work.force, nodes.free
    for k in range(nf):
        n = free_index[k]
        xx, yy, zz, xy, xz, yz = M[n, 0], M[n, 1], M[n, 2], M[n, 3], M[n, 4], M[n, 5]
        c00, c11, c22 = yy * zz - yz * yz, xx * zz - xz * xz, xx * yy - xy * xy
        c01, c02, c12 = xz * yz - xy * zz, xy * yz - yy * xz, xy * xz - xx * yz
        inv = 1.0 / (xx * c00 + xy * c01 + xz * c02)
        b0, b1, b2 = F[n, 0], F[n, 1], F[n, 2]
        dy[3 * nf + 3 * k] = (c00 * b0 + c01 * b1 + c02 * b2) * inv
        dy[3 * nf + 3 * k + 1] = (c01 * b0 + c11 * b1 + c12 * b2) * inv
        dy[3 * nf + 3 * k + 2] = (c02 * b0 + c12 * b1 + c22 * b2) * inv
    local, acc = nodes.rigid_rows, work.body_acceleration
    for b in range(local.shape[0]):
        for q in range(2):
            for r in range(3):
                dy[3 * nf + 3 * local[b, q] + r] = acc[b, q, r]


@kernel
def derivative_at(t, y, s, samples, nodes, el, bodies, env, work, dy):
    """:func:`derivative` called from Python (the tests'; runs call it from the compiled steps)."""
    derivative(t, y, s, samples, nodes, el, bodies, env, work, dy)


# --- bookkeeping after each step --------------------------------------------------------------
@kernel
def snap_update(t, T, snap, events, count):
    """One step of :meth:`kanat.lumped.snap.SnapTracker.update` on its arrays; closed events are
    appended to ``events`` (time, element, peak, rate) from row ``count``; returns the new count."""
    taut, active, start, peak, rate = snap.taut, snap.active, snap.start, snap.peak, snap.rate
    prev_T, prev_time = snap.previous_tension, snap.previous_time
    dt = max(t - prev_time[0], 1e-300)
    for k in range(T.shape[0]):
        r = (T[k] - prev_T[k]) / dt
        now = T[k] > 0.0
        if active[k] and not now:
            events[count, 0], events[count, 1] = start[k], k
            events[count, 2], events[count, 3] = peak[k], rate[k]
            count += 1
            active[k] = False
        if now and not taut[k]:
            start[k], peak[k], rate[k] = t, 0.0, 0.0
            active[k] = True
        if active[k]:
            peak[k] = max(peak[k], T[k])
            rate[k] = max(rate[k], r)
        taut[k] = now
        prev_T[k] = T[k]
    prev_time[0] = t
    return count


@kernel
def tensions_at(y, s, samples, nodes, el, bodies, work):
    """Element tensions at ``y`` into ``work.tension`` (vessel at sample ``s``)."""
    x, v, T = work.x, work.v, work.tension
    place(y, samples.position[s], samples.velocity[s], nodes, x, v)
    place_rigid(x, v, bodies.rig)
    kernels.tensions(x, v, el, T)


@kernel
def finite(y):
    """Whether every entry of ``y`` is finite."""
    for i in range(y.shape[0]):
        if not np.isfinite(y[i]):
            return False
    return True


# --- schemes ----------------------------------------------------------------------------------
@kernel
def rk4_steps(t0, h, steps, y, samples, nodes, el, bodies, env, work, snap, events):
    """Classical RK4 steps from ``(t0, y)``; vessel samples at ``t0 + h j / 2``. The snap update of
    each new state uses the tensions of the next step's first evaluation (at that very state).
    Stops early when the event buffer could overflow or the state is non-finite. Returns
    (steps done, events)."""
    n = y.shape[0]
    k1, k2, k3, k4, tmp = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    count, T = np.int64(0), work.tension       # not a literal 0: see kanat.jit
    for step in range(steps):
        t = t0 + step * h
        derivative(t, y, 2 * step, samples, nodes, el, bodies, env, work, k1)
        if step > 0:                                  # the state reached by the previous step
            count = snap_update(t, T, snap, events, count)
            if count + T.shape[0] > events.shape[0]:
                return step, count
        for i in range(n):
            tmp[i] = y[i] + 0.5 * h * k1[i]
        derivative(t + 0.5 * h, tmp, 2 * step + 1, samples, nodes, el, bodies, env, work, k2)
        for i in range(n):
            tmp[i] = y[i] + 0.5 * h * k2[i]
        derivative(t + 0.5 * h, tmp, 2 * step + 1, samples, nodes, el, bodies, env, work, k3)
        for i in range(n):
            tmp[i] = y[i] + h * k3[i]
        derivative(t + h, tmp, 2 * step + 2, samples, nodes, el, bodies, env, work, k4)
        for i in range(n):
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
        if not finite(y):
            return step + 1, count
    tensions_at(y, 2 * steps, samples, nodes, el, bodies, work)
    return steps, snap_update(t0 + steps * h, T, snap, events, count)


@kernel
def abm4_steps(t0, h, steps, y, history, samples, nodes, el, bodies, env, work, snap, events):
    """ABM4 PECE steps (``history`` (4, n): ``f_n .. f_n-3``, updated in place); as :func:`rk4_steps`."""
    n = y.shape[0]
    fp, yp = np.empty(n), np.empty(n)
    count = np.int64(0)                       # not a literal 0: see kanat.jit
    for step in range(steps):
        if count + work.tension.shape[0] > events.shape[0]:
            return step, count
        t1 = t0 + (step + 1) * h
        for i in range(n):
            yp[i] = y[i] + h * (55.0 * history[0, i] - 59.0 * history[1, i] + 37.0 * history[2, i]
                                - 9.0 * history[3, i]) / 24.0
        derivative(t1, yp, 2 * step + 2, samples, nodes, el, bodies, env, work, fp)
        for i in range(n):
            y[i] += h * (9.0 * fp[i] + 19.0 * history[0, i] - 5.0 * history[1, i] + history[2, i]) / 24.0
            for r in range(3, 0, -1):
                history[r, i] = history[r - 1, i]
        derivative(t1, y, 2 * step + 2, samples, nodes, el, bodies, env, work, history[0])
        count = snap_update(t1, work.tension, snap, events, count)    # the corrector's evaluation is at y
        if not finite(y):
            return step + 1, count
    return steps, count
