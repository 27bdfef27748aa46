"""The lumped model's kernels that runs call from Python, compiled at install (:mod:`kanat.aot`).

Python code calls them from here (``entries.element_forces(...)``): each name is an entry point
(:class:`kanat.aot.EntryPoint`) that runs the version compiled at install when it is current and
the arguments match it, numba's kernel otherwise (made on first use, so a run that needs none of
numba's kernels compiles nothing). Compiled kernels call each other directly, in their own modules.

The argument specifications below are the layouts the Python side builds, each group of arrays a
named record (:func:`kanat.aot.record`) with one builder (``FusedArrays``, ``track_samples``,
``sea_arrays`` and ``implicit_scheme`` in :mod:`kanat.lumped.advance`, ``Network.elements`` in
:mod:`kanat.lumped.network`, ``RigidBodies.arrays`` in :mod:`kanat.lumped.rigid`, the seabed's
``Contact`` and ``Laid`` in :mod:`kanat.lumped.system`, ``SnapTracker.kernel_arrays`` in
:mod:`kanat.lumped.snap`); the stepping
kernels come in one version per combination of the optional 6-DOF bodies and seabed contact
(None when a network has none, which prunes their code).
"""
from __future__ import annotations

from functools import partial

from kanat import aot
from kanat.aot import B1, BOOL, F1, F2, F3, F4, FLOAT, I1, I2, INT
from kanat.physics.contact import Bed, ContactLaw

Track = aot.record(
    "Track", "kanat.lumped.entries",
    position=F3, velocity=F3,               # the vessel's nodes at each sample time [m], [m/s] (k, n_vessel, 3)
    heading=F1,                             # the vessel's heading at each sample time [rad] (k,)
)
"""The vessel's nodes sampled at the times a compiled call needs (row ``s`` for sample ``s``), built by
:func:`kanat.lumped.advance.track_samples`."""
Nodes = aot.record(
    "Nodes", "kanat.lumped.entries",
    free=I1,                                # the free nodes (their order is that of the state vector)
    vessel=I1, anchor=I1,                   # the nodes moved by the vessel, the anchored nodes
    anchor_position=F2,                     # the anchored nodes' positions [m]
    force=F2,                               # constant nodal loads (weights, body forces) [N]
    mass=F1,                                # nodal masses of bodies and points [kg]
    is_free=B1,                             # per node: free
    rigid_rows=I2,                          # 6-DOF bodies' two pseudo-nodes: rows among the free nodes
)
"""The nodes of a network as the kernels read them, built by :class:`kanat.lumped.advance.FusedArrays`."""
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
Rig = aot.record(
    "Rig", "kanat.lumped.entries",
    reference_node=I1, angle_node=I1,       # per body b: the pseudo-nodes of its reference point r and Euler angles
    rigid_mass=F3,                          # rigid-body mass M_rb about r, body axes [kg, kg m, kg m^2] (nb, 6, 6)
    added_mass=F3,                          # added mass A, body axes (nb, 6, 6)
    hydrostatic_stiffness=F3,               # C of rigid eq. 4, body axes [N/m, N m/rad] (nb, 6, 6)
    linear_damping=F3, quadratic_damping=F3,    # B_1 [N s/m], B_2 [N s^2/m^2] of rigid eq. 3, body axes (nb, 6, 6)
    drag_area=F2,                           # C_D A per degree of freedom [m^2, m^5] (nb, 6)
    gravity_centre=F2, buoyancy_centre=F2,  # c_g, c_b in body axes [m] (nb, 3)
    scalars=F2,                             # m g [N], B [N], B / g [kg], hydrostatics (0 none, 1 without the
                                            # tilt, 2 with it), surface-piercing (1/0), m [kg] (nb, 6)
    force=F2,                               # constant external force [N] (nb, 3)
    rest=F2,                                # position [m] and orientation [rad] the restoring acts about (nb, 6)
    fairlead_node=I1, fairlead_body=I1,     # per fairlead f: its node and its body
    fairlead_offset=F2,                     # p_b of rigid eq. 1, body axes [m] (k, 3)
)
"""The 6-DOF bodies as the kernels read them (kanat.lumped.rigid, eqs. 1-4), built by
:meth:`kanat.lumped.rigid.RigidBodies.arrays`."""
Laid = aot.record(
    "Laid", "kanat.lumped.entries",
    origin=F2,                              # x_ref: where each node's line was laid from [m] (n, 3)
    direction=F2,                           # a: the direction it was laid in, zero for none (n, 3)
    distance=F1,                            # s: the node's distance along it [m] (n,)
)
"""Where each node lay, ``x_ref + s a``, for the equilibrium's seabed friction
(:mod:`kanat.physics.contact`), built by :func:`kanat.lumped.system.laid_lines`."""
Contact = aot.record(
    "Contact", "kanat.lumped.entries",
    area=F1,                                # contact area A_n per node [m^2] (n,)
    seabed=Bed,                             # the seabed's geometry (physics.contact.bed_of)
    law=ContactLaw,                         # the contact law's parameters (physics.contact.contact_law)
    laid=Laid,                              # where each node lay (equilibrium friction)
)
"""The seabed contact as the kernels read it (:mod:`kanat.physics.contact`, eqs. 1-4), built by
:class:`kanat.lumped.system.LumpedSystem`; None in a network without a seabed."""
Sea = aot.record(
    "Sea", "kanat.lumped.entries",
    amplitude=F1,                           # a_j [m] (n,): the components of the linear sea (waves eq. 2)
    omega=F1,                               # angular frequency [rad/s] (n,)
    wavenumber=F1,                          # k_j [1/m] (n,)
    cos_direction=F1, sin_direction=F1,     # cos, sin of the heading of propagation (n,)
    phase=F1,                               # phi_j [rad] (n,)
    depth=FLOAT,                            # water depth h [m]; <= 0: deep water
    depth_factor=F1,                        # 1 / (1 - e^{-2 k_j h}) (1 in deep water) (n,)
    wheeler=FLOAT,                          # 1.0: Wheeler stretching (waves eq. 7), 0.0: none
    ramp=FLOAT,                             # the waves' ramp-up time (waves eq. 8) [s]
)
"""The linear sea as the kernels read it (:mod:`kanat.lumped.fast`, ``sea_add``), built by
:func:`kanat.lumped.advance.sea_arrays`; no components in calm water."""
Environment = aot.record(
    "Environment", "kanat.lumped.entries",
    rho=FLOAT, g=FLOAT,                     # water density [kg/m^3], gravity [m/s^2]
    current_depths=F1, current_velocities=F2,   # the current table: depths z [m], velocities (k, 3) [m/s]
    sea=Sea,                                # the linear sea's components
    still=BOOL,                             # water kinematics constant in space and time
    elevation_bound=FLOAT,                  # >= the largest surface elevation [m] (0: no waves)
    current_ramp=FLOAT,                     # the current's ramp-up time [s]
)
"""The water as the kernels read it, built by :class:`kanat.lumped.advance.FusedArrays`."""
Bodies = aot.record(
    "Bodies", "kanat.lumped.entries",
    load_node=I1,                           # nodes carrying a 3-DOF body's or point's drag and fluid inertia
    drag_area=F1,                           # 0.5 rho C_d A per loaded node [kg/m]
    spreading=F1,                           # otter boards' spreading force coefficient per loaded node
    fluid_inertia=F1,                       # added mass and Froude-Krylov per loaded node [kg]
    buoy_node=I1, buoy_area=F1, buoy_height=F1,   # surface buoys: keel node, waterplane area [m^2], height [m]
    rig=Rig,                                # 6-DOF bodies (kanat.lumped.rigid), or None
    contact=Contact,                        # seabed contact (kanat.physics.contact), or None
    float_node=I1, float_diameter=F1,       # spherical inline floats: node, diameter [m] and buoyancy fully
    float_buoyancy=F1,                      # submerged [N] (kanat.physics.immersion)
)
"""Bodies, buoys and the seabed as the kernels read them, built by
:class:`kanat.lumped.advance.FusedArrays`; ``rig`` and ``contact`` are None in a network without
6-DOF bodies or seabed contact, which prunes their code from the kernels (:data:`BODIES`)."""
Work = aot.record(
    "Work", "kanat.lumped.entries",
    x=F2, v=F2,                             # all nodes' positions [m] and velocities [m/s] (n, 3)
    force=F2,                               # nodal forces [N] (n, 3)
    mass=F2,                                # packed symmetric nodal mass blocks xx, yy, zz, xy, xz, yz [kg] (n, 6)
    tension=F1, strain=F1,                  # element tensions [N], strains (m,)
    midpoint=F2,                            # element midpoints [m] (m, 3)
    water_velocity=F2, water_acceleration=F2,   # at element midpoints [m/s], [m/s^2] (m, 3)
    load_position=F2, load_velocity=F2, load_acceleration=F2,   # water at loaded nodes (nl, 3)
    wet=F1,                                 # wetted fraction of each element (m,)
    body_acceleration=F3,                   # 6-DOF bodies' pseudo-nodes' accelerations [m/s^2] (nb, 2, 3)
    body_velocity=F2, body_water_acceleration=F2,   # water at the bodies' reference points (nb, 3)
    body_elevation=F1,                      # surface elevation over each body [m] (nb,)
    normal_force=F1,                        # seabed normal force per node [N] (n,)
    line_tangent=F2,                        # the line's direction at each node (seabed friction) (n, 3)
    body_position=F2,                       # the bodies' reference points [m] (nb, 3)
)
"""The scratch arrays of the lumped right-hand side, built by :class:`kanat.lumped.advance.FusedArrays`
(its results are read from them: ``work.tension`` after a call)."""
Snap = aot.record(
    "Snap", "kanat.lumped.entries",
    taut=B1, active=B1,                     # per element: taut now, in an open event
    start=F1, peak=F1, rate=F1,             # the open events' start [s], peak tension [N], rise rate [N/s]
    previous_tension=F1,                    # the tensions of the last update [N]
    previous_time=F1,                       # the time of the last update [s] (1,)
)
"""The snap tracker's live arrays, updated in place by :func:`kanat.lumped.fast.snap_update`,
built by :meth:`kanat.lumped.snap.SnapTracker.kernel_arrays`."""
ImplicitScheme = aot.record(
    "ImplicitScheme", "kanat.lumped.entries",
    alpha_m=FLOAT, alpha_f=FLOAT,           # generalized-alpha weights of the old acceleration and state
    gamma=FLOAT, beta=FLOAT,                # Newmark's parameters (kanat.lumped.implicit eq. 1)
    max_iterations=INT,                     # Newton iterations a step may take
    tolerance=FLOAT,                        # increment, relative to max(1 m/s^2, max |a|), that ends them
)
"""The generalized-alpha scheme as the fused implicit steps read it, built by
:func:`kanat.lumped.advance.implicit_scheme`."""
Band = aot.record(
    "Band", "kanat.lumped.entries",
    position=I1,                            # each node's block row in the band order, -1 if prescribed (n,)
    half_width=INT,                         # the band's half-width in 3 x 3 node blocks
    factors=F4,                             # the tangent (implicit.py eq. 3), then its block LU (n_free, 2 w + 1, 3, 3)
    element_stiffness=F3, element_damping=F3, element_drag=F3,   # K, C, D of kernels.tangent_blocks (m, 3, 3)
    contact_stiffness=F3, contact_damping=F3,   # K_c, C_c of kanat.physics.contact.contact_tangent (n, 3, 3)
    memory=F1,                              # (5,): the factors' step (0: none), the time and step of the history
                                            # previous, the factors' contraction estimate and their age in steps
    in_contact=B1,                          # the nodes on the seabed when the factors were built (n,)
    previous=F2,                            # the acceleration one step before the history's time (n_free, 3)
)
"""The fused implicit steps' band tangent, its scratch blocks and what they keep between calls
(:func:`kanat.lumped.fast_implicit.steps`), built by :class:`kanat.lumped.advance.FusedArrays`."""
register = partial(aot.register, module="_lumped")       # the lumped model's own extension module
BODIES = tuple(Bodies.narrowed(rig=rig, contact=seabed) for rig in (None, Rig) for seabed in (None, Contact))
"""The ``bodies`` argument with and without 6-DOF bodies and seabed contact."""

register("track_states", "kanat.lumped.fast", (F1, F2, F1, F2, F2, F1))
register("harmonic_points", "kanat.lumped.fast", (F1, I1, F1, F1, F1, FLOAT, F2, F3, F3))
register("rk4_steps", "kanat.lumped.fast",
         *((FLOAT, FLOAT, INT, F1, Track, Nodes, Elements, bodies, Environment, Work, Snap, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("abm4_steps", "kanat.lumped.fast",
         *((FLOAT, FLOAT, INT, F1, F2, Track, Nodes, Elements, bodies, Environment, Work, Snap, F2) for bodies in BODIES),
         returns=(INT, INT), module="_lumped_explicit")
register("implicit_steps", "kanat.lumped.fast_implicit",
         *((FLOAT, FLOAT, INT, ImplicitScheme, F2, F2, F2, Track, Track, Nodes, Elements, bodies, Environment, Work,
            Band, Snap, F2, F1) for bodies in BODIES),
         returns=(INT, INT, INT, BOOL), function="steps")
register("elastic_row", "kanat.lumped.kernels", (I1, I1, F2, F2, INT, FLOAT), returns=(FLOAT, FLOAT))
register("element_forces", "kanat.lumped.kernels", (F2, F2, F2, F2, F1, F2, F1, Elements, F2, F2, F1, F1),
         twin="kanat.lumped.oracle_numpy.element_forces_numpy")
register("lumped_solve", "kanat.lumped.kernels", (F3, F2, B1, F2), twin="kanat.lumped.oracle_numpy.lumped_solve_into")
register("tensions", "kanat.lumped.kernels", (F2, F2, Elements, F1))
register("add_body_loads", "kanat.lumped.kernels", (F2, F2, F2, F2, I1, F1, F1, F1, FLOAT, FLOAT, F2))
register("place_fairleads", "kanat.lumped.rigid", (F2, F2, Rig))
register("rigid_accelerations", "kanat.lumped.rigid", (F2, F2, F2, F2, F2, F2, F1, FLOAT, Rig, F3))
register("contact_forces", "kanat.physics.contact", (F2, F2, I1, I1, F1, Bed, ContactLaw, Laid, F2, F2, F1))


# the entry points Python code calls (``entries.element_forces(...)``; kanat.aot.EntryPoint)
(track_states, harmonic_points, rk4_steps, abm4_steps, implicit_steps, elastic_row, element_forces, lumped_solve,
 tensions, add_body_loads, place_fairleads, rigid_accelerations, contact_forces) = map(aot.EntryPoint, (
    "track_states", "harmonic_points", "rk4_steps", "abm4_steps", "implicit_steps", "elastic_row", "element_forces",
    "lumped_solve", "tensions", "add_body_loads", "place_fairleads", "rigid_accelerations", "contact_forces"))


# An output's loads in one compiled call (kanat.lumped.output_loads) ---------------------------
OutputLoads = aot.record(
    "OutputLoads", "kanat.lumped.entries",
    calm=BOOL,                              # no waves: the wetted fractions worked out in the call
    node_force=F2, node_mass=F1,            # constant nodal loads [N] (n, 3), nodal body masses [kg] (n,)
    water_velocity=F2, water_acceleration=F2,   # at the element midpoints [m/s], [m/s^2] (m, 3)
    wet=F1,                                 # wetted fraction of each element (m,): an input with waves
    force=F2,                               # nodal forces [N] (n, 3)
    mass=F2,                                # packed nodal mass blocks xx, yy, zz, xy, xz, yz [kg] (n, 6)
    tension=F1, strain=F1,                  # element_forces' element tensions [N] and strains (m,)
    line_tension=F1,                        # kernels.tensions' element tensions [N] (m,): the outputs'
    tangent=F2,                             # the seabed friction's work array (n, 3)
    normal_force=F1,                        # the seabed's normal force on each node [N] (n,)
)
"""What :func:`kanat.lumped.output_loads.output_loads` reads and writes, built once per run by
:meth:`kanat.lumped.system.LumpedSystem.output_loads` over the system's own arrays."""
register("output_loads", "kanat.lumped.output_loads", *((F2, F2, Elements, seabed, OutputLoads) for seabed in (None, Contact)),
         twin="kanat.lumped.oracle_numpy.output_loads_numpy")
output_loads = aot.EntryPoint("output_loads")
