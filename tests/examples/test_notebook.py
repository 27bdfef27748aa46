"""The getting-started notebook runs from top to bottom and shows what it says.

Oracle: the run's first output equals the statics solution it starts from (to the
difference of the two discretizations, below 1e-3), the dynamic run ends ``ok``, and every
plot cell produces a picture.
"""
import re
import time

import pytest

from helpers import EXAMPLES

NOTEBOOK = EXAMPLES / "notebook" / "getting_started.ipynb"


@pytest.mark.slow
def test_getting_started_notebook_executes(tmp_path):
    nbformat = pytest.importorskip("nbformat", reason="the test extra installs nbformat")
    nbclient = pytest.importorskip("nbclient", reason="the test extra installs nbclient")
    pytest.importorskip("ipykernel", reason="the test extra installs ipykernel")
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    start = time.perf_counter()
    nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(NOTEBOOK.parent.parent.parent)}}).execute()
    elapsed = time.perf_counter() - start
    outputs = [o for cell in notebook.cells if cell.cell_type == "code" for o in cell.outputs]
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert not [o for o in outputs if o.output_type == "error"]
    assert "ok - 121 outputs" in text
    assert sum("image/png" in o.get("data", {}) for o in outputs) >= 3
    difference = float(re.search(r"start_difference = (\S+)", text).group(1))
    assert difference < 1e-3
    assert elapsed < 120, f"the notebook took {elapsed:.0f} s; keep it under 30 s on a warm machine"
