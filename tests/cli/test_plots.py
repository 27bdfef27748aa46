"""The pictures draw what the result holds: each cable its own line, true projections, honest axes.

Oracle: the result dataset itself. Every line of geometry carries a ``gid``; its data must
equal the result's positions projected on the view's two axes (minus the tow point's
horizontal position when the tow point moves), node for node -- a projection such as
``hypot(x, y) * sign(x)`` or a polyline joining two cables cannot pass. Axis limits are
checked against the least spans of :mod:`kanat.report.geometry`.
"""
import warnings

import numpy as np
import pytest

from helpers_results import network_result
from kanat.report.geometry import MIN_HEIGHT_SPAN, cable_nodes
from kanat.report.overview import plot_overview
from kanat.report.run_plot import VIEWS, plot_run
from kanat.report.statics_plot import plot_statics

from helpers import ROOT

EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))
MOORDYN = sorted((ROOT / "examples" / "moordyn").glob("*.dat"))      # drawn at their steady state


def _lines(fig) -> dict:
    return {line.get_gid(): line for ax in fig.axes for line in ax.get_lines() if line.get_gid()}


def _axes(fig, title_start: str):
    found = [ax for ax in fig.axes if ax.get_title().startswith(title_start)]
    return found[0] if found else None


def check_run_picture(ds, fig) -> int:
    """Every snapshot line against the result; returns how many lines were checked."""
    lines, nodes = _lines(fig), cable_nodes(ds)
    vessel = ds["vessel_position"].values
    moving = np.ptp(vessel[:, :2], axis=0).max() > 1e-6 * max(np.ptp(ds["position"].values), 1.0)
    planar = _axes(fig, "plan") is None
    checked = 0
    for gid, line in lines.items():
        view, _, rest = gid.partition("/")
        if view not in VIEWS or "/" not in rest:
            continue
        cable, index = rest.rsplit("/", 1)
        i = int(index)
        xyz = ds["position"].values[i, nodes[cable]].copy()
        if moving:
            xyz[:, :2] -= vessel[i, :2]
        a, b = VIEWS[view]
        np.testing.assert_allclose(line.get_xdata(), xyz[:, a], atol=1e-9, err_msg=gid)
        np.testing.assert_allclose(line.get_ydata(), xyz[:, b], atol=1e-9, err_msg=gid)
        checked += 1
    snapshots = {gid.rsplit("/", 1)[1] for gid in lines if gid.startswith("elevation/")}
    assert checked == len(snapshots) * len(nodes) * (1 if planar else 2)
    for ax in fig.axes:
        if ax.get_title().startswith(("elevation", "plan")):
            assert ax.get_aspect() == 1.0
    return checked


def test_network_in_a_turn_draws_each_cable_in_true_projection():
    ds = network_result()
    fig = plot_run(ds)
    assert check_run_picture(ds, fig) == 3 * 3 * 2
    lines = _lines(fig)
    # the turned port cable: a hypot(x, y) * sign(x) projection would be metres off
    xyz = ds["position"].values[1, cable_nodes(ds)["port"]] - [*ds["vessel_position"].values[1, :2], 0]
    wrong = np.hypot(xyz[:, 0], xyz[:, 1]) * np.sign(xyz[:, 0])
    assert np.abs(lines["elevation/port/1"].get_xdata() - wrong).max() > 10
    assert len(lines["elevation/port/2"].get_xdata()) == 4               # its own 4 nodes only
    body = lines["elevation-body/hub/2"]
    hub = ds["body_position"].values[2, 0] - [*ds["vessel_position"].values[2, :2], 0]
    assert (body.get_xdata()[0], body.get_ydata()[0]) == pytest.approx((hub[0], hub[2]))


def test_still_body_is_flat_not_blown_up_to_fill_the_axis():
    ds = network_result(turn=False, still_body_noise=1e-9)
    fig = plot_run(ds)
    depth = _axes(fig, "body depth")                             # drawn down: its y axis inverted
    low, high = sorted(depth.get_ylim())
    assert high - low >= MIN_HEIGHT_SPAN
    tension = _axes(fig, "tension")
    low, high = tension.get_ylim()
    largest = ds["tension"].values[:, [0, 5, 9]].max() / 1e3
    assert high - low >= 0.05 * largest * (1 - 1e-9)                   # kN: 5 % of the largest value


def test_planar_run_has_no_plan_view():
    ds = network_result(turn=False)
    ds["position"].values[..., 1] = 0.0
    ds["body_position"].values[..., 1] = 0.0
    fig = plot_run(ds)
    assert _axes(fig, "plan") is None
    assert check_run_picture(ds, fig) == 3 * 3


def test_statics_picture_from_a_dataset_and_from_the_solver_agree():
    import kanat
    from kanat.statics import solve_statics as solve

    case = kanat.load_case(ROOT / "examples" / "towed_body.yaml")
    result = solve(case)
    ds = kanat.solve_statics(case)
    from_result, from_ds = _lines(plot_statics(result)), _lines(plot_statics(ds))
    line = from_ds["elevation/tow"]
    np.testing.assert_allclose(line.get_xdata(), ds["position"].values[:, 0])
    np.testing.assert_allclose(line.get_ydata(), ds["position"].values[:, 2])
    np.testing.assert_allclose(from_result["elevation/tow"].get_xydata(), line.get_xydata())
    np.testing.assert_allclose(from_ds["tension/tow"].get_ydata(), ds["tension"].values / 1e3)


@pytest.mark.parametrize("speed, title", [("speed_kn: 6", "tow speed 6 kn"), ("speed: 3.0", "tow speed 3 m/s")])
def test_statics_picture_gives_the_tow_speed_in_the_unit_of_its_case(speed, title):
    import kanat

    text = (ROOT / "examples" / "towed_body.yaml").read_text()
    assert "speed_kn: 6" in text
    ds = kanat.solve_statics(kanat.load_case(text.replace("speed_kn: 6", speed)))
    elevation = _axes(plot_statics(ds), "elevation")
    assert elevation.get_title().endswith(title)


def test_sphere_result_is_drawn_from_its_dataset():
    import kanat

    ds = kanat.solve_statics(kanat.load_case(ROOT / "examples" / "sphere_two_cables.yaml"))
    fig = plot_statics(ds)
    cable = fig.axes[0].get_lines()[0]
    np.testing.assert_allclose(cable.get_xdata(), ds["x"].values)
    np.testing.assert_allclose(cable.get_ydata(), ds["y"].values)


def test_overview_draws_the_state_in_3d():
    ds = network_result()
    fig = plot_overview(ds)
    lines = _lines(fig)
    for cable, index in cable_nodes(ds).items():
        x, y, z = lines[f"cable/{cable}"].get_data_3d()
        np.testing.assert_allclose(np.column_stack([x, y, z]), ds["position"].values[-1, index])


def test_short_turn_run_picture_matches_its_result(tmp_path):
    import kanat

    case = kanat.load_case(ROOT / "examples" / "turn_360_3d.yaml")
    data = case.model_dump(mode="json", by_alias=True, exclude_unset=True)
    data["simulation"] = {**data["simulation"], "duration": 150.0}
    ds = kanat.simulate(kanat.load_case(data))
    fig = plot_run(ds, tmp_path / "turn.png")
    assert _axes(fig, "plan") is not None                          # the turn leaves the x-z plane
    assert check_run_picture(ds, fig) == 12
    assert (tmp_path / "turn.png").stat().st_size > 20_000


@pytest.mark.slow
@pytest.mark.parametrize("path", EXAMPLES + MOORDYN, ids=lambda p: p.name)
def test_every_example_picture_matches_its_result(path, tmp_path):
    import kanat

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(path)
        if case.model == "pitch":
            pytest.skip("the pitch model has no cables; its figures are kanat.report.pitch_plot's")
        ds = kanat.solve_statics(case) if path.suffix == ".dat" else kanat.simulate(case)
    fig = plot_run(ds, tmp_path / "picture.png")
    if "time" in ds.dims:
        check_run_picture(ds, fig)
    elif "position" in ds and "alpha" not in ds:
        for cable, index in cable_nodes(ds).items():
            line = _lines(fig)[f"elevation/{cable}"]
            np.testing.assert_allclose(line.get_xdata(), ds["position"].values[index, 0])
            np.testing.assert_allclose(line.get_ydata(), ds["position"].values[index, 2])
