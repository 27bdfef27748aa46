"""The picture of a run shows what matters for its kind of system (kanat.report.kinds).

Oracle: the result dataset and the case embedded in it. Each test reads back what was drawn
(lines' data by ``gid``, axis titles, legend entries, line colours) and compares it with the
result: the fairlead tensions are the tensions at the cable ends on the body (the anchor ends'
tensions are not drawn), surge and heave are the body's displacement from the first output,
pitch its second attitude angle in degrees, the top tension the tension at the vessel end, and
each cable of a network is drawn in one colour of its own and named in the legend.
"""
import warnings
from pathlib import Path

import numpy as np
import pytest

from helpers_results import network_result
from kanat.report.geometry import cable_nodes
from kanat.report.kinds import choose, system_kind
from kanat.report.run_plot import plot_run

from helpers import ROOT


NETWORK_CASE = """\
name: towed-network
model: lumped
environment: {depth: 500}
line_types:
  wire: {diameter: 0.02, mass: 1.0, weight_in_water: 8.0, axial_stiffness: 1.0e7, drag_normal: 1.2,
         drag_tangential: 0.01}
bodies:
  hub: {mass: 500, net_buoyancy: -2000, drag_area: 0.5}
  board_port: {mass: 200, net_buoyancy: -500, drag_area: 0.5}
  board_stbd: {mass: 200, net_buoyancy: -500, drag_area: 0.5}
vessel:
  tow_point: [0, 0, 0]
  track:
    - {straight: {speed: 2, duration: 20}}
cables:
  - {name: tow, line_type: wire, length: 100, segments: 4, from: vessel, to: hub}
  - {name: port, line_type: wire, length: 50, segments: 3, from: hub, to: board_port}
  - {name: stbd, line_type: wire, length: 50, segments: 3, from: hub, to: board_stbd}
simulation: {duration: 20, output_dt: 10}
"""


def _lines(fig) -> dict:
    return {line.get_gid(): line for ax in fig.axes for line in ax.get_lines() if line.get_gid()}


def _axes(fig, title_start: str):
    found = [ax for ax in fig.axes if ax.get_title().startswith(title_start)]
    assert found, f"no axes titled {title_start!r}: {[ax.get_title() for ax in fig.axes]}"
    return found[0]


def _legend(ax) -> list[str]:
    return [text.get_text() for text in ax.get_legend().get_texts()]


def _short_run(path: Path, duration: float):
    import kanat

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(path)
        data = case.model_dump(mode="json", by_alias=True, exclude_unset=True)
        data["simulation"] = {**data["simulation"], "duration": duration}
        return kanat.simulate(kanat.load_case(data))


@pytest.fixture(scope="module")
def moored():
    """The surge-decay buoy, its first 4 s: the surge starts to decay."""
    return _short_run(ROOT / "examples" / "mooring_buoy_decay.yaml", 4.0)


@pytest.mark.slow
def test_moored_picture_draws_fairlead_tensions_not_the_anchor_ends(moored):
    ds = moored
    fig = plot_run(ds)
    nodes, lines = cable_nodes(ds), _lines(fig)
    ax = _axes(fig, "fairlead tensions")
    assert sorted(_legend(ax)) == [f"leg{k} at body buoy" for k in (1, 2, 3)]
    for k in (1, 2, 3):
        fairlead = nodes[f"leg{k}"][-1]                       # each leg runs from its anchor to the buoy
        drawn = lines[f"tension/leg{k} at body buoy"]
        np.testing.assert_allclose(drawn.get_ydata(), ds["tension"].values[:, fairlead] / 1e3, rtol=1e-12)
    drawn = np.concatenate([line.get_ydata()[1:] for line in ax.get_lines()])   # after the start at rest, slack
    anchors = ds["tension"].values[1:, [nodes[f"leg{k}"][0] for k in (1, 2, 3)]] / 1e3
    assert drawn.min() > 2 * anchors.max()                    # the anchor ends carry far less: not drawn


@pytest.mark.slow
def test_moored_picture_draws_surge_heave_and_pitch_of_the_body(moored):
    ds = moored
    lines = _lines(plot_run(ds))
    position = ds["body_position"].values[:, 0]
    np.testing.assert_allclose(lines["surge/buoy"].get_ydata(), position[:, 0] - position[0, 0], atol=1e-12)
    np.testing.assert_allclose(lines["heave/buoy"].get_ydata(), position[:, 2] - position[0, 2], atol=1e-12)
    np.testing.assert_allclose(lines["pitch/buoy"].get_ydata(),
                               np.degrees(ds["body_attitude"].values[:, 0, 1]), atol=1e-12)
    assert lines["surge/buoy"].get_ydata()[-1] < -0.1        # released 12 m off: pulled back towards x = 0


@pytest.mark.slow
def test_moored_geometry_gives_each_line_its_colour_and_a_legend(moored):
    ds = moored
    fig = plot_run(ds)
    lines = _lines(fig)
    for view in ("elevation", "plan"):
        colours = {}
        for gid, line in lines.items():
            parts = gid.split("/")
            if parts[0] == view and len(parts) == 3:
                colours.setdefault(parts[1], set()).add(line.get_color())
        assert sorted(colours) == ["leg1", "leg2", "leg3"]
        assert all(len(c) == 1 for c in colours.values())     # one colour per line, at every output
        assert len(set.union(*colours.values())) == 3         # and three different colours
        assert {"leg1", "leg2", "leg3"} <= set(_legend(_axes(fig, view)))


def test_network_picture_colours_and_names_every_cable():
    ds = network_result()
    ds.attrs["case_yaml"] = NETWORK_CASE
    assert system_kind(ds) == "network"
    fig = plot_run(ds)
    lines, nodes = _lines(fig), cable_nodes(ds)
    for view in ("elevation", "plan"):
        legend = _legend(_axes(fig, view))
        for k, name in enumerate(nodes):
            assert name in legend
            drawn = [line for gid, line in lines.items() if gid.startswith(f"{view}/{name}/")]
            assert len(drawn) == ds.sizes["time"]
            assert {line.get_color() for line in drawn} == {f"C{k}"}
    # the top tension: at the vessel end of the tow (its first node), not at the bridles
    top = lines["tension/tow at vessel"]
    np.testing.assert_allclose(top.get_ydata(), ds["tension"].values[:, nodes["tow"][0]] / 1e3)
    assert [gid for gid in lines if gid.startswith("tension/")] == ["tension/tow at vessel"]
    # the bodies' depth, positive down
    np.testing.assert_allclose(lines["depth/hub"].get_ydata(), -ds["body_position"].values[:, 0, 2])


def test_single_cable_without_a_case_is_coloured_by_time():
    ds = network_result().isel(node=slice(0, 5), body=[0])        # the tow alone
    assert choose(ds).kind == "towed" and not choose(ds).by_cable
    fig = plot_run(ds)
    colours = {line.get_color() for gid, line in _lines(fig).items() if gid.startswith("elevation/tow/")}
    assert len({tuple(np.atleast_1d(c)) for c in colours}) == ds.sizes["time"]
    assert _legend(_axes(fig, "elevation"))[:3] == ["t = 0 s", "t = 10 s", "t = 20 s"]


@pytest.mark.slow
def test_towed_picture_draws_top_tension_depth_and_shape():
    ds = _short_run(ROOT / "examples" / "speed_step_2d.yaml", 20.0)
    fig = plot_run(ds)
    lines, nodes = _lines(fig), cable_nodes(ds)
    assert choose(ds).kind == "towed"
    (label,) = [gid for gid in lines if gid.startswith("tension/")]
    assert label.endswith("at vessel")
    cable = label.split("/")[1].split(" at ")[0]
    np.testing.assert_allclose(lines[label].get_ydata(), ds["tension"].values[:, nodes[cable][0]] / 1e3)
    if ds.sizes.get("body", 0):
        body = str(ds["body"].values[0])
        np.testing.assert_allclose(lines[f"depth/{body}"].get_ydata(), -ds["body_position"].values[:, 0, 2])
        assert _axes(fig, "body depth").yaxis_inverted()      # depth drawn down
    last = ds.sizes["time"] - 1
    shape = lines[f"elevation/{cable}/{last}"]
    np.testing.assert_allclose(shape.get_ydata(), ds["position"].values[last, nodes[cable], 2])


def _array(value) -> np.ndarray:
    """A plotly JSON array: a list, or base64 typed data (``{"dtype": ..., "bdata": ...}``)."""
    if isinstance(value, dict):
        import base64

        return np.frombuffer(base64.b64decode(value["bdata"]), dtype=np.dtype(value["dtype"]))
    return np.asarray(value, dtype=float)


def test_report_shows_what_the_picture_shows():
    from kanat.report.html_result import dynamic_page

    ds = network_result()
    ds.attrs["case_yaml"] = NETWORK_CASE
    figure = dynamic_page(ds, "network.nc").figures["plot-body-history"]
    titles = [note["text"] for note in figure["layout"]["annotations"]]
    assert titles[:2] == ["top tension (at the vessel) [kN]", "body depth [m]"]
    traces = {trace["name"]: trace for trace in figure["data"]}
    np.testing.assert_allclose(_array(traces["tow at vessel"]["y"]), ds["tension"].values[:, 0] / 1e3)
    for k, body in enumerate(ds["body"].values):
        np.testing.assert_allclose(_array(traces[f"{body} depth"]["y"]), -ds["body_position"].values[:, k, 2])
    np.testing.assert_allclose(_array(traces["vessel speed"]["y"]), 2.0)       # the helper's vessel: 2 m/s
