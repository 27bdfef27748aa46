"""The spatial continuum kernels' data layout: end parameters, nodal data and the band of the Newton
matrix, for the flexible cable (:mod:`.loads3d`, :mod:`.rows3d`) and with bending stiffness
(:mod:`.bending3d`); :mod:`kanat.continuum.kernels3d` describes them.

Plain constants, apart from the compiled kernels, so that a run whose kernels were compiled ahead
of time (:mod:`kanat.aot`) reads them without numba.
"""
from __future__ import annotations

LOWER = UPPER = 8
# End parameters: kind, velocity (3, chart), mass + added mass, net buoyancy, 0.5 rho C_D S, force (3, chart),
# wave-inertia coefficient, surface buoy rho g A_w and height, wave elevation, winch pay-out speed
(B3_KIND, B3_V0, B3_V1, B3_V2, B3_MASS, B3_BUOY, B3_DRAG, B3_F0, B3_F1, B3_F2, B3_WAVE, B3_WPA, B3_HEIGHT, B3_ETA,
 B3_PAYOUT) = range(15)
NBPAR3 = 15
# Nodal data (chart coordinates): water velocity, water acceleration, position R, direction of the line on the seabed
UX3, AX3, RX3, DX3 = 0, 3, 6, 9
NENV3 = 12

# With bending stiffness (kanat.continuum.bending3d): ten unknowns per node
NV_BENDING = 10
WIDTH_BENDING = 14                  # sub- (= super-) diagonals: kernels2d.bandwidth(10)
# End parameters after NBPAR3: a clamped end and its angles in the chart.
B3_CLAMP, B3_PHI0, B3_THETA0 = NBPAR3, NBPAR3 + 1, NBPAR3 + 2
NBPAR3_BENDING = NBPAR3 + 3
