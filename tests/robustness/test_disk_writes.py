"""Exports, reports and studies on a disk that cannot hold them: refused before anything is
written, or, when the disk fills up during the write, one sentence and no partial file.

The same techniques as tests/robustness/test_disk_full.py: the free space the writers see is patched
(:func:`kanat.io.space._free_bytes`), and a small tmpfs (mounted by the test; skipped where
mounting is not permitted) fills up for real while its free space is reported as plenty.
Oracles: the sizes of the files written on a roomy disk (the estimates must cover them), the
file system after a refusal or a failed write (nothing left, no temporary), and a study stopped
by a full disk then continued, against the same study run at once (bit for bit).
"""
import json
import subprocess

import numpy as np
import pytest

from helpers import short_case
from helpers_results import network_result
from kanat.errors import OutputWriteError
from kanat.io import space
from kanat.io.export import csv_bytes, export_csv, export_vtk, vtk_bytes
from kanat.io.results import read_result, write_result

pytest.importorskip("meshio", reason="the vtk extra (in the test extra) provides meshio")


def files_in(folder):
    return sorted(p.name for p in folder.rglob("*") if p.is_file())


def total_size(folder):
    return sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())


@pytest.fixture
def tiny_disk(tmp_path, monkeypatch):
    """A 256 kiB tmpfs at ``tmp_path/disk`` whose free space the writers are told is plenty."""
    disk = tmp_path / "disk"
    disk.mkdir()
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(disk)],
                             capture_output=True, text=True)
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.strip()}")
    monkeypatch.setattr(space, "_free_bytes", lambda path: float("inf"))
    try:
        yield disk
    finally:
        subprocess.run(["umount", "-l", str(disk)], capture_output=True)


@pytest.mark.parametrize("export, estimate", [(export_vtk, vtk_bytes), (export_csv, csv_bytes)])
def test_an_exports_estimate_covers_what_it_writes(tmp_path, export, estimate):
    ds = network_result()
    export(ds, tmp_path / "out")
    written = total_size(tmp_path / "out")
    assert written <= estimate(ds) <= 6 * written + 64 * 1024, (written, estimate(ds))


@pytest.mark.parametrize("export, estimate, what", [(export_vtk, vtk_bytes, "the VTK export"),
                                                    (export_csv, csv_bytes, "the CSV export")])
def test_an_export_the_disk_cannot_hold_is_refused_before_writing(tmp_path, monkeypatch, export, estimate, what):
    ds = network_result()
    monkeypatch.setattr(space, "_free_bytes", lambda path: estimate(ds) / 2)
    with pytest.raises(OutputWriteError) as refused:
        export(ds, tmp_path / "out")
    message = str(refused.value)
    assert message.startswith(f"{what} of ") and "nothing was written" in message and "\n" not in message
    needed = float(message.split("needs about ")[1].split(" MiB")[0])
    assert needed == pytest.approx((estimate(ds) + space.SPACE_MARGIN) / 1024**2, abs=0.06)
    assert files_in(tmp_path / "out") == []


@pytest.mark.slow
@pytest.mark.parametrize("export, what", [(export_vtk, "the VTK export"), (export_csv, "the CSV export")])
def test_an_export_on_a_disk_that_fills_up_leaves_nothing_behind(tiny_disk, export, what):
    ds = network_result()
    big = ds.isel(time=np.arange(ds.sizes["time"]).repeat(40))       # ~40 times the tmpfs, as outputs
    big = big.assign_coords(time=np.arange(big.sizes["time"], dtype=float))
    with pytest.raises(OutputWriteError) as stopped:
        export(big, tiny_disk / "out")
    message = str(stopped.value)
    assert message.startswith(f"{what} to {tiny_disk / 'out'}") and "which were removed" in message
    assert "filled up while it was written" in message and "\n" not in message
    assert files_in(tiny_disk) == []


@pytest.mark.slow
def test_a_report_the_disk_cannot_hold_is_refused_and_leaves_no_file(tmp_path, monkeypatch):
    from kanat.report.html_report import write_report

    result = tmp_path / "result.nc"
    write_result(network_result(), result)
    monkeypatch.setattr(space, "_free_bytes", lambda path: 1024.0 ** 2)
    with pytest.raises(OutputWriteError, match=r"report.html needs about [0-9.]+ MiB but the disk holding .* has "
                                               r"1.0 MiB free: nothing was written; free some space"):
        write_report(result, tmp_path / "report.html")
    assert files_in(tmp_path) == ["result.nc"]


@pytest.mark.slow
def test_a_report_on_a_disk_that_fills_up_leaves_no_file(tmp_path, tiny_disk):
    from kanat.report.html_report import write_report

    result = tmp_path / "result.nc"
    write_result(network_result(), result)
    with pytest.raises(OutputWriteError, match=r"report.html was not written: the disk holding .* filled up "
                                               r"while it was written .*; the partial file was removed"):
        write_report(result, tiny_disk / "report.html")
    assert files_in(tiny_disk) == []


# --- studies ------------------------------------------------------------------------------

VARY = {"cables[0].length": [900, 1000, 1100]}


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    path = tmp_path_factory.mktemp("base") / "short.yaml"
    path.write_text(short_case(duration=20, segments=10))
    return path


@pytest.fixture(scope="module")
def whole(base, tmp_path_factory):
    from kanat.sweep import sweep

    out = tmp_path_factory.mktemp("whole")
    sweep(base, VARY, out, scheduler="serial")
    return out


@pytest.mark.slow
def test_a_studys_estimate_covers_its_results(base, whole):
    from kanat.io.stream import CHUNK_OUTPUTS
    from kanat.model.run_checks import RESULT_CHUNK_OUTPUTS
    from kanat.sweep import plan_study

    assert RESULT_CHUNK_OUTPUTS == CHUNK_OUTPUTS
    plan = plan_study(base, VARY)
    for spec in plan.cases:
        written = (whole / "results" / f"{spec.name}.nc").stat().st_size
        assert written <= spec.result_bytes <= 3 * written, (written, spec.result_bytes)


def test_a_study_the_disk_cannot_hold_is_refused_before_its_first_case(base, tmp_path, monkeypatch):
    from kanat.sweep import plan_study, sweep

    needed = sum(c.result_bytes for c in plan_study(base, VARY).cases)
    monkeypatch.setattr(space, "_free_bytes", lambda path: needed / 2)
    with pytest.raises(OutputWriteError) as refused:
        sweep(base, VARY, tmp_path, scheduler="serial")
    message = str(refused.value)
    assert message.startswith("the study's 3 cases left to run (their results and records) needs about ")
    assert "nothing was written" in message and "store less often (output_dt)" in message
    assert not list((tmp_path / "results").glob("*")) and not list((tmp_path / "records").glob("*"))


@pytest.mark.slow
def test_a_study_whose_disk_fills_up_stops_and_continues_bit_for_bit(base, whole, tmp_path, monkeypatch):
    from kanat.sweep import sweep

    real = space._free_bytes
    room = _calls_for_one_case(base, tmp_path / "probe", monkeypatch, real)
    calls = {"n": 0}

    def running_out(path):                     # the study's check, the first case and its record, then none
        calls["n"] += 1
        return real(path) if calls["n"] <= room else 0.0
    monkeypatch.setattr(space, "_free_bytes", running_out)
    out = tmp_path / "study"
    with pytest.raises(OutputWriteError) as stopped:
        sweep(base, VARY, out, scheduler="serial")
    message = str(stopped.value)
    assert message.startswith(f"the study in {out} stopped at case case001_") and "(1 of 3 cases finished and kept)" in message
    assert message.endswith("run the same study again, it continues with the cases not finished") and "\n" not in message
    kept = {p.stem: json.loads(p.read_text())["status"] for p in (out / "records").glob("*.json")}
    assert list(kept.values()) == ["ok"]
    monkeypatch.setattr(space, "_free_bytes", real)
    again = sweep(base, VARY, out, scheduler="serial")
    assert (again.ran, again.skipped, again.failed) == (2, 1, 0)
    for result in sorted((whole / "results").glob("*.nc")):
        a, b = read_result(result), read_result(out / "results" / result.name)
        for name in ("position", "tension"):
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=f"{result.name} {name}")


def _calls_for_one_case(base, out, monkeypatch, real) -> int:
    """How many times a study of the first case alone asks for the free space."""
    from kanat.sweep import sweep

    calls = {"n": 0}

    def counting(path):
        calls["n"] += 1
        return real(path)
    monkeypatch.setattr(space, "_free_bytes", counting)
    sweep(base, {"cables[0].length": [900]}, out, scheduler="serial")
    monkeypatch.setattr(space, "_free_bytes", real)
    return calls["n"]
