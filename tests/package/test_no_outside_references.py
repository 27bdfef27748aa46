"""The package's docstrings and comments cite its own theory pages (docs/theory/), never documents
outside the repository: the specification, the seeds' papers by task number, the style guide's rules."""
import re
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2] / "src" / "kanat"
OUTSIDE = re.compile(r"SPEC §|SPEC\.md|\.\./shared|STYLE rule|\bseed \d{3}\b")


def test_no_module_cites_anything_outside_the_repository():
    found = [f"{path.relative_to(SOURCE)}:{number}: {line.strip()}" for path in sorted(SOURCE.rglob("*.py"))
             for number, line in enumerate(path.read_text().splitlines(), 1) if OUTSIDE.search(line)]
    assert not found, "cite docs/theory/ instead:\n" + "\n".join(found)
