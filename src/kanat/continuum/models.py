"""The planar and spatial continuum models behind one interface, for the run loop and the schemes.

Both adapters have the same methods, so nothing above them asks which one it holds:

* ``initial()``, ``step(state, dt, coefficients)`` (the generalized-α family), ``outputs(state)``,
  ``save(state)`` / ``restore(t, saved)``;
* ``velocities(t)`` (both ends, global frame) and ``origin(t)`` (the first end's position);
* ``tangents(state)`` (global unit tangents) and ``tension(state)``;
* ``line_force(state)``: the cable's force ``T t + S`` at each node, global frame
  (:func:`kanat.continuum.outputs.line_force`);
* ``world(state, dt)`` and ``advanced(state, start, y, chart, dt)`` for Kaliukh & Vusatiuk's schemes
  (:mod:`kanat.continuum.factorized.system`).

``dimensions: auto`` picks the planar model when the case stays in the x–z plane
(:func:`kanat.model.plane.out_of_plane` finds nothing) and the spatial one otherwise.

The initial state is the discrete steady state of the box equations, found by Newton from the
statics of the case's cable (:mod:`kanat.continuum.start`).

The spatial adapter lives in :mod:`kanat.continuum.models3d`, imported only for a spatial case
(a planar run then loads none of the 3-D kernels); ``models.SpatialModel`` still names it.
"""
from __future__ import annotations

import numpy as np

from kanat.continuum import kernels2d as k
from kanat.continuum.drive import Drive
from kanat.continuum.model2d import planar_cable, positions
from kanat.continuum.outputs import line_force
from kanat.continuum.start import STEADY_PASSES, static_shape
from kanat.continuum.stepper import State, steady, step
from kanat.continuum.vessel_motion import vessel_track
from kanat.model.plane import out_of_plane


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
        self.own_rows = cable.rows()                 # built once (a uniform cable builds it per call)

    @classmethod
    def from_case(cls, case) -> PlanarModel:
        """The planar model of a case's single cable (refusing what leaves the x–z plane)."""
        cable = planar_cable(case)
        return cls(cable, Drive(cable, vessel_track(case.vessel, case.environment)), case)

    def initial(self) -> State:
        cable, drive = self.cable, self.drive
        static = static_shape(self.case, cable.name, cable.s)
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
        return step(self.cable, state, dt, coefficients, self.drive, self.own_rows)

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

    def line_force(self, state) -> np.ndarray:
        """The cable's force ``T t + S n`` at each node (N+1, 3) [N], global frame
        (:func:`kanat.continuum.outputs.line_force`; ``n = (-sin phi, cos phi)``, the shear ``S``
        of a line with bending stiffness)."""
        y = state.y
        phi = y[:, 3]
        shear = None
        if y.shape[1] == 6:
            normal = np.column_stack([-np.sin(phi), np.zeros_like(phi), np.cos(phi)])
            shear = y[:, 4:5] * normal
        return line_force(y[:, 0], self.tangents(state), shear)

    def world(self, state, dt):
        """``(World, y, None)`` of a step of ``dt`` from ``state`` (Kaliukh & Vusatiuk's schemes)."""
        from kanat.continuum.factorized.system import CableSystem, World, end_data

        cable, rho = self.cable, self.cable.params[k.RHO]
        v0, v1 = (np.asarray(v, dtype=float) for v in self.drive.velocities(state.t + dt))
        ends = [end_data(e, v, rho, np.asarray(e.force, dtype=float)) for e, v in ((cable.start, v0), (cable.end, v1))]
        return World(CableSystem(cable.params, 2), cable.current_at(state.xz[:, 1], state.t + dt), np.array([0.0, 1.0]),
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


def model_for(case):
    """The planar or the spatial adapter, by ``simulation.dimensions`` (``auto``: planar if it fits)."""
    wanted = case.simulation.dimensions
    if wanted == 3 or (wanted == "auto" and out_of_plane(case)):
        from kanat.continuum.models3d import SpatialModel

        return SpatialModel(case)
    return PlanarModel.from_case(case)


def __getattr__(name):
    """``SpatialModel``, ``spatial_cable`` and ``bending_guess3`` from :mod:`kanat.continuum.models3d`
    (imported on first use: module docstring)."""
    if name in ("SpatialModel", "spatial_cable", "bending_guess3"):
        from kanat.continuum import models3d

        return getattr(models3d, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
