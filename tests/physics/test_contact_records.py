"""The seabed contact's kernel inputs, the records ``Bed`` and ``ContactLaw`` of kanat.physics.contact:

* ``bed_of`` gives the plane seabed's penetration and normal (oracle: :meth:`PlaneSeabed.penetration`,
  and the normal ``(-sin, 0, cos)`` of the slope);
* ``contact_law`` carries the case's ``environment.seabed`` values, switches the friction off
  (both coefficients 0) and selects the equilibrium's friction, which ``contact_forces`` reads by
  name: a node displaced ``u`` along the direction it lay in feels ``-mu_a N tanh(u / u_s)``
  (eq. (1)'s ``N = k_b delta A`` at rest; oracle written out here);
* a seabed the kernels do not know is refused.

The kernels run as plain Python (:meth:`kanat.aot.Lookup.python_only`): nothing is compiled.
"""
import math

import numpy as np
import pytest

from kanat import aot
from kanat.lumped.entries import Laid
from kanat.model.environment import Seabed
from kanat.physics import contact
from kanat.physics.seabed import PlaneSeabed


@pytest.mark.parametrize("slope_deg", [0.0, 12.0, -20.0])
def test_the_bed_gives_the_plane_seabeds_penetration_and_normal(slope_deg):
    seabed = PlaneSeabed(depth=80.0, slope_deg=slope_deg)
    bed = contact.bed_of(seabed)
    assert aot.matches(bed, contact.Bed)
    points = np.array([[0.0, 0.0, -80.5], [30.0, 4.0, -70.0], [-25.0, -3.0, -75.0]])
    angle = math.radians(slope_deg)
    with aot.LOOKUP.python_only():
        for point, want in zip(points, seabed.penetration(points)):
            delta, nx, nz = contact.penetration_at(*point, bed)
            assert delta == pytest.approx(want, rel=1e-14, abs=1e-12)
            assert (nx, nz) == pytest.approx((-math.sin(angle), math.cos(angle)), rel=1e-15)


def test_the_contact_law_carries_the_seabed_block():
    block = Seabed(stiffness=2.0e6, damping=1.0e5, friction=0.3, lateral_friction=0.5)
    law = contact.contact_law(block)
    assert aot.matches(law, contact.ContactLaw)
    assert (law.stiffness, law.damping, law.friction_axial, law.friction_lateral) == (2.0e6, 1.0e5, 0.3, 0.5)
    assert (law.slip_velocity, law.slip_displacement) == (contact.SLIP_VELOCITY, contact.SLIP_DISPLACEMENT)
    assert law.equilibrium is False
    still = contact.contact_law(block, equilibrium=True, friction=False)
    assert (still.friction_axial, still.friction_lateral, still.equilibrium) == (0.0, 0.0, True)
    assert still.stiffness == 2.0e6


def test_the_equilibrium_friction_is_read_from_the_law_by_name():
    """One node on a flat seabed, 0.01 m in, displaced 5e-5 m past where it lay along +x."""
    block = Seabed(stiffness=3.0e6, damping=3.0e5, friction=0.4)
    bed, law = contact.bed_of(PlaneSeabed(depth=100.0)), contact.contact_law(block, equilibrium=True)
    x = np.array([[-5.0, 0.0, -100.01], [0.0, 0.0, -100.01], [5.0, 0.0, -100.01]])
    el_i, el_j = np.array([0, 1]), np.array([1, 2])
    area = np.array([0.0, 0.5, 0.0])
    direction = np.zeros((3, 3))
    direction[1] = [1.0, 0.0, 0.0]
    u = 5.0e-5
    laid = Laid(origin=np.zeros((3, 3)), direction=direction, distance=np.array([0.0, -u, 0.0]))
    F, N = np.zeros((3, 3)), np.zeros(3)
    with aot.LOOKUP.python_only():
        contact.contact_forces(x, np.zeros((3, 3)), el_i, el_j, area, bed, law, laid, np.zeros((3, 3)), F, N)
    normal = 3.0e6 * 0.01 * 0.5                                  # k_b delta A, at rest
    assert N[1] == pytest.approx(normal, rel=1e-9)
    assert F[1] == pytest.approx([-0.4 * normal * math.tanh(u / contact.SLIP_DISPLACEMENT), 0.0, normal], rel=1e-9)
    assert N[0] == N[2] == 0.0 and not F[0].any() and not F[2].any()


def test_a_seabed_the_kernels_do_not_know_is_refused():
    with pytest.raises(TypeError, match="no contact kernel for the seabed"):
        contact.bed_of(object())
