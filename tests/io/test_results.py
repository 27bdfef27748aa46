"""Result files: names, units and provenance of case-format.md, written and read back."""
import hashlib

import numpy as np
import pytest
from scipy.constants import knot

import kanat
from kanat.io import load_case, parse_case
from kanat.io.results import case_sha256, failed_dataset, read_result, statics_dataset, write_result
from kanat.statics import solve_statics

from helpers import EXAMPLES



def test_statics_result_round_trip_keeps_names_units_and_provenance(tmp_path):
    case = load_case(EXAMPLES / "towed_body.yaml")
    result = solve_statics(case)
    path = write_result(statics_dataset(result, wall_time_s=0.5), tmp_path / "r.nc")
    ds = read_result(path)
    assert set(ds.dims) == {"node", "xyz", "body", "cable", "anchor"}      # cable, anchor: mooring results
    assert ds.sizes["anchor"] == 0 and ds["seabed_contact_length"].values.tolist() == [0.0]
    expected_units = {"s": "m", "position": "m", "velocity": "m/s", "tension": "N",
                      "body_position": "m", "vessel_position": "m", "vessel_heading": "rad"}
    for name, unit in expected_units.items():
        assert ds[name].attrs["units"] == unit
    assert list(ds["xyz"].values) == ["x", "y", "z"]
    assert ds.sizes["node"] == 101 and set(ds["cable"].values) == {"tow"}
    assert ds.attrs["kanat_version"] == kanat.__version__
    assert ds.attrs["case_sha256"] == case_sha256(case)
    assert ds.attrs["status"] == "ok" and ds.attrs["model"] == "statics"
    assert ds.attrs["wall_time_s"] == 0.5
    np.testing.assert_allclose(ds["tension"].values, result.cables["tow"].tension)
    np.testing.assert_allclose(ds["body_position"].sel(body="sled").values, result.bodies["sled"])
    np.testing.assert_allclose(ds["velocity"].values[:, 0], 6 * knot, rtol=1e-12)


def test_case_hash_ignores_layout_and_comments_but_not_values():
    text = (EXAMPLES / "towed_body.yaml").read_text()
    same = parse_case("# a comment\n" + text.replace("length: 1000", "length:   1000.0"))
    other = parse_case(text.replace("length: 1000", "length: 1001"))
    base = parse_case(text)
    assert case_sha256(same) == case_sha256(base) != case_sha256(other)
    assert len(case_sha256(base)) == len(hashlib.sha256().hexdigest())


def test_sphere_result_has_sphere_variables_and_attributes(tmp_path):
    case = load_case(EXAMPLES / "sphere_two_cables.yaml")
    ds = read_result(write_result(statics_dataset(solve_statics(case)), tmp_path / "s.nc"))
    for name in ("alpha", "tau", "x", "y"):
        assert ds[name].dims == ("node",)
    assert ds.attrs["alpha0_deg"] == pytest.approx(46.9, abs=0.1)
    assert ds.attrs["tau0"] == pytest.approx(0.6066, abs=5e-4)
    assert ds.attrs["convention"] == "published"
    assert abs(ds.attrs["eps1_percent"]) < 0.01 and abs(ds.attrs["eps2_percent"]) < 0.01


def test_failed_run_writes_its_status(tmp_path):
    case = load_case(EXAMPLES / "towed_body.yaml")
    ds = read_result(write_result(failed_dataset(case, "shooting lost the solution"), tmp_path / "f.nc"))
    assert ds.attrs["status"] == "failed: shooting lost the solution"
    assert ds.attrs["case_name"] == "towed-body-6kn"


def test_write_is_atomic_no_partial_file_left(tmp_path):
    case = load_case(EXAMPLES / "towed_body.yaml")
    write_result(statics_dataset(solve_statics(case)), tmp_path / "r.nc")
    assert [p.name for p in tmp_path.iterdir()] == ["r.nc"]
