"""Small result datasets with known geometry, laid out as kanat writes them (kanat.io.schema names)."""
import numpy as np
import xarray as xr


def network_result(times=(0.0, 10.0, 20.0), turn=True, still_body_noise=0.0):
    """Three cables joined at a body, towed by a vessel that moves (and turns) in time.

    Cables: ``tow`` (vessel -> hub, 5 nodes), ``port`` and ``stbd`` (hub -> boards, 4 nodes
    each), in 3-D: the boards sit at y = +-30 m. The vessel moves along +x at 2 m/s (and turns
    the whole system by 30 deg per output when ``turn``). Body ``hub`` stays at a fixed depth
    with ``still_body_noise`` of round-off on its height.
    """
    times = np.asarray(times, dtype=float)
    base = {"tow": np.column_stack([np.linspace(0, -100, 5), np.zeros(5), np.linspace(0, -40, 5)]),
            "port": np.column_stack([np.linspace(-100, -150, 4), np.linspace(0, 30, 4), np.full(4, -40.0)]),
            "stbd": np.column_stack([np.linspace(-100, -150, 4), np.linspace(0, -30, 4), np.full(4, -40.0)])}
    names = [n for n, xyz in base.items() for _ in range(len(xyz))]
    s = np.concatenate([np.linspace(0, 100 if n == "tow" else 50, len(xyz)) for n, xyz in base.items()])
    local = np.concatenate(list(base.values()))
    position, vessel, bodies = [], [], []
    for k, t in enumerate(times):
        angle = np.radians(30.0 * k) if turn else 0.0
        rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
        origin = np.array([2.0 * t, 0.0, 0.0])
        position.append(local @ rotation.T + origin)
        vessel.append(origin)
        hub = np.array([-100.0, 0.0, -40.0]) @ rotation.T + origin
        hub[2] += still_body_noise * (-1) ** k
        bodies.append([hub, position[-1][8], position[-1][12]])
    n = len(names)
    tension = 1e4 + 100 * np.arange(len(times))[:, None] + np.linspace(0, 1, n)[None, :]
    segments = [name for name, xyz in base.items() for _ in range(len(xyz) - 1)]
    return xr.Dataset(
        {"position": (("time", "node", "xyz"), np.array(position), {"units": "m"}),
         "velocity": (("time", "node", "xyz"), np.ones((len(times), n, 3)), {"units": "m/s"}),
         "tension": (("time", "node"), tension, {"units": "N"}),
         "segment_tension": (("time", "segment"), np.full((len(times), len(segments)), 5e3), {"units": "N"}),
         "body_position": (("time", "body", "xyz"), np.array(bodies), {"units": "m"}),
         "vessel_position": (("time", "xyz"), np.array(vessel), {"units": "m"})},
        coords={"time": ("time", times, {"units": "s"}), "s": ("node", s, {"units": "m"}),
                "cable": ("node", np.array(names)), "segment_cable": ("segment", np.array(segments)),
                "xyz": ["x", "y", "z"], "body": ["hub", "board_port", "board_stbd"]},
        attrs={"case_name": "network", "model": "lumped", "scheme": "rk4", "status": "ok"})
