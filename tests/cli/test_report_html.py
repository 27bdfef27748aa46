"""The HTML report as a file, and the study verbs of the command line.

Oracles: the page's embedded JSON read back and compared with kanat.analysis computed here;
a statics result's tension from the result file; the sweep verb's summary against the
Python API's serial run of the same study.
"""
import json
import re

import pytest
import typer
from typer.testing import CliRunner

from kanat.analysis import node_statistics
from kanat.cli_study import parse_vary, parse_window, register
from kanat.errors import KanatError
from kanat.io import parse_case
from kanat.io.results import read_result
from kanat.report.html_report import write_report
from kanat.sweep import read_summary

from helpers import run, short_case

URL = re.compile(r"""(?:src|href)\s*=\s*["']?(https?:)?//""", re.I)


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    path = tmp_path_factory.mktemp("run") / "run.nc"
    assert run(parse_case(short_case()), path).ok
    return path


def embedded(html: str, element_id: str):
    match = re.search(rf'<script type="application/json" id="{element_id}">(.*?)</script>', html, re.S)
    return json.loads(match.group(1))


def table_headers(html: str) -> set:
    """Every table column header of the page."""
    return {re.sub(r"<[^>]+>", "", h).strip() for h in re.findall(r"<th[^>]*>(.*?)</th>", html, re.S)}


def summary_rows(html: str) -> dict:
    """The summary statistics table: ``statistic -> (unit, value)``."""
    rows = {}
    for row in re.findall(r"<tr>(.*?)</tr>", html, re.S):
        cells = [re.sub(r"<[^>]+>", "", c).strip() for c in re.findall(r"<td[^>]*>(.*?)</td>", row, re.S)]
        if len(cells) == 3:
            rows[cells[0]] = (cells[2], cells[1])
    return rows


def app():
    cli = typer.Typer()
    cli.command("noop")(lambda: None)
    register(cli)
    return cli


def test_result_page_is_self_contained_and_holds_the_statistics(result, tmp_path):
    path = write_report(result, tmp_path / "r.html", nodes=["tow@0", "tow@500"], window=(20, None))
    html = path.read_text()
    assert "plotly.js v" in html and html.count("<html") == 1
    ours = html[:html.index("<script>/**")] + html[html.index("</head>"):]     # all but plotly.js's own code
    assert not URL.search(ours), "the page loads something from the network"   # (the browser test watches requests)
    ds = read_result(result)
    stats = node_statistics(ds, nodes=["tow@0", "tow@500"], window=(20, None))
    for value in (*stats["max"].values, *stats["mpm"].values):
        assert f"{value / 1e3:.5g}" in html                          # the statistics table, in kN
    headers = table_headers(html)
    for name in ("min", "max", "mean", "std", "MPM"):
        assert f"{name} [kN]" in headers and f"{name} [m]" in headers    # node tension, body depth
    assert "tension at the chosen nodes [N]" not in html
    in_window = ds["tension"].values[ds["time"].values >= 20]
    assert summary_rows(html)["tension_max"] == ("kN", f"{float(in_window.max()) / 1e3:.5g}")
    assert summary_rows(html)["depth_mean_sled"][0] == "m"
    animation = embedded(html, "kanat-animation")
    assert animation["times"] == list(ds["time"].values) and animation["nodes"] == ds.sizes["node"]
    assert "window 20 to 60 s" in html
    assert path.stat().st_size < 8e6


def test_statics_result_page(tmp_path):
    from kanat.io import load_case
    from kanat.io.results import statics_dataset, write_result
    from kanat.statics import solve_statics

    from helpers import EXAMPLES

    result = write_result(statics_dataset(solve_statics(load_case(EXAMPLES / "towed_body.yaml"))), tmp_path / "s.nc")
    html = write_report(result, tmp_path / "s.html").read_text()
    assert "plot-shape" in embedded(html, "kanat-figures")
    assert summary_rows(html)["tension_max"] == ("kN", f"{float(read_result(result)['tension'].max()) / 1e3:.5g}")
    assert "value" in table_headers(html) and "unit" in table_headers(html)


def test_report_errors_name_the_problem(tmp_path, result):
    with pytest.raises(KanatError, match="no body 'sledge' in this result; bodies: sled"):
        write_report(result, tmp_path / "x.html", bodies=["sledge"])
    with pytest.raises(KanatError, match="no cable 'towline'; cables: tow"):
        write_report(result, tmp_path / "x.html", nodes=["towline@0"])
    with pytest.raises(KanatError, match="does not exist"):
        write_report(tmp_path / "missing.nc", tmp_path / "x.html")
    (tmp_path / "bad.nc").write_text("not netcdf")
    with pytest.raises(KanatError, match="not a (kanat|readable) result file"):
        write_report(tmp_path / "bad.nc", tmp_path / "x.html")
    with pytest.raises(KanatError, match="not a study directory"):
        write_report(tmp_path, tmp_path / "x.html")


def test_cli_parsers():
    assert parse_vary(["a.b=1,2", "c[0].d = 3:5:1"]) == {"a.b": "1,2", "c[0].d": " 3:5:1"}
    assert parse_window("100:") == (100.0, None) and parse_window(":50") == (None, 50.0)
    with pytest.raises(KanatError, match="write KEY=VALUES"):
        parse_vary(["nothing"])
    with pytest.raises(KanatError, match="START:END"):
        parse_window("abc")


def test_sweep_and_report_verbs(tmp_path):
    base = tmp_path / "base.yaml"
    base.write_text(short_case(duration=20))
    runner = CliRunner()
    out = runner.invoke(app(), ["sweep", str(base), "--vary", "vessel.track[1].to_speed_kn=8:10:2",
                                "--vary", "simulation.scheme=generalized-alpha,rk9", "-o", str(tmp_path / "st"),
                                "--scheduler", "serial", "--report", str(tmp_path / "st.html")])
    assert out.exit_code == 0, out.output
    assert "4 cases" in out.output and "2 failed" in out.output
    summary, keys, _ = read_summary(tmp_path / "st")
    assert keys == ["vessel.track[1].to_speed_kn", "simulation.scheme"]
    assert list(summary["status"].values) == ["ok", "failed", "ok", "failed"]
    direct = read_result(tmp_path / "st" / "results" / f"{summary['name'].values[2]}.nc")
    assert float(summary["tension_max"].values[2]) == pytest.approx(float(direct["tension"].max()), rel=1e-12)
    assert "unknown continuum scheme" in (tmp_path / "st.html").read_text()
    bad = runner.invoke(app(), ["sweep", str(base), "--vary", "vessel.track[7].to_speed_kn=8", "-o",
                                str(tmp_path / "bad"), "--scheduler", "serial"])
    assert bad.exit_code == 1 and "vessel.track[7]" in bad.output
    page = runner.invoke(app(), ["report", str(tmp_path / "st"), "-o", str(tmp_path / "again.html")])
    assert page.exit_code == 0 and (tmp_path / "again.html").exists()


def test_report_never_overwrites_its_sources(result, tmp_path):
    before = result.read_bytes()
    with pytest.raises(KanatError, match="is also an input"):
        write_report(result, result)
    assert result.read_bytes() == before                                  # the result is intact
    with pytest.raises(KanatError, match="is a directory; give a file name, e.g. .*report.html"):
        write_report(result, tmp_path)
    with pytest.raises(KanatError, match="does not exist. Create it first"):
        write_report(result, tmp_path / "missing" / "r.html")
    page = write_report(result, tmp_path / "r.html")
    assert page.read_text().startswith("<!DOCTYPE html>") and not list(tmp_path.glob(".*"))   # no temporaries
