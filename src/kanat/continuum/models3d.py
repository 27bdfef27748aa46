"""The spatial continuum model's adapter (:class:`SpatialModel`), with the interface of
:mod:`kanat.continuum.models` (whose module docstring lists it).

Apart from the planar adapter so that a planar run imports none of the spatial model's kernels
(:mod:`kanat.continuum.spatial` and its 3-D rows, loads and bending): :func:`models.model_for`
imports this module only for a spatial case.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.chart import angles, choose_chart, frames, needs_rechart, rechart
from kanat.continuum.model2d import _end as planar_end
from kanat.continuum.model2d import planar_cable
from kanat.continuum.outputs import line_force
from kanat.continuum.start import STEADY_PASSES, static_shape
from kanat.continuum.spatial import UP, SpatialCable, SpatialEnd, SpatialState, positions3, step3, steady3
from kanat.continuum.vessel_motion import vessel_track


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


class SpatialModel:
    """Adapter of the spatial model (:mod:`spatial`, :mod:`chart`)."""

    dimensions = 3

    def __init__(self, case):
        self.case = case
        self.cable = spatial_cable(case)
        self.track = vessel_track(case.vessel, case.environment)
        self._rows = self.cable.rows()              # a uniform cable builds its rows at every call

    def velocities(self, t):
        v0 = self.track.tow_state(t).velocity if self.cable.start.moving else np.zeros(3)
        return v0, np.zeros(3)

    def origin(self, t):
        if self.cable.start.moving:
            return self.track.tow_state(t).position
        return np.asarray(self.cable.start.position, dtype=float)

    def initial(self) -> SpatialState:
        cable = self.cable
        static = static_shape(self.case, cable.name, cable.s)
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
        return step3(self.cable, state, dt, coefficients, self, self._rows)

    def tangents(self, state) -> np.ndarray:
        """Global unit tangents (N+1, 3)."""
        return frames(state.y, state.chart)[0]

    def line_force(self, state) -> np.ndarray:
        """The cable's force ``T t + S_n n + S_b b`` at each node (N+1, 3) [N], global frame
        (:func:`kanat.continuum.outputs.line_force`; the shear of a line with bending stiffness,
        :mod:`kanat.continuum.bending3d`)."""
        y = state.y
        t, n, b = frames(y, state.chart)
        shear = y[:, 6:7] * n + y[:, 7:8] * b if y.shape[1] == 10 else None
        return line_force(y[:, 0], t, shear)

    def world(self, state, dt):
        """``(World, y, chart)`` of a step of ``dt`` from ``state``, re-charted first when a tangent
        nears the pole (Kaliukh & Vusatiuk's schemes)."""
        from kanat.continuum.factorized.system import CableSystem, World, end_data

        cable, rho = self.cable, self.cable.params[k.RHO]
        y, chart = state.y, state.chart
        if needs_rechart(y):
            new = choose_chart(frames(y, chart)[0])
            y, _ = rechart(y, state.rate, chart, new)
            chart = new
        v0, v1 = (np.asarray(v, dtype=float) @ chart for v in self.velocities(state.t + dt))
        ends = [end_data(e, v, rho, np.asarray(e.force, dtype=float) @ chart) for e, v in
                ((cable.start, v0), (cable.end, v1))]
        current = cable.current_at(state.xyz[:, 2], state.t + dt) @ chart
        return World(CableSystem(cable.params, 3), current, chart.T @ UP, ends[0], ends[1], cable.ds), y, chart

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
                        None if plain else grid, planar.sea, planar.seabed, planar.winch, planar.current_ramp,
                        water_surface=planar.water_surface)


