"""kanat.analysis against hand-computed values on synthetic result datasets.

Oracles: small series whose statistics are worked out by hand in the comments; a sine over
whole periods (mean M, std A/sqrt(2), k up-crossings, so the Rayleigh MPM is
M + A sqrt(ln k)); Parseval for the Welch spectrum (the PSD integrates to A^2/2).
"""
import math

import numpy as np
import pytest
import xarray as xr

from kanat.analysis import (body_depth_excursions, body_statistics, most_probable_maximum, node_statistics,
                            range_graph, select_nodes, snap_events, snap_summary, spectral_peak, summary_statistics,
                            tension_spectrum, time_window, upcrossings)
from kanat.errors import KanatError

HAND = np.array([3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0])
# mean 31/8 = 3.875; mean of squares 173/8 = 21.625; variance 21.625 - 3.875^2 = 6.609375;
# centred: -0.875 -2.875 0.125 -2.875 1.125 5.125 -1.875 2.125 -> 3 up-crossings
HAND_STD = math.sqrt(6.609375)


def synthetic(tension, depth=None, cables=("a", "a", "b", "b"), s=(0.0, 10.0, 0.0, 5.0), dt=1.0, events=None):
    """A dynamic result with the case-format names: tension (time, node), bodies at given depths."""
    tension = np.asarray(tension, float)
    nt, nn = tension.shape
    time = np.arange(nt) * dt
    position = np.zeros((nt, nn, 3))
    position[:, :, 0] = np.asarray(s)[None, :]
    depth = np.zeros((nt, 0)) if depth is None else np.asarray(depth, float).reshape(nt, -1)
    body_position = np.zeros((nt, depth.shape[1], 3))
    body_position[:, :, 2] = -depth
    data = {"tension": (("time", "node"), tension), "position": (("time", "node", "xyz"), position),
            "s": ("node", np.asarray(s, float)), "cable": ("node", np.array(cables, dtype=object)),
            "body_position": (("time", "body", "xyz"), body_position),
            "vessel_position": (("time", "xyz"), np.zeros((nt, 3)))}
    coords = {"time": time, "body": np.array([f"b{k}" for k in range(depth.shape[1])], dtype=object)}
    if events is not None:
        data.update({f"event_{k}": ("event", np.asarray(v)) for k, v in events.items() if k != "cables"})
        data["segment_cable"] = ("segment", np.array(events["cables"], dtype=object))
    return xr.Dataset(data, coords=coords, attrs={"model": "lumped", "wall_time_s": 1.5})


def hand_dataset():
    tension = np.column_stack([HAND, HAND * 2, np.full(8, 7.0), np.arange(8.0)])
    return synthetic(tension, depth=[100, 105, 98, 110, 101, 99, 104, 100])


def test_node_statistics_by_hand():
    stats = node_statistics(hand_dataset(), nodes=[0, "b@0", "b@end"])
    assert list(stats["node"].values) == [0, 2, 3]
    assert stats["min"].values[0] == 1.0 and stats["max"].values[0] == 9.0
    assert stats["mean"].values[0] == pytest.approx(3.875, rel=1e-15)
    assert stats["std"].values[0] == pytest.approx(HAND_STD, rel=1e-15)
    assert stats["mpm"].values[0] == pytest.approx(3.875 + HAND_STD * math.sqrt(2 * math.log(3)), rel=1e-15)
    assert stats["mpm"].values[1] == 7.0                      # constant: MPM is the mean
    assert np.isnan(stats["mpm"].values[2])                    # a ramp has no up-crossing: no narrow-band MPM
    assert stats["mean"].values[2] == 3.5 and stats["std"].values[2] == pytest.approx(math.sqrt(5.25))


def test_window_selects_inclusive_samples():
    stats = node_statistics(hand_dataset(), nodes=[0], window=(2, 5))     # 4, 1, 5, 9
    assert (stats["min"].item(), stats["max"].item(), stats["mean"].item()) == (1.0, 9.0, 4.75)
    assert stats.attrs["window"] == [2.0, 5.0]
    with pytest.raises(KanatError, match="holds no output; the run covers 0 to 7 s"):
        time_window(hand_dataset(), (20, 30))


def test_rayleigh_mpm_of_a_sine_over_whole_periods():
    mean, amp, periods, per = 5000.0, 300.0, 20, 40
    t = np.arange(periods * per) / per            # period 1 s, half a sample late: one up-crossing per period
    x = mean + amp * np.sin(2 * np.pi * t - np.pi / per)
    window = t[-1] - t[0]
    assert upcrossings(x[:, None])[0] == periods
    assert most_probable_maximum(x, window) == pytest.approx(mean + amp * math.sqrt(math.log(periods)), rel=1e-12)
    n = periods * 10800.0 / window                                  # 3 hours at the same rate
    expected = mean + amp / math.sqrt(2) * math.sqrt(2 * math.log(n))
    assert most_probable_maximum(x, window, duration=10800.0) == pytest.approx(expected, rel=1e-12)


def test_body_statistics_and_depth_excursions_by_hand():
    ds = hand_dataset()                                    # depth 100 105 98 110 101 99 104 100
    stats = body_statistics(ds)
    assert stats["max"].item() == 110 and stats["min"].item() == 98 and stats["mean"].item() == 102.125
    ex = body_depth_excursions(ds)
    assert [ex[k].item() for k in ("initial_depth", "min_depth", "max_depth", "excursion", "rise", "dive")] == \
        [100, 98, 110, 12, 2, 10]
    assert (ex["time_of_min_depth"].item(), ex["time_of_max_depth"].item()) == (2.0, 3.0)
    late = body_depth_excursions(ds, (4, None))            # 101 99 104 100
    assert [late[k].item() for k in ("initial_depth", "rise", "dive", "excursion")] == [101, 2, 3, 5]


def test_range_graph_along_each_cable():
    tension = [[1.0, 4.0, 0.0, 2.0], [3.0, 2.0, 6.0, 2.0], [2.0, 0.0, 3.0, 2.0]]
    rg = range_graph(synthetic(tension))
    np.testing.assert_array_equal(rg["min"].values, [1, 0, 0, 2])
    np.testing.assert_array_equal(rg["max"].values, [3, 4, 6, 2])
    np.testing.assert_array_equal(rg["mean"].values, [2, 2, 3, 2])
    np.testing.assert_array_equal(rg["s"].values, [0, 10, 0, 5])
    assert list(rg["cable"].values) == ["a", "a", "b", "b"]


EVENTS = {"time": [5.0, 1.0, 3.0], "segment": [2, 0, 2], "peak_tension": [900.0, 400.0, 700.0],
          "rise_rate": [1e4, 3e3, 5e3], "cables": ["a", "a", "b"]}


def test_snap_event_tables():
    ds = synthetic(np.ones((8, 4)), events=EVENTS)
    table = snap_events(ds)
    assert list(table["time"]) == [1.0, 3.0, 5.0] and list(table["cable"]) == ["a", "b", "b"]
    assert list(table["peak_tension"]) == [400.0, 700.0, 900.0]
    summary = snap_summary(ds).set_index("cable")
    assert summary.loc["b", "events"] == 2 and summary.loc["b", "peak_tension_max"] == 900.0
    assert summary.loc["a", "rise_rate_max"] == 3e3
    assert list(snap_events(ds, (2, 6))["time"]) == [3.0, 5.0]
    assert len(snap_events(synthetic(np.ones((8, 4))))) == 0   # none recorded: empty table


def test_tension_spectrum_peak_and_parseval():
    amp, f0, dt, n = 200.0, 0.125, 0.5, 4096                  # f0 on a Welch bin for 256-sample segments
    t = np.arange(n) * dt
    tension = np.column_stack([1e4 + amp * np.sin(2 * np.pi * f0 * t)] * 4)
    spectrum = tension_spectrum(synthetic(tension, dt=dt), segment_s=128.0)
    df = spectrum["frequency"].values[1]
    assert df == pytest.approx(1 / 128.0)
    assert spectral_peak(spectrum).values[0] == pytest.approx(f0)
    assert spectrum["psd"].values[:, 0].sum() * df == pytest.approx(amp**2 / 2, rel=1e-2)
    assert list(spectrum["node"].values) == [0, 2]             # first node of each cable by default


def test_spectrum_refuses_uneven_sampling():
    ds = synthetic(np.ones((20, 4))).assign_coords(time=np.r_[np.arange(10.0), 10.5 + np.arange(10.0)])
    with pytest.raises(KanatError, match="not evenly spaced"):
        tension_spectrum(ds)


def test_summary_statistics_by_hand():
    stats = summary_statistics(synthetic(np.column_stack([HAND, HAND * 2, np.full(8, 7.0), np.arange(8.0)]),
                                         depth=[100, 105, 98, 110, 101, 99, 104, 100], events=EVENTS))
    assert stats["tension_max"] == 18.0 and stats["tension_min"] == 0.0
    assert stats["top_tension_mean"] == 3.875 and stats["top_tension_max"] == 9.0
    assert stats["depth_max_b0"] == 110 and stats["depth_excursion_b0"] == 12
    assert stats["snap_events"] == 3 and stats["snap_peak_tension_max"] == 900.0
    assert stats["wall_time_s"] == 1.5


def test_node_selectors_and_their_errors():
    ds = hand_dataset()
    assert list(select_nodes(ds, ["a@0", "a@7", "b@end", -1, "1"])) == [0, 1, 3, 3, 1]
    with pytest.raises(KanatError, match="no cable 'c'; cables: a, b"):
        select_nodes(ds, "c@0")
    with pytest.raises(KanatError, match="nodes 0 to 3"):
        select_nodes(ds, [4])
