"""Rigid bodies with 6 degrees of freedom in the lumped model (theory/moorings.md §7 "Rigid bodies").

A ``dof: 6`` body is two pseudo-nodes among the generalized coordinates: its reference point
``r`` and its Euler angles ``Theta = (roll, pitch, yaw)`` (``R = Rz(yaw) Ry(pitch) Rx(roll)``,
:func:`kanat.physics.motion.rotation_matrix`), with velocities ``r_dot`` and ``Theta_dot``.
Its fairleads are nodes prescribed by them::

    (1)  x_f = r + R p_b,   v_f = r_dot + w x (R p_b),   w = E(Theta) Theta_dot

(``E`` as :func:`kanat.physics.motion.angular_velocity`). The Newton–Euler equations about
the reference point, in the global frame, with ``p = R p_b`` a fairlead's arm and ``c = R c_g``
the centre of gravity::

    (2)  [M6 + sum_f J_f^T M_f J_f] [a; w_dot] = F6 + sum_f J_f^T (F_f - M_f w x (w x p))
         J_f = [I, -S(p)],   M6 = T (M_rb + A) T^T,   T = diag(R, R)
    (3)  F6 = [F_static - m w x (w x c); M_static - w x (I_O w)] + T f_b + [(rho V I + A_tt) a_w; A_rt a_w]

``M_rb`` the rigid-body mass matrix about the reference point (:meth:`Body.rigid_body_mass_matrix`),
``A`` the added mass (body axes; its Coriolis terms neglected), ``M_f, F_f`` the lumped mass
block and force of the line nodes at fairlead ``f`` (the lines' half elements ride on the
body). Static loads: the net buoyancy at the reference point, the moment of the weight ``m g`` at
``c`` and the buoyancy ``B = net_buoyancy + m g`` at the centre of buoyancy, and with a hydrostatic
stiffness ``C`` (given or ``rho g A_w``, ``B GM``; body axes) the restoring about the body's given
``position`` and ``orientation_deg`` (``R_0``). When ``C`` restores roll or pitch (a metacentric
height) it holds the weight's and buoyancy's levers along the body's vertical at the reference,
and only the centres' offsets across it turn the body; otherwise the whole levers turn
(:mod:`kanat.physics.hydrostatics` eqs. 1-3, shared with network statics)::

    (4)  [F; M] = -[H (C dxi)_t; R (C dxi)_r],   H = Rz(yaw),
         dxi = (H^T (r - r_0 - eta e_z), k x k_0 + (yaw - yaw_0) k_0),   k = R^T e_z,   k_0 = R_0^T e_z

(``eta`` the wave surface at ``r`` for a surface-piercing body, 0 otherwise). ``k x k_0`` is the
tilt from the reference in body axes, of length ``sin`` of the angle between the two verticals:
the restoring is that of the body's actual tilt whatever its heading (for ``C44 = C55 = B GM``
and a level reference, ``M = B GM (z_b x e_z)``, ``|M| = B GM sin(tilt)``), and heave and surge
follow the heading, not the tilt (buoyancy stays vertical). To first order about a level
reference ``dxi = (H^T dr, R^T dphi)`` with ``dphi`` the small rotation in the global frame, so
the linearised stiffness (:mod:`kanat.frequency.rigid`) is ``T C T^T`` in ``(dr, dphi)``: symmetric.
Body-axes loads
``f_b = -B_1 nu - B_2 |nu| nu - 1/2 rho C_D A |nu_r| nu_r`` with ``nu = (R^T r_dot, R^T w)`` and
``nu_r`` the same relative to the water. Finally ``Theta_ddot = E^-1 (w_dot - E_dot Theta_dot)``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kanat.jit import inner, kernel
from kanat.lumped.entries import Rig
from kanat.physics.hydrostatics import restoring_displacement, weight_buoyancy_moment
from kanat.physics.motion import point_jacobian


@dataclass(frozen=True, eq=False)
class RigidBodies:
    """The 6-DOF bodies of a network as arrays (per body ``b``; matrices in body axes).

    Attributes
    ----------
    names : list of str
    ref_node, rot_node : ndarray of int, shape (nb,)
        Pseudo-nodes of the reference point and of the Euler angles.
    guess : ndarray, shape (2 nb, 3)
        Their initial values (position; orientation [rad]), interleaved ref, rot.
    mass6, added6, hydro, linear, quadratic : ndarray, shape (nb, 6, 6)
    drag : ndarray, shape (nb, 6)
        ``C_D A`` per degree of freedom [m^2, m^5].
    cog, cob : ndarray, shape (nb, 3)
    scalars : ndarray, shape (nb, 6)
        ``m g`` [N], buoyancy ``B`` [N], displaced mass ``B / g`` [kg], hydrostatics (0 none, 1 without
        roll or pitch restoring, 2 with it: :attr:`Body.tilt_in_stiffness`), surface-piercing (1/0),
        mass ``m`` [kg].
    force : ndarray, shape (nb, 3)
        Constant external force [N].
    reference : ndarray, shape (nb, 6)
        Position and orientation [rad] the hydrostatic restoring acts about.
    fairlead_node, fairlead_body : ndarray of int, shape (k,)
    fairlead_offset : ndarray, shape (k, 3)
    """

    names: list
    ref_node: np.ndarray
    rot_node: np.ndarray
    guess: np.ndarray
    mass6: np.ndarray
    added6: np.ndarray
    hydro: np.ndarray
    linear: np.ndarray
    quadratic: np.ndarray
    drag: np.ndarray
    cog: np.ndarray
    cob: np.ndarray
    scalars: np.ndarray
    force: np.ndarray
    reference: np.ndarray
    fairlead_node: np.ndarray
    fairlead_body: np.ndarray
    fairlead_offset: np.ndarray

    @property
    def count(self) -> int:
        return len(self.names)

    def arrays(self) -> Rig:
        """The record the compiled kernels take (:class:`kanat.lumped.entries.Rig`)."""
        return Rig(reference_node=self.ref_node, angle_node=self.rot_node, rigid_mass=self.mass6,
                   added_mass=self.added6, hydrostatic_stiffness=self.hydro, linear_damping=self.linear,
                   quadratic_damping=self.quadratic, drag_area=self.drag, gravity_centre=self.cog,
                   buoyancy_centre=self.cob, scalars=self.scalars, force=self.force, rest=self.reference,
                   fairlead_node=self.fairlead_node, fairlead_body=self.fairlead_body,
                   fairlead_offset=self.fairlead_offset)


def _matrix(value) -> np.ndarray:
    return np.zeros((6, 6)) if value is None else np.asarray(value, dtype=float)


def rigid_bodies(case, builder) -> RigidBodies:
    """The 6-DOF bodies that ``builder`` (:class:`kanat.lumped.network._Builder`) placed fairleads on."""
    env = case.environment
    rho, g = env.water_density, env.gravity
    names = [name for name in case.bodies if any(body == name for _, body, _ in builder.fairleads)]
    first = len(builder.kinds)
    rows = {k: [] for k in ("guess", "mass6", "added6", "hydro", "linear", "quadratic", "drag", "cog", "cob",
                            "scalars", "force", "reference")}
    for name in names:
        body = case.bodies[name]
        angles = np.radians(body.orientation_deg)
        position = np.asarray(body.position, float)
        rows["guess"] += [position, angles]
        rows["mass6"].append(body.rigid_body_mass_matrix())
        rows["added6"].append(_matrix(body.added_mass_matrix))
        rows["hydro"].append(body.hydrostatic_stiffness_matrix(rho, g))
        rows["linear"].append(_matrix(body.linear_damping))
        rows["quadratic"].append(_matrix(body.quadratic_damping))
        rows["drag"].append(np.zeros(6) if body.drag_areas is None else np.asarray(body.drag_areas, float))
        rows["cog"].append(np.asarray(body.center_of_gravity, float))
        rows["cob"].append(np.asarray(body.buoyancy_point, float))
        hydro_on = float(body.hydrostatic_stiffness is not None or body.waterplane_area is not None)
        hydro_on += float(body.tilt_in_stiffness)              # 2: C holds the tilt (module docstring)
        buoyancy = body.buoyancy(g)
        rows["scalars"].append([body.mass * g, buoyancy, buoyancy / g, hydro_on,
                                float(body.waterplane_area is not None), body.mass])
        rows["force"].append(np.asarray(body.force, float))
        rows["reference"].append(np.concatenate([position, angles]))
    nb = len(names)
    fair = [(node, names.index(body), offset) for node, body, offset in builder.fairleads]
    stack = lambda k, shape: np.array(rows[k], dtype=float).reshape(shape)  # noqa: E731
    return RigidBodies(
        names=names, ref_node=first + 2 * np.arange(nb, dtype=np.int64),
        rot_node=first + 1 + 2 * np.arange(nb, dtype=np.int64), guess=stack("guess", (2 * nb, 3)),
        mass6=stack("mass6", (nb, 6, 6)), added6=stack("added6", (nb, 6, 6)), hydro=stack("hydro", (nb, 6, 6)),
        linear=stack("linear", (nb, 6, 6)), quadratic=stack("quadratic", (nb, 6, 6)), drag=stack("drag", (nb, 6)),
        cog=stack("cog", (nb, 3)), cob=stack("cob", (nb, 3)), scalars=stack("scalars", (nb, 6)),
        force=stack("force", (nb, 3)), reference=stack("reference", (nb, 6)),
        fairlead_node=np.array([f[0] for f in fair], dtype=np.int64),
        fairlead_body=np.array([f[1] for f in fair], dtype=np.int64),
        fairlead_offset=np.array([f[2] for f in fair], dtype=float).reshape(-1, 3))


def body_inertia(rigid: RigidBodies, node_mass) -> np.ndarray:
    """Each body's generalized mass in body axes, the left side of eq. (2) (nb, 6, 6) [kg, kg m, kg m^2]:
    ``M_rb + A + sum_f J_f^T m_f J_f`` with ``J_f = [I, -S(p_f)]``, ``p_f`` a fairlead's offset and
    ``m_f`` its line nodes' lumped mass (``node_mass``, (n,) [kg])."""
    inertia = rigid.mass6 + rigid.added6
    for node, body, offset in zip(rigid.fairlead_node, rigid.fairlead_body, rigid.fairlead_offset):
        jacobian = point_jacobian(offset)
        inertia[body] += node_mass[node] * jacobian.T @ jacobian
    return inertia


def fairlead_mobility(rigid: RigidBodies, inverse) -> np.ndarray:
    """The largest inverse mass [1/kg] each fairlead node moves with, riding on its body (k,)::

        (5)  1 / m_f = lambda_max(J_f M^-1 J_f^T),   J_f = [I, -S(p_f)]

    ``M`` the body's generalized mass (:func:`body_inertia`), ``inverse`` (nb, 6, 6) its inverse: the
    point mobility of the body at the fairlead, largest over the directions (rotation invariant, so
    taken in body axes). An element pulling on the fairlead accelerates it as it would a node of mass
    ``m_f``: that is the mass its axial frequency sees (:mod:`kanat.lumped.stepping` eq. 1)."""
    out = np.zeros(len(rigid.fairlead_node))
    for f, (body, offset) in enumerate(zip(rigid.fairlead_body, rigid.fairlead_offset)):
        jacobian = point_jacobian(offset)
        out[f] = float(np.max(np.linalg.eigvalsh(jacobian @ inverse[body] @ jacobian.T)))
    return out


def body_rates(rigid: RigidBodies, inverse) -> tuple[np.ndarray, np.ndarray]:
    """Each body's own highest angular frequency and damping rate [1/s] (nb,): the largest
    ``sqrt|lambda|`` of ``M^-1 C`` and ``|lambda|`` of ``M^-1 B_1`` (``C`` the hydrostatic stiffness,
    ``B_1`` the linear damping, ``M`` :func:`body_inertia`, ``inverse`` (nb, 6, 6) its inverse): its
    modes on its own springs, for the explicit schemes' safe step (:mod:`kanat.lumped.stepping` eq. 4)."""
    omega = np.array([np.max(np.abs(np.linalg.eigvals(m @ c)), initial=0.0) ** 0.5
                      for m, c in zip(inverse, rigid.hydro)])
    sigma = np.array([np.max(np.abs(np.linalg.eigvals(m @ b)), initial=0.0) for m, b in zip(inverse, rigid.linear)])
    return omega, sigma


# --- compiled kinematics and dynamics ---------------------------------------------------------
@inner
def rotation(roll, pitch, yaw, R):
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` into ``R`` (3, 3)."""
    cr, sr, cp, sp, cy, sy = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), \
        math.cos(yaw), math.sin(yaw)
    R[0, 0], R[0, 1], R[0, 2] = cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr
    R[1, 0], R[1, 1], R[1, 2] = sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr
    R[2, 0], R[2, 1], R[2, 2] = -sp, cp * sr, cp * cr


@inner
def omega_of(th, thd, w):
    """``w = E(Theta) Theta_dot`` (module eq. 1) into ``w`` (3,)."""
    cp, sp, cy, sy = math.cos(th[1]), math.sin(th[1]), math.cos(th[2]), math.sin(th[2])
    w[0] = thd[0] * cp * cy - thd[1] * sy
    w[1] = thd[0] * cp * sy + thd[1] * cy
    w[2] = thd[2] - thd[0] * sp


@kernel
def place_fairleads(x, v, rig):
    """Fairlead nodes' positions and velocities from their bodies' pseudo-nodes (eq. 1); ``rig`` a
    :class:`kanat.lumped.entries.Rig`."""
    ref, rot, offset, owner, nodes = rig.reference_node, rig.angle_node, rig.fairlead_offset, rig.fairlead_body, \
        rig.fairlead_node
    R, w = np.empty((3, 3)), np.empty(3)
    for f in range(nodes.shape[0]):
        b = owner[f]
        rotation(x[rot[b], 0], x[rot[b], 1], x[rot[b], 2], R)
        omega_of(x[rot[b]], v[rot[b]], w)
        for r in range(3):
            p = R[r, 0] * offset[f, 0] + R[r, 1] * offset[f, 1] + R[r, 2] * offset[f, 2]
            x[nodes[f], r] = x[ref[b], r] + p
        p0, p1, p2 = x[nodes[f], 0] - x[ref[b], 0], x[nodes[f], 1] - x[ref[b], 1], x[nodes[f], 2] - x[ref[b], 2]
        v[nodes[f], 0] = v[ref[b], 0] + w[1] * p2 - w[2] * p1
        v[nodes[f], 1] = v[ref[b], 1] + w[2] * p0 - w[0] * p2
        v[nodes[f], 2] = v[ref[b], 2] + w[0] * p1 - w[1] * p0


@inner
def matmul3(A, B, out):
    """``out = A B`` (3 x 3), scalar loops (no ``@`` in kernels: kanat.jit)."""
    for i in range(3):
        for j in range(3):
            out[i, j] = A[i, 0] * B[0, j] + A[i, 1] * B[1, j] + A[i, 2] * B[2, j]


@inner
def turn(R, c, out):
    """``out = R c`` (3,)."""
    for i in range(3):
        out[i] = R[i, 0] * c[0] + R[i, 1] * c[1] + R[i, 2] * c[2]


@inner
def solve6(A, b):
    """Solve ``A z = b`` (6, 6) in place by Gaussian elimination with partial pivoting."""
    n = 6
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(A[i, k]) > abs(A[p, k]):
                p = i
        if p != k:
            for j in range(n):
                A[k, j], A[p, j] = A[p, j], A[k, j]
            b[k], b[p] = b[p], b[k]
        for i in range(k + 1, n):
            factor = A[i, k] / A[k, k]
            for j in range(k, n):
                A[i, j] -= factor * A[k, j]
            b[i] -= factor * b[k]
    for k in range(n - 1, -1, -1):
        s = b[k]
        for j in range(k + 1, n):
            s -= A[k, j] * b[j]
        b[k] = s / A[k, k]


@inner
def rotate6(R, A, out):
    """``out = T A T^T`` with ``T = diag(R, R)`` (6, 6)."""
    for i in range(6):
        for j in range(6):
            s = 0.0
            bi, bj = 3 * (i // 3), 3 * (j // 3)
            for k in range(3):
                for q in range(3):
                    s += R[i - bi, k] * A[bi + k, bj + q] * R[j - bj, q]
            out[i, j] = s


@inner
def static_loads(b, x, R, eta, g_vec, rig, F6):
    """Weight, buoyancy, hydrostatic restoring (module eq. 4) and constant force of body ``b`` into ``F6``."""
    ref, rot, hydro, cog, cob = rig.reference_node, rig.angle_node, rig.hydrostatic_stiffness, rig.gravity_centre, \
        rig.buoyancy_centre
    sc, force, reference = rig.scalars, rig.force, rig.rest
    weight, buoyancy, hydro_on, surface = sc[b, 0], sc[b, 1], sc[b, 3], sc[b, 4]
    for r in range(3):
        F6[r] += force[b, r]
    F6[2] += buoyancy - weight
    if hydro_on > 0.0:
        d, load = np.empty(6), np.zeros(6)
        hydrostatic_displacement(b, x, R, eta, surface, reference, rot, ref, d)
        cy, sy = math.cos(x[rot[b], 2]), math.sin(x[rot[b], 2])
        for i in range(6):
            for j in range(6):
                load[i] -= hydro[b, i, j] * d[j]
        F6[0] += cy * load[0] - sy * load[1]
        F6[1] += sy * load[0] + cy * load[1]
        F6[2] += load[2]
        for r in range(3):
            F6[3 + r] += R[r, 0] * load[3] + R[r, 1] * load[4] + R[r, 2] * load[5]
    roll0, pitch0, k0 = reference[b, 3], reference[b, 4], np.empty(3)   # k0 = R_0^T e_z
    k0[0], k0[1], k0[2] = -math.sin(pitch0), math.cos(pitch0) * math.sin(roll0), math.cos(pitch0) * math.cos(roll0)
    weight_buoyancy_moment(R, k0, cog[b], cob[b], weight, buoyancy, 1.0 if hydro_on > 1.5 else 0.0, F6[3:])


@inner
def hydrostatic_displacement(b, x, R, eta, surface, reference, rot, ref, d):
    """``dxi`` (6,) of module eq. (4) (:func:`kanat.physics.hydrostatics.restoring_displacement`):
    the reference point's displacement in the heading frame ``H = Rz(yaw)`` (heave from the wave
    surface ``eta`` for a surface-piercing body), then the tilt ``k x k_0`` and the yaw change,
    in body axes."""
    R0, dr = np.empty((3, 3)), np.empty(3)
    rotation(reference[b, 3], reference[b, 4], reference[b, 5], R0)
    for r in range(3):
        dr[r] = x[ref[b], r] - reference[b, r]
    if surface > 0.0:
        dr[2] -= eta
    restoring_displacement(R, R0, dr, x[rot[b], 2], reference[b, 5], d)


@inner
def body_axes_loads(b, R, vel, w, uw, rho, rig, F6):
    """Damping and drag of body ``b`` (module eq. 3, ``f_b``) turned to the global frame."""
    linear, quadratic, drag = rig.linear_damping, rig.quadratic_damping, rig.drag_area
    nu, nur, fb = np.empty(6), np.empty(6), np.zeros(6)
    for r in range(3):
        nu[r] = R[0, r] * vel[0] + R[1, r] * vel[1] + R[2, r] * vel[2]
        nu[3 + r] = R[0, r] * w[0] + R[1, r] * w[1] + R[2, r] * w[2]
        nur[r] = R[0, r] * (vel[0] - uw[0]) + R[1, r] * (vel[1] - uw[1]) + R[2, r] * (vel[2] - uw[2])
        nur[3 + r] = nu[3 + r]
    for i in range(6):
        for j in range(6):
            fb[i] -= linear[b, i, j] * nu[j] + quadratic[b, i, j] * abs(nu[j]) * nu[j]
        fb[i] -= 0.5 * rho * drag[b, i] * abs(nur[i]) * nur[i]
    for r in range(3):
        F6[r] += R[r, 0] * fb[0] + R[r, 1] * fb[1] + R[r, 2] * fb[2]
        F6[3 + r] += R[r, 0] * fb[3] + R[r, 1] * fb[4] + R[r, 2] * fb[5]


@inner
def fairlead_terms(b, x, F, M, w, rig, M6, F6):
    """The lines' nodes at body ``b``'s fairleads riding on it: ``J^T M_f J`` and ``J^T (F_f - M_f w x
    (w x p))`` (module eq. 2); ``M`` packed (n, 6) blocks (kernels.PACKED order)."""
    ref, nodes, owner = rig.reference_node, rig.fairlead_node, rig.fairlead_body
    Mf, S, MS = np.empty((3, 3)), np.empty((3, 3)), np.empty((3, 3))
    SMS, SM = np.empty((3, 3)), np.empty((3, 3))
    for f in range(nodes.shape[0]):
        if owner[f] != b:
            continue
        n = nodes[f]
        p0, p1, p2 = x[n, 0] - x[ref[b], 0], x[n, 1] - x[ref[b], 1], x[n, 2] - x[ref[b], 2]
        Mf[0, 0], Mf[1, 1], Mf[2, 2] = M[n, 0], M[n, 1], M[n, 2]
        Mf[0, 1], Mf[1, 0], Mf[0, 2], Mf[2, 0], Mf[1, 2], Mf[2, 1] = M[n, 3], M[n, 3], M[n, 4], M[n, 4], \
            M[n, 5], M[n, 5]
        S[0, 0], S[0, 1], S[0, 2] = 0.0, -p2, p1
        S[1, 0], S[1, 1], S[1, 2] = p2, 0.0, -p0
        S[2, 0], S[2, 1], S[2, 2] = -p1, p0, 0.0
        matmul3(Mf, S, MS)
        matmul3(S, MS, SMS)
        matmul3(S, Mf, SM)
        c0, c1, c2 = w[1] * p2 - w[2] * p1, w[2] * p0 - w[0] * p2, w[0] * p1 - w[1] * p0
        cc = np.array([w[1] * c2 - w[2] * c1, w[2] * c0 - w[0] * c2, w[0] * c1 - w[1] * c0])
        f = np.empty(3)
        for r in range(3):
            f[r] = F[n, r] - (Mf[r, 0] * cc[0] + Mf[r, 1] * cc[1] + Mf[r, 2] * cc[2])
        for r in range(3):
            F6[r] += f[r]
            for q in range(3):
                M6[r, q] += Mf[r, q]
                M6[r, 3 + q] -= MS[r, q]
                M6[3 + r, q] += SM[r, q]
                M6[3 + r, 3 + q] -= SMS[r, q]
        F6[3] += p1 * f[2] - p2 * f[1]
        F6[4] += p2 * f[0] - p0 * f[2]
        F6[5] += p0 * f[1] - p1 * f[0]


@kernel
def rigid_accelerations(x, v, F, M, uw, aw, eta, rho, rig, acc):
    """Accelerations of every 6-DOF body (module eqs. 2-3): ``acc`` (nb, 2, 3) holds ``a`` and
    ``Theta_ddot``; the bodies' pseudo-node rows of ``F`` (n, 3) and packed ``M`` (n, 6) get the
    force, moment and diagonal mass blocks (for the equilibrium). ``uw, aw`` (nb, 3) and ``eta``
    (nb,) the water at the reference points; ``rig`` a :class:`kanat.lumped.entries.Rig`."""
    ref, rot, mass6, added6, cog, sc = rig.reference_node, rig.angle_node, rig.rigid_mass, rig.added_mass, \
        rig.gravity_centre, rig.scalars
    R, w, Mg, M6, F6 = np.empty((3, 3)), np.empty(3), np.empty((6, 6)), np.empty((6, 6)), np.empty(6)
    c, wc, Iw = np.empty(3), np.empty(3), np.empty(3)
    g_vec = np.zeros(3)
    for b in range(ref.shape[0]):
        th, thd = x[rot[b]], v[rot[b]]
        rotation(th[0], th[1], th[2], R)
        omega_of(th, thd, w)
        rotate6(R, mass6[b], Mg)
        rotate6(R, added6[b], M6)
        F6[:] = 0.0
        m, rhoV = sc[b, 5], sc[b, 2]
        turn(R, cog[b], c)
        wc[0], wc[1], wc[2] = w[1] * c[2] - w[2] * c[1], w[2] * c[0] - w[0] * c[2], w[0] * c[1] - w[1] * c[0]
        for r in range(3):
            Iw[r] = Mg[3 + r, 3] * w[0] + Mg[3 + r, 4] * w[1] + Mg[3 + r, 5] * w[2]
        for r in range(3):
            F6[r] -= m * (w[(r + 1) % 3] * wc[(r + 2) % 3] - w[(r + 2) % 3] * wc[(r + 1) % 3])
            F6[3 + r] -= w[(r + 1) % 3] * Iw[(r + 2) % 3] - w[(r + 2) % 3] * Iw[(r + 1) % 3]
        for i in range(6):
            for q in range(3):
                F6[i] += M6[i, q] * aw[b, q]
            if i < 3:
                F6[i] += rhoV * aw[b, i]
        for i in range(6):
            for j in range(6):
                M6[i, j] += Mg[i, j]
        static_loads(b, x, R, eta[b], g_vec, rig, F6)
        body_axes_loads(b, R, v[ref[b]], w, uw[b], rho, rig, F6)
        fairlead_terms(b, x, F, M, w, rig, M6, F6)
        for r in range(3):
            F[ref[b], r], F[rot[b], r] = F6[r], F6[3 + r]
            M[ref[b], r], M[rot[b], r] = M6[r, r], M6[3 + r, 3 + r]
        M[ref[b], 3], M[ref[b], 4], M[ref[b], 5] = M6[0, 1], M6[0, 2], M6[1, 2]
        M[rot[b], 3], M[rot[b], 4], M[rot[b], 5] = M6[3, 4], M6[3, 5], M6[4, 5]
        solve6(M6, F6)
        for r in range(3):
            acc[b, 0, r] = F6[r]
        angular_to_euler(th, thd, F6, acc, b)


@inner
def angular_to_euler(th, thd, wdot, acc, b):
    """``Theta_ddot = E^-1 (w_dot - E_dot Theta_dot)`` into ``acc[b, 1]`` (``wdot`` = F6[3:])."""
    cp, sp, cy, sy = math.cos(th[1]), math.sin(th[1]), math.cos(th[2]), math.sin(th[2])
    dr, dp, dy = thd[0], thd[1], thd[2]
    e0 = dr * (-sp * dp * cy - cp * sy * dy) - dp * cy * dy
    e1 = dr * (-sp * dp * sy + cp * cy * dy) - dp * sy * dy
    e2 = -dr * cp * dp
    q0, q1, q2 = wdot[3] - e0, wdot[4] - e1, wdot[5] - e2
    roll = (cy * q0 + sy * q1) / cp
    acc[b, 1, 0] = roll
    acc[b, 1, 1] = -sy * q0 + cy * q1
    acc[b, 1, 2] = q2 + sp * roll
