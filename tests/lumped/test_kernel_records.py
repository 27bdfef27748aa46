"""The lumped kernels' inputs as named records (:mod:`kanat.lumped.entries`) and the cost of their check.

* Every record is what numba and the install-time compiler take: a named tuple of its class whose
  fields have the declared types; the records a system's one builder makes
  (:class:`kanat.lumped.advance.FusedArrays`, the snap tracker) match exactly one declared version
  of the stepping entries (the one without 6-DOF bodies and seabed, for a towed network; the one
  with both, for a buoy moored on the seabed in waves, whose 6-DOF bodies, seabed contact and sea
  are records too).
* The 6-DOF bodies' record read by field name places the fairleads where module eq. (1) of
  :mod:`kanat.lumped.rigid` puts them (oracle: ``r + R p_b`` and ``r_dot + w x (R p_b)`` in NumPy,
  with :func:`kanat.physics.motion.rotation_matrix` and ``angular_velocity``).
* The guarantee: a record with a field of another dtype, or a plain tuple of the same arrays,
  never reaches the install-time code; it goes to numba's kernel, which gives the answer of the
  right record (oracle: numba's kernel on the record as built, bit for bit).
* The cost: a record is checked field by field once, then by identity, so the check of a fused
  ``rk4_steps`` call's arguments takes a few microseconds of CPU (oracle: the same check of the
  same arrays as plain tuples, which is what every call paid before).
"""
import time
from types import SimpleNamespace

import numpy as np
import pytest

from kanat import aot, api
from kanat.lumped import entries, time_error
from kanat.lumped.advance import FusedArrays, implicit_scheme, track_samples
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.system import LumpedSystem
from kanat.physics.contact import Bed, ContactLaw
from kanat.physics.motion import angular_velocity, rotation_matrix

from helpers import EXAMPLES
from test_lumped_fast import network_case

RECORDS = (entries.Nodes, entries.Elements, entries.Bodies, entries.Environment, entries.Work, entries.Snap,
           entries.Track, entries.ImplicitScheme, entries.Band, entries.Rig, entries.Contact, entries.Laid,
           entries.Sea, Bed, ContactLaw)


@pytest.fixture(scope="module")
def built():
    case = network_case(waves=None, profile=False)
    system = LumpedSystem(build_network(case), case)
    arrays = FusedArrays(system)
    snap = SnapTracker(0.0, np.zeros(system.net.n_elements)).kernel_arrays()
    return system, arrays, snap


def rk4_arguments(system, arrays, snap):
    n = len(system.free_index)
    samples = track_samples(system, np.array([0.0, 0.005, 0.01]))
    return (0.0, 0.01, 1, np.zeros(6 * n), samples, arrays.nodes, arrays.el, arrays.bodies, arrays.env,
            arrays.work, snap, arrays.events)


@pytest.mark.parametrize("kind", RECORDS, ids=lambda kind: kind.__name__)
def test_each_record_is_a_named_tuple_of_its_class_to_numba(kind):
    from kanat.aot_build import numba_type
    from numba import types

    typed = numba_type(kind)
    assert isinstance(typed, types.BaseNamedTuple) and typed.instance_class is kind
    assert len(typed) == len(kind._fields) == len(kind.SPECIFICATION)
    narrowed = numba_type(entries.Bodies.narrowed(rig=None, contact=None))
    assert narrowed.instance_class is entries.Bodies and narrowed[7] == types.none and narrowed[8] == types.none


def test_the_built_records_match_one_version_of_the_stepping_entries(built):
    args = rk4_arguments(*built)
    for record in args[5:11]:
        assert type(record) in RECORDS and aot.matches(record, type(record)) or type(record) is entries.Bodies
    matching = [i for i, spec in enumerate(aot.ENTRIES["rk4_steps"].versions) if aot.matches(args, spec)]
    assert matching == [0]                                   # no 6-DOF body, no seabed contact


@pytest.fixture(scope="module")
def moored():
    """A buoy (a 6-DOF body) moored by three chains resting on the seabed, in irregular waves."""
    case = api.load_case(EXAMPLES / "mooring_buoy_waves.yaml")
    system = LumpedSystem(build_network(case), case)
    return system, FusedArrays(system), SnapTracker(0.0, np.zeros(system.net.n_elements)).kernel_arrays()


def test_the_bodies_seabed_and_sea_are_records_of_the_version_with_both(moored):
    system, arrays, snap = moored
    rig, contact, sea = arrays.bodies.rig, arrays.bodies.contact, arrays.env.sea
    for record, kind in ((rig, entries.Rig), (contact, entries.Contact), (contact.laid, entries.Laid),
                         (contact.seabed, Bed), (contact.law, ContactLaw), (sea, entries.Sea)):
        assert type(record) is kind and aot.matches(record, kind)
    assert rig.rigid_mass is system.net.rigid.mass6 and rig.fairlead_offset is system.net.rigid.fairlead_offset
    assert contact.area is system.net.node_contact_area and np.count_nonzero(contact.area) > 10
    block = system.case.environment.seabed
    assert contact.seabed.depth == 100.0 and contact.seabed.cos_slope == 1.0 and contact.seabed.sin_slope == 0.0
    assert (contact.law.stiffness, contact.law.damping) == (block.stiffness, block.damping)
    assert contact.law.equilibrium is False                 # a run's friction, in velocity
    np.testing.assert_array_equal(sea.amplitude, system.sea.amplitude)
    assert len(sea.amplitude) > 10 and sea.depth == 100.0
    versions = aot.ENTRIES["rk4_steps"].versions
    matching = [i for i, spec in enumerate(versions) if aot.matches(rk4_arguments(system, arrays, snap), spec)]
    assert matching == [3]                                   # 6-DOF bodies and seabed contact (entries.BODIES)
    assert aot.matches((np.zeros((3, 3)), np.zeros((3, 3)), tuple(rig)), aot.ENTRIES["place_fairleads"].versions[0]) \
        is False                                             # a plain tuple never reaches the compiled code


def test_the_rig_record_places_the_fairleads_by_eq_1(moored):
    system, arrays, _ = moored
    rig, rng = arrays.bodies.rig, np.random.default_rng(5)
    x, v = rng.normal(0.0, 20.0, (system.net.n_nodes, 3)), rng.normal(0.0, 1.0, (system.net.n_nodes, 3))
    x[rig.angle_node] = rng.uniform(-0.4, 0.4, (len(rig.angle_node), 3))
    entries.place_fairleads(x, v, rig)
    for node, body, offset in zip(rig.fairlead_node, rig.fairlead_body, rig.fairlead_offset):
        ref, angles = rig.reference_node[body], rig.angle_node[body]
        arm = rotation_matrix(*x[angles]) @ offset
        np.testing.assert_allclose(x[node], x[ref] + arm, rtol=0, atol=1e-12)
        np.testing.assert_allclose(v[node], v[ref] + np.cross(angular_velocity(x[angles], v[angles]), arm),
                                   rtol=0, atol=1e-12)
    assert len(rig.fairlead_node) == 3 and np.abs(x[rig.fairlead_node] - x[rig.reference_node[0]]).max() > 2.0


def implicit_arguments(system, arrays, snap):
    n, steps = len(system.free_index), 2
    track = track_samples(system, np.array([0.01, 0.02, 0.01, 0.02]))
    mid, end = (entries.Track(*(part[rows] for part in track)) for rows in (slice(None, steps), slice(steps, None)))
    x, v, a = np.zeros((n, 3)), np.zeros((n, 3)), np.zeros((n, 3))
    scheme = implicit_scheme(GeneralizedAlphaLumped())
    return (0.0, 0.01, steps, scheme, x, v, a, mid, end, arrays.nodes, arrays.el, arrays.bodies, arrays.env,
            arrays.work, arrays.band, snap, arrays.events, time_error.empty())


def test_the_implicit_steps_take_the_explicit_steps_records(built):
    """The fused implicit call reads the very records the explicit one does (no second copy) and its own
    scheme, band and vessel records, and matches exactly one declared version of its entry."""
    implicit, explicit = implicit_arguments(*built), rk4_arguments(*built)
    for got, want in zip(implicit[9:14] + implicit[15:17], explicit[5:]):   # nodes ... work, snap, events
        assert got is want
    for record in (implicit[3], implicit[7], implicit[8], implicit[14]):   # scheme, mid, end, band
        assert aot.matches(record, type(record))
    scheme = GeneralizedAlphaLumped()
    assert tuple(implicit[3][:4]) == scheme.coefficients
    assert (implicit[3].max_iterations, implicit[3].tolerance) == (scheme.max_iterations, scheme.tolerance)
    matching = [i for i, spec in enumerate(aot.ENTRIES["implicit_steps"].versions) if aot.matches(implicit, spec)]
    assert matching == [0]                                   # no 6-DOF body, no seabed contact


def test_a_wrong_dtype_in_a_record_goes_to_numbas_kernel(built):
    system, arrays, _ = built
    calls = []
    compiled = SimpleNamespace(tensions__0=lambda *args: calls.append(args))
    tensions = aot._kernel("tensions", compiled)
    x = np.ascontiguousarray(np.random.default_rng(3).normal(0.0, 30.0, (system.net.n_nodes, 3)))
    v = np.zeros_like(x)
    want = np.zeros(system.net.n_elements)
    aot.kernel("tensions")                                   # warm the lookup
    from kanat.lumped.kernels import tensions as numba_tensions
    numba_tensions(x, v, arrays.el, want)

    tensions(x, v, arrays.el, np.zeros_like(want))
    assert len(calls) == 1                                   # the record as built: the compiled version
    narrow = arrays.el._replace(first_node=arrays.el.first_node.astype(np.int32))
    got = np.zeros_like(want)
    tensions(x, v, narrow, got)
    assert len(calls) == 1                                   # never handed to the compiled code
    np.testing.assert_array_equal(got, want)
    assert np.count_nonzero(want) > 5
    with pytest.raises(Exception, match="first_node"):       # a plain tuple has no field names: numba says so
        tensions(x, v, tuple(arrays.el), got)
    assert len(calls) == 1


def check_time(check, args, repeats=7, calls=2000) -> float:
    """The least CPU time of one ``check(args)`` over ``repeats`` runs of ``calls`` [s]."""
    best = np.inf
    for _ in range(repeats):
        start = time.process_time()
        for _ in range(calls):
            check(args)
        best = min(best, (time.process_time() - start) / calls)
    return best


def test_a_fused_calls_check_takes_a_few_microseconds(built):
    args = rk4_arguments(*built)
    spec = aot.ENTRIES["rk4_steps"].versions[0]
    check = aot.checker(spec)
    assert check(args)
    fast = check_time(check, args)
    plain = tuple(tuple(a) if type(a) in RECORDS else a for a in args)     # the same arrays, unnamed
    plain_spec = tuple(aot.as_record(s).specification if aot.is_record(s) else s for s in spec)
    slow = check_time(aot.checker(plain_spec), plain)
    print(f"rk4_steps argument check: {fast * 1e6:.2f} us with records, {slow * 1e6:.2f} us field by field")
    assert fast < 5e-6 and fast < slow / 3
