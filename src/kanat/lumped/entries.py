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
ELEMENTS = (I1, I1, F1, F1, F1, F1, F1, F1, F1, F1, F1, I1, I1, I1, F2, F2, F1, F1, F1,
            I1, I1, I1, F1)                          # ... and the bending triples (kanat.lumped.bending)
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
         *((FLOAT, FLOAT, INT, F1, SAMPLES, NODES, ELEMENTS, bodies, ENV, WORK, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("abm4_steps", "kanat.lumped.fast",
         *((FLOAT, FLOAT, INT, F1, F2, SAMPLES, NODES, ELEMENTS, bodies, ENV, WORK, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("implicit_steps", "kanat.lumped.fast_implicit",
         *((FLOAT, FLOAT, INT, (FLOAT,) * 4, INT, FLOAT, F2, F2, F2, SAMPLES, SAMPLES, I1, INT, NODES, ELEMENTS,
            bodies, ENV, WORK, (F3,) * 5, F4, F1, B1, F2, SNAP, F2) for bodies in BODIES),
         returns=(INT, INT, INT, BOOL), function="steps")
register("elastic_row", "kanat.lumped.kernels", (I1, I1, F2, F2, INT, FLOAT), returns=(FLOAT, FLOAT))
register("element_forces", "kanat.lumped.kernels", (F2, F2, F2, F2, F1, F2, F1, ELEMENTS, F2, F2, F1, F1))
register("lumped_solve", "kanat.lumped.kernels", (F3, F2, B1, F2))
register("tensions", "kanat.lumped.kernels", (F2, F2, I1, I1, F1, F1, I1, I1, I1, F2, F2, F1))
register("add_body_loads", "kanat.lumped.kernels", (F2, F2, F2, F2, I1, F1, F1, F1, FLOAT, FLOAT, F2))
register("place_fairleads", "kanat.lumped.rigid", (F2, F2, RIG))
register("rigid_accelerations", "kanat.lumped.rigid", (F2, F2, F2, F2, F2, F2, F1, FLOAT, RIG, F3))
register("contact_forces", "kanat.physics.contact", (F2, F2, I1, I1, F1, F1, F1, CONTACT, F2, F2, F1))


# the entry points Python code calls (``entries.element_forces(...)``; kanat.aot.EntryPoint)
(track_states, rk4_steps, abm4_steps, implicit_steps, elastic_row, element_forces, lumped_solve, tensions,
 add_body_loads, place_fairleads, rigid_accelerations, contact_forces) = map(aot.EntryPoint, (
    "track_states", "rk4_steps", "abm4_steps", "implicit_steps", "elastic_row", "element_forces", "lumped_solve",
    "tensions", "add_body_loads", "place_fairleads", "rigid_accelerations", "contact_forces"))
