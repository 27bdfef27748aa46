"""A first guess for the lumped equilibrium of a cable with a free tail: each element trailing at
the critical angle of the relative flow, floating where it reaches the surface.

A free tail carries no tension at its end, so near it the line lies where its normal drag carries
its weight; in a uniform flow a whole inextensible tail does (theory/continuum.md eq. (C15),
:func:`kanat.physics.drag.critical_angle`)::

    (1)  R sin^2(phi) = |w| cos(phi),   R = 0.5 rho d C_n |u|^2,   u = U_current(z) - U_frame

and the tension grows from the tail with the tangential weight and drag along a straight line.
The guess marches from the attached end, element by element, each along the horizontal relative
flow ``u`` at its upper node's depth, inclined by its own line type's ``phi`` below it (above it
for a buoyant line): the exact steady shape of an inextensible line of one line type in a uniform
flow, a close one otherwise (sections, a sheared current, stretch), which Newton's method corrects
in a few iterations. In still water (``phi = pi/2``) a heavy tail hangs straight down and a buoyant
one stands straight up, its tension the weight in water of the part beyond (closed form); a tail
clamped at its attached end keeps the network's guess along the clamp (a cantilever is no plumb line).

A buoyant tail that reaches the surface floats there (the lumped model's elements are partly dry
near the surface, :mod:`kanat.lumped.kernels` eq. (7)): a horizontal element of diameter ``d`` at
centreline height ``z`` is wet over the fraction ``phi_w = 1/2 - z/d`` of its height, and floats where
the buoyancy it keeps carries its weight, ``w + (1 - phi_w) B = 0`` (``B = m g - w`` the weight of the
water it displaces per unit length)::

    (2)  z_float = -d (1/2 + w / B)          (w < 0)

The guess lays such a tail from where it would cross ``z_float`` along the surface flow at
``z_float``: the floating part's exact shape, which carries only its tangential drag. On still
water a floating tail carries no tension, and the lumped model has no unique equilibrium for it:
its place on the surface is free, and so is its shape, since an element's wetted fraction depends
only on its highest and lowest points (a sawtooth of nodes alternately at the surface and 1 m down,
every element wet over the same fraction, balances as well as the flat line: the iteration ends in
one, residual 3e-9 N, for examples/towed_array.yaml with the array buoyant, 2 N/m, from 30 m down).
The guess refuses that case with the plumb top's height above the surface.

A heavy tail that reaches the seabed lies on it from there (:func:`_laid`): an element that would cross
the seabed ends on it, and the elements beyond run along it, along the horizontal relative flow at the
seabed downstream, or, in still water, along -x: astern of the vessel's heading at the start (every
track starts at heading 0), the way a cable paid out under way lies. In still water the laid part
carries no tension and its direction is not determined by the physics (any horizontal direction
balances as well); -x is kanat's documented choice, made deterministic here. Left plumb, such a tail
starts with nodes far below the seabed: 150 m of chain hung from the surface in 100 m of water had
its last 50 m heaped at the touchdown point after Newton's method (every slack element there is an
equilibrium of the lumped model), and the run that followed broke off on the heap's zero-length
elements.

Without it the network's own guess leaves such a tail at 45 degrees below the tow point
(:func:`kanat.lumped.network._guess_positions`): for ``examples/towed_array.yaml`` (300 m at 8 kn,
a critical angle of 2.8 degrees) the tail's 190 m to go at 0.25 element per iteration takes the
iteration through states stretched to 10 % (residual 2e5 N against a 5 kN tow) and it fails in
400 iterations; from eq. (1) the taut phase converges in 6. A still buoyant tail 400 m down, left at
45 degrees below the tow point, failed in 400 iterations (88 N left at 30 elements); plumb, it converges in 1.
"""
from __future__ import annotations

import numpy as np

from kanat.errors import SolverError
from kanat.lumped.network import GUESS_STRETCH
from kanat.physics.drag import trailing_direction
from kanat.physics.seabed import seabed_of

STILL_LAY = np.array([-1.0, 0.0])
"""Horizontal direction along which a heavy tail's part on the seabed lies in still water: -x, astern of
the vessel's starting heading (module docstring)."""


def free_tails(case) -> list[tuple[str, bool]]:
    """The cables with a free end: ``(name, reversed)``, reversed when the free end is ``from``."""
    tails = []
    for cable in case.cables:
        if cable.to.kind == "free" and cable.from_.kind != "free":
            tails.append((cable.name, False))
        elif cable.from_.kind == "free" and cable.to.kind != "free":
            tails.append((cable.name, True))
    return tails


def free_tail_guess(net, case, x, velocity) -> np.ndarray | None:
    """``x`` (n, 3) with every free tail's nodes placed by eq. (1), floating at eq. (2) where a buoyant
    tail reaches the surface in a flow there, laid on the seabed where a heavy one reaches it (:func:`_laid`),
    or None when the case has no free tail to place (none, or only
    tails clamped at their attached end in still water). Still water is the case's current definition
    without a horizontal velocity in any row of its table (:meth:`kanat.model.environment.Current.table`)
    and no way on, wherever the nodes are. Elements are stretched by the network guess's
    ``GUESS_STRETCH``, so that the equilibrium's tangent is regular from the start.

    Parameters
    ----------
    net : kanat.lumped.network.Network
    case : kanat.model.Case
    x : ndarray, shape (n, 3)
        The guess of every other node; the attached ends' places are taken from it [m].
    velocity : ndarray, shape (3,)
        The steady frame's velocity ``U_frame`` [m/s].

    Raises
    ------
    SolverError
        A buoyant tail that would float on still water: in still water, or where the current leaves the
        surface still (module docstring).
    """
    _, currents = case.environment.current.table()
    still = not np.any(np.asarray(velocity, dtype=float)[:2]) and not np.any(currents[:, :2])
    cables = {cable.name: cable for cable in case.cables}
    tails = [(name, reversed_) for name, reversed_ in free_tails(case)
             if not (still and (cables[name].end_b if reversed_ else cables[name].end_a).clamped)]
    if not tails:
        return None
    x = np.array(x, dtype=float)
    seabed = seabed_of(case.environment)
    for name, reversed_ in tails:
        nodes, elements = _tail(net, name, reversed_)
        for node, after, element in zip(nodes[:-1], nodes[1:], elements):
            x[after], stranded = _next_node(net, case, element, x[node], velocity)
            if stranded:
                raise SolverError(_still_float_message(net, name, x[nodes[0]], elements, still))
            if seabed is not None and seabed.penetration(x[after]) > 0.0:
                x[after] = _laid(case, seabed, x[node], x[after], velocity)
    return x


def floating_height(net, element) -> float:
    """Centreline height [m] at which a horizontal buoyant element floats on the mean surface, eq. (2)."""
    return -float(net.el_diameter[element]) * (0.5 + float(net.el_weight[element] / net.el_buoyancy[element]))


def _tail(net, name, reversed_) -> tuple[np.ndarray, np.ndarray]:
    """A tail's nodes and elements, from its attached end to its free one."""
    nodes = net.node_index[net.node_cable == name]
    first = net.cable_first_element[net.cable_names.index(name)]
    elements = np.arange(first, first + len(nodes) - 1)
    return (nodes[::-1], elements[::-1]) if reversed_ else (nodes, elements)


def _flow(case, position, velocity) -> np.ndarray:
    """Horizontal relative flow (2,) at ``position``'s depth [m/s]."""
    return (np.asarray(case.environment.current.at(float(position[2])), dtype=float) - np.asarray(velocity))[:2]


def _next_node(net, case, element, position, velocity) -> tuple[np.ndarray, bool]:
    """The lower node (3,) of an element whose upper node is at ``position``: along eq. (1), or up to and
    along the surface at eq. (2) for a buoyant element that would rise above it; and True where the
    water at the surface is still, so that the element would float with nothing to lay it out."""
    length = GUESS_STRETCH * float(net.el_length[element])
    weight = float(net.el_weight[element])
    after = position + length * trailing_direction(weight, net.el_cn[element], _flow(case, position, velocity))
    height = floating_height(net, element) if weight < 0.0 else np.inf
    if after[2] <= height:
        return after, False
    rise = max(height - float(position[2]), 0.0)
    surface = _flow(case, np.array([0.0, 0.0, height]), velocity)
    speed = float(np.hypot(surface[0], surface[1]))
    if speed == 0.0:
        return after, True
    reach = np.sqrt(max(length**2 - rise**2, 0.0))
    return position + np.array([reach * surface[0] / speed, reach * surface[1] / speed, rise]), False


def _laid(case, seabed, position, below, velocity) -> np.ndarray:
    """The lower node (3,) of an element from ``position`` whose end ``below`` lies under the seabed: the
    element runs straight to the seabed (or starts on it) and the rest of its length along it, in the
    horizontal relative flow's direction at the seabed or :data:`STILL_LAY` in still water."""
    length = float(np.linalg.norm(below - position))
    over = max(-float(seabed.penetration(position)), 0.0)            # the upper node's height above the bed
    depth = float(seabed.penetration(below))
    reached = position + (below - position) * over / (over + depth)
    flow = _flow(case, reached, velocity)
    speed = float(np.hypot(flow[0], flow[1]))
    lay = flow / speed if speed > 0.0 else STILL_LAY
    along = np.array([lay[0], lay[1], lay[0] * seabed.gradient])      # the seabed plane's tangent over ``lay``
    rest = length - float(np.linalg.norm(reached - position))
    return reached + rest * along / np.linalg.norm(along)


def _still_float_message(net, name, origin, elements, still) -> str:
    """Why a buoyant tail afloat on still water has no equilibrium to find, and what to change: in still
    water, the height its plumb top would stand above the surface (unstretched, heavy parts straight down)."""
    reason = ("floating there it carries no tension, and its place and shape on the surface are not "
              "determined (the lumped model has no unique equilibrium for it)")
    if not still:
        return (f"cable '{name}' is a buoyant free tail that reaches the surface where the water is still: "
                f"{reason}; give the tow point more depth, a current at the surface or way on, or a shorter "
                "buoyant part")
    heights = float(origin[2]) - np.cumsum(np.sign(net.el_weight[elements]) * net.el_length[elements])
    top = float(np.max(heights))
    return (f"cable '{name}' is a buoyant free tail in still water that would stand straight up to {top:.3f} m "
            f"above the surface: {reason}; give the tow point at least that much more depth, a current or way "
            "on, or a shorter buoyant part")
