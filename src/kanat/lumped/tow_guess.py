"""A first guess for the lumped equilibrium of a cable with a free tail: each element trailing at
the critical angle of the relative flow.

A free tail carries no tension at its end, so near it the line lies where its normal drag carries
its weight; in a uniform flow a whole inextensible tail does (theory/continuum.md eq. (C15),
:func:`kanat.physics.drag.critical_angle`)::

    (1)  R sin^2(phi) = |w| cos(phi),   R = 0.5 rho d C_n |u|^2,   u = U_current(z) - U_frame

and the tension grows from the tail with the tangential weight and drag along a straight line.
The guess marches from the attached end, element by element, each along the horizontal relative
flow ``u`` at its upper node's depth, inclined by its own line type's ``phi`` below it (above it
for a buoyant line): the exact steady shape of an inextensible line of one line type in a uniform
flow, a close one otherwise (sections, a sheared current, stretch), which Newton's method corrects
in a few iterations.

Without it the network's own guess leaves such a tail at 45 degrees below the tow point
(:func:`kanat.lumped.network._guess_positions`): for ``examples/towed_array.yaml`` (300 m at 8 kn,
a critical angle of 2.8 degrees) the tail's 190 m to go at 0.25 element per iteration takes the
iteration through states stretched to 10 % (residual 2e5 N against a 5 kN tow) and it fails in
400 iterations; from eq. (1) the taut phase converges in 6.
"""
from __future__ import annotations

import numpy as np

from kanat.physics.drag import critical_angle


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
    """``x`` (n, 3) with every free tail's nodes placed by eq. (1), or None when the case has none or no
    flow passes them (still water, no way on: a clamped beam or a hanging line keeps the network's guess).
    Still water is the case's current definition without a horizontal velocity in any row of its table
    (:meth:`kanat.model.environment.Current.table`), wherever the nodes are.

    Parameters
    ----------
    net : kanat.lumped.network.Network
    case : kanat.model.Case
    x : ndarray, shape (n, 3)
        The guess of every other node; the attached ends' places are taken from it [m].
    velocity : ndarray, shape (3,)
        The steady frame's velocity ``U_frame`` [m/s].
    """
    tails = free_tails(case)
    _, currents = case.environment.current.table()
    still = not np.any(np.asarray(velocity, dtype=float)[:2]) and not np.any(currents[:, :2])
    if not tails or still:
        return None
    x = np.array(x, dtype=float)
    for name, reversed_ in tails:
        nodes = net.node_index[net.node_cable == name]
        first = net.cable_first_element[net.cable_names.index(name)]
        elements = np.arange(first, first + len(nodes) - 1)
        if reversed_:
            nodes, elements = nodes[::-1], elements[::-1]
        for node, after, element in zip(nodes[:-1], nodes[1:], elements):
            x[after] = x[node] + net.el_length[element] * _trailing_direction(net, case, element, x[node], velocity)
    return x


def _trailing_direction(net, case, element, position, velocity) -> np.ndarray:
    """Unit vector (3,) from an element's upper node to its lower one, eq. (1)."""
    flow = np.asarray(case.environment.current.at(float(position[2])), dtype=float) - np.asarray(velocity)
    horizontal = flow[:2]
    speed = float(np.linalg.norm(horizontal))
    weight = float(net.el_weight[element])
    phi = critical_angle(weight, net.el_cn[element], speed)
    along = horizontal / speed if speed > 0.0 else np.zeros(2)
    return np.array([np.cos(phi) * along[0], np.cos(phi) * along[1], -np.sign(weight) * np.sin(phi)])
