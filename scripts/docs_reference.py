"""Regenerate the documentation pages that are generated from the code.

    python scripts/docs_reference.py

writes ``docs/reference/case-format.md`` (every case key and result name, from the
pydantic models and ``kanat.io.schema``), ``docs/reference/support.md`` (the support table
of ``kanat.model.support``) and ``docs/schemes.md`` (the scheme registry). The functions
that make them are in ``kanat.cli_docs``; ``tests/model/test_reference.py`` fails when a
committed page differs from what they make now.
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def pages() -> dict[Path, str]:
    """Every generated page and its text."""
    from kanat.cli_docs import reference_page, schemes_page, support_page

    return {ROOT / "docs" / "reference" / "case-format.md": reference_page(),
            ROOT / "docs" / "reference" / "support.md": support_page(),
            ROOT / "docs" / "schemes.md": schemes_page()}


def main() -> int:
    for path, text in pages().items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        print(f"wrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
