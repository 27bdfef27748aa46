"""The water's acceleration on a submerged point body of the lumped model (system eq. 2):
Morison's inertia ``(rho V + m_a) a_w``, its Froude–Krylov part ``rho V a_w`` included.

Oracle: a buoyant sphere-like body held down by a light vertical tether of length ``L`` is an
inverted pendulum of horizontal stiffness ``k = B_net / L``; in a regular deep-water wave the
surge obeys ``(m + m_a) x'' + k x = (rho V + m_a) a_w(t)``, ``a_w = omega^2 a e^{k_w z} sin(omega t)``
at the body's depth ``z``: the forced amplitude is ``(rho V + m_a) A / (k - (m + m_a) omega^2)``.
Without the Froude–Krylov part it would be half of that here (``m_a = rho V``).
"""
import math

import numpy as np
import pytest
from scipy.optimize import curve_fit

from helpers import run
from kanat.io.results import read_result
from kanat.model import Case

G, RHO = 9.81, 1025.0
VOLUME, MASS, TETHER, DEPTH_BODY = 1.0, 525.0, 30.0, 20.0
HEIGHT, PERIOD = 2.0, 8.0


def tethered_body_case(duration):
    line = dict(diameter=0.01, mass=0.1, axial_stiffness=1e8, drag_normal=0.0, drag_tangential=0.0,
                added_mass=0.0)
    body = dict(mass=MASS, net_buoyancy=(RHO * VOLUME - MASS) * G, added_mass=RHO * VOLUME, drag_area=0.0,
                position=[0.0, 0.0, -DEPTH_BODY])
    return Case.model_validate(dict(
        model="lumped", name="tethered body",
        environment={"depth": 60.0, "water_density": RHO, "gravity": G,
                     "waves": {"type": "regular", "height": HEIGHT, "period": PERIOD, "heading_deg": 0.0}},
        line_types={"wire": line}, bodies={"float": body},
        cables=[dict(name="tether", line_type="wire", length=TETHER, segments=6,
                     **{"from": f"anchor:[0, 0, {-DEPTH_BODY - TETHER}]"}, to="float")],
        simulation={"duration": duration, "output_dt": 0.1}))


@pytest.mark.slow
def test_a_tethered_body_surges_with_morisons_inertia_in_a_regular_wave(tmp_path):
    duration = 20 * PERIOD
    run(tethered_body_case(duration), tmp_path / "r.nc")
    ds = read_result(tmp_path / "r.nc")
    assert ds.attrs["status"] == "ok"
    t = ds["time"].values
    x = ds["body_position"].values[:, 0, 0]
    omega = 2 * math.pi / PERIOD
    wavenumber = omega**2 / G                                       # deep water: k h = 3.8 at 60 m
    z = ds["body_position"].values[0, 0, 2]
    accel = omega**2 * HEIGHT / 2 * math.exp(wavenumber * z)
    stiffness = (RHO * VOLUME - MASS) * G / TETHER                 # the tether's weight: 0.06 % of it
    inertia = MASS + RHO * VOLUME
    expected = 2 * RHO * VOLUME * accel / (stiffness - inertia * omega**2)

    def response(t, c, s, cn, sn, wn, x0):      # forced wave-frequency part + free pendulum swing
        return c * np.cos(omega * t) + s * np.sin(omega * t) + cn * np.cos(wn * t) + sn * np.sin(wn * t) + x0

    keep = t > 4 * PERIOD
    guess = [0.0, expected, 0.0, 0.0, math.sqrt(stiffness / inertia), 0.0]
    (c, s, *_), _ = curve_fit(response, t[keep], x[keep], p0=guess)
    assert math.hypot(c, s) == pytest.approx(abs(expected), rel=0.02)     # 1.0 % measured
