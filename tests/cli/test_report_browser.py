"""The HTML reports opened in a real headless browser (Debian's chromium driven by playwright).

No console errors; the expected plots are drawn; the numbers the browser decodes from the
page equal kanat.analysis's (the oracle: the same statistics computed here with NumPy);
the animation advances and its frames are the result's positions; a screenshot of each
page is saved in the test's tmp dir. Without chromium the test fails under CI (CI=true)
and is skipped elsewhere.
"""
import os
import shutil

import numpy as np
import pytest

from kanat.analysis import range_graph
from kanat.io import parse_case
from kanat.io.results import read_result
from kanat.report.html_report import write_report
from kanat.sweep import sweep

from helpers import run, short_case

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
        "--disable-sync", "--no-first-run"]
RESULT_PLOTS = ["plot-tension-history", "plot-body-history", "plot-range-graph", "plot-spectra", "plot-animation"]


def _unavailable(reason):
    if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
        pytest.fail(f"{reason}; .ci/run installs Debian's chromium and the test extra installs playwright")
    pytest.skip(reason)


@pytest.fixture(scope="module")
def browser():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _unavailable("playwright is not installed")
    if not (os.path.exists(CHROMIUM) or shutil.which("chromium")):
        _unavailable("chromium is not installed")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium"),
                              headless=True, args=ARGS)
        yield b
        b.close()


def open_page(browser, path):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    errors = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("request", lambda r: errors.append(f"network request {r.url}") if not r.url.startswith(
        ("file:", "data:", "blob:", "about:")) else None)
    page.goto(path.as_uri())
    page.wait_for_function("window.KANAT && window.KANAT.drawn.length > 0")
    return page, errors


@pytest.fixture(scope="module")
def result(tmp_path_factory):
    path = tmp_path_factory.mktemp("run") / "run.nc"
    assert run(parse_case(short_case()), path).ok
    return path


@pytest.mark.slow
def test_result_report_in_chromium(browser, result, tmp_path):
    html = write_report(result, tmp_path / "report.html")
    page, errors = open_page(browser, html)
    assert page.evaluate("window.KANAT.drawn") == RESULT_PLOTS
    for plot in RESULT_PLOTS:
        assert page.locator(f"#{plot} .main-svg").count() >= 1, plot          # plotly drew it
    ds = read_result(result)
    rg = range_graph(ds)
    drawn = page.evaluate("Array.from(document.getElementById('plot-range-graph')._fullData[0].y)")  # decoded
    np.testing.assert_allclose(drawn, rg["max"].values / 1e3, rtol=1e-12)

    first = page.evaluate("document.getElementById('plot-animation')._fullData[0].x[0]")
    page.click("#plot-animation-play")
    page.wait_for_function("+document.getElementById('plot-animation').getAttribute('data-frame') >= 5",
                           timeout=10_000)
    page.click("#plot-animation-play")                                    # pause
    frame = int(page.get_attribute("#plot-animation", "data-frame"))
    x0 = page.evaluate("document.getElementById('plot-animation').data[0].x[0]")
    assert x0 == pytest.approx(ds["position"].values[frame, 0, 0], abs=1e-3) and x0 > first   # the tow point moved
    assert not page.is_checked("#plot-animation-follow")                 # the vessel travels less than the cable
    page.check("#plot-animation-follow")                                  # positions relative to the vessel
    x_end = page.evaluate("document.getElementById('plot-animation')._fullData[0].x.slice(-1)[0]")
    vessel_x = ds["vessel_position"].values[frame, 0]
    assert x_end == pytest.approx(ds["position"].values[frame, -1, 0] - vessel_x, abs=1e-3)
    page.uncheck("#plot-animation-follow")
    last = ds.sizes["time"] - 1
    page.evaluate(f"window.KANAT.animation.show({last})")
    z_end = page.evaluate("document.getElementById('plot-animation').data[0].z.slice(-1)[0]")
    assert z_end == pytest.approx(ds["position"].values[last, -1, 2], abs=1e-3)
    assert page.inner_text("#plot-animation-time") == f"t = {ds['time'].values[last]:.1f} s"
    page.locator("#animation").screenshot(path=str(tmp_path / "animation.png"))
    page.screenshot(path=str(tmp_path / "report.png"), full_page=True)
    assert (tmp_path / "report.png").stat().st_size > 10_000
    assert errors == []


@pytest.mark.slow
def test_study_report_in_chromium(browser, tmp_path):
    base = tmp_path / "base.yaml"
    base.write_text(short_case(duration=30))
    study = sweep(base, {"vessel.track[1].to_speed_kn": [8, 10, 12], "cables[0].length": [800, 1000]},
                  tmp_path / "study", scheduler="serial")
    html = write_report(tmp_path / "study", tmp_path / "study.html")
    page, errors = open_page(browser, html)
    traces = page.evaluate("document.getElementById('plot-study').data.length")
    assert traces == 2                                                    # one line per cable length
    page.select_option("#study-y", "tension_max")
    page.select_option("#study-group", "(none)")
    drawn = page.evaluate("Array.from(document.getElementById('plot-study').data[0].y)")
    expected = study.summary["tension_max"].values[np.argsort(study.summary["vessel.track[1].to_speed_kn"].values,
                                                              kind="stable")]
    np.testing.assert_allclose(sorted(drawn), sorted(expected / 1e3), rtol=1e-12)   # shown in kN
    grid = page.evaluate("document.getElementById('plot-map').data[0].z")
    assert np.array(grid).shape == (2, 3)                                 # lengths x speeds
    assert page.locator("#plot-study-histories .main-svg").count() >= 1
    page.screenshot(path=str(tmp_path / "study.png"), full_page=True)
    assert (tmp_path / "study.png").stat().st_size > 10_000
    assert errors == []
