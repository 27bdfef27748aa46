"""The lumped kernels' inputs as named records (:mod:`kanat.lumped.entries`) and the cost of their check.

* Every record is what numba and the install-time compiler take: a named tuple of its class whose
  fields have the declared types; the records a system's one builder makes
  (:class:`kanat.lumped.advance.FusedArrays`, the snap tracker) match exactly one declared version
  of the stepping entries (the one without 6-DOF bodies and seabed, for a towed network).
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

from kanat import aot
from kanat.lumped import entries, time_error
from kanat.lumped.advance import FusedArrays, implicit_scheme, track_samples
from kanat.lumped.integrators import GeneralizedAlphaLumped
from kanat.lumped.network import build_network
from kanat.lumped.snap import SnapTracker
from kanat.lumped.system import LumpedSystem

from test_lumped_fast import network_case

RECORDS = (entries.Nodes, entries.Elements, entries.Bodies, entries.Environment, entries.Work, entries.Snap,
           entries.Track, entries.ImplicitScheme, entries.Band)


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
