"""Exports for other tools read back to the result they came from.

Oracles: meshio's own reader (the VTK files hold the result's positions and tensions, node
for node, with line cells joining only nodes of one cable); the XML of the .pvd collection
(every output time, every file present); pandas' CSV reader (the tidy tables hold every
value with its coordinates); the case embedded in the result loads back to the same case
(same SHA-256).
"""
import xml.etree.ElementTree as ET

import numpy as np
import pandas as pd
import pytest
import typer
from typer.testing import CliRunner

from helpers_results import network_result
from kanat.cli_docs import register
from kanat.io.export import cable_cells, export_csv, export_vtk
from kanat.io.results import write_result

from helpers import EXAMPLES

meshio = pytest.importorskip("meshio", reason="the vtk extra (in the test extra) provides meshio")


def _collection(pvd):
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), int(d.get("part")), d.get("file")) for d in root.iter("DataSet")]


def test_vtk_time_series_reads_back_to_the_result(tmp_path):
    ds = network_result()
    pvd = export_vtk(ds, tmp_path / "vtk")
    entries = _collection(pvd)
    assert [t for t, part, _ in entries if part == 0] == list(ds["time"].values)
    names = list(dict.fromkeys(ds["cable"].values.tolist()))
    for i, (time, part, name) in enumerate(e for e in entries if e[1] == 0):
        mesh = meshio.read(pvd.parent / name)
        np.testing.assert_allclose(mesh.points, ds["position"].values[i])
        np.testing.assert_allclose(mesh.point_data["tension"], ds["tension"].values[i])
        np.testing.assert_allclose(mesh.point_data["s"], ds["s"].values)
        lines = mesh.cells_dict["line"]
        assert len(lines) == ds.sizes["node"] - len(names)             # no cell joins two cables
        cable = ds["cable"].values
        assert all(cable[a] == cable[b] and b == a + 1 for a, b in lines)
        np.testing.assert_allclose(mesh.cell_data["segment_tension"][0], ds["segment_tension"].values[i])
        assert [names[k] for k in mesh.cell_data["cable"][0]] == list(ds["segment_cable"].values)
    for i, (time, part, name) in enumerate(e for e in entries if e[1] == 1):
        bodies = meshio.read(pvd.parent / name)
        np.testing.assert_allclose(bodies.points, ds["body_position"].values[i])


def test_statics_result_is_one_frame(tmp_path):
    import kanat

    ds = kanat.solve_statics(kanat.load_case(EXAMPLES / "towed_body.yaml"))
    pvd = export_vtk(ds, tmp_path / "vtk")
    (entry, body), = [_collection(pvd)[0:2]]
    mesh = meshio.read(pvd.parent / entry[2])
    np.testing.assert_allclose(mesh.points, ds["position"].values)
    np.testing.assert_allclose(meshio.read(pvd.parent / body[2]).points, ds["body_position"].values)


def test_cable_cells_join_consecutive_nodes_of_one_cable():
    names, cells, owner = cable_cells(["a", "a", "a", "b", "b", "c", "c", "c"])
    assert names == ["a", "b", "c"]
    assert cells.tolist() == [[0, 1], [1, 2], [3, 4], [5, 6], [6, 7]]
    assert owner.tolist() == [0, 0, 1, 2, 2]


def test_tidy_csv_holds_every_value_with_its_coordinates(tmp_path):
    ds = network_result()
    files = export_csv(ds, tmp_path / "csv")
    assert {f.name for f in files} >= {"position.csv", "tension.csv", "body_position.csv", "attributes.csv"}
    tension = pd.read_csv(tmp_path / "csv" / "tension.csv")
    assert list(tension.columns) == ["time [s]", "node", "s [m]", "cable", "tension [N]"]
    table = tension.pivot(index="time [s]", columns="node", values="tension [N]")
    np.testing.assert_allclose(table.values, ds["tension"].values)
    position = pd.read_csv(tmp_path / "csv" / "position.csv")
    z = position[position["xyz"] == "z"].pivot(index="time [s]", columns="node", values="position [m]")
    np.testing.assert_allclose(z.values, ds["position"].values[..., 2])
    assert (position.groupby("node")["cable"].first().values == ds["cable"].values).all()
    attributes = pd.read_csv(tmp_path / "csv" / "attributes.csv")
    assert dict(zip(attributes["name"], attributes["value"]))["status"] == "ok"


def test_embedded_case_is_written_and_loads_back(tmp_path):
    import kanat
    from kanat.io.results import case_sha256

    case = kanat.load_case(EXAMPLES / "towed_body.yaml")
    export_csv(kanat.solve_statics(case), tmp_path)
    assert case_sha256(kanat.load_case(tmp_path / "case.yaml")) == case_sha256(case)


def test_export_command(tmp_path):
    app = typer.Typer()
    register(app)
    result_file = write_result(network_result(), tmp_path / "run.nc")
    runner = CliRunner()
    done = runner.invoke(app, ["export", str(result_file), "--vtk", str(tmp_path / "vtk"), "--csv", str(tmp_path / "csv")])
    assert done.exit_code == 0, done.output
    assert (tmp_path / "vtk" / "network.pvd").exists() and (tmp_path / "csv" / "tension.csv").exists()
    nothing = runner.invoke(app, ["export", str(result_file)])
    assert nothing.exit_code == 1 and "--vtk" in nothing.output
    missing = runner.invoke(app, ["export", str(tmp_path / "none.nc"), "--csv", str(tmp_path / "c")])
    assert missing.exit_code == 1 and "no such" in missing.output
