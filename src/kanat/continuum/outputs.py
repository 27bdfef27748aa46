"""Outputs of the continuum model computed from its state, beyond the nodal series (case-format.md).

* ``seabed_contact_length(cable)``: the unstretched length of the cable resting on the seabed,
  ``sum_j ds_j (c_j + c_{j+1}) / 2`` with ``c = 1`` at a node resting on it: half an interval per
  resting node, as the lumped model counts half an element (theory/moorings.md eq. (M8a));
* ``anchor_force(anchor)`` and ``body_force(body)``: the cable's force ``F = T t + S`` at its ends,
  ``+F`` on its ``from`` end and ``-F`` on its ``to`` end, and ``F(j + 1) - F(j)`` on an inline body
  over its junction interval (:func:`line_force`, :func:`end_forces`, :func:`inline_forces`): the
  lumped model's outputs of the same names (:mod:`kanat.lumped.mooring_outputs`) in the limit of
  short elements, whose half element's loads vanish with them; uplift is the anchor force's +z part.
"""
from __future__ import annotations

import numpy as np

RESTING_FRACTION = 0.5
"""A node rests on the seabed when it is less than this many static penetrations ``w / (k_b d)``
above the seabed's plane. The box method's nodes on a resting line alternate about the static sink,
from a tenth of it above the plane to 2.5 times it below (docs/continuum.md, seabed contact): a
test on the penetration's sign alone would miss every other one; a node lifting off at the
touchdown is a segment's rise above the plane, far beyond this."""


def seabed_contact_length(penetration: np.ndarray, spacing: np.ndarray, static: float) -> float:
    """The unstretched length of a cable resting on the seabed [m] (theory/moorings.md eq. (M8a)).

    Parameters
    ----------
    penetration : ndarray, shape (n_nodes,)
        Each node's depth below the seabed's plane along its normal [m] (negative above it:
        :meth:`kanat.continuum.grid.SeabedContact.penetration`).
    spacing : ndarray, shape (n_nodes - 1,)
        Each interval's unstretched length ``ds`` [m] (0 for an inline body's junction).
    static : float
        The contact law's static penetration ``w / (k_b d)`` [m], the largest of the cable's intervals.

    Returns
    -------
    float
        ``sum_j ds_j (c_j + c_{j+1}) / 2``, ``c_j = 1`` where the penetration exceeds
        ``-RESTING_FRACTION static``, else 0.
    """
    resting = (np.asarray(penetration) > -RESTING_FRACTION * static).astype(float)
    return float(np.sum(spacing * 0.5 * (resting[:-1] + resting[1:])))


def line_force(tension: np.ndarray, tangent: np.ndarray, shear: np.ndarray | None = None) -> np.ndarray:
    """The cable's force at each node, ``F = T t + S`` [N] (theory/continuum.md §1; with bending
    stiffness Gobat & Grosenbaugh's shear ``S``, normal to ``t``): the pull of the cable beyond the
    node (larger ``s``) on the cable before it.

    Parameters
    ----------
    tension : ndarray, shape (n_nodes,)
        Effective tension ``T`` [N].
    tangent : ndarray, shape (n_nodes, 3)
        Unit tangent ``t`` along increasing ``s``, global frame.
    shear : ndarray, shape (n_nodes, 3), optional
        Shear force ``S`` [N], global frame; none for a perfectly flexible cable.

    Returns
    -------
    ndarray, shape (n_nodes, 3)
    """
    force = np.asarray(tension, dtype=float)[:, None] * np.asarray(tangent, dtype=float)
    return force if shear is None else force + shear


def end_forces(force: np.ndarray, ends: list[str]) -> np.ndarray:
    """The cable's force on what holds its ends [N]: ``+F(0)`` on its ``from`` end, ``-F(L)`` on its
    ``to`` end (``F`` = :func:`line_force`; statics' ``T t`` pulls the ``from`` end along ``+t``).
    With the line resting on the seabed at an anchor, ``F(0)`` is the tension there, the seabed
    carrying the weight of what rests on it: the lumped model's anchor force less the weight and
    friction of its resting half element (:mod:`kanat.lumped.mooring_outputs`).

    Parameters
    ----------
    force : ndarray, shape (n_nodes, 3)
    ends : list of {"from", "to"}

    Returns
    -------
    ndarray, shape (len(ends), 3)
    """
    rows = [force[0] if end == "from" else -force[-1] for end in ends]
    return np.array(rows, dtype=float).reshape(len(ends), 3)


def inline_forces(force: np.ndarray, junctions: np.ndarray) -> np.ndarray:
    """The cable's force on each inline body [N], ``F(j + 1) - F(j)`` over its junction interval
    ``(j, j + 1)``: the section after it pulls the body along ``+t``, the one before along ``-t``.

    Parameters
    ----------
    force : ndarray, shape (n_nodes, 3)
        :func:`line_force`.
    junctions : ndarray of int, shape (n_inline,)
        The zero-length intervals that carry the inline bodies, in the order of their bodies.

    Returns
    -------
    ndarray, shape (n_inline, 3)
    """
    junctions = np.asarray(junctions, dtype=int)
    return force[junctions + 1] - force[junctions]
