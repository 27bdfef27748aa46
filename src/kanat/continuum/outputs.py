"""Outputs of the continuum model computed from its state, beyond the nodal series (case-format.md).

* ``seabed_contact_length(cable)``: the unstretched length of the cable resting on the seabed,
  ``sum_j ds_j (c_j + c_{j+1}) / 2`` with ``c = 1`` at a node resting on it: half an interval per
  resting node, as the lumped model counts half an element (theory/moorings.md eq. (M8a)).
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
