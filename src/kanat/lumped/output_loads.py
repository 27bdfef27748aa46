"""An output's loads in one compiled call: what the lumped model's outputs and checks read.

An output of the lumped model (:meth:`kanat.lumped.adapter.LumpedModel.outputs`) needs, at the
state's time, every element's tension (``segment_tension``, the node tensions and the snap
tracker), the nodal forces (the anchors' and bodies' forces) with the seabed's normal force at
every node (the contact length) and the elements' strains (the strain check). They are the
right-hand side's loads of :mod:`kanat.lumped.system`, eqs. (1)-(2), whose pieces have compiled
kernels of their own; :func:`output_loads` calls them in one go, in the order
:meth:`kanat.lumped.system.LumpedSystem.loads` does, so the numbers are the same to the last bit:

1. the element tensions, :func:`kanat.lumped.kernels.tensions` (kernels eqs. 1-2a) into
   ``out.line_tension``;
2. in calm water, the wetted fraction of every element (:func:`kanat.lumped.kernels.wetted_fraction`
   under the still surface ``eta = 0``; an element below ``z = 0`` by more than its radius is wet)
   into ``out.wet``; with waves ``out.wet`` is filled before the call;
3. the element forces, packed mass blocks, tensions and strains,
   :func:`kanat.lumped.kernels.element_forces` (kernels eqs. 1-8), into ``out.force``, ``out.mass``,
   ``out.tension``, ``out.strain``;
4. the bending forces, :func:`kanat.lumped.bending.bending_forces` (bending eq. 3), added to
   ``out.force``;
5. the seabed contact, :func:`kanat.physics.contact.contact_forces` (contact eqs. 1-4), added to
   ``out.force``, with ``out.normal_force`` the normal force ``N`` of each node (nothing without a
   seabed: ``contact`` None).

The loads of bodies, floats and buoys and the 6-DOF bodies stay with the Python caller, after
the call, as in ``loads``. The plain-NumPy twin is
:func:`kanat.lumped.oracle_numpy.output_loads_numpy`.
"""
from __future__ import annotations

from kanat.jit import inner, kernel
from kanat.lumped import kernels
from kanat.lumped.bending import bending_forces
from kanat.physics.contact import contact_forces


@kernel
def output_loads(x, v, el, contact, out):
    """Steps 1-5 of the module docstring for all nodes' positions and velocities.

    Parameters
    ----------
    x, v : ndarray, shape (n, 3)
        All nodes' positions [m] and velocities [m/s], prescribed ones included.
    el : kanat.lumped.entries.Elements
        The elements, their laws and bending triples.
    contact : kanat.lumped.entries.Contact or None
        The seabed contact; None without a seabed (its code then pruned).
    out : kanat.lumped.entries.OutputLoads
        The constant nodal loads, the water at the element midpoints and the results (module
        docstring), overwritten but for the inputs.
    """
    kernels.tensions(x, v, el, out.line_tension)
    if out.calm:
        calm_wetted(x, el.first_node, el.second_node, el.diameter, out.wet)
    kernels.element_forces(x, v, out.water_velocity, out.water_acceleration, out.wet, out.node_force,
                           out.node_mass, el, out.force, out.mass, out.tension, out.strain)
    bending_forces(x, el.bend_before, el.bend_node, el.bend_after, el.bend_stiffness, out.force)
    if contact is not None:
        contact_forces(x, v, el.first_node, el.second_node, contact.area, contact.seabed, contact.law,
                       contact.laid, out.tangent, out.force, out.normal_force)


@inner
def calm_wetted(x, el_i, el_j, diameter, wet):
    """Wetted fraction of every element under the still surface ``z = 0``: 1 below it,
    ``-low / (top - low)`` across it, 0 above it (kernels ``wetted_fraction``, ``eta = 0``), with
    ``low, top`` the element's lowest and highest point (centreline -/+ half its diameter)."""
    for k in range(el_i.shape[0]):
        i, j = el_i[k], el_j[k]
        top = max(x[i, 2], x[j, 2]) + 0.5 * diameter[k]
        if not top >= 0.0:                    # as the Python path's ``near``, NaN included
            wet[k] = 1.0
            continue
        low = min(x[i, 2], x[j, 2]) - 0.5 * diameter[k]
        wet[k] = min(max((0.0 - low) / max(top - low, 1e-300), 0.0), 1.0)
