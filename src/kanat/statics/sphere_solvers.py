"""Solvers of Naumov & Agievich's sphere on two cables (theory/statics.md §3): shooting and collocation.

The problem, its equations and the solution type are in :mod:`kanat.statics.sphere`.
Shooting integrates eqs. (10)-(11) from the sphere A with ``solve_ivp`` and finds
``(alpha(0), tau(0))`` by root finding on the residuals (18)-(19); collocation solves
the same equations with ``solve_bvp`` and the four end conditions at once. A failed
first guess falls back to the paper's case-1 answer, a straight-chord guess and
continuation from case 1 (:func:`solve_sphere`).
"""
from __future__ import annotations

from dataclasses import fields, replace

import numpy as np
from scipy.integrate import solve_bvp, solve_ivp
from scipy.optimize import root

from kanat.errors import CaseError, SolverError
from kanat.statics.sphere import (PAPER_CASE_1, TAU_MIN, SphereGroups, SphereSolution, cable_rhs,
                                  convention_sign, groups_from_dimensional, sphere_residuals)

#: Converged when both residuals are below this [%]; set by the integration tolerance.
RESIDUAL_TOL_PERCENT = 1e-7
#: Relative / absolute tolerance of the shooting integration (DOP853).
SHOOT_RTOL, SHOOT_ATOL = 1e-11, 1e-13
#: Collocation tolerance of solve_bvp; 1e-9 keeps it within ~1e-10 of shooting.
BVP_TOL, BVP_MAX_NODES = 1e-9, 20_000
#: Continuation in lambda from the paper's case 1: first step, smallest step.
CONTINUATION_STEP, CONTINUATION_MIN_STEP = 0.25, 1.0 / 512
#: (alpha0 [rad], tau0) solving PAPER_CASE_1 in each convention: the continuation start.
REFERENCE_ANSWER = {"published": (0.818367, 0.606623), "physical": (0.496522, 0.372559)}


class _NotConverged(Exception):
    """One attempt failed; the message says why. Caught by the fallback driver."""


def _shoot(groups, alpha0, tau0, sigma_eval=None, rtol=SHOOT_RTOL):
    """Integrate eqs. (10)-(11) from A with ``x = y = 0`` at A.

    Returns the ``solve_ivp`` result; raises :class:`_NotConverged` if the tension
    falls to ``TAU_MIN`` (the cable would go slack) or the integration fails.
    """
    if not tau0 > TAU_MIN:
        raise _NotConverged(f"tau0 = {tau0:.4g} is not positive")

    def slack(sigma, z, g):
        return z[1] - TAU_MIN

    slack.terminal, slack.direction = True, -1
    sol = solve_ivp(cable_rhs, (0.0, 1.0), [alpha0, tau0, 0.0, 0.0], method="DOP853",
                    t_eval=sigma_eval, rtol=rtol, atol=SHOOT_ATOL * rtol / SHOOT_RTOL,
                    events=slack, args=(groups,))
    if sol.status == 1:
        raise _NotConverged(f"cable goes slack (tau -> 0) at sigma = {sol.t_events[0][0]:.3f}")
    if sol.status != 0:
        raise _NotConverged(f"integration failed: {sol.message}")
    return sol


def _profile_from_shot(groups, convention, alpha0, tau0, n_nodes, method, info=""):
    """A :class:`SphereSolution` from one shot, shifted so that B is the origin."""
    sigma = np.linspace(0.0, 1.0, n_nodes)
    sol = _shoot(groups, alpha0, tau0, sigma)
    alpha, tau, x, y = sol.y
    x, y = x - x[-1], y - y[-1]
    eps1, eps2 = sphere_residuals(groups, convention, alpha0, tau0, x[0], y[0])
    return SphereSolution(groups, convention, method, float(alpha0), float(tau0), eps1, eps2,
                          sigma, alpha, tau, x, y, info=info)


def shoot_sphere(groups, alpha0, tau0, convention="published", n_nodes=101):
    """One shot from A with given ``(alpha0 [rad], tau0)``: shape and residuals.

    This is the paper's own procedure (its figs. 2, 3) without the root finding;
    the returned solution has ``method="single shot"`` and whatever residuals result.
    """
    try:
        return _profile_from_shot(groups, convention, alpha0, tau0, n_nodes, "single shot")
    except _NotConverged as exc:
        raise SolverError(f"shot from alpha0 = {np.degrees(alpha0):.3f} deg, tau0 = {tau0}: "
                          f"{exc}; increase tau0") from None


def _shooting_residual(p, groups, convention):
    """``(eps1, eps2) / 100`` after a shot from ``p = (alpha0, tau0)``."""
    sol = _shoot(groups, p[0], p[1])
    x_A, y_A = -sol.y[2, -1], -sol.y[3, -1]
    return np.array(sphere_residuals(groups, convention, p[0], p[1], x_A, y_A)) / 100.0


def _solve_shooting(groups, convention, guess, n_nodes):
    """Shooting: root of the residuals in ``(alpha0, tau0)`` by MINPACK's hybrd."""
    _shooting_residual(np.asarray(guess, float), groups, convention)  # guess must shoot

    def fun(p):
        try:
            return _shooting_residual(p, groups, convention)
        except _NotConverged:
            return np.full(2, 1e3)  # a failed shot reads as a bad step: hybrd shrinks it

    sol = root(fun, np.asarray(guess, float), method="hybr", options={"xtol": 1e-13})
    profile = _profile_from_shot(groups, convention, *sol.x, n_nodes, "shooting")
    worst = max(abs(profile.eps1_percent), abs(profile.eps2_percent))
    if not worst < RESIDUAL_TOL_PERCENT:
        message = " ".join(sol.message.split())
        raise _NotConverged(f"root finding stopped with |eps| = {worst:.2e} % ({message})")
    return replace(profile, info=f"{sol.nfev} shots")


def _bvp_guess(groups, guess, sigma):
    """Initial profile for solve_bvp: a loose shot from the guess, else a straight chord."""
    try:
        z = _shoot(groups, guess[0], guess[1], sigma, rtol=1e-6).y.copy()
        if z.shape[1] != sigma.size:
            raise _NotConverged("short shot")
    except _NotConverged:
        z = np.empty((4, sigma.size))
        z[0], z[1] = guess[0], guess[1]
        z[2], z[3] = np.cos(guess[0]) * sigma, -np.sin(guess[0]) * sigma
    z[2] -= z[2, -1]
    z[3] -= z[3, -1]
    return z


def _solve_collocation(groups, convention, guess, n_nodes):
    """Collocation: solve_bvp on eqs. (10)-(11) with ``x(1) = y(1) = eps1 = eps2 = 0``."""
    def bc(za, zb):
        eps = sphere_residuals(groups, convention, za[0], za[1], za[2], za[3])
        return np.array([zb[2], zb[3], eps[0] / 100.0, eps[1] / 100.0])

    mesh = np.linspace(0.0, 1.0, 41)
    sol = solve_bvp(lambda s, z: cable_rhs(s, z, groups), bc, mesh, _bvp_guess(groups, guess, mesh),
                    tol=BVP_TOL, bc_tol=BVP_TOL, max_nodes=BVP_MAX_NODES)
    if sol.status != 0:
        raise _NotConverged(f"solve_bvp: {sol.message}")
    if sol.y[1].min() <= 10 * TAU_MIN:
        raise _NotConverged(f"slack cable (min tau = {sol.y[1].min():.2e})")
    sigma = np.linspace(0.0, 1.0, n_nodes)
    alpha, tau, x, y = sol.sol(sigma)
    alpha[0], tau[0], x[0], y[0] = sol.y[:, 0]  # the nodal values at A, exactly
    eps1, eps2 = sphere_residuals(groups, convention, alpha[0], tau[0], x[0], y[0])
    return SphereSolution(groups, convention, "collocation", float(alpha[0]), float(tau[0]),
                          eps1, eps2, sigma, alpha, tau, x, y,
                          info=f"{sol.x.size} mesh nodes, {sol.niter} iterations")


#: Solvers by name: ``fn(groups, convention, guess, n_nodes) -> SphereSolution``.
METHODS = {"shooting": _solve_shooting, "collocation": _solve_collocation}


def chord_guess(groups, convention="published"):
    """Cheap ``(alpha0 [rad], tau0)``: a straight cable of chord 1 from A to B.

    A is where the circles ``|A - B| = 1`` and ``|A - C| = LoL`` meet above the
    bottom; ``tau0`` balances the sphere with a straight cable and a taut line
    (falls back to the sphere's load ``sqrt(QkL^2 + RkL^2)`` if that gives tau0 <= 0).
    """
    x_a = (1.0 - groups.LoL**2 + groups.x_C**2) / (2.0 * groups.x_C)
    y_a = np.sqrt(max(1.0 - x_a**2, 1e-6))
    alpha0 = float(np.arctan2(y_a, -x_a))
    t = np.array([np.cos(alpha0), -np.sin(alpha0)])
    u = np.array([groups.x_C - x_a, -y_a]) / np.hypot(groups.x_C - x_a, y_a)
    load = np.array([convention_sign(convention) * groups.RkL, groups.QkL])
    try:
        tau0 = float(np.linalg.solve(np.column_stack([t, u]), -load)[0])
    except np.linalg.LinAlgError:
        tau0 = 0.0
    return alpha0, (tau0 if tau0 > 0 else float(np.hypot(groups.QkL, groups.RkL)))


def _blend(start, end, lam):
    """Groups ``(1 - lam) start + lam end``, field by field."""
    return SphereGroups(**{f.name: (1 - lam) * getattr(start, f.name) + lam * getattr(end, f.name)
                           for f in fields(SphereGroups)})


def _continuation(groups, convention, solve, n_nodes):
    """Step from the paper's case 1 (known answer) to ``groups`` in lambda in [0, 1].

    The step grows by 1.5 after a success and halves after a failure; each step starts
    from the previous converged ``(alpha0, tau0)``.
    """
    current = solve(PAPER_CASE_1, convention, REFERENCE_ANSWER[convention], n_nodes)
    lam, step, n_steps = 0.0, CONTINUATION_STEP, 0
    while lam < 1.0:
        trial = min(1.0, lam + step)
        try:
            current = solve(_blend(PAPER_CASE_1, groups, trial), convention,
                            (current.alpha0, current.tau0), n_nodes)
        except (_NotConverged, CaseError) as exc:
            step /= 2
            if step < CONTINUATION_MIN_STEP:
                raise _NotConverged(f"continuation from the paper's case 1 stalled at "
                                    f"lambda = {lam:.4f} ({exc})") from None
            continue
        lam, step, n_steps = trial, min(1.5 * step, 0.5), n_steps + 1
    return replace(current, info=f"continuation from the paper's case 1 in {n_steps} steps; "
                                 + current.info)


def _quiet(solve):
    """``solve`` with floating-point warnings off: failed iterates may overflow, and
    every result is checked by its residuals instead."""
    def wrapped(*args):
        with np.errstate(all="ignore"):
            return solve(*args)
    return wrapped


def _candidate_guesses(groups, convention, initial_guess):
    """Named ``(alpha0, tau0)`` guesses to try in turn before continuation."""
    out = [] if initial_guess is None else [("the given initial guess", tuple(initial_guess))]
    out.append(("the paper's case-1 answer", REFERENCE_ANSWER[convention]))
    out.append(("the straight-chord guess", chord_guess(groups, convention)))
    return out


def solve_sphere(groups, convention="published", method="shooting", n_nodes=101,
                 initial_guess=None, scales=None) -> SphereSolution:
    """Equilibrium of the sphere on two cables (theory/statics.md §3, paper eqs. 10-19).

    Parameters
    ----------
    groups : SphereGroups
        Dimensionless groups (eq. 16).
    convention : {"published", "physical"}
        Direction of the sphere's drag, see the module docstring.
    method : {"shooting", "collocation"}
        Solver, see :data:`METHODS`.
    n_nodes : int
        Number of output stations along ``sigma``, uniform on [0, 1].
    initial_guess : tuple of float, optional
        ``(alpha0 [rad], tau0)``. Tried first; then the paper's case-1 answer, the
        straight-chord guess (:func:`chord_guess`), and continuation from case 1.
    scales : SphereScales, optional
        Attached to the solution for the SI properties ``s, X, Y, T, T_line``.

    Returns
    -------
    SphereSolution
        Residuals below ``RESIDUAL_TOL_PERCENT`` (1e-7 %).

    Raises
    ------
    SolverError
        When every guess and the continuation fail; the message lists each attempt.
    """
    convention_sign(convention)
    if n_nodes < 2:
        raise ValueError(f"n_nodes must be >= 2, got {n_nodes}")
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; valid: {sorted(METHODS)}")
    solve, tried = _quiet(METHODS[method]), []
    for label, guess in _candidate_guesses(groups, convention, initial_guess):
        try:
            sol = solve(groups, convention, guess, n_nodes)
            return replace(sol, scales=scales, info=f"from {label}; {sol.info}")
        except _NotConverged as exc:
            tried.append(f"{label} (alpha0 = {np.degrees(guess[0]):.2f} deg, "
                         f"tau0 = {guess[1]:.4g}): {exc}")
    try:
        return replace(_continuation(groups, convention, solve, n_nodes), scales=scales)
    except _NotConverged as exc:
        tried.append(str(exc))
    raise SolverError(
        f"{method} found no equilibrium for {groups} ({convention} convention). Tried:\n  "
        + "\n  ".join(tried) + "\nPass initial_guess=(alpha0_rad, tau0) from a converged "
        "neighbour (e.g. sweep_flow_speed from a speed that converges) or try the other "
        f"method. Check that the sphere can hold the cable up: buoyancy QkL = {groups.QkL:.4g} "
        f"against cable weight Psi = {groups.Psi:.4g} (this model has no seabed contact).")


def sweep_flow_speed(speeds, *, sphere_diameter, net_buoyancy, cable_diameter, cable_length,
                     cable_weight, line_length, anchor_x, water_density=1025.0, c_90=1.2,
                     c_0=0.04, c_u=0.44, convention="published", method="shooting",
                     n_nodes=101) -> list[SphereSolution]:
    """Equilibria over flow speeds, each solved from the previous one's answer.

    Parameters
    ----------
    speeds : array_like, shape (m,)
        Flow speeds ``V`` [m/s] in the order to visit them (sorted is best).
    sphere_diameter, ..., c_u
        As in :func:`groups_from_dimensional`.
    convention, method, n_nodes
        As in :func:`solve_sphere`.

    Returns
    -------
    list of SphereSolution, length m
        With scales, so ``T``, ``X``, ``Y`` are in SI.
    """
    out, guess = [], None
    for speed in np.asarray(speeds, float):
        groups, scales = groups_from_dimensional(
            speed, sphere_diameter, net_buoyancy, cable_diameter, cable_length, cable_weight,
            line_length, anchor_x, water_density=water_density, c_90=c_90, c_0=c_0, c_u=c_u)
        sol = solve_sphere(groups, convention, method, n_nodes, initial_guess=guess,
                           scales=scales)
        out.append(sol)
        guess = (sol.alpha0, sol.tau0)
    return out
