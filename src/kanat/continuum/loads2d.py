"""The planar continuum kernels' nodal loads and end rows (:mod:`kanat.continuum.kernels2d` describes them,
:mod:`.layout2d` holds their data layout); :mod:`kanat.continuum.rows2d` assembles the interval rows and
the Newton system from them.
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel
from kanat.continuum.layout2d import *  # noqa: F403  the kernels read the layout as globals


@inner
def _law_segment(T, p):
    """Knot ``(t0, e0)`` and slope of the law's segment holding ``T`` (the last knot below it)."""
    n = int(p[LAW])
    i = 0
    if n > 2:                                  # a linear law (two knots) needs no search
        low, high = 0, n - 2                   # bisection for the last knot < T, within [0, n - 2]
        while low < high:
            mid = (low + high + 1) // 2
            if p[LAW + 1 + mid] < T.real:
                low = mid
            else:
                high = mid - 1
        i = low
    t0, t1 = p[LAW + 1 + i], p[LAW + 2 + i]
    e0, e1 = p[LAW + 1 + n + i], p[LAW + 2 + n + i]
    return t0, e0, (e1 - e0) / (t1 - t0)


@kernel
def transverse_tension(T, p):
    """The tension of the normal momentum row and its slope: ``T`` at or above the floor
    ``T_f = p[TFLOOR]``, below it ``T_f (1 + exp(2 (T - T_f) / T_f)) / 2`` (equal to ``T`` with its slope
    at ``T_f``, falling to ``T_f / 2`` at full compression); ``T`` when ``T_f = 0``.

    A slack interval (``T <= 0``) then keeps a small geometric stiffness: the normal row of a cable
    in compression, ``m v_t = T phi_s + ...``, is ill-posed (its short waves grow at a rate
    ``sqrt(-T / m) pi / ds``), and the floor keeps it a string's, as WHOI Cable's does; the
    tangential and compatibility rows keep the true ``T`` (the compression the result reports).
    Complex-capable (branch on ``Re T``).
    """
    floor = p[TFLOOR]
    if floor <= 0.0 or T.real >= floor:
        return T, 1.0 + 0.0 * T
    slope = np.exp(2.0 * (T - floor) / floor)
    return 0.5 * floor * (1.0 + slope), slope


@kernel
def strain(T, p):
    """Strain ``e(T)`` of the elastic law: piecewise linear through its knots, extended linearly.

    A linear law ``e = T / EA`` is the two knots ``(0, 0), (EA, 1)``. Within a segment the law
    is linear in ``T``, so complex-step derivatives pass through it exactly.
    """
    t0, e0, slope = _law_segment(T.real, p)         # the segment depends on Re T only: one version
    return e0 + slope * (T - t0)


@kernel
def compliance(T, p):
    """``de/dT`` of the elastic law at ``T`` [1/N] (piecewise constant)."""
    return _law_segment(T.real, p)[2]


@kernel
def node_load(T, u, v, phi, ucx, ucz, p):
    """``(f_t, f_n)``: weight in water and drag per unit unstretched length (theory/continuum.md §1)."""
    c, s = np.cos(phi), np.sin(phi)
    root = np.sqrt(1.0 + strain(T, p))
    ur = u - (ucx * c + ucz * s)
    vr = v - (-ucx * s + ucz * c)
    ft = -p[W0] * s - 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT] * ur * np.sqrt(ur * ur) * root
    fn = -p[W0] * c - 0.5 * p[RHO] * p[DIAM] * p[CN] * vr * np.sqrt(vr * vr) * root
    return ft, fn


@inner
def node_load_jacobian(T, u, v, phi, ucx, ucz, p, jac):
    """:func:`node_load` (real) and its derivatives ``jac[i, q] = d f_i / d (T, u, v, phi)_q`` (2, 4).

    With ``a = rho pi d C_t / 2``, ``b = rho d C_n / 2``, ``r = sqrt(1 + e(T))``:
    ``d(x|x|)/dx = 2|x|``, ``dr/dT = e'(T) / (2 r)``, ``du_r/dphi = -v_c``, ``dv_r/dphi = u_c``
    (``u_c, v_c`` the current's tangential and normal components).
    """
    c, s = np.cos(phi), np.sin(phi)
    t0, e0, slope = _law_segment(T, p)
    root = np.sqrt(1.0 + e0 + slope * (T - t0))
    droot = 0.5 * slope / root
    uc, vc = ucx * c + ucz * s, -ucx * s + ucz * c
    ur, vr = u - uc, v - vc
    a = 0.5 * p[RHO] * np.pi * p[DIAM] * p[CT]
    b = 0.5 * p[RHO] * p[DIAM] * p[CN]
    jac[0, 0] = -a * ur * abs(ur) * droot
    jac[0, 1] = -2.0 * a * abs(ur) * root
    jac[0, 2] = 0.0
    jac[0, 3] = -p[W0] * c + 2.0 * a * abs(ur) * root * vc
    jac[1, 0] = -b * vr * abs(vr) * droot
    jac[1, 1] = 0.0
    jac[1, 2] = -2.0 * b * abs(vr) * root
    jac[1, 3] = p[W0] * s - 2.0 * b * abs(vr) * root * uc
    return -p[W0] * s - a * ur * abs(ur) * root, -p[W0] * c - b * vr * abs(vr) * root


@kernel
def smooth_sign(a):
    """``tanh(a)``, also for complex ``a`` far from 0 (where numba's complex tanh overflows)."""
    if a.real > 20.0:
        return 1.0 + 0.0 * a
    if a.real < -20.0:
        return -1.0 + 0.0 * a
    return np.tanh(a)


@kernel
def seabed_force(vx, vz, rx, rz, p):
    """Seabed force per unstretched length ``(F_x, F_z)`` on a node at predicted position
    ``(rx, rz) + PRED (vx, vz)`` moving at ``(vx, vz)`` (module docstring; complex-capable)."""
    n0, n1 = p[SB_N0], p[SB_N1]
    depth = p[SB_C0] - (n0 * (rx + p[PRED] * vx) + n1 * (rz + p[PRED] * vz))
    zero = 0.0 * vx
    if depth.real < 0.0:
        return zero, zero
    ramp = depth / CONTACT_RAMP if depth.real < CONTACT_RAMP else 1.0 + 0.0 * depth
    normal = p[DIAM] * (p[SB_K] * depth - p[SB_C] * ramp * (n0 * vx + n1 * vz))
    if normal.real < 0.0:
        return zero, zero
    friction = -p[SB_MUA] * normal * smooth_sign((n1 * vx - n0 * vz) / FRICTION_SPEED)
    return normal * n0 + friction * n1, normal * n1 - friction * n0


@inner
def seabed_force_jacobian(vx, vz, rx, rz, p, g):
    """:func:`seabed_force` (real) and ``g[i, j] = dF_i / dV_j`` (2, 2)."""
    g[0, 0] = g[0, 1] = g[1, 0] = g[1, 1] = 0.0
    n0, n1 = p[SB_N0], p[SB_N1]
    depth = p[SB_C0] - (n0 * (rx + p[PRED] * vx) + n1 * (rz + p[PRED] * vz))
    if depth < 0.0:
        return 0.0, 0.0
    rate = n0 * vx + n1 * vz
    ramp, slope = (depth / CONTACT_RAMP, 1.0 / CONTACT_RAMP) if depth < CONTACT_RAMP else (1.0, 0.0)
    normal = p[DIAM] * (p[SB_K] * depth - p[SB_C] * ramp * rate)
    if normal < 0.0:
        return 0.0, 0.0
    # dN/dV = stiff n_b: d(depth)/dV = -PRED n_b, d(rate)/dV = n_b
    stiff = -p[DIAM] * ((p[SB_K] - p[SB_C] * slope * rate) * p[PRED] + p[SB_C] * ramp)
    th = np.tanh((n1 * vx - n0 * vz) / FRICTION_SPEED)
    sech2 = 1.0 - th * th
    mu = p[SB_MUA]
    friction = -mu * normal * th
    dfx, dfz = (-mu * (th * stiff * n0 + normal * sech2 / FRICTION_SPEED * n1),
                -mu * (th * stiff * n1 - normal * sech2 / FRICTION_SPEED * n0))   # d friction / dV
    g[0, 0] = n0 * stiff * n0 + n1 * dfx
    g[0, 1] = n0 * stiff * n1 + n1 * dfz
    g[1, 0] = n1 * stiff * n0 - n0 * dfx
    g[1, 1] = n1 * stiff * n1 - n0 * dfz
    return normal * n0 + friction * n1, normal * n1 - friction * n0


@kernel
def extra_load(T, u, v, phi, env, p):
    """``(f_t, f_n)`` of wave inertia and seabed contact (module docstring; complex-capable)."""
    c, s = np.cos(phi), np.sin(phi)
    disp = p[M] - p[W0] / p[GRAV]
    ax, az = env[AX], env[AZ]
    ft = disp * (ax * c + az * s)
    fn = (disp + p[MA]) * (-ax * s + az * c)
    if p[SB_ON] != 0.0:
        fx, fz = seabed_force(u * c - v * s, u * s + v * c, env[RX], env[RZ], p)
        ft = ft + fx * c + fz * s
        fn = fn - fx * s + fz * c
    return ft, fn


@inner
def extra_load_jacobian(T, u, v, phi, env, p, jac):
    """:func:`extra_load` (real) and ``jac[i, q] = d f_i / d (T, u, v, phi)_q`` (2, 4).

    ``V = u t + v n``: ``dV/du = t``, ``dV/dv = n``, ``dV/dphi = u n - v t``; ``dt/dphi = n``,
    ``dn/dphi = -t``; ``f_t = F.t``, ``f_n = F.n`` for a global force ``F(V)`` with ``dF/dV = G``.
    """
    c, s = np.cos(phi), np.sin(phi)
    disp = p[M] - p[W0] / p[GRAV]
    ax, az = env[AX], env[AZ]
    at, an = ax * c + az * s, -ax * s + az * c
    for i in range(2):
        for q in range(4):
            jac[i, q] = 0.0
    ft, fn = disp * at, (disp + p[MA]) * an
    jac[0, 3] = disp * an
    jac[1, 3] = -(disp + p[MA]) * at
    if p[SB_ON] != 0.0:
        g = np.empty((2, 2))
        fx, fz = seabed_force_jacobian(u * c - v * s, u * s + v * c, env[RX], env[RZ], p, g)
        dv = np.empty((2, 3))                      # dV/d(u, v, phi), rows x and z
        dv[0, 0], dv[1, 0] = c, s
        dv[0, 1], dv[1, 1] = -s, c
        dv[0, 2], dv[1, 2] = -u * s - v * c, u * c - v * s
        for q in range(3):
            gx = g[0, 0] * dv[0, q] + g[0, 1] * dv[1, q]
            gz = g[1, 0] * dv[0, q] + g[1, 1] * dv[1, q]
            jac[0, q + 1] += gx * c + gz * s
            jac[1, q + 1] += -gx * s + gz * c
        jac[0, 3] += -fx * s + fz * c
        jac[1, 3] += -fx * c - fz * s
        ft += fx * c + fz * s
        fn += -fx * s + fz * c
    return ft, fn


@kernel
def weighted(x, y, d, p):
    """States at ``[am]`` and ``[ak]`` and the rate at ``[am]`` for one node (shapes (nv,))."""
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    nv = x.shape[0]
    m, k, r = np.empty(nv, x.dtype), np.empty(nv, x.dtype), np.empty(nv, x.dtype)
    for i in range(nv):
        xdot = (x[i] - y[i]) / (gamma * dt) - (1.0 - gamma) / gamma * d[i]
        m[i] = (1.0 - am) * x[i] + am * y[i]
        k[i] = (1.0 - ak) * x[i] + ak * y[i]
        r[i] = (1.0 - am) * xdot + am * d[i]
    return m, k, r


@inner
def surface_buoyancy(z, b):
    """Buoyancy of a surface buoy's waterplane, ``rho g A_w clip(eta - z, 0, h)``, and its derivative by ``z``."""
    immersion = b[B_ETA] - z
    if b[B_WPA] == 0.0 or immersion.real <= 0.0:
        return 0.0 * z, 0.0
    if immersion.real >= b[B_HEIGHT]:
        return b[B_WPA] * b[B_HEIGHT] + 0.0 * z, 0.0
    return b[B_WPA] * immersion, -b[B_WPA]


@inner
def float_immersion(z, eta, diameter):
    """Submerged share ``f`` of a spherical float centred at ``z`` and ``df/dz`` (the kernels' twin of
    :func:`kanat.physics.immersion.sphere_fraction`, eqs. (1)-(2))."""
    u = (eta - z) / diameter + 0.5
    if u.real <= 0.0:
        return 0.0 * z, 0.0
    if u.real >= 1.0:
        return 1.0 + 0.0 * z, 0.0
    return u * u * (3.0 - 2.0 * u), (-6.0 * u.real * (1.0 - u.real) / diameter)


@inner
def end_jacobian(x, y, d, env, p, b, side, out, jac, extras):
    """The ``nv / 2`` rows of one end (module docstring) into ``out`` and their derivatives by
    the end node's unknowns ``x`` into ``jac`` (nv/2, nv), real.

    Weighted states depend on ``x`` as ``dm/dx = 1 - a_m``, ``dk/dx = 1 - a_k``,
    ``dr/dx = (1 - a_m) / (gamma dt)``; the body's drag ``b |w| w`` of the relative water
    velocity ``w`` has the derivative ``b (|w| I + w w^T / |w|)`` (zero at rest).
    """
    nv = x.shape[0]
    bend = False
    if extras is not None:                 # None: a plain cable (rows2d docstring); its branches compile away
        bend = nv == 6
    for i in range(nv // 2):
        for q in range(nv):
            jac[i, q] = 0.0
    kind = int(b[B_KIND])
    if kind == VELOCITY:
        c, s = np.cos(x[3]), np.sin(x[3])
        out[0] = x[1] - (b[B_V0] * c + b[B_V1] * s) - b[B_PAYOUT]
        out[1] = x[2] - (-b[B_V0] * s + b[B_V1] * c)
        jac[0, 1], jac[0, 3] = 1.0, b[B_V0] * s - b[B_V1] * c
        jac[1, 2], jac[1, 3] = 1.0, b[B_V0] * c + b[B_V1] * s
        if bend:
            if b[B_CLAMP] != 0.0:
                out[2], jac[2, 3] = x[3] - b[B_PHI0], 1.0
            else:
                out[2], jac[2, 5] = x[5], 1.0
        return
    am, ak, gamma, dt = p[AM], p[AK], p[GAMMA], p[DT]
    cm, ck, cr = 1.0 - am, 1.0 - ak, (1.0 - am) / (gamma * dt)
    m1, m2 = cm * x[1] + am * y[1], cm * x[2] + am * y[2]
    k0, k1, k2, k3 = (ck * x[0] + ak * y[0], ck * x[1] + ak * y[1], ck * x[2] + ak * y[2],
                      ck * x[3] + ak * y[3])
    r1, r2, r3 = (cr * (x[1] - y[1]) - cm * (1.0 - gamma) / gamma * d[1] + am * d[1],
                  cr * (x[2] - y[2]) - cm * (1.0 - gamma) / gamma * d[2] + am * d[2],
                  cr * (x[3] - y[3]) - cm * (1.0 - gamma) / gamma * d[3] + am * d[3])
    if kind == FREE:
        if bend:
            out[0], out[1], out[2] = x[0] / p[EA], x[4] / p[EA], x[5] / p[EA]
            jac[0, 0], jac[1, 4], jac[2, 5] = 1.0 / p[EA], 1.0 / p[EA], 1.0 / p[EA]
            return
        # the load's derivatives go through jac (2, 4) as scratch: no allocation in the plain version
        fn = node_load_jacobian(k0, k1, k2, k3, env[UX], env[UZ], p, jac)[1]
        d0, d1, d2, d3 = jac[1, 0], jac[1, 1], jac[1, 2], jac[1, 3]
        if extras is not None:
            extra = np.empty((2, 4))
            fn += extra_load_jacobian(k0, k1, k2, k3, env, p, extra)[1]
            d0, d1, d2, d3 = d0 + extra[1, 0], d1 + extra[1, 1], d2 + extra[1, 2], d3 + extra[1, 3]
        mn = p[INERTIA] * (p[M] + p[MA])
        out[0] = x[0] / p[EA]
        out[1] = mn * (r2 + m1 * r3) - fn
        jac[0, 0], jac[0, 1], jac[0, 2], jac[0, 3] = 1.0 / p[EA], 0.0, 0.0, 0.0
        jac[1, 0] = -d0 * ck
        jac[1, 1] = mn * r3 * cm - d1 * ck
        jac[1, 2] = mn * cr - d2 * ck
        jac[1, 3] = mn * m1 * cr - d3 * ck
        return
    c, s = np.cos(k3), np.sin(k3)
    wt = env[UX] * c + env[UZ] * s - k1                     # water relative to the body, along t and n
    wn = -env[UX] * s + env[UZ] * c - k2
    at, an = env[AX] * c + env[AZ] * s, -env[AX] * s + env[AZ] * c
    speed = np.sqrt(wt * wt + wn * wn)
    lift = dlift = 0.0
    if extras is not None:
        lift, dlift = surface_buoyancy(env[RZ] + p[PRED] * (k1 * s + k2 * c), b)
    buoy = b[B_BUOY] + lift
    shear = k0 * 0.0
    if bend:
        shear = ck * x[4] + ak * y[4]
    mass = p[INERTIA] * b[B_MASS]
    hd = b[B_DRAG]
    out[0] = mass * (r1 - m2 * r3) - (-side * k0 + buoy * s + hd * speed * wt + b[B_F0] * c + b[B_F1] * s
                                      + b[B_WAVE] * at)
    out[1] = mass * (r2 + m1 * r3) - (-side * shear + buoy * c + hd * speed * wn - b[B_F0] * s + b[B_F1] * c
                                      + b[B_WAVE] * an)
    g00 = g01 = g11 = 0.0
    if speed > 0.0:
        g00, g01, g11 = hd * (speed + wt * wt / speed), hd * wt * wn / speed, hd * (speed + wn * wn / speed)
    dwt3, dwn3 = wn + k2, -(wt + k1)            # d(wt)/d(phi), d(wn)/d(phi); d(wt)/du = d(wn)/dv = -1
    dz1, dz2, dz3 = p[PRED] * s, p[PRED] * c, p[PRED] * (k1 * c - k2 * s)
    jac[0, 0] = side * ck
    jac[0, 1] = mass * cr + (g00 - dlift * dz1 * s) * ck
    jac[0, 2] = -mass * r3 * cm + (g01 - dlift * dz2 * s) * ck
    jac[0, 3] = -mass * m2 * cr - (buoy * c - b[B_F0] * s + b[B_F1] * c + g00 * dwt3 + g01 * dwn3
                                   + b[B_WAVE] * an + dlift * dz3 * s) * ck
    jac[1, 1] = mass * r3 * cm + (g01 - dlift * dz1 * c) * ck
    jac[1, 2] = mass * cr + (g11 - dlift * dz2 * c) * ck
    jac[1, 3] = mass * m1 * cr - (-buoy * s - b[B_F0] * c - b[B_F1] * s + g01 * dwt3 + g11 * dwn3
                                  - b[B_WAVE] * at + dlift * dz3 * c) * ck
    if bend:
        jac[1, 4] = side * ck
        out[2], jac[2, 5] = x[5], 1.0

