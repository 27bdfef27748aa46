"""The lumped model's kernels that runs call from Python, compiled at install (:mod:`kanat.aot`).

Python code calls them from here (``entries.element_forces(...)``): each name is an entry point
(:class:`kanat.aot.EntryPoint`) that runs the version compiled at install when it is current and
the arguments match it, numba's kernel otherwise (made on first use, so a run that needs none of
numba's kernels compiles nothing). Compiled kernels call each other directly, in their own modules.

The argument specifications below are the layouts the Python side builds (``FusedArrays`` in
:mod:`kanat.lumped.advance`, ``LumpedSystem`` in :mod:`kanat.lumped.system`); the stepping
kernels come in one version per combination of the optional 6-DOF bodies and seabed contact
(None when a network has none, which prunes their code).
"""
from __future__ import annotations

from functools import partial

from kanat import aot
from kanat.aot import B1, BOOL, F1, F2, F3, F4, FLOAT, I1, I2, INT

SAMPLES = (F3, F3, F1)                                   # vessel points' positions, velocities, headings
NODES = (I1, I1, I1, F2, F2, F1, B1, I2)                 # free, prescribed, ... (kanat.lumped.advance)
Elements = aot.record(
    "Elements", "kanat.lumped.entries",
    first_node=I1, second_node=I1,          # element k joins nodes first_node[k] and second_node[k]
    length=F1,                              # unstretched length L0 [m]
    mass=F1, added_mass=F1,                 # m, normal added mass m_a [kg/m]
    weight=F1,                              # weight in water w0 [N/m]
    displaced=F1,                           # rho A [kg/m]
    drag_normal=F1, drag_tangential=F1,     # c_n, c_t: 0.5 rho d C_d [kg/m^2]
    stretch_drag=F1,                        # > 0: drag on the stretched length
    damping=F1,                             # Kelvin-Voigt C_E2 [N s]
    law=I1,                                 # row of the element's elastic law in the law arrays
    law_kind=I1, law_size=I1, law_strains=F2, law_values=F2,   # the laws (kanat.lumped.network.law_arrays)
    added_mass_tangential=F1,               # m_at [kg/m]
    buoyancy=F1,                            # rho g A [N/m]
    diameter=F1,                            # d [m]
    bend_before=I1, bend_node=I1, bend_after=I1, bend_stiffness=F1,   # bending triples (kanat.lumped.bending)
    compression_stiffness=F1,               # > 0: the element is a bar that also pushes (kernels eq. 2a) [N]
)
"""The elements of a network as the kernels read them (``elements.length[k]``): one field per
property, filled by :meth:`kanat.lumped.network.Network.elements` and nowhere else
(theory/lumped.md §2; docs/contributing.md, adding a line property)."""
RIG = (I1, I1, F3, F3, F3, F3, F3, F2, F2, F2, F2, F2, F2, I1, I1, F2)   # 6-DOF bodies (kanat.lumped.rigid)
CONTACT = (F2, F2, F1)                                   # seabed: plane, tangents, parameters
SEABED = (F1, F1, F1, CONTACT)
SEA = (F1, F1, F1, F1, F1, F1, FLOAT, F1, FLOAT, FLOAT)
ENV = (FLOAT, FLOAT, F1, F2, SEA, BOOL, FLOAT, FLOAT)
WORK = (F2, F2, F2, F2, F1, F1, F2, F2, F2, F2, F2, F2, F2, F1, F3, F2, F2, F1, F1, F2, F2)
SNAP = (B1, B1, F1, F1, F1, F1, F1)
register = partial(aot.register, module="_lumped")       # the lumped model's own extension module
BODIES = tuple((I1, F1, F1, F1, I1, F1, F1, rig, seabed)
               for rig in (None, RIG) for seabed in (None, SEABED))
"""The ``bodies`` argument with and without 6-DOF bodies and seabed contact."""

register("track_states", "kanat.lumped.fast", (F1, F2, F1, F2, F2, F1))
register("rk4_steps", "kanat.lumped.fast",
         *((FLOAT, FLOAT, INT, F1, SAMPLES, NODES, Elements, bodies, ENV, WORK, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("abm4_steps", "kanat.lumped.fast",
         *((FLOAT, FLOAT, INT, F1, F2, SAMPLES, NODES, Elements, bodies, ENV, WORK, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("implicit_steps", "kanat.lumped.fast_implicit",
         *((FLOAT, FLOAT, INT, (FLOAT,) * 4, INT, FLOAT, F2, F2, F2, SAMPLES, SAMPLES, I1, INT, NODES, Elements,
            bodies, ENV, WORK, (F3,) * 5, F4, F1, B1, F2, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT, INT, BOOL), function="steps")
register("elastic_row", "kanat.lumped.kernels", (I1, I1, F2, F2, INT, FLOAT), returns=(FLOAT, FLOAT))
register("element_forces", "kanat.lumped.kernels", (F2, F2, F2, F2, F1, F2, F1, Elements, F2, F2, F1, F1),
         twin="kanat.lumped.oracle_numpy.element_forces_numpy")
register("lumped_solve", "kanat.lumped.kernels", (F3, F2, B1, F2), twin="kanat.lumped.oracle_numpy.lumped_solve_into")
register("tensions", "kanat.lumped.kernels", (F2, F2, Elements, F1))
register("add_body_loads", "kanat.lumped.kernels", (F2, F2, F2, F2, I1, F1, F1, F1, FLOAT, FLOAT, F2))
register("place_fairleads", "kanat.lumped.rigid", (F2, F2, RIG))
register("rigid_accelerations", "kanat.lumped.rigid", (F2, F2, F2, F2, F2, F2, F1, FLOAT, RIG, F3))
register("contact_forces", "kanat.physics.contact", (F2, F2, I1, I1, F1, F1, F1, CONTACT, F2, F2, F1))


# the entry points Python code calls (``entries.element_forces(...)``; kanat.aot.EntryPoint)
(track_states, rk4_steps, abm4_steps, implicit_steps, elastic_row, element_forces, lumped_solve, tensions,
 add_body_loads, place_fairleads, rigid_accelerations, contact_forces) = map(aot.EntryPoint, (
    "track_states", "rk4_steps", "abm4_steps", "implicit_steps", "elastic_row", "element_forces", "lumped_solve",
    "tensions", "add_body_loads", "place_fairleads", "rigid_accelerations", "contact_forces"))
