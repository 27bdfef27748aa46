"""The planar and spatial continuum models behind one interface, for the run loop and the schemes.

Both adapters have the same methods, so nothing above them asks which one it holds:

* ``initial()``, ``step(state, dt, coefficients)`` (the generalized-α family), ``outputs(state)``,
  ``save(state)`` / ``restore(t, saved)``;
* ``velocities(t)`` (both ends, global frame) and ``origin(t)`` (the first end's position);
* ``tangents(state)`` (global unit tangents) and ``tension(state)``;
* ``world(state, dt)`` and ``advanced(state, start, y, chart, dt)`` for seed 000's schemes
  (:mod:`kanat.continuum.factorized.system`).

``dimensions: auto`` picks the planar model when the case stays in the x–z plane
(:func:`kanat.model.plane.out_of_plane` finds nothing) and the spatial one otherwise.

The initial state is the discrete steady state of the box equations, found by Newton from the
statics of the case's cable: the planar solvers for a plain cable in the x–z plane, the 3-D
single-cable statics (:mod:`kanat.statics.shooting3d`) for a cable of several sections, with inline
bodies, a surface buoy, a current with a y component or anything else off the plane.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.chart import angles, choose_chart, frames, needs_rechart, rechart
from kanat.continuum.drive import Drive
from kanat.continuum.factorized.system import CableSystem, World, end_data
from kanat.continuum.model2d import _end as planar_end
from kanat.continuum.model2d import planar_cable, positions
from kanat.continuum.spatial import UP, SpatialCable, SpatialEnd, SpatialState, positions3, step3, steady3
from kanat.continuum.stepper import State, steady, step
from kanat.model.plane import out_of_plane
from kanat.statics import CableSolution
from kanat.statics.march import steady_guess
from kanat.statics.setup import cable_problems
from kanat.vessel.track import VesselTrack


STEADY_PASSES = 4
"""Steady solves at most, each with the current (and the seabed) at the previous solve's node positions."""


def needs_spatial_statics(case) -> bool:
    """True when the planar statics cannot give the cable's shape (module docstring)."""
    cable, env = case.cables[0], case.environment
    ends = [case.bodies[e.name] for e in cable.ends if e.kind == "body"]
    slope = env.seabed is not None and (env.seabed.slope_deg != 0 or env.seabed.friction > 0)
    return (len(cable.sections) > 1 or bool(cable.attachments) or bool(out_of_plane(case)) or slope
            or any(b.surface_buoy is not None for b in ends))


def _static_shape(case, name, s) -> CableSolution:
    """The statics solution of the case's cable at stations ``s`` (the initial guess).

    A cable with a free tail has no statics solution of its own (statics refuses free ends);
    its guess is :func:`free_tail_guess`, which the discrete steady solve then corrects.
    """
    if case.cables[0].to.kind == "free":
        return free_tail_guess(case, s)
    if needs_spatial_statics(case):
        from kanat.statics.setup3d import cable_problem3
        from kanat.statics.solve3d import solve_cable3

        return solve_cable3(cable_problem3(case), "auto", s)
    return steady_guess(cable_problems(case)[name], s)


def free_tail_guess(case, s) -> CableSolution:
    """A straight cable trailing from the tow point at the critical angle of the relative flow.

    ``cos(phi_c) = (-w + sqrt(w^2 + 4R^2)) / (2R)``, ``R = 0.5 rho d C_n U^2`` (SPEC §7.4); the
    tension grows from 0 at the tail with the tangential weight and drag. Vertical in still water.
    """
    env, cable = case.environment, case.cables[0]
    lt = case.line_types[cable.line_type]
    w = lt.weight_in_water_value(env.water_density, env.gravity)
    speed = case.vessel.initial_speed - env.current.at(0.0)[0]
    r = 0.5 * env.water_density * lt.diameter * lt.drag_normal * speed**2
    phi = np.arccos((-w + np.sqrt(w * w + 4 * r * r)) / (2 * r)) if r > 0 else 0.5 * np.pi
    along = np.array([-np.sign(speed) * np.cos(phi) if speed else 0.0, -np.sin(phi)])
    per_length = w * np.sin(phi) + 0.5 * env.water_density * np.pi * lt.diameter * lt.drag_tangential * (
        speed * np.cos(phi))**2
    tension = np.maximum(per_length * (cable.length - s), 1e-6 * w * cable.length)
    origin = np.array([case.vessel.tow_point[0], case.vessel.tow_point[2]])
    xz = origin + np.outer(s, along)
    return CableSolution(s, xz[:, 0], xz[:, 1], np.outer(tension, along), "free-tail guess")


def bending_guess(cable, y: np.ndarray) -> np.ndarray:
    """Shear 0 and moment ``EI dphi/ds`` (node averages of the intervals' curvature) appended to a
    flexible planar guess (n, 4) when the cable has bending stiffness."""
    if cable.nv == 4:
        return y
    rows = cable.rows()
    ds = np.where(rows[:, k.DS] > 0, rows[:, k.DS], 1.0)
    moment = np.where(rows[:, k.DS] > 0, rows[:, k.EI] * np.diff(y[:, 3]) / ds, 0.0)
    nodes = np.zeros(len(y))
    nodes[:-1] += 0.5 * moment
    nodes[1:] += 0.5 * moment
    return np.column_stack([y, np.zeros(len(y)), nodes])


def bending_guess3(cable, y: np.ndarray) -> np.ndarray:
    """Shear 0 and moment ``EI kappa`` (node averages of the intervals' ``M_n = EI cos(phi) theta_s``,
    ``M_b = EI phi_s``) appended to a flexible spatial guess (n, 6) when the cable has bending stiffness."""
    if cable.nv == 6:
        return y
    rows = cable.rows()
    ds = np.where(rows[:, k.DS] > 0, rows[:, k.DS], 1.0)
    ei = np.where(rows[:, k.DS] > 0, rows[:, k.EI], 0.0) / ds
    mean_cos = 0.5 * (np.cos(y[:-1, 4]) + np.cos(y[1:, 4]))
    moments = np.column_stack([ei * mean_cos * np.diff(y[:, 5]), ei * np.diff(y[:, 4])])
    nodes = np.zeros((len(y), 2))
    nodes[:-1] += 0.5 * moments
    nodes[1:] += 0.5 * moments
    return np.column_stack([y, np.zeros((len(y), 2)), nodes])


class PlanarModel:
    """Adapter of the planar model (:mod:`model2d`, :mod:`stepper`).

    Parameters
    ----------
    cable : PlanarCable
    drive : Drive
        Or any object with ``velocities(t)`` and ``origin(t)`` in the x–z plane (tests drive
        straight cables this way).
    case : kanat.model.Case, optional
        The case the cable comes from (its statics give the initial state).
    """

    dimensions = 2

    def __init__(self, cable, drive, case=None):
        self.case, self.cable, self.drive = case, cable, drive
        self.track = getattr(drive, "track", None)

    @classmethod
    def from_case(cls, case) -> PlanarModel:
        """The planar model of a case's single cable (refusing what leaves the x–z plane)."""
        cable = planar_cable(case)
        return cls(cable, Drive(cable, VesselTrack.from_model(case.vessel)), case)

    def initial(self) -> State:
        cable, drive = self.cable, self.drive
        static = _static_shape(self.case, cable.name, cable.s)
        v0, phi = drive.velocities(0.0)[0], np.unwrap(static.angle)     # continuous through +-pi
        guess = np.column_stack([static.tension, v0[0] * np.cos(phi) + v0[1] * np.sin(phi),
                                 -v0[0] * np.sin(phi) + v0[1] * np.cos(phi), phi])
        y = bending_guess(cable, guess)
        xz = np.column_stack([static.x, static.z])
        for _ in range(STEADY_PASSES):               # the current is taken at the steady state's own nodes
            y = steady(cable, y, drive.velocities(0.0), xz)
            moved, xz = xz, positions(cable, y, drive.origin(0.0))
            if np.max(np.abs(moved - xz)) <= 1e-10 * cable.length:
                break
        rows, s = (cable.rows().copy(), cable.s.copy()) if cable.winch is not None else (None, None)
        return State(0.0, y, np.zeros_like(y), xz, rows, s)

    def step(self, state, dt, coefficients):
        return step(self.cable, state, dt, coefficients, self.drive)

    def velocities(self, t):
        """End velocities ``(v0, v1)`` (3,) in the global frame [m/s]."""
        return tuple(np.array([v[0], 0.0, v[1]]) for v in self.drive.velocities(t))

    def origin(self, t):
        """Position (3,) of the first end [m]."""
        x, z = self.drive.origin(t)
        return np.array([x, 0.0, z])

    def tangents(self, state) -> np.ndarray:
        """Global unit tangents (N+1, 3)."""
        phi = state.y[:, 3]
        return np.column_stack([np.cos(phi), np.zeros_like(phi), np.sin(phi)])

    def world(self, state, dt):
        """``(World, y, None)`` of a step of ``dt`` from ``state`` (seed 000's schemes)."""
        cable, rho = self.cable, self.cable.params[k.RHO]
        v0, v1 = (np.asarray(v, dtype=float) for v in self.drive.velocities(state.t + dt))
        ends = [end_data(e, v, rho, np.asarray(e.force, dtype=float)) for e, v in ((cable.start, v0), (cable.end, v1))]
        return World(CableSystem(cable.params, 2), cable.current_at(state.xz[:, 1]), np.array([0.0, 1.0]),
                     ends[0], ends[1], cable.ds), state.y, None

    def advanced(self, state, start, y, chart, dt) -> State:
        """The state holding ``y`` at ``t + dt``, its rate ``(y - start) / dt``."""
        t1 = state.t + dt
        return State(t1, y, (y - start) / dt, positions(self.cable, y, self.drive.origin(t1)))

    def outputs(self, state) -> dict:
        y, xz = state.y, state.xz
        c, s, zeros = np.cos(y[:, 3]), np.sin(y[:, 3]), np.zeros(len(y))
        return {"position": np.column_stack([xz[:, 0], zeros, xz[:, 1]]),
                "velocity": np.column_stack([y[:, 1] * c - y[:, 2] * s, zeros, y[:, 1] * s + y[:, 2] * c]),
                "tension": y[:, 0]}

    def save(self, state) -> dict:
        saved = {"y": state.y, "rate": state.rate, "xz": state.xz}
        if state.rows is not None:
            saved.update(rows=state.rows, s=state.s)
        return saved

    def restore(self, t, saved) -> State:
        return State(t, saved["y"], saved["rate"], saved["xz"], saved.get("rows"), saved.get("s"))


class SpatialModel:
    """Adapter of the spatial model (:mod:`spatial`, :mod:`chart`)."""

    dimensions = 3

    def __init__(self, case):
        self.case = case
        self.cable = spatial_cable(case)
        self.track = VesselTrack.from_model(case.vessel)

    def velocities(self, t):
        v0 = self.track.state(t).velocity if self.cable.start.moving else np.zeros(3)
        return v0, np.zeros(3)

    def origin(self, t):
        if self.cable.start.moving:
            return self.track.state(t).position
        return np.asarray(self.cable.start.position, dtype=float)

    def initial(self) -> SpatialState:
        cable = self.cable
        static = _static_shape(self.case, cable.name, cable.s)
        tangents = static.force3 / static.tension[:, None]
        chart = choose_chart(tangents)
        phi, theta = angles(tangents, chart)
        guess = np.column_stack([static.tension, np.zeros((len(phi), 3)), phi, theta])
        t, n, b = frames(guess, chart)
        v0 = self.velocities(0.0)[0]
        guess[:, 1:4] = np.column_stack([t @ v0, n @ v0, b @ v0])
        y, xyz = bending_guess3(cable, guess), static.position
        for _ in range(STEADY_PASSES):               # the current is taken at the steady state's own nodes
            y = steady3(cable, y, chart, self.velocities(0.0), xyz)
            moved, xyz = xyz, positions3(cable, y, chart, self.origin(0.0))
            if np.max(np.abs(moved - xyz)) <= 1e-10 * cable.length:
                break
        rows, s = (cable.rows().copy(), cable.s.copy()) if cable.winch is not None else (None, None)
        return SpatialState(0.0, y, np.zeros_like(y), xyz, chart, rows, s)

    def step(self, state, dt, coefficients):
        return step3(self.cable, state, dt, coefficients, self)

    def tangents(self, state) -> np.ndarray:
        """Global unit tangents (N+1, 3)."""
        return frames(state.y, state.chart)[0]

    def world(self, state, dt):
        """``(World, y, chart)`` of a step of ``dt`` from ``state``, re-charted first when a tangent
        nears the pole (seed 000's schemes)."""
        cable, rho = self.cable, self.cable.params[k.RHO]
        y, chart = state.y, state.chart
        if needs_rechart(y):
            new = choose_chart(frames(y, chart)[0])
            y, _ = rechart(y, state.rate, chart, new)
            chart = new
        v0, v1 = (np.asarray(v, dtype=float) @ chart for v in self.velocities(state.t + dt))
        ends = [end_data(e, v, rho, np.asarray(e.force, dtype=float) @ chart) for e, v in
                ((cable.start, v0), (cable.end, v1))]
        return World(CableSystem(cable.params, 3), cable.current_at(state.xyz[:, 2]) @ chart, chart.T @ UP,
                     ends[0], ends[1], cable.ds), y, chart

    def advanced(self, state, start, y, chart, dt) -> SpatialState:
        """The state holding ``y`` (in ``chart``) at ``t + dt``, its rate ``(y - start) / dt``."""
        t1 = state.t + dt
        return SpatialState(t1, y, (y - start) / dt, positions3(self.cable, y, chart, self.origin(t1)), chart)

    def outputs(self, state) -> dict:
        t, n, b = frames(state.y, state.chart)
        u, v, w = state.y[:, 1:2], state.y[:, 2:3], state.y[:, 3:4]
        return {"position": state.xyz, "velocity": u * t + v * n + w * b, "tension": state.y[:, 0]}

    def save(self, state) -> dict:
        saved = {"y": state.y, "rate": state.rate, "xyz": state.xyz, "chart": state.chart}
        if state.rows is not None:
            saved.update(rows=state.rows, s=state.s)
        return saved

    def restore(self, t, saved) -> SpatialState:
        return SpatialState(t, saved["y"], saved["rate"], saved["xyz"], saved["chart"], saved.get("rows"),
                            saved.get("s"))


def spatial_cable(case) -> SpatialCable:
    """The spatial model of a case's single cable (same rules as :func:`model2d.planar_cable`)."""
    planar = planar_cable(case, check_plane=False)    # validates the ends and builds the parameters
    cable = case.cables[0]

    def end(e, key, first):
        made = planar_end(case, e, key, first)
        if e.kind == "vessel":
            return SpatialEnd(made.kind, moving=True, position=tuple(case.vessel.tow_point))
        if e.kind == "anchor":
            return SpatialEnd(made.kind, position=tuple(e.position))
        if e.kind == "body":
            body = case.bodies[e.name]
            return SpatialEnd(made.kind, made.mass, body.net_buoyancy, body.drag_area, tuple(body.force),
                              wave_mass=made.wave_mass, waterplane=made.waterplane, height=made.height)
        return SpatialEnd(made.kind)

    z, rows = case.environment.current.table()
    grid = planar.grid
    if grid is None:
        from kanat.continuum.grid import cable_grid

        grid = cable_grid(case, 0, planar.seabed)
    plain = grid.uniform and not grid.bending and planar.seabed is None and planar.winch is None
    return SpatialCable(cable.name, cable.length, cable.segments, planar.params,
                        end(cable.from_, "cables[0].from", True), end(cable.to, "cables[0].to", False), z, rows,
                        None if plain else grid, planar.sea, planar.seabed, planar.winch)


def model_for(case):
    """The planar or the spatial adapter, by ``simulation.dimensions`` (``auto``: planar if it fits)."""
    wanted = case.simulation.dimensions
    if wanted == 3 or (wanted == "auto" and out_of_plane(case)):
        return SpatialModel(case)
    return PlanarModel.from_case(case)
