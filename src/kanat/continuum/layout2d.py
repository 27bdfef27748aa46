"""The planar continuum kernels' data layout: the parameter row of an interval, the nodal data,
the end conditions and the band of the Newton matrix (:mod:`kanat.continuum.kernels2d` describes them).

Plain constants, apart from the compiled kernels of :mod:`.loads2d` and :mod:`.rows2d`, so that
a run whose kernels were compiled ahead of time (:mod:`kanat.aot`) reads them without numba.
"""
from __future__ import annotations

from kanat.physics.seabed import SLIP_VELOCITY

# Parameter row of an interval (see :func:`kanat.continuum.model2d.parameters`).
M, MA, W0, EA, DIAM, CN, CT, RHO, DS, AM, AK, GAMMA, DT, INERTIA = range(14)
GRAV, EI, CONV, PRED, KIND, SECTION = range(14, 20)
# seabed: on/off, k_b [Pa/m], c_b [Pa s/m], friction along and across, plane n_b . r = c0 (normal n_b)
SB_ON, SB_K, SB_C, SB_MUA, SB_MUL, SB_C0, SB_N0, SB_N1, SB_N2 = range(20, 29)
# an inline body (interval of kind JUNCTION): mass + added mass, net buoyancy, 0.5 rho C_D S,
# constant force (3 components), wave-inertia coefficient M_a + rho Vol
JB_MASS, JB_BUOY, JB_DRAG, JB_F0, JB_F1, JB_F2, JB_WAVE = range(29, 36)
# the tension floor T_f [N] of the normal momentum row (0: none; :func:`loads2d.transverse_tension`)
TFLOOR = 36
# a spherical inline float (kanat.physics.immersion): its diameter (0: a constant net buoyancy), its
# buoyancy fully submerged B_f [N] and the wave elevation over it [m] (filled per step)
JB_DIAMETER, JB_FULL, JB_ETA = 37, 38, 39
NPAR = 40
# The elastic law follows the scalars: p[LAW] = n knots, then n tensions (ascending), then n strains.
LAW = NPAR
CABLE, JUNCTION = 0, 1
# Nodal data (one row per node): water velocity (current + waves), water acceleration, position R.
UX, UZ, AX, AZ, RX, RZ = range(6)
NENV = 6
# End conditions: kind and parameters.
VELOCITY, BODY, FREE = 0, 1, 2
(B_KIND, B_V0, B_V1, B_MASS, B_BUOY, B_DRAG, B_F0, B_F1, B_WAVE, B_WPA, B_HEIGHT, B_ETA, B_PAYOUT, B_CLAMP,
 B_PHI0) = range(15)
NBPAR = 15
FRICTION_SPEED = SLIP_VELOCITY   # m/s: v_s of Coulomb friction mu N tanh(v / v_s), as the lumped model's
CONTACT_RAMP = 1.0e-3            # m: the contact damping ramps in over this penetration (the lumped model's
                                 # 0.2 mm ramp makes the box scheme's Newton iteration fail at a touchdown
                                 # in examples/surface_mooring_waves.yaml; 1 mm runs it)
STEP = 1e-30           # complex-step size: derivative = imag(R(x + i h)) / h, exact to round-off
LOWER = UPPER = 5      # bandwidths of the Jacobian of a flexible cable (8 with bending)


def bandwidth(nv: int) -> int:
    """Sub- (= super-) diagonals of the Jacobian for ``nv`` unknowns per node (4: 5, 6: 8)."""
    return nv // 2 + nv - 1
