"""Advancing a run by many steps: the fused compiled path where it applies, else step by step.

:func:`advance` is what the driver calls between two outputs. For the lumped mass matrix
and the built-in ``rk4`` and ``abm4`` schemes it hands the whole stretch to
:mod:`kanat.lumped.fast` (:class:`FusedArrays` packs the network, environment and work
arrays once per run); any other scheme (the implicit one, a user's own) or the consistent
mass matrix goes through ``scheme.step`` with the tensions and snap events updated after
every step in Python. Both paths give the same states to round-off (tests). A compiled
implicit step whose Newton iteration fails is retaken as compiled half steps (up to
:data:`COMPILED_HALVINGS` deep), and where even those fail, by the explicit ``rk4`` at its safe
step (:func:`_explicit`, counted in the state's ``explicit`` and said in the run's notes): an
implicit run never fails where ``rk4`` succeeds.
"""
from __future__ import annotations

import numpy as np

from kanat.lumped import entries, fast, fast_implicit, stepping
from kanat.lumped.integrators import ABM4, RK4, GeneralizedAlphaLumped, pack, state_positions, unpack


COMPILED_HALVINGS = 3       # a failed compiled implicit step is retried as 2, 4, 8 compiled half steps
CALL_STEPS = 50_000
"""Most steps of one compiled call: the interpreter gets control back (and Ctrl-C is handled)
every 50 000 steps, a few seconds of a large network at most, and the vessel's samples for a
call (``2 steps + 1`` times) stay a few MB, whatever the output interval."""


def supports(system, scheme) -> bool:
    """Whether the fused path can run ``scheme`` on ``system``."""
    return (type(scheme) in (RK4, ABM4, GeneralizedAlphaLumped) and not system.consistent
            and system.steady_velocity is None)


class FusedArrays:
    """The typed-array tuples :mod:`kanat.lumped.fast` takes, built once from a system.

    Attributes
    ----------
    nodes, el, bodies, env, work : tuple
        See :func:`kanat.lumped.fast.loads`: ``nodes`` (free, vessel, anchor nodes, anchor
        positions, nodal loads and masses, free flags, 6-DOF pseudo-nodes' free-local rows),
        ``el`` the element arrays, ``bodies`` (load nodes, drag, spreading, fluid inertia, buoys,
        rigid bodies, seabed contact), ``env`` (rho, g, current table, sea, still, elevation
        bound, current ramp [s]), ``work`` the scratch arrays.
    """

    def __init__(self, system):
        net = system.net
        n, m, nl, nb = net.n_nodes, net.n_elements, len(net.load_node), net.rigid.count
        local = np.searchsorted(system.free_index, np.stack([net.rigid.ref_node, net.rigid.rot_node], -1))
        self.nodes = (system.free_index.astype(np.int64), net.vessel_nodes.astype(np.int64),
                      net.anchor_nodes.astype(np.int64), np.ascontiguousarray(net.anchor_position, float),
                      np.ascontiguousarray(net.node_force, float), system.node_mass, net.free.copy(),
                      np.ascontiguousarray(local.reshape(nb, 2), dtype=np.int64))
        self.el = system.el_args
        buoys = net.body_node[net.buoy_body] if len(net.buoy_body) else np.zeros(0, np.int64)
        self.bodies = (net.load_node.astype(np.int64), net.load_drag_area.astype(float),
                       net.load_spreading.astype(float), net.node_fluid_inertia.astype(float), buoys.astype(np.int64),
                       net.buoy_area.astype(float), net.buoy_height.astype(float),
                       system.rig if net.rigid.count else None,                     # None: pruned from the kernels
                       system.contact if len(system.contact[0]) else None)
        cz, cu = system.current.table()
        ramp = float(system.current.ramp)
        still = system.sea is None and len(cz) == 1 and ramp == 0.0   # water kinematics constant in space and time
        self.env = (system.rho, system.g, cz, cu, sea_arrays(system.sea), still, system.eta_bound, ramp)
        self.work = (np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 6)), np.zeros(m),
                     np.zeros(m), np.zeros((m, 3)), np.zeros((m, 3)), np.zeros((m, 3)), np.zeros((nl, 3)),
                     np.zeros((nl, 3)), np.zeros((nl, 3)), np.zeros((n, 3)), np.ones(m), np.zeros((nb, 2, 3)),
                     np.zeros((nb, 3)), np.zeros((nb, 3)), np.zeros(nb), np.zeros(n), np.zeros((n, 3)),
                     np.zeros((nb, 3)))
        if still:                                                     # set once: uw (m, 3), bu (nl, 3)
            self.work[7][:], self.work[10][:] = cu[0], cu[0]
            if nb:
                self.work[15][:] = cu[0]
        self.events = np.zeros((max(fast.EVENT_BUFFER_MIN, 4 * m), 4))
        self.position, self.bandwidth = fast_implicit.band_order(net, system.free_index)
        self.blocks = (np.zeros((m, 3, 3)), np.zeros((m, 3, 3)), np.zeros((m, 3, 3)), np.zeros((n, 3, 3)),
                       np.zeros((n, 3, 3)))
        self.band = np.zeros((len(system.free_index), 2 * self.bandwidth + 1, 3, 3))   # 3 x 3 node blocks
        # fast_implicit.steps: the step of the factors in band (0: none), the time and step of the history
        # previous, the factors' contraction estimate and age; the nodes on the seabed when band was built
        self.tangent = np.zeros(5)
        self.in_contact = np.zeros(n, dtype=np.bool_)
        self.previous = np.zeros((len(system.free_index), 3))


def sea_arrays(sea) -> tuple:
    """A :class:`kanat.physics.waves.LinearSea` (or None) as the tuple :func:`fast.sea_add` takes;
    ``depth <= 0`` stands for deep water, then 1.0 for Wheeler stretching (0.0 none) and the ramp [s]."""
    if sea is None:
        empty = np.zeros(0)
        return empty, empty, empty, empty, empty, empty, 0.0, empty, 0.0, 0.0
    depth = 0.0 if sea.depth is None else float(sea.depth)
    inv = 1.0 / (1.0 - np.exp(-2.0 * sea.k * depth)) if depth > 0 else np.ones_like(sea.k)
    return (np.asarray(sea.amplitude, float), np.asarray(sea.omega, float), np.asarray(sea.k, float),
            np.cos(sea.direction), np.sin(sea.direction), np.asarray(sea.phase, float), depth, inv,
            1.0 if sea.stretching == "wheeler" else 0.0, float(sea.ramp))


def track_samples(system, times: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vessel nodes' positions, velocities (k, n_vessel, 3) and the heading (k,) at ``times`` (k,)
    (:meth:`kanat.lumped.system.LumpedSystem.vessel_points`: track and prescribed motion)."""
    pos, vel, heading = system.vessel_points(np.ascontiguousarray(times, dtype=float))
    return np.ascontiguousarray(pos), np.ascontiguousarray(vel), np.ascontiguousarray(heading)


def _arrays(system) -> FusedArrays:
    if getattr(system, "_fused", None) is None:
        system._fused = FusedArrays(system)
    return system._fused


def advance(scheme, system, state, h: float, steps: int, tracker, tensions) -> tuple[dict, int]:
    """Take ``steps`` steps of size ``h`` from ``state``, updating ``tracker`` after each.

    Parameters
    ----------
    scheme : kanat.schemes.Scheme
    system : kanat.lumped.system.LumpedSystem
    state : dict
        The scheme's state (not modified).
    tracker : kanat.lumped.snap.SnapTracker
    tensions : callable
        ``tensions(state) -> T`` (m,), the element tensions of a state (Python path).

    Returns
    -------
    state : dict
    taken : int
        Steps taken (fewer than ``steps`` only when the state became non-finite).
    """
    if not supports(system, scheme):
        for done in range(steps):
            state = scheme.step(system, state, h)
            tracker.update(state["t"], tensions(state))
            if not np.all(np.isfinite(state_positions(state)[0])):
                return state, done + 1
        return state, steps
    state = {k: (np.array(v) if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    taken = 0
    if isinstance(scheme, GeneralizedAlphaLumped):        # each call starts afresh: a run resumed from a
        arrays = _arrays(system)                           # checkpoint takes the very same iterations
        arrays.tangent[:] = 0.0
        arrays.in_contact[:] = False
    while taken < steps and isinstance(scheme, ABM4) and len(state["history"]) < 4:
        state = scheme.step(system, state, h)                     # RK4 start-up, in Python
        tracker.update(state["t"], tensions(state))
        taken += 1
    while taken < steps:
        batch = min(steps - taken, CALL_STEPS)
        if isinstance(scheme, GeneralizedAlphaLumped):
            done, failed = _fused_implicit(scheme, system, state, h, batch, tracker)
            if failed and not _halved(scheme, system, state, h, tracker, COMPILED_HALVINGS):
                _explicit(system, state, h, tracker)
            done += failed
        else:
            done = _fused(scheme, system, state, h, batch, tracker)
        taken += done
        if not np.all(np.isfinite(state_positions(state)[0])):
            break
    return state, taken


def _halved(scheme, system, state, h, tracker, levels: int) -> bool:
    """Take one failed step of ``h`` as two compiled steps of ``h / 2`` (each halved again where it
    fails, ``levels`` deep); ``state`` is updated in place. False (and ``state`` untouched) when
    even that fails."""
    if levels == 0:
        return False
    saved = {k: (np.array(v) if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    for _ in range(2):
        done, failed = _fused_implicit(scheme, system, state, 0.5 * h, 1, tracker)
        if failed and not _halved(scheme, system, state, 0.5 * h, tracker, levels - 1):
            cuts = state["cuts"]                        # every failed attempt counts, kept or not
            state.clear()
            state.update(saved, cuts=cuts)
            return False
    return True


def _explicit(system, state, h, tracker) -> None:
    """Take one step of ``h`` of the implicit ``state`` (updated in place) by compiled ``rk4`` steps
    at the explicit safe step of the state (:mod:`kanat.lumped.stepping`), and restart the implicit
    scheme from their end with the acceleration of eq. (1) there; the steps are added to the state's
    ``explicit`` count."""
    net = system.net
    x = system.full(state["t"], state["x"], state["v"])[0]
    info = stepping.step_info(net, x, False, system.case.environment.seabed)
    count = max(1, int(np.ceil(h / info.safe_step(RK4) - 1e-9)))
    sub = {"t": float(state["t"]), "y": pack(state["x"], state["v"])}
    done = _fused(RK4(), system, sub, h / count, count, tracker)
    xf, vf = (np.array(part) for part in unpack(sub["y"]))
    a = system.acceleration(sub["t"], xf, vf) if done == count else np.full_like(xf, np.nan)
    state.update(t=sub["t"], x=xf, v=vf, a=a, explicit=state.get("explicit", 0) + done)
    _arrays(system).tangent[:] = 0.0                    # the implicit factors start afresh


def _fused_implicit(scheme, system, state, h, steps, tracker) -> tuple[int, bool]:
    """Compiled generalized-α steps from ``state`` (updated in place; a failed step counts as a cut):
    (steps taken, failed)."""
    arrays = _arrays(system)
    t0 = float(state["t"])
    af = scheme.coefficients[1]
    step = np.arange(steps) + 1.0
    pos, vel, heading = track_samples(system, t0 + h * np.concatenate([step - af, step]))    # one sampling
    mid, end = (pos[:steps], vel[:steps], heading[:steps]), (pos[steps:], vel[steps:], heading[steps:])
    x, v, a = (np.array(state[k], dtype=float) for k in ("x", "v", "a"))
    done, iterations, count, failed = entries.implicit_steps(
        t0, h, steps, scheme.coefficients, scheme.max_iterations, scheme.tolerance, x, v, a, mid, end,
        arrays.position, arrays.bandwidth, arrays.nodes, arrays.el, arrays.bodies, arrays.env, arrays.work,
        arrays.blocks, arrays.band, arrays.tangent, arrays.in_contact, arrays.previous, tracker.kernel_arrays(), arrays.events)
    tracker.absorb(arrays.events[:count].copy())
    state.update(t=t0 + done * h, x=x, v=v, a=a, iterations=state["iterations"] + iterations,
                 cuts=state.get("cuts", 0) + int(failed))            # the failed step is retaken in halves
    system.evaluations += iterations
    return done, failed


def _fused(scheme, system, state, h, steps, tracker) -> int:
    """One compiled call from ``state`` (updated in place); returns the steps it took."""
    arrays = _arrays(system)
    t0 = float(state["t"])
    samples = track_samples(system, t0 + 0.5 * h * np.arange(2 * steps + 1))
    snap = tracker.kernel_arrays()
    args = (samples, arrays.nodes, arrays.el, arrays.bodies, arrays.env, arrays.work, snap, arrays.events)
    if isinstance(scheme, ABM4):
        done, count = entries.abm4_steps(t0, h, steps, state["y"], state["history"], *args)
    else:
        done, count = entries.rk4_steps(t0, h, steps, state["y"], *args)
    tracker.absorb(arrays.events[:count].copy())
    state["t"] = t0 + done * h
    system.evaluations += done * scheme.evaluations_per_step
    return done


def element_tensions(system, state, out: np.ndarray) -> np.ndarray:
    """Element tensions (m,) of a scheme state, written into ``out`` (the Python path)."""
    x, v, _, _ = system.full(state["t"], *state_positions(state))
    entries.tensions(x, v, system.el_args, out)
    return out
