"""Fused generalized-α steps: the implicit scheme of :mod:`kanat.lumped.implicit` compiled whole.

Each step solves the same equations as :func:`kanat.lumped.implicit.generalized_alpha_step`
(its eqs. 1-3: Newmark update, residual ``M a_m - F`` at ``t_m``, tangent
``(1 - alpha_m) M + (1 - alpha_f) (gamma h C + beta h^2 K)``) with the lumped mass, but the
force evaluation (:func:`kanat.lumped.fast.loads`), the tangent blocks
(:func:`kernels.tangent_blocks`), its assembly and the linear solve run in numba. The
tangent is stored as a band of 3 x 3 node blocks over the free nodes in a bandwidth-reducing
order (reverse Cuthill–McKee, :func:`band_order`: one block either side of the diagonal for a
line) and factorized by block LU without pivoting between blocks, each pivot block inverted
exactly by cofactors — the matrix is dominated by its mass blocks, and its geometric and drag
parts are positive semidefinite — at ``O(n b^2)`` block operations. The blocks are written out
by hand rather than left to LAPACK's band solver: a line's band is 3 x 3 blocks wide, and the
block form takes 23 % less time per step on the three-leg mooring than the same LU on the
scalar band (30.0 against 39.1 us; its substitution is a chain of dependent rows, which the
3 x 3 blocks cut by three). The iteration is modified Newton (:func:`newton_step`): the
factors are reused across iterations and steps while they contract the increments fast, and
rebuilt where they do not or where the seabed contact changed, so most iterations cost a force
evaluation and a band substitution. A step whose Newton iteration fails is
handed back; :mod:`kanat.lumped.advance` then takes it with the Python scheme, which halves it.
The Python path is this module's twin (tests).
"""
from __future__ import annotations

import numpy as np
from kanat.jit import inner, kernel

from kanat.lumped import fast, kernels
from kanat.lumped.band_solve import reverse_cuthill_mckee
from kanat.lumped.bending import bending_blocks
from kanat.physics.contact import contact_tangent

ACCELERATION_SCALE = 1.0    # m/s^2, as kanat.lumped.implicit
CONTRACTION = 0.1           # an increment above this fraction of the one before rebuilds the tangent (0.25: 15 %
                            # more iterations on the three-leg mooring at 0.0125 s; a rebuild costs ~4 iterations)
FACTOR_AGE = 16             # steps after which the factors are rebuilt anyway (see newton_step)
LINE_SEARCH_HALVINGS = 4    # a Newton increment that raises the residual is halved at most this often
CARRIED_RATE_FLOOR = 0.05   # the least eta a step's first iteration takes from earlier steps (see newton_step)
MOTION_FLOOR = 1e-6         # m per node: the least displacement of a step the time-error estimate divides by
                            # (and the least d_0 of kanat.lumped.time_error eq. 2)


def band_order(net, free_index) -> tuple[np.ndarray, int]:
    """Position of each free node in the band order (n_nodes,; -1 for prescribed nodes) and the
    band's half-width in nodes (3 x 3 blocks): reverse Cuthill–McKee
    (:func:`kanat.lumped.band_solve.reverse_cuthill_mckee`) on the graph of the elements and the
    bending triples' outer nodes between free nodes."""
    n_free = len(free_index)
    local = -np.ones(net.n_nodes, dtype=np.int64)
    local[free_index] = np.arange(n_free)
    a, b = local[np.r_[net.el_i, net.bend[0]]], local[np.r_[net.el_j, net.bend[2]]]   # bending joins i-1, i+1
    keep = (a >= 0) & (b >= 0)
    neighbours = [set() for _ in range(n_free)]
    for i, j in zip(a[keep].tolist(), b[keep].tolist()):
        neighbours[i].add(j)
        neighbours[j].add(i)
    order = reverse_cuthill_mckee(neighbours)
    rank = np.empty(n_free, dtype=np.int64)
    rank[order] = np.arange(n_free)
    position = -np.ones(net.n_nodes, dtype=np.int64)
    position[free_index] = rank
    return position, int(np.max(np.abs(rank[a[keep]] - rank[b[keep]]), initial=0))


@inner
def band_add(A, bw, pi, pj, block, scale):
    """Add ``scale * block`` (3 x 3) at block row ``pi``, block column ``pj``."""
    d = pj - pi + bw
    for r in range(3):
        for q in range(3):
            A[pi, d, r, q] += scale * block[r, q]


@kernel
def band_factor(A, bw):
    """Block LU of ``A`` ((nb, 2 bw + 1, 3, 3) block band) in place, without pivoting between blocks;
    the diagonal blocks hold their inverses. False on a singular or non-finite pivot block."""
    nb = A.shape[0]
    for k in range(nb):
        D = A[k, bw]
        c00 = D[1, 1] * D[2, 2] - D[1, 2] * D[2, 1]
        c01 = D[1, 2] * D[2, 0] - D[1, 0] * D[2, 2]
        c02 = D[1, 0] * D[2, 1] - D[1, 1] * D[2, 0]
        det = D[0, 0] * c00 + D[0, 1] * c01 + D[0, 2] * c02
        if det == 0.0 or not np.isfinite(det):
            return False
        inv = 1.0 / det
        i00, i10, i20 = c00 * inv, c01 * inv, c02 * inv
        i01 = (D[0, 2] * D[2, 1] - D[0, 1] * D[2, 2]) * inv
        i11 = (D[0, 0] * D[2, 2] - D[0, 2] * D[2, 0]) * inv
        i21 = (D[0, 1] * D[2, 0] - D[0, 0] * D[2, 1]) * inv
        i02 = (D[0, 1] * D[1, 2] - D[0, 2] * D[1, 1]) * inv
        i12 = (D[0, 2] * D[1, 0] - D[0, 0] * D[1, 2]) * inv
        i22 = (D[0, 0] * D[1, 1] - D[0, 1] * D[1, 0]) * inv
        D[0, 0], D[0, 1], D[0, 2] = i00, i01, i02
        D[1, 0], D[1, 1], D[1, 2] = i10, i11, i12
        D[2, 0], D[2, 1], D[2, 2] = i20, i21, i22
        top = min(nb, k + bw + 1)
        for i in range(k + 1, top):
            L = A[i, k - i + bw]
            for r in range(3):
                a0, a1, a2 = L[r, 0], L[r, 1], L[r, 2]
                L[r, 0] = a0 * D[0, 0] + a1 * D[1, 0] + a2 * D[2, 0]
                L[r, 1] = a0 * D[0, 1] + a1 * D[1, 1] + a2 * D[2, 1]
                L[r, 2] = a0 * D[0, 2] + a1 * D[1, 2] + a2 * D[2, 2]
            for j in range(k + 1, top):
                U, T = A[k, j - k + bw], A[i, j - i + bw]
                for r in range(3):
                    l0, l1, l2 = L[r, 0], L[r, 1], L[r, 2]
                    for q in range(3):
                        T[r, q] -= l0 * U[0, q] + l1 * U[1, q] + l2 * U[2, q]
    return True


@kernel
def band_substitute(A, bw, b):
    """Solve ``L U x = b`` in place with the factors of :func:`band_factor`."""
    nb = A.shape[0]
    for i in range(1, nb):
        s0, s1, s2 = b[3 * i], b[3 * i + 1], b[3 * i + 2]
        for k in range(max(0, i - bw), i):
            L = A[i, k - i + bw]
            y0, y1, y2 = b[3 * k], b[3 * k + 1], b[3 * k + 2]
            s0 -= L[0, 0] * y0 + L[0, 1] * y1 + L[0, 2] * y2
            s1 -= L[1, 0] * y0 + L[1, 1] * y1 + L[1, 2] * y2
            s2 -= L[2, 0] * y0 + L[2, 1] * y1 + L[2, 2] * y2
        b[3 * i], b[3 * i + 1], b[3 * i + 2] = s0, s1, s2
    for k in range(nb - 1, -1, -1):
        s0, s1, s2 = b[3 * k], b[3 * k + 1], b[3 * k + 2]
        for j in range(min(nb, k + bw + 1) - 1, k, -1):
            U = A[k, j - k + bw]
            y0, y1, y2 = b[3 * j], b[3 * j + 1], b[3 * j + 2]
            s0 -= U[0, 0] * y0 + U[0, 1] * y1 + U[0, 2] * y2
            s1 -= U[1, 0] * y0 + U[1, 1] * y1 + U[1, 2] * y2
            s2 -= U[2, 0] * y0 + U[2, 1] * y1 + U[2, 2] * y2
        D = A[k, bw]
        b[3 * k] = D[0, 0] * s0 + D[0, 1] * s1 + D[0, 2] * s2
        b[3 * k + 1] = D[1, 0] * s0 + D[1, 1] * s1 + D[1, 2] * s2
        b[3 * k + 2] = D[2, 0] * s0 + D[2, 1] * s1 + D[2, 2] * s2


@inner
def seabed_tangent(A, bw, position, free_index, contact, work, Kc, Cc, c_damp, c_stiff):
    """The seabed contact's blocks in the band tangent; nothing (nor compiled) when ``contact`` is None."""
    if contact is not None:
        x, v, normal_force = work.x, work.v, work.normal_force
        contact_tangent(x, v, contact.area, contact.seabed, contact.law, normal_force, work.line_tangent, Kc, Cc)
        for f in range(free_index.shape[0]):
            node = free_index[f]
            if normal_force[node] > 0.0:
                p = position[node]
                for r in range(3):
                    for q in range(3):
                        A[p, bw, r, q] += c_stiff * Kc[node, r, q]
                for r in range(3):
                    for q in range(3):
                        A[p, bw, r, q] += c_damp * Cc[node, r, q]


@inner
def bending_tangent(A, bw, position, x, el, c_stiff):
    """The bending's Gauss-Newton blocks (:func:`kanat.lumped.bending.bending_blocks`, eq. 4) times
    ``c_stiff`` in the band tangent."""
    triples = el.bend_node.shape[0]
    if triples == 0:
        return
    J, K = np.empty((3, 3, 3)), np.empty((triples, 3, 3, 3, 3))
    bending_blocks(x, el.bend_before, el.bend_node, el.bend_after, el.bend_stiffness, J, K)
    for p in range(triples):
        nodes = (el.bend_before[p], el.bend_node[p], el.bend_after[p])
        for m in range(3):
            pm = position[nodes[m]]
            for n in range(3):
                pn = position[nodes[n]]
                if pm >= 0 and pn >= 0:
                    band_add(A, bw, pm, pn, K[p, m, n], c_stiff)


@inner
def assemble(band, nodes, el, bodies, env, work, c_mass, c_damp, c_stiff):
    """Tangent ``c_mass M + c_damp (C + D + D_body + C_c) + c_stiff (K + K_c)`` in the band storage
    ``band.factors`` (kernels eq. tangent_blocks; body drag ``-dF/dv``; seabed contact ``K_c, C_c`` of
    :func:`kanat.physics.contact.contact_tangent`), at the state in ``work``; ``band`` is an
    :class:`kanat.lumped.entries.Band`."""
    x, v, M, uw, bu = work.x, work.v, work.mass, work.water_velocity, work.load_velocity
    A, bw, position = band.factors, band.half_width, band.position
    K, C, D = band.element_stiffness, band.element_damping, band.element_drag
    Kc, Cc = band.contact_stiffness, band.contact_damping
    A[:, :, :, :] = 0.0
    kernels.tangent_blocks(x, v, uw, el, K, C, D)
    el_i, el_j = el.first_node, el.second_node
    for k in range(el_i.shape[0]):       # band_add written out: a call per block passing arrays costs more
        pi, pj = position[el_i[k]], position[el_j[k]]
        for a, b, sign in ((pi, pi, 1.0), (pi, pj, -1.0), (pj, pi, -1.0), (pj, pj, 1.0)):
            if a >= 0 and b >= 0:
                d, stiff, damp = b - a + bw, sign * c_stiff, sign * c_damp
                for r in range(3):
                    for q in range(3):
                        A[a, d, r, q] += stiff * K[k, r, q]
                        A[a, d, r, q] += damp * C[k, r, q]
                        if a == b:                            # each end's drag on its own velocity
                            A[a, d, r, q] += c_damp * D[k, r, q]
    bending_tangent(A, bw, position, x, el, c_stiff)
    free_index = nodes.free
    for f in range(free_index.shape[0]):
        p, node = position[free_index[f]], free_index[f]
        for r in range(3):
            for q in range(3):
                A[p, bw, r, q] += c_mass * M[node, fast.PACKED[r][q]]
    seabed_tangent(A, bw, position, free_index, bodies.contact, work, Kc, Cc, c_damp, c_stiff)
    body_node, drag_area, rho = bodies.load_node, bodies.drag_area, env.rho
    block = np.empty((3, 3))
    for b in range(body_node.shape[0]):
        node = body_node[b]
        if position[node] < 0:
            continue
        ur0, ur1, ur2 = bu[b, 0] - v[node, 0], bu[b, 1] - v[node, 1], bu[b, 2] - v[node, 2]
        speed = np.sqrt(ur0 * ur0 + ur1 * ur1 + ur2 * ur2)
        inv = 1.0 / max(speed, 1e-12)
        ur = (ur0, ur1, ur2)
        for r in range(3):
            for q in range(3):
                block[r, q] = 0.5 * rho * drag_area[b] * ((speed if r == q else 0.0) + ur[r] * ur[q] * inv)
        band_add(A, bw, position[node], position[node], block, c_damp)


@inner
def contact_changed(contact, normal_force, in_contact):
    """Whether a node touched or left the seabed since ``in_contact`` was recorded (then record it);
    False (and nothing compiled) when ``contact`` is None."""
    changed = False
    if contact is not None:
        for a in range(normal_force.shape[0]):
            now = normal_force[a] > 0.0
            if now != in_contact[a]:
                in_contact[a] = now
                changed = True
    return changed


@inner
def newton_step(t, h, scheme, x0, v0, a0, vm_pos, vm_vel, vm_head, nodes, el, bodies, env, work, band,
                out_x, out_v, out_a):
    """One generalized-α step (implicit.py eqs. 1-3) of ``scheme`` (an
    :class:`kanat.lumped.entries.ImplicitScheme`) by modified Newton from the predictor in ``out_a``,
    the factors ``A`` and their memory ``tangent`` in ``band`` (an :class:`kanat.lumped.entries.Band`:
    ``factors``, ``memory``); returns the iterations used, or ``-iterations`` when it did not converge.

    The factors of eq. (3) in ``A`` are kept across iterations and steps (``tangent[0]`` holds
    the step they were built for, 0 for none) and rebuilt at the current iterate only where they
    no longer serve: a new step size, a node that touched or left the seabed (its contact
    stiffness is many times its inertia term), or an increment larger than :data:`CONTRACTION`
    times the one before (the tangent has drifted from the state). With the contraction rate
    ``q = |da_k| / |da_k-1|`` of two increments under one matrix, the iterate's remaining error
    is estimated as ``eta |da_k|``, ``eta = q / (1 - q)`` (Hairer & Wanner, Solving ODEs II, 2nd
    ed., IV.8 eq. 8.10); the step is accepted when that estimate, or the increment itself, is below
    ``tolerance * max(1 m/s^2, max |a_1|)`` — the criterion of the full Newton in implicit.py,
    which the converged steps therefore match to the tolerance. The first iteration of a step has
    no rate of its own: it takes the last one measured under the same factors (``tangent[3]``),
    raised to the power 0.8 — RADAU5's ``FACCON = MAX(FACCON, UROUND)**0.8`` (Hairer & Wanner,
    IV.8, the code's step start), which lets it drift towards 1 over the steps it is not
    measured — so a step whose first increment is already small enough ends there, with one
    force evaluation. The carried rate is taken as at least :data:`CARRIED_RATE_FLOOR`: a rate
    measured while the line was nearly linear (a slack line falling freely contracts at 1e-10)
    says nothing of the next step, where an element may snap taut, and a first increment 1e8
    times the tolerance was accepted on it (a released line falling through its own slack
    stretched 187 % at dt 0.01 s, where rk4 and a measured rate keep it within 0.1 %). New factors start with the rate unknown (0). Factors :data:`FACTOR_AGE`
    steps old (``tangent[4]``) are rebuilt whatever their rate: the tangent drifts with the
    tension and the drag, and fresh factors contract enough for more steps to end after their
    first iteration (the three-leg mooring of ``benchmarks/bench_mooring_moordyn.py``, 12.5 ms,
    300 s with an output every 5 s: 47 400 force evaluations and 0.76 s with factors kept until
    their rate exceeds :data:`CONTRACTION`, whatever its value from 0.01 to 0.1; 41 600, 38 800 and
    36 000 evaluations, 0.70, 0.69 and 0.71 s, with factors at most 32, 16 and 8 steps old).

    A line search guards the iteration: where an increment raised the residual's 2-norm, it is
    halved (up to :data:`LINE_SEARCH_HALVINGS` times) and the factors are rebuilt at the shorter
    iterate, which breaks the two-cycles a node sets up when its seabed contact switches on and
    off from one iterate to the next (Dennis & Schnabel, Numerical Methods for Unconstrained
    Optimization, 1983, §6.3, with the simple decrease test)."""
    am, af, gamma, beta = scheme.alpha_m, scheme.alpha_f, scheme.gamma, scheme.beta
    max_iterations, tolerance = scheme.max_iterations, scheme.tolerance
    position, bw, A = band.position, band.half_width, band.factors
    tangent, in_contact = band.memory, band.in_contact
    nf = x0.shape[0]
    free_index = nodes.free
    ym, rhs = np.empty(6 * nf), np.empty(3 * nf)           # (x_m, v_m) flat, as fast.loads takes them
    last = np.empty((nf, 3))                               # the last increment, for the line search
    F, M = work.force, work.mass
    a1 = out_a                                             # holds the predictor on entry
    tm = t + (1.0 - af) * h
    refresh = tangent[0] != h or tangent[4] >= FACTOR_AGE
    previous, norm_before, backtracks = 0.0, np.inf, 0
    if tangent[3] > 0.0:
        tangent[3] = max(tangent[3], CARRIED_RATE_FLOOR) ** 0.8
    for iteration in range(1, max_iterations + 1):
        for f in range(nf):
            for r in range(3):
                x1 = x0[f, r] + h * v0[f, r] + h * h * ((0.5 - beta) * a0[f, r] + beta * a1[f, r])
                v1 = v0[f, r] + h * ((1.0 - gamma) * a0[f, r] + gamma * a1[f, r])
                ym[3 * f + r] = (1.0 - af) * x1 + af * x0[f, r]
                ym[3 * nf + 3 * f + r] = (1.0 - af) * v1 + af * v0[f, r]
        fast.loads(tm, ym, vm_pos, vm_vel, vm_head, nodes, el, bodies, env, work)
        norm = 0.0
        for f in range(nf):
            node = free_index[f]
            p = position[node]
            for r in range(3):
                s = -F[node, r]
                for q in range(3):
                    s += M[node, fast.PACKED[r][q]] * ((1.0 - am) * a1[f, q] + am * a0[f, q])
                rhs[3 * p + r] = -s
                norm += s * s
        if not fast.finite(rhs):
            tangent[0] = 0.0
            return -iteration
        if contact_changed(bodies.contact, work.normal_force, in_contact):
            refresh = True
        if norm > norm_before and backtracks < LINE_SEARCH_HALVINGS:
            backtracks += 1                                # the residual grew: halve the last increment
            for f in range(nf):
                for r in range(3):
                    last[f, r] *= 0.5
                    a1[f, r] -= last[f, r]
            refresh = True
            continue
        norm_before, backtracks = norm, 0
        refreshed = refresh
        if refresh:
            assemble(band, nodes, el, bodies, env, work, 1.0 - am, (1.0 - af) * gamma * h, (1.0 - af) * beta * h * h)
            tangent[0] = h if band_factor(A, bw) else 0.0
            tangent[3], tangent[4] = 0.0, 0.0
            if tangent[0] == 0.0:
                return -iteration
            refresh = False
        band_substitute(A, bw, rhs)
        biggest, scale = 0.0, ACCELERATION_SCALE
        for f in range(nf):
            p = position[free_index[f]]
            for r in range(3):
                last[f, r] = rhs[3 * p + r]
                a1[f, r] += rhs[3 * p + r]
                biggest = max(biggest, abs(rhs[3 * p + r]))
                scale = max(scale, abs(a1[f, r]))
        measured = iteration > 1 and not refreshed              # the same iteration matrix as the last increment
        rate = biggest / previous if measured else 1.0
        if measured:
            tangent[3] = rate / (1.0 - rate) if rate < 1.0 else 0.0
        if biggest <= tolerance * scale or (not refreshed and 0.0 < tangent[3] * biggest <= tolerance * scale):
            for f in range(nf):
                for r in range(3):
                    out_x[f, r] = x0[f, r] + h * v0[f, r] + h * h * ((0.5 - beta) * a0[f, r] + beta * a1[f, r])
                    out_v[f, r] = v0[f, r] + h * ((1.0 - gamma) * a0[f, r] + gamma * a1[f, r])
            return iteration
        if measured and rate > CONTRACTION:
            refresh = True
        previous = biggest
    tangent[0] = 0.0
    return -max_iterations


@inner
def observe_error(t, factor, h, x, a, na, nx, estimate):
    """The local displacement error ``e = factor h^2 (a_n+1 - a_n)`` of each free node at ``t = t_n+1``
    (:mod:`kanat.lumped.time_error`, eq. 1): its largest norm into ``estimate[0:3]`` (value, time, free node),
    its 2-norm over the step's displacement's or ``d_0 sqrt(n_free)`` (``d_0`` in ``estimate[8]``), eq. (2),
    into ``estimate[3:5]`` (value, time)."""
    nf = a.shape[0]
    c = factor * h * h
    error, moved = 0.0, 0.0
    for f in range(nf):
        size = 0.0
        for r in range(3):
            e = c * (na[f, r] - a[f, r])
            size += e * e
            moved += (nx[f, r] - x[f, r]) ** 2
        error += size
        if np.sqrt(size) > estimate[0]:
            estimate[0], estimate[1], estimate[2] = np.sqrt(size), t, f
    ratio = np.sqrt(error) / max(np.sqrt(moved), max(MOTION_FLOOR, estimate[8]) * np.sqrt(nf))
    if ratio > estimate[3]:
        estimate[3], estimate[4] = ratio, t


@kernel
def steps(t0, h, count, scheme, x, v, a, mid_samples, end_samples, nodes, el, bodies, env, work, band, snap,
          events, estimate):
    """Up to ``count`` steps of ``scheme`` (an :class:`kanat.lumped.entries.ImplicitScheme`) from
    ``(t0, x, v, a)`` (updated in place), tracking snaps after each. Returns (steps done, Newton
    iterations, events, failed): it stops before a step whose Newton iteration fails, before the
    event buffer could overflow, or on a non-finite state. The vessel is sampled at the steps'
    force balance (``mid_samples``) and ends (``end_samples``), both :class:`kanat.lumped.entries.Track`.

    ``band`` (an :class:`kanat.lumped.entries.Band`) holds the factors and what persists between
    calls: ``band.memory`` (5,), the step of the factors (:func:`newton_step`), the time and step
    of the acceleration history ``band.previous`` (the acceleration one step before that time),
    the factors' last contraction estimate ``eta`` and their age in steps (:func:`newton_step`);
    ``band.in_contact`` (n,), the nodes on the seabed when the factors were built. Each step's
    predictor is ``a_1 = 2 a - a_prev`` where the history is that of this state and step, else
    ``a_1 = a``. ``estimate`` (:data:`kanat.lumped.time_error.SIZE`,): the running maxima of the local
    time-integration error estimate (:mod:`kanat.lumped.time_error`), updated after each step; it only
    observes."""
    tangent, previous = band.memory, band.previous
    nf = x.shape[0]
    nx, nv, na = np.empty((nf, 3)), np.empty((nf, 3)), np.empty((nf, 3))
    y = np.empty(6 * nf)
    factor = scheme.beta - 1.0 / 6.0 + 0.5 * (scheme.alpha_m - scheme.alpha_f)      # time_error eq. 1
    iterations, n_events = 0, np.int64(0)      # not a literal 0: see kanat.jit
    for step in range(count):
        if n_events + work.tension.shape[0] > events.shape[0]:
            return step, iterations, n_events, False
        t = t0 + step * h
        extrapolate = tangent[1] == t and tangent[2] == h        # previous holds a(t - h)
        for f in range(nf):
            for r in range(3):
                na[f, r] = 2.0 * a[f, r] - previous[f, r] if extrapolate else a[f, r]
        used = newton_step(t0 + step * h, h, scheme, x, v, a,
                           mid_samples.position[step], mid_samples.velocity[step], mid_samples.heading[step],
                           nodes, el, bodies, env, work, band, nx, nv, na)
        if used < 0:
            return step, iterations, n_events, True
        iterations += used
        if estimate[5] <= 0.0:                                  # past a start's steps (time_error.START_STEPS)
            observe_error(t + h, factor, h, x, a, na, nx, estimate)
        else:
            estimate[5] -= 1.0
        for f in range(nf):
            for r in range(3):
                previous[f, r] = a[f, r]
                x[f, r], v[f, r], a[f, r] = nx[f, r], nv[f, r], na[f, r]
                y[3 * f + r], y[3 * nf + 3 * f + r] = nx[f, r], nv[f, r]
        tangent[1], tangent[2], tangent[4] = t + h, h, tangent[4] + 1.0
        fast.tensions_at(y, step, end_samples, nodes, el, bodies, work)
        n_events = fast.snap_update(t0 + (step + 1) * h, work.tension, snap, events, n_events)
        if not fast.finite(y):
            return step + 1, iterations, n_events, False
    return count, iterations, n_events, False
