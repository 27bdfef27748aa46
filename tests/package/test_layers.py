"""The package's layers point down only (style rule 13) and no package's modules import each other in a
cycle: import-linter's contracts in pyproject.toml."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from helpers import ROOT



def test_no_lower_layer_imports_a_higher_one():
    command = shutil.which("lint-imports") or pytest.fail("import-linter is not installed (the test extra has it)")
    result = subprocess.run([command, "--no-cache"], cwd=ROOT, capture_output=True, text=True, timeout=300,
                            env={"PYTHONPATH": str(ROOT / "src"), "PATH": str(Path(sys.executable).parent)})
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    assert "0 broken" in result.stdout
