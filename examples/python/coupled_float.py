"""A floating body integrated here, moored by kanat's lines through ``kanat.Coupling``.

    python examples/python/coupled_float.py [PICTURE.png]

The host program is the few lines of ``Float`` below: a platform of the OC4 semi-submersible's
mass that moves in surge, sway and heave (no rotation), with its added mass, the hydrostatic
stiffness of its waterplane and a linear damping, and the mooring force kanat returns. Its three
chain lines (anchors 837.6 m out in 200 m of water, fairleads 40.868 m out, 14 m down) are given
as a case in memory. The platform is let go 4 m downwind of its equilibrium and drifts back and
forth: the period of its surge is compared with the one its mass and the mooring's stiffness
give, ``2 pi sqrt((m + a) / k)``, the stiffness ``k`` from kanat's equilibria 0.5 m either side.

Each coupling step the host gives kanat the fairleads' positions and velocities at ``t`` and gets
the lines' forces at ``t + dt`` (MoorDyn's convention: docs/coupling.md); it then steps its own
body with them (semi-implicit Euler).
"""
import math
import sys
from dataclasses import dataclass

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import kanat  # noqa: E402

ANGLES = np.radians([180.0, 60.0, 300.0])
FAIRLEADS = np.stack([40.868 * np.cos(ANGLES), 40.868 * np.sin(ANGLES), np.full(3, -14.0)], -1)
ANCHORS = np.stack([837.6 * np.cos(ANGLES), 837.6 * np.sin(ANGLES), np.full(3, -200.0)], -1)


def mooring_case():
    """The three chains as a case in memory (the lines' ends on the body are vessel points)."""
    cables = [{"name": f"line{k + 1}", "line_type": "chain", "length": 835.35, "segments": 20,
               "from": {"anchor": ANCHORS[k].tolist()}, "to": {"vessel": FAIRLEADS[k].tolist()}}
              for k in range(3)]
    return kanat.load_case({
        "name": "three-chain", "model": "lumped",
        "environment": {"depth": 200.0, "seabed": {"stiffness": 3e6, "damping": 3e5}},
        "line_types": {"chain": {"diameter": 0.0766, "mass": 113.35, "axial_stiffness": 7.536e8,
                                 "drag_normal": 2.0, "drag_tangential": 0.4, "added_mass": 4.72}},
        "cables": cables, "simulation": {"duration": 1.0, "dt": 0.2}})


@dataclass
class Float:
    """A rigid platform in surge, sway and heave: ``(m + a) x'' = F_mooring + F_hydrostatic - c x' + W``."""

    mass: float = 1.3473e7                        # kg, OC4 semi-submersible
    added_mass: tuple = (8.0e6, 8.0e6, 1.4e7)     # kg, surge, sway, heave
    waterplane: float = 390.0                     # m^2, heave stiffness rho g A
    damping: float = 5.0e4                        # N s/m, linear, every direction
    rho_g: float = 1025.0 * 9.81

    def acceleration(self, z, velocity, mooring, balance):
        """Acceleration (3,) at heave ``z`` with the mooring force (3,), ``balance`` the still
        buoyancy's excess over the weight (what holds the mooring's pull down at rest)."""
        force = mooring - self.damping * velocity
        force[2] += balance - self.rho_g * self.waterplane * z
        return force / (self.mass + np.asarray(self.added_mass))


def surge_stiffness(case, step=0.5):
    """The mooring's surge stiffness [N/m] from equilibria ``step`` either side of the middle."""
    pulls = []
    for dx in (-step, step):
        forces = kanat.Coupling(case).initialize(FAIRLEADS + [dx, 0.0, 0.0])
        pulls.append(forces[:, 0].sum())
    return -(pulls[1] - pulls[0]) / (2 * step)


def main(picture: str = "coupled_float.png") -> None:
    case = mooring_case()
    body = Float()
    coupling = kanat.Coupling(case)
    balance = -coupling.initialize(FAIRLEADS)[:, 2].sum()        # buoyancy - weight at z = 0
    x, v = np.array([4.0, 0.0, 0.0]), np.zeros(3)
    forces = coupling.initialize(FAIRLEADS + x)
    dt, times, surge, tension = 0.2, [0.0], [x[0]], [np.linalg.norm(forces, axis=1)]
    for k in range(1500):                                        # 300 s
        t = k * dt
        forces = coupling.step(t, dt, FAIRLEADS + x, np.broadcast_to(v, (3, 3)))
        v = v + dt * body.acceleration(x[2], v, forces.sum(axis=0), balance)
        x = x + dt * v
        times.append(t + dt)
        surge.append(x[0])
        tension.append(np.linalg.norm(forces, axis=1))
    times, surge, tension = np.array(times), np.array(surge), np.array(tension)

    up = np.flatnonzero((surge[:-1] < 0.0) & (surge[1:] >= 0.0))
    crossings = times[up] - surge[up] * dt / (surge[up + 1] - surge[up])
    period = float(np.mean(np.diff(crossings)))
    k = surge_stiffness(case)
    expected = 2 * math.pi * math.sqrt((body.mass + body.added_mass[0]) / k)
    print(f"surge period {period:.2f} s; from the mooring's stiffness {k / 1e3:.2f} kN/m: {expected:.2f} s; "
          f"surge from {surge[0]:.2f} m to {surge[-1]:.3f} m after {times[-1]:.0f} s; "
          f"fairlead tension up to {tension.max() / 1e3:.0f} kN")

    fig, (motion, pull) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    motion.plot(times, surge)
    motion.set(title="platform surge (its own integrator)", xlabel="t [s]", ylabel="surge [m]")
    for j, name in enumerate(coupling.points):
        pull.plot(times, tension[:, j] / 1e3, label=name)
    pull.set(title="fairlead tension (kanat.Coupling)", xlabel="t [s]", ylabel="tension [kN]")
    pull.legend()
    fig.savefig(picture, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:2])
