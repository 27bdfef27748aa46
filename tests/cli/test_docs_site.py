"""The documentation site: built strictly, complete, and carrying its own content.

Oracles: MkDocs itself (``mkdocs build --strict`` fails on a broken link, a missing anchor
or a page that does not render); the README (its two commands appear verbatim on the
getting-started page); the examples folder (every case file has its section and pictures in
the gallery); the repository (no page points to files outside it).
"""
import importlib.util
import os
import re
import subprocess
import sys

import pytest

from helpers import ROOT

DOCS = ROOT / "docs"


def _gallery():
    spec = importlib.util.spec_from_file_location("gallery", ROOT / "scripts" / "gallery.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("gallery", module)
    spec.loader.exec_module(module)
    return module


def test_site_builds_strictly(tmp_path):
    pytest.importorskip("mkdocs", reason="the docs extra (pip install -e '.[docs]', included in "
                                         "the test extra) provides mkdocs")
    pytest.importorskip("mkdocstrings", reason="the docs extra provides mkdocstrings")
    pytest.importorskip("material", reason="the docs extra provides mkdocs-material")
    result = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(tmp_path / "site")],
                            cwd=ROOT, capture_output=True, text=True, env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
                            timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    api = (tmp_path / "site" / "reference" / "api" / "index.html").read_text(encoding="utf-8")
    for name in ("load_case", "solve_statics", "simulate", "read_result"):
        assert f'id="kanat.api.{name}"' in api, f"{name} is not documented on the API page"
    gallery = (tmp_path / "site" / "gallery" / "index.html").read_text(encoding="utf-8")
    assert gallery.count("<img") >= len(_gallery().example_files())


def test_readme_commands_are_on_the_getting_started_page():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    page = (DOCS / "getting-started.md").read_text(encoding="utf-8")
    commands = re.findall(r"```bash\n(.*?)\n```", readme, flags=re.S)
    assert len(commands) >= 2
    for command in commands[:2]:
        assert command in page


def test_gallery_shows_every_example_with_its_pictures():
    gallery = _gallery()
    page = (DOCS / "gallery.md").read_text(encoding="utf-8")
    files = gallery.example_files()
    assert len(files) >= 20
    for path in files:
        title = path.relative_to(ROOT).as_posix()
        assert f"## {title}" in page, f"{title} is not in the gallery: run python scripts/gallery.py"
    for picture in re.findall(r"\]\(gallery/([^)]+)\)", page):
        png = DOCS / "gallery" / picture
        assert png.exists() and png.stat().st_size > 10_000, picture


def test_every_page_is_in_the_navigation():
    import yaml

    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text(encoding="utf-8"))

    def pages(node):
        if isinstance(node, str):
            yield node
        elif isinstance(node, dict):
            for value in node.values():
                yield from pages(value)
        elif isinstance(node, list):
            for value in node:
                yield from pages(value)
    listed = set(pages(config["nav"]))
    present = {p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")}
    assert present <= listed, f"pages missing from mkdocs.yml's nav: {sorted(present - listed)}"


@pytest.mark.parametrize("page", sorted(p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")))
def test_pages_point_to_nothing_outside_the_repository(page):
    text = (DOCS / page).read_text(encoding="utf-8")
    assert "../shared" not in text and "SPEC.md" not in text
    assert not re.search(r"SPEC §", text), "the specification is not part of the repository; link a page"
    assert not re.search(r"(?<![/\w-])case-format\.md", text.replace("reference/case-format.md", "")
                         .replace("(case-format.md", "")), "link reference/case-format.md"
