"""The documentation says things cleanly: docstring roles rendered as links, keys never broken,
and every README figure with the command and the machine that made it.

Oracles: the role syntax itself (each rewritten role must become exactly one optional autorefs
link to the full path of an object that exists), the package's docstrings (after rewriting,
none shows a raw role), and benchmarks/RESULTS.md (each command a README row names heads a
section there).
"""
import importlib.util
import re
import sys

import pytest

from helpers import ROOT

ROLE = re.compile(r":(func|meth|class|mod|data|attr):`")


def _roles():
    spec = importlib.util.spec_from_file_location("griffe_roles", ROOT / "scripts" / "griffe_roles.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("griffe_roles", module)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def package():
    griffe = pytest.importorskip("griffe", reason="the docs extra provides griffe")
    return griffe.load("kanat", search_paths=[str(ROOT / "src")], extensions=griffe.load_extensions(_roles().Roles))


def test_roles_become_links_to_full_paths(package):
    api = package["api"]
    text = api.docstring.value
    assert not ROLE.search(text)
    assert '<autoref identifier="kanat.api.MODELS" optional><code>MODELS</code></autoref>' in text
    assert '<autoref identifier="kanat.dynamics" optional><code>kanat.dynamics</code></autoref>' in text


def test_a_short_role_shows_the_last_name_only(package):
    rewrite = _roles().rewrite
    linked = rewrite("see :class:`~kanat.io.result_table.ResultTable` and :func:`kanat.simulate()`", package)
    assert linked == ('see <autoref identifier="kanat.io.result_table.ResultTable" optional><code>ResultTable'
                      '</code></autoref> and <autoref identifier="kanat.simulate" optional><code>kanat.simulate'
                      '</code></autoref>')


def test_no_docstring_of_the_api_pages_keeps_a_raw_role(package):
    pages = "".join((ROOT / "docs" / "reference" / name).read_text() for name in ("api.md", "modules.md"))
    shown = re.findall(r"^::: (kanat[\w.]*)", pages, flags=re.M)
    assert len(shown) >= 20
    raw = []
    for path in shown:
        obj = package[path[len("kanat."):]] if path != "kanat" else package
        for item in [obj, *obj.members.values()]:
            if not item.is_alias and item.docstring is not None and ROLE.search(item.docstring.value):
                raw.append(item.path)
    assert raw == []


def test_the_front_door_example_is_an_examples_section():
    import kanat.api

    text = kanat.api.__doc__
    assert "\nExamples\n--------\n>>> import kanat" in text


def test_reference_keys_are_not_broken_in_their_column():
    css = (ROOT / "docs" / "stylesheets" / "tables.css").read_text()
    assert "td:first-child > code" in css and "white-space: nowrap" in css
    assert "stylesheets/tables.css" in (ROOT / "mkdocs.yml").read_text()


def test_every_readme_figure_names_its_command_and_machine():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    results = (ROOT / "benchmarks" / "RESULTS.md").read_text(encoding="utf-8")
    table = readme[readme.index("| case | kanat whole process"):].split("\n\n")[0].splitlines()[2:]
    assert len(table) >= 13
    for row in table:
        last = row.rstrip(" |").rsplit("|", 1)[1]
        command = re.search(r"`(python benchmarks/[^`]+)`", last)
        assert command, row
        assert re.search(r"20\d\d-\d\d-\d\d, 2-core x86_64 VM", last), row
        assert "load" in last, row
        script = command.group(1).split()[1]
        assert (ROOT / script).exists(), script
        assert f"`{command.group(1).split(' --')[0]}" in results, command.group(1)
