"""Collocation solver for the 3-D steady cable (:mod:`kanat.statics.spatial`): ``scipy.integrate.solve_bvp``.

Independent of shooting: each piece (a section, or the part of one between inline bodies) has its
own copy of the state ``(x, y, z, F_x, F_y, F_z)`` over ``sigma`` in [0, 1] (``s = start + sigma
length``), and the pieces are joined by boundary conditions -- continuity, or the jump of an
inline body -- so ``solve_bvp`` sees one smooth system of ``6 P`` equations and ``6 P`` boundary
conditions (3 at each end). A line resting on the seabed from an anchor is solved over its
suspended part, with the touchdown tension, the grounded length and the azimuth as unknown
parameters and the touchdown state as the first piece's start (the grounded length must stay
within the piece the guess put it in; the solver re-plans once if it moves out). Variables are
scaled (positions by ``L``, forces by the line's weight) and the flow is brought up from zero in
steps when the full problem fails from the still-water guess (the shooting solution's still-water
start).
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_bvp

from kanat.errors import SolverError
from kanat.statics.collocation import MAX_NODES, TOL, _continued
from kanat.statics.guess3d import grounding_guess, still_water_force
from kanat.statics.shooting3d import Path, _integrate, _solution, anchored_or_suspended
from kanat.statics.solution import CableSolution
from kanat.statics.spatial import CableBVP3, Fixed3, Piece, check_solvable, end_residual, grounded_states, jump, rhs

MESH = 41
NAME = "3-D collocation"


class _System:
    """Pieces stacked into one ``solve_bvp`` system (module docstring)."""

    def __init__(self, problem: CableBVP3, pieces, first_start=None):
        self.problem, self.pieces = problem, list(pieces)
        self.count = len(self.pieces)
        force = problem.reference_force()
        self.scale = np.tile([problem.length] * 3 + [force] * 3, self.count)
        self.first_start = first_start          # None: pieces[0].start is fixed

    def lengths(self, p):
        out = np.array([piece.length for piece in self.pieces])
        if self.first_start is not None and p is not None:
            out[0] = self.pieces[0].end - p[1] * self.problem.length
        return out

    def fun(self, flowed, sigma, y, p):
        lengths = self.lengths(p)
        states = y * self.scale[:, None]
        out = np.empty_like(states)
        for i, piece in enumerate(self.pieces):
            out[6 * i:6 * i + 6] = lengths[i] * rhs(piece, flowed.flow, states[6 * i:6 * i + 6])
        return out / self.scale[:, None]

    def joints(self, flowed, ya, yb):
        a, b = ya * self.scale, yb * self.scale
        rows = []
        for i in range(self.count - 1):
            across = jump(flowed, self.pieces[i].end, b[6 * i:6 * i + 6], True)
            rows.append((a[6 * (i + 1):6 * (i + 1) + 6] - across) / self.scale[:6])
        return rows


def _guess(problem: CableBVP3, system: _System, start_state, start_s: float):
    """Stacked states of the still-water shooting integration from ``start_state`` at ``start_s``."""
    path = Path()
    still = problem.with_flow(0.0)
    _integrate(still, start_s, start_state, problem.length if start_s < problem.length else 0.0, path)
    sigma = np.linspace(0.0, 1.0, MESH)
    y = np.empty((6 * system.count, MESH))
    for i, piece in enumerate(system.pieces):
        lo = max(piece.start, start_s) if i == 0 else piece.start
        s = lo + sigma * (piece.end - lo)
        for j, value in enumerate(s):
            y[6 * i:6 * i + 6, j] = path._at(still, value, j == 0 and i > 0)
    return sigma, y / system.scale[:, None]


def solve_collocation3(problem: CableBVP3, s_out=None) -> CableSolution:
    """Solve the 3-D steady cable by collocation (module docstring); same stations as shooting."""
    check_solvable(problem)
    s_out = np.linspace(0.0, problem.length, 101) if s_out is None else np.asarray(s_out, dtype=float)
    return anchored_or_suspended(problem, s_out, _grounded, _suspended)


def _oriented(problem: CableBVP3) -> CableBVP3:
    """The problem with its fixed end first (a body at ``s = 0`` is reversed onto ``s = L``)."""
    if isinstance(problem.start, Fixed3):
        return problem
    length = problem.length
    pieces = tuple(Piece(p.line, length - p.end, length - p.start) for p in reversed(problem.pieces))
    joints = tuple((length - s, load) for s, load in reversed(problem.joints))
    return CableBVP3(pieces, joints, problem.end, problem.start, problem.flow, problem.seabed)


def _suspended(problem: CableBVP3, s_out):
    """The line off the seabed, collocated from its fixed end; its profile ``() -> (x, z)`` [m]."""
    reverse = not isinstance(problem.start, Fixed3)
    work = _oriented(problem)
    system = _System(work, work.pieces)
    origin = np.asarray(work.start.position, dtype=float)
    far_scale = work.length if isinstance(work.end, Fixed3) else work.reference_force()

    def solve_at(factor, guess):
        flowed = work.with_flow(factor)
        mesh, y0 = guess[0], guess[1]

        def bc(ya, yb):
            a, b = ya * system.scale, yb * system.scale
            rows = [(a[0:3] - origin) / work.length, *system.joints(flowed, ya, yb),
                    end_residual(flowed, 1, b[-6:]) / far_scale]
            return np.concatenate(rows)
        return solve_bvp(lambda s, y: system.fun(flowed, s, y, None), bc, mesh, y0, tol=TOL, max_nodes=MAX_NODES)

    sigma, y0 = _guess(work, system, np.concatenate([origin, still_water_force(work, 0)]), 0.0)
    result = _continued(solve_at, (sigma, y0, None), "suspended line", NAME)
    y = _sample(work, system, result, np.linspace(0.0, work.length, 2001))
    fine_x, fine_z = y[0], y[2]
    stations = work.length - s_out[::-1] if reverse else s_out
    out = _sample(work, system, result, stations)
    if reverse:
        out = out[:, ::-1]
        out[3:6] *= -1.0                    # F = T t with t reversed
    return _solution(s_out, out, "collocation", 0.0, int(result.niter)), lambda: (fine_x, fine_z)


def _sample(problem, system: _System, result, s_out, start_s: float = 0.0):
    out = np.empty((6, len(s_out)))
    lengths = system.lengths(result.p)
    for n, s in enumerate(s_out):
        second = n > 0 and s_out[n - 1] == s
        for i, piece in enumerate(system.pieces):
            lo = piece.end - lengths[i]
            last = i == system.count - 1
            if s < piece.end or (s == piece.end and (last or not second)) or last:
                sigma = min(max((s - lo) / lengths[i], 0.0), 1.0)
                out[:, n] = result.sol(sigma)[6 * i:6 * i + 6] * system.scale[6 * i:6 * i + 6]
                break
    return out


def _grounded(problem: CableBVP3, s_out, anchor: int) -> CableSolution:
    work = problem if anchor == 0 else _oriented_anchor_last(problem)
    tension, grounded, psi = grounding_guess(work, 0)
    for _ in range(2):
        first = next(i for i, p in enumerate(work.pieces) if p.end > grounded)
        system = _System(work, work.pieces[first:], first_start=True)
        result = _grounded_solve(work, system, tension, grounded, psi)
        tension, grounded_new, psi = result.p[0] * work.reference_force(), result.p[1] * work.length, result.p[2]
        if work.pieces[first].start <= grounded_new < work.pieces[first].end:
            grounded = grounded_new
            break
        grounded = min(max(grounded_new, 0.0), 0.999 * work.length)
    else:
        raise SolverError("3-D collocation: the touchdown point moved across a section joint twice; use shooting")
    stations = s_out if anchor == 0 else work.length - s_out[::-1]
    out = np.empty((6, len(stations)))
    on_ground = stations <= grounded
    if np.any(on_ground):
        out[:, on_ground] = grounded_states(work, 0, tension, grounded, psi, stations[on_ground])[0]
    if np.any(~on_ground):
        out[:, ~on_ground] = _sample(work, system, result, stations[~on_ground])
    if anchor == 1:
        out = out[:, ::-1]
        out[3:6] *= -1.0
    return _solution(s_out, out, "collocation", float(grounded), int(result.niter))


def _oriented_anchor_last(problem: CableBVP3) -> CableBVP3:
    length = problem.length
    pieces = tuple(Piece(p.line, length - p.end, length - p.start) for p in reversed(problem.pieces))
    joints = tuple((length - s, load) for s, load in reversed(problem.joints))
    return CableBVP3(pieces, joints, problem.end, problem.start, problem.flow, problem.seabed)


def _grounded_solve(work: CableBVP3, system: _System, tension, grounded, psi):
    reference, length = work.reference_force(), work.length
    far_scale = length if isinstance(work.end, Fixed3) else reference

    def solve_at(factor, guess):
        flowed = work.with_flow(factor)
        mesh, y0, p0 = guess

        def bc(ya, yb, p):
            a, b = ya * system.scale, yb * system.scale
            _, touchdown = grounded_states(flowed, 0, p[0] * reference, p[1] * length, p[2], [0.0])
            rows = [(a[0:6] - touchdown) / system.scale[:6], *system.joints(flowed, ya, yb),
                    end_residual(flowed, 1, b[-6:]) / far_scale]
            return np.concatenate(rows)
        return solve_bvp(lambda s, y, p: system.fun(flowed, s, y, p), bc, mesh, y0, p=p0, tol=TOL,
                         max_nodes=MAX_NODES)

    _, touchdown = grounded_states(work.with_flow(0.0), 0, tension, grounded, psi, [0.0])
    sigma, y0 = _guess(work, system, touchdown, grounded)
    p0 = np.array([tension / reference, grounded / length, psi])
    return _continued(solve_at, (sigma, y0, p0), "line on the seabed", NAME)
