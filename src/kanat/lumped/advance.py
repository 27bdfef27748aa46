"""Advancing a run by many steps: the fused compiled path where it applies, else step by step.

:func:`advance` is what the driver calls between two outputs. For the lumped mass matrix
and the built-in ``rk4`` and ``abm4`` schemes it hands the whole stretch to
:mod:`kanat.lumped.fast` (:class:`FusedArrays` packs the network, environment and work
arrays once per run); any other scheme (the implicit one, a user's own) or the consistent
mass matrix goes through ``scheme.step`` with the tensions and snap events updated after
every step in Python. Both paths give the same states to round-off (tests). A compiled
implicit step whose Newton iteration fails is retaken as compiled half steps (up to
:data:`COMPILED_HALVINGS` deep, by the step control both models share,
:class:`kanat.step_control.Halving`), and where even those fail, by the explicit ``rk4`` at its
safe step (:func:`_explicit`, counted in the state's ``explicit`` and said in the run's notes): an
implicit run never fails where ``rk4`` succeeds. Each scheme's compiled run is found in
:data:`COMPILED` by its class. Every implicit step, on either path, also updates the run's
estimate of its local time-integration error (:mod:`kanat.lumped.time_error`, kept as
:func:`time_error_estimate`), which only observes; its start is judged once by a step pair
(:func:`check_start`).
"""
from __future__ import annotations

import functools
from dataclasses import replace

import numpy as np

from kanat.errors import SolverError
from kanat.lumped import entries, fast, fast_implicit, stepping, time_error
from kanat.lumped.integrators import ABM4, RK4, ExplicitState, GeneralizedAlphaLumped, pack, unpack
from kanat.lumped.snap import SnapTracker
from kanat.step_control import Halving, StepRefused

COMPILED_HALVINGS = 3       # a failed compiled implicit step is retried as 2, 4, 8 compiled half steps
HALVING = Halving(COMPILED_HALVINGS)
CALL_STEPS = 50_000
"""Most steps of one compiled call: the interpreter gets control back (and Ctrl-C is handled)
every 50 000 steps, a few seconds of a large network at most, and the vessel's samples for a
call (``2 steps + 1`` times) stay a few MB, whatever the output interval."""


def supports(system, scheme) -> bool:
    """Whether the fused path can run ``scheme`` on ``system``: a scheme with a compiled run
    (:data:`COMPILED`), the lumped mass matrix, no steady frame."""
    return type(scheme) in COMPILED and not system.consistent and system.steady_velocity is None


class FusedArrays:
    """The named records :mod:`kanat.lumped.fast` takes (:mod:`kanat.lumped.entries`), built once
    from a system: their one builder.

    Attributes
    ----------
    nodes : kanat.lumped.entries.Nodes
    el : kanat.lumped.entries.Elements
        The system's (:meth:`kanat.lumped.network.Network.elements`).
    bodies : kanat.lumped.entries.Bodies
    env : kanat.lumped.entries.Environment
    work : kanat.lumped.entries.Work
        The scratch arrays, their water kinematics set once where the water is still.
    events : numpy.ndarray
        The snap events' buffer (k, 4) the stepping kernels fill.
    band : kanat.lumped.entries.Band
        The implicit steps' band tangent in the band order of
        :func:`kanat.lumped.fast_implicit.band_order`, its scratch blocks and what persists
        between calls (:func:`kanat.lumped.fast_implicit.steps`).
    """

    def __init__(self, system):
        net = system.net
        n, m, nl, nb = net.n_nodes, net.n_elements, len(net.load_node), net.rigid.count
        local = np.searchsorted(system.free_index, np.stack([net.rigid.ref_node, net.rigid.rot_node], -1))
        self.nodes = entries.Nodes(
            free=system.free_index.astype(np.int64), vessel=net.vessel_nodes.astype(np.int64),
            anchor=net.anchor_nodes.astype(np.int64), anchor_position=np.ascontiguousarray(net.anchor_position, float),
            force=np.ascontiguousarray(net.node_force, float), mass=system.node_mass, is_free=net.free.copy(),
            rigid_rows=np.ascontiguousarray(local.reshape(nb, 2), dtype=np.int64))
        self.el = system.el_args
        buoys = net.body_node[net.buoy_body] if len(net.buoy_body) else np.zeros(0, np.int64)
        self.bodies = entries.Bodies(
            load_node=net.load_node.astype(np.int64), drag_area=net.load_drag_area.astype(float),
            spreading=net.load_spreading.astype(float), fluid_inertia=net.node_fluid_inertia.astype(float),
            buoy_node=buoys.astype(np.int64), buoy_area=net.buoy_area.astype(float),
            buoy_height=net.buoy_height.astype(float),
            float_node=net.body_node[net.float_body].astype(np.int64), float_diameter=net.float_diameter.astype(float),
            float_buoyancy=net.float_buoyancy.astype(float),
            rig=system.rig if net.rigid.count else None,                          # None: pruned from the kernels
            contact=system.contact)                                               # None without a seabed
        cz, cu = system.current.table()
        ramp = float(system.current.ramp)
        still = system.sea is None and len(cz) == 1 and ramp == 0.0   # water kinematics constant in space and time
        self.env = entries.Environment(
            rho=system.rho, g=system.g, current_depths=cz, current_velocities=cu, sea=sea_arrays(system.sea),
            still=still, elevation_bound=system.eta_bound, current_ramp=ramp)
        self.work = entries.Work(
            x=np.zeros((n, 3)), v=np.zeros((n, 3)), force=np.zeros((n, 3)), mass=np.zeros((n, 6)),
            tension=np.zeros(m), strain=np.zeros(m), midpoint=np.zeros((m, 3)), water_velocity=np.zeros((m, 3)),
            water_acceleration=np.zeros((m, 3)), load_position=np.zeros((nl, 3)), load_velocity=np.zeros((nl, 3)),
            load_acceleration=np.zeros((nl, 3)), wet=np.ones(m), body_acceleration=np.zeros((nb, 2, 3)),
            body_velocity=np.zeros((nb, 3)), body_water_acceleration=np.zeros((nb, 3)), body_elevation=np.zeros(nb),
            normal_force=np.zeros(n), line_tangent=np.zeros((n, 3)), body_position=np.zeros((nb, 3)))
        if still:                                                     # set once: the uniform current
            self.work.water_velocity[:], self.work.load_velocity[:] = cu[0], cu[0]
            if nb:
                self.work.body_velocity[:] = cu[0]
        self.events = np.zeros((max(fast.EVENT_BUFFER_MIN, 4 * m), 4))
        position, half_width = fast_implicit.band_order(net, system.free_index)
        nf = len(system.free_index)
        self.band = entries.Band(
            position=position, half_width=half_width, factors=np.zeros((nf, 2 * half_width + 1, 3, 3)),
            element_stiffness=np.zeros((m, 3, 3)), element_damping=np.zeros((m, 3, 3)),
            element_drag=np.zeros((m, 3, 3)), contact_stiffness=np.zeros((n, 3, 3)),
            contact_damping=np.zeros((n, 3, 3)), memory=np.zeros(5), in_contact=np.zeros(n, dtype=np.bool_),
            previous=np.zeros((nf, 3)))


def sea_arrays(sea) -> entries.Sea:
    """A :class:`kanat.physics.waves.LinearSea` (or None: no components) as the record
    :func:`fast.sea_add` takes (:class:`kanat.lumped.entries.Sea`, its one builder); ``depth <= 0``
    stands for deep water."""
    if sea is None:
        empty = np.zeros(0)
        return entries.Sea(amplitude=empty, omega=empty, wavenumber=empty, cos_direction=empty, sin_direction=empty,
                           phase=empty, depth=0.0, depth_factor=empty, wheeler=0.0, ramp=0.0)
    depth = 0.0 if sea.depth is None else float(sea.depth)
    inv = 1.0 / (1.0 - np.exp(-2.0 * sea.k * depth)) if depth > 0 else np.ones_like(sea.k)
    return entries.Sea(amplitude=np.asarray(sea.amplitude, float), omega=np.asarray(sea.omega, float),
                       wavenumber=np.asarray(sea.k, float), cos_direction=np.cos(sea.direction),
                       sin_direction=np.sin(sea.direction), phase=np.asarray(sea.phase, float), depth=depth,
                       depth_factor=inv, wheeler=1.0 if sea.stretching == "wheeler" else 0.0, ramp=float(sea.ramp))


def track_samples(system, times: np.ndarray) -> entries.Track:
    """Vessel nodes' positions, velocities (k, n_vessel, 3) and the heading (k,) at ``times`` (k,)
    (:meth:`kanat.lumped.system.LumpedSystem.vessel_points`: track and prescribed motion), the
    :class:`kanat.lumped.entries.Track` record's one builder."""
    pos, vel, heading = system.vessel_points(np.ascontiguousarray(times, dtype=float))
    return entries.Track(position=np.ascontiguousarray(pos), velocity=np.ascontiguousarray(vel),
                         heading=np.ascontiguousarray(heading))


def implicit_scheme(scheme) -> entries.ImplicitScheme:
    """A :class:`kanat.lumped.integrators.GeneralizedAlphaLumped` as the fused implicit steps read
    it: the :class:`kanat.lumped.entries.ImplicitScheme` record's one builder."""
    return _implicit_record(tuple(float(value) for value in scheme.coefficients), int(scheme.max_iterations),
                            float(scheme.tolerance))


@functools.lru_cache(maxsize=16)
def _implicit_record(coefficients: tuple, max_iterations: int, tolerance: float) -> entries.ImplicitScheme:
    """One record per set of values: the compiled call's check passes a record it has seen at once."""
    alpha_m, alpha_f, gamma, beta = coefficients
    return entries.ImplicitScheme(alpha_m=alpha_m, alpha_f=alpha_f, gamma=gamma, beta=beta,
                                  max_iterations=max_iterations, tolerance=tolerance)


def time_error_estimate(system) -> np.ndarray:
    """The running maxima of the implicit scheme's local error estimate over ``system``'s run so far
    (:data:`kanat.lumped.time_error.SIZE`,; :func:`kanat.lumped.time_error.empty` before the first step),
    updated in place by the steps."""
    if getattr(system, "_time_error", None) is None:
        system._time_error = time_error.empty(time_error.motion_floor(system.net.el_length))
    return system._time_error


def _arrays(system) -> FusedArrays:
    if getattr(system, "_fused", None) is None:
        system._fused = FusedArrays(system)
    return system._fused


def advance(scheme, system, state, h: float, steps: int, tracker, tensions):
    """Take ``steps`` steps of size ``h`` from ``state``, updating ``tracker`` after each.

    The scheme's compiled run (:data:`COMPILED`) takes them where :func:`supports` says it can,
    else the scheme's own ``step`` one by one.

    Parameters
    ----------
    scheme : kanat.schemes.Scheme
    system : kanat.lumped.system.LumpedSystem
    state : kanat.lumped.integrators.SchemeState
        The scheme's state (not modified).
    tracker : kanat.lumped.snap.SnapTracker
    tensions : callable
        ``tensions(state) -> T`` (m,), the element tensions of a state (Python path).

    Returns
    -------
    state : kanat.lumped.integrators.SchemeState
    taken : int
        Steps taken (fewer than ``steps`` only when the state became non-finite).
    """
    if isinstance(scheme, GeneralizedAlphaLumped) and time_error.start_pending(time_error_estimate(system)):
        check_start(scheme, system, state, h, tensions)
    if not supports(system, scheme):
        return _python_steps(scheme, system, state, h, steps, tracker, tensions)
    return COMPILED[type(scheme)](scheme, system, state, h, steps, tracker, tensions)


def check_start(scheme, system, state, h: float, tensions) -> None:
    """Eq. (3) of :mod:`kanat.lumped.time_error` for the start at ``state``: its first
    :data:`kanat.lumped.time_error.START_STEPS` steps taken again at ``h`` and at ``h/2`` (by
    :func:`advance`, on copies, with snap tracking of their own), their tensions compared at the steps'
    ends; kept in the estimate's ``[6:8]``. It only observes: the estimate's other entries and the
    system's force count are put back. A pair that turns non-finite or fails is compared up to there."""
    estimate = time_error_estimate(system)
    kept, evaluations = estimate.copy(), system.evaluations
    estimate[6] = 0.0                                           # checked: the pair's own steps do not recurse
    times, tension = [], {1: [], 2: []}
    runs = {k: state for k in (1, 2)}
    try:
        for _ in range(time_error.START_STEPS):
            for k in (1, 2):
                tracker = SnapTracker(runs[k].t, tensions(runs[k]).copy())
                runs[k] = advance(scheme, system, runs[k], h / k, k, tracker, tensions)[0]
            if not (_finite(runs[1]) and _finite(runs[2])):
                break
            times.append(runs[1].t)
            for k in (1, 2):
                tension[k].append(tensions(runs[k]).copy())
    except SolverError:
        pass                                                    # the run itself will say what failed
    finally:
        estimate[:] = kept
        system.evaluations = evaluations
    estimate[6:8] = time_error.start_difference(np.array(times), np.array(tension[1]), np.array(tension[2]))


def _python_steps(scheme, system, state, h, steps, tracker, tensions):
    """``steps`` of the scheme's own ``step``, the tracker (and, for generalized-α, the time error
    estimate) updated after each."""
    implicit = isinstance(scheme, GeneralizedAlphaLumped)
    for done in range(steps):
        before = state
        state = scheme.step(system, state, h)
        if implicit:
            time_error.observe(time_error_estimate(system), state.t, h, scheme.coefficients, before.x, before.a,
                               state.a, state.x)
        tracker.update(state.t, tensions(state))
        if not _finite(state):
            return state, done + 1
    return state, steps


def _finite(state) -> bool:
    return bool(np.all(np.isfinite(state.positions()[0])))


def _explicit_run(scheme, system, state, h, steps, tracker, tensions, taken: int = 0):
    """``rk4`` or ``abm4`` (its history complete) in compiled calls of at most :data:`CALL_STEPS` steps."""
    state = state.copy()                                  # the calls advance its arrays in place
    while taken < steps:
        state, done = _fused(scheme, system, state, h, min(steps - taken, CALL_STEPS), tracker)
        taken += done
        if not _finite(state):
            break
    return state, taken


def _abm4_run(scheme, system, state, h, steps, tracker, tensions):
    """``abm4``: its RK4 start-up in Python (until four rates are known), then compiled."""
    taken = 0
    while taken < steps and len(state.history) < 4:
        state = scheme.step(system, state, h)
        tracker.update(state.t, tensions(state))
        taken += 1
    return _explicit_run(scheme, system, state, h, steps, tracker, tensions, taken)


def _implicit_run(scheme, system, state, h, steps, tracker, tensions):
    """Generalized-α in compiled calls; a step a call fails is retaken by :func:`_retake`."""
    band = _arrays(system).band              # each call starts afresh: a run resumed from a
    band.memory[:] = 0.0                     # checkpoint takes the very same iterations
    band.in_contact[:] = False
    taken = 0
    while taken < steps:
        state, done, iterations, failed = _fused_implicit(scheme, system, state, h, min(steps - taken, CALL_STEPS),
                                                          tracker)
        state = replace(state, iterations=state.iterations + iterations, cuts=state.cuts + int(failed))
        if failed:
            state = _retake(scheme, system, state, h, tracker)
        taken += done + failed
        if not _finite(state):
            break
    return state, taken


def _retake(scheme, system, state, h, tracker):
    """The step of ``h`` a compiled call failed, as compiled half steps (:data:`HALVING`), else by
    ``rk4`` (:func:`_explicit`); its work is added to the state's counts."""
    def attempt(current, step):
        new, done, iterations, failed = _fused_implicit(scheme, system, current, step, 1, tracker)
        if failed:
            raise StepRefused("the compiled Newton iteration did not converge", iterations)
        return new, iterations

    def fallback(current, step):
        return _explicit(system, current, step, tracker)

    new, work = HALVING.retake(attempt, state, h, fallback)
    return replace(new, iterations=state.iterations + work.iterations, cuts=state.cuts + work.cuts)


def _explicit(system, state, h, tracker):
    """One step of ``h`` of the implicit ``state`` by compiled ``rk4`` steps at the explicit safe step
    of the state (:mod:`kanat.lumped.stepping`), the implicit scheme restarted from their end with the
    acceleration of eq. (1) there; the steps are added to the state's ``explicit`` count."""
    net = system.net
    x = system.full(state.t, state.x, state.v)[0]
    info = stepping.step_info(net, x, False, system.case.environment.seabed)
    count = max(1, int(np.ceil(h / info.safe_step(RK4) - 1e-9)))
    sub, done = _fused(RK4(), system, ExplicitState(float(state.t), pack(state.x, state.v)), h / count, count,
                       tracker)
    xf, vf = (np.array(part) for part in unpack(sub.y))
    a = system.acceleration(sub.t, xf, vf) if done == count else np.full_like(xf, np.nan)
    _arrays(system).band.memory[:] = 0.0                # the implicit factors start afresh
    time_error.restart(time_error_estimate(system))     # and the error estimate passes over the restart
    return replace(state, t=sub.t, x=xf, v=vf, a=a, explicit=state.explicit + done)


def _fused_implicit(scheme, system, state, h, steps, tracker):
    """Compiled generalized-α steps from ``state`` (not modified): the new state, the steps done, the
    Newton iterations spent and whether the call stopped at a step it failed (the state's counts are
    the caller's to add)."""
    arrays = _arrays(system)
    t0 = float(state.t)
    af = scheme.coefficients[1]
    step = np.arange(steps) + 1.0
    track = track_samples(system, t0 + h * np.concatenate([step - af, step]))    # one sampling: balances, ends
    mid, end = (entries.Track(*(part[rows] for part in track)) for rows in (slice(None, steps), slice(steps, None)))
    x, v, a = (np.array(value, dtype=float) for value in (state.x, state.v, state.a))
    done, iterations, count, failed = entries.implicit_steps(
        t0, h, steps, implicit_scheme(scheme), x, v, a, mid, end, arrays.nodes, arrays.el, arrays.bodies,
        arrays.env, arrays.work, arrays.band, tracker.kernel_arrays(), arrays.events, time_error_estimate(system))
    tracker.absorb(arrays.events[:count].copy())
    system.evaluations += iterations
    return replace(state, t=t0 + done * h, x=x, v=v, a=a), done, iterations, failed


def _fused(scheme, system, state, h, steps, tracker):
    """One compiled call of ``rk4`` or ``abm4`` from ``state``, whose arrays it advances in place:
    the state at its end and the steps it took."""
    arrays = _arrays(system)
    t0 = float(state.t)
    samples = track_samples(system, t0 + 0.5 * h * np.arange(2 * steps + 1))
    snap = tracker.kernel_arrays()
    args = (samples, arrays.nodes, arrays.el, arrays.bodies, arrays.env, arrays.work, snap, arrays.events)
    done, count = FUSED_CALLS[type(scheme)](t0, h, steps, state, args)
    tracker.absorb(arrays.events[:count].copy())
    system.evaluations += done * scheme.evaluations_per_step
    return replace(state, t=t0 + done * h), done


def _rk4_call(t0, h, steps, state, args):
    return entries.rk4_steps(t0, h, steps, state.y, *args)


def _abm4_call(t0, h, steps, state, args):
    return entries.abm4_steps(t0, h, steps, state.y, state.history, *args)


FUSED_CALLS = {RK4: _rk4_call, ABM4: _abm4_call}
"""The compiled call of each explicit scheme: ``(t0, h, steps, state, args) -> (steps done, events)``."""
COMPILED = {RK4: _explicit_run, ABM4: _abm4_run, GeneralizedAlphaLumped: _implicit_run}
"""Each scheme's compiled run: ``(scheme, system, state, h, steps, tracker, tensions) -> (state, taken)``."""


def element_tensions(system, state, out: np.ndarray) -> np.ndarray:
    """Element tensions (m,) of a scheme state, written into ``out`` (the Python path)."""
    x, v, _, _ = system.full(state.t, *state.positions())
    entries.tensions(x, v, system.el_args, out)
    return out
