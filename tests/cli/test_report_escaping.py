"""The HTML reports escape everything a user controls (issue 14 item 6).

Script, ``<img onerror>``, ``<svg onload>`` and quotes are put into every user string that
reaches a page: the case name, the result's file name, cable and body names, attribute
names and values of the result file, the base case's file name, varied values and a
failure message of a study. Oracles: an HTML parser (the page holds only kanat's own tags,
no event-handler attribute, and the payloads only in escaped form) and a real browser
(Debian's chromium via playwright: no injected script runs, no dialog opens, and the
strings are displayed exactly as written, in the page and in plotly's legends).
"""
import os
import shutil
from html.parser import HTMLParser

import numpy as np
import pytest
import yaml

from kanat.io import parse_case
from kanat.io.results import read_result, write_result
from kanat.report.html_report import write_report
from kanat.sweep import sweep

from helpers import run, short_case

PAYLOAD = """q"'><script>window.__xss.push('script')</script><img src=x onerror="window.__xss.push('img')">""" \
          """<svg onload=window.__xss.push('svg')><!--"""
FILE_PAYLOAD = """q"'><img src=x onerror="window.__xss.push('file')"><svg onload=window.__xss.push('file-svg')>"""
"""A file name cannot hold '/': the file-name payload has no closing tags."""
RAW = ("<script>window.__xss", "<img src=x", "<svg onload", "<!--")
ALLOWED_TAGS = {"html", "head", "meta", "title", "style", "script", "body", "header", "h1", "h2", "h3", "p", "nav",
                "a", "main", "section", "table", "thead", "tbody", "tr", "th", "td", "div", "span", "code", "button",
                "input", "label", "select", "pre"}
CHROMIUM = "/usr/bin/chromium"


def hostile_case(duration=20) -> str:
    """short_case with the payload as the case, cable and body name."""
    data = yaml.safe_load(short_case(duration=duration, segments=10))
    data["name"] = PAYLOAD
    data["cables"][0]["name"] = "cable " + PAYLOAD
    data["bodies"] = {"body " + PAYLOAD: data["bodies"]["sled"]}
    data["cables"][0]["to"] = "body " + PAYLOAD
    return yaml.safe_dump(data, sort_keys=False)


@pytest.fixture(scope="module")
def hostile_result(tmp_path_factory):
    folder = tmp_path_factory.mktemp("result")
    path = folder / f"{FILE_PAYLOAD}.nc"
    assert run(parse_case(hostile_case()), path).ok
    ds = read_result(path)
    ds.attrs["remark " + PAYLOAD] = PAYLOAD                       # attribute name and value
    write_result(ds, path)
    return path


@pytest.fixture(scope="module")
def hostile_study(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    base = folder / f"{FILE_PAYLOAD}.yaml"
    base.write_text(hostile_case(duration=10))
    result = sweep(base, {"name": [PAYLOAD, "../../x"], "simulation.scheme": ["generalized-alpha", PAYLOAD]},
                   folder / "study", scheduler="serial")
    assert list(result.summary["status"].values) == ["ok", "failed", "ok", "failed"]
    assert PAYLOAD in str(result.summary["message"].values[1])   # the failure message repeats the value
    return folder / "study"


class Tags(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.tags, self.handlers, self.scripts, self.texts = set(), [], [], []

    def handle_starttag(self, tag, attrs):
        self.tags.add(tag)
        self.handlers += [(tag, name) for name, _ in attrs if name.lower().startswith("on")]
        if tag == "script":
            self.scripts.append(dict(attrs).get("type", ""))

    def handle_data(self, data):
        self.texts.append(data)


def check_page(html: str, json_data: int):
    """Only kanat's tags and scripts; the payload only escaped; the user text shown as written."""
    for raw in RAW:
        assert raw not in html, f"raw {raw!r} reached the page"
    parser = Tags()
    parser.feed(html)
    assert parser.tags <= ALLOWED_TAGS, parser.tags - ALLOWED_TAGS
    assert parser.handlers == []
    assert parser.scripts.count("") == len(parser.scripts) - 2 - json_data        # plotly.js, boot, page scripts
    assert parser.scripts.count("application/json") == 2 + json_data               # template, figures, data
    text = "".join(parser.texts)
    assert PAYLOAD in text                                # a text node holds the string exactly (HTML-decoded)
    assert "&lt;script&gt;window.__xss" in html          # ... because it is escaped in the markup


def test_result_page_escapes_every_user_string(hostile_result, tmp_path):
    html = write_report(hostile_result, tmp_path / "r.html").read_text()
    check_page(html, json_data=1)                                                  # the animation's data
    for name in ("cable " + PAYLOAD, "body " + PAYLOAD, "remark " + PAYLOAD, FILE_PAYLOAD):
        assert name.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") in html.replace(
            "&#34;", '"').replace("&#39;", "'")
    assert '\\u003cscript\\u003ewindow.__xss' in html       # in the embedded JSON (plotly names, animation)


def test_study_page_escapes_every_user_string(hostile_study, tmp_path):
    html = write_report(hostile_study, tmp_path / "s.html").read_text()
    check_page(html, json_data=1)                                                  # the study's columns
    assert "unknown continuum scheme" in html or "simulation.scheme" in html      # the failure is shown


def _browser():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        return None, "playwright is not installed"
    if not (os.path.exists(CHROMIUM) or shutil.which("chromium")):
        return None, "chromium is not installed"
    return sync_playwright, ""


@pytest.fixture(scope="module")
def browser():
    launcher, reason = _browser()
    if launcher is None:
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
            pytest.fail(reason)
        pytest.skip(reason)
    with launcher() as p:
        b = p.chromium.launch(executable_path=CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium"),
                              headless=True, args=["--no-sandbox", "--disable-gpu"])
        yield b
        b.close()


def open_hostile(browser, path):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    events = []
    page.add_init_script("window.__xss = [];")
    page.on("dialog", lambda d: (events.append(f"dialog {d.message}"), d.dismiss()))
    page.on("pageerror", lambda e: events.append(f"error {e}"))
    page.on("request", lambda r: events.append(f"request {r.url}") if not r.url.startswith(
        ("file:", "data:", "blob:", "about:")) else None)
    page.goto(path.as_uri())
    page.wait_for_function("window.KANAT && window.KANAT.drawn.length > 0")
    return page, events


@pytest.mark.slow
def test_no_injected_script_runs_in_the_result_page(browser, hostile_result, tmp_path):
    page, events = open_hostile(browser, write_report(hostile_result, tmp_path / "r.html"))
    page.click("#plot-animation-play")
    page.wait_for_function("+document.getElementById('plot-animation').getAttribute('data-frame') >= 3")
    page.click("#plot-animation-play")
    page.hover("#plot-range-graph .nsewdrag >> nth=0")                           # hover labels: names
    assert page.evaluate("window.__xss") == [] and events == []
    assert page.inner_text("header h1") == f"kanat report: {PAYLOAD}"             # shown as written
    legend = page.evaluate("Array.from(document.querySelectorAll('#plot-range-graph .legendtext'))"
                           ".map(e => e.textContent)")
    assert f"cable {PAYLOAD} max" in legend                                       # plotly shows it as text
    cells = page.evaluate("Array.from(document.querySelectorAll('#summary td')).map(e => e.textContent)")
    assert PAYLOAD in cells and FILE_PAYLOAD in " ".join(cells)
    assert np.isfinite(page.evaluate("window.KANAT.animation.frames"))


@pytest.mark.slow
def test_no_injected_script_runs_in_the_study_page(browser, hostile_study, tmp_path):
    page, events = open_hostile(browser, write_report(hostile_study, tmp_path / "s.html"))
    page.select_option("#study-x", "vary:name")                                   # the varied name as x axis
    page.select_option("#study-group", "simulation.scheme")
    page.select_option("#map-x", "vary:name")
    assert page.evaluate("window.__xss") == [] and events == []
    failed = page.evaluate("Array.from(document.querySelectorAll('#study td')).map(e => e.textContent)")
    assert any(PAYLOAD in cell for cell in failed)                                # the failure message, as written
    assert f"{FILE_PAYLOAD}.yaml" in page.inner_text("#study code")                 # the base case's path
    ticks = page.evaluate("Array.from(document.querySelectorAll('#plot-map .xtick text')).map(e => e.textContent)")
    assert PAYLOAD in ticks and "../../x" in ticks
