"""The example notebooks run top to bottom in a kernel (their widget cells display without a browser)."""

from pathlib import Path

import pytest

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.ipynb"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_example_notebook_runs(path, tmp_path):
    nbformat = pytest.importorskip("nbformat", reason="nbformat comes with JupyterLab (python/requirements-test.txt)")
    nbclient = pytest.importorskip("nbclient", reason="nbclient comes with JupyterLab (python/requirements-test.txt)")
    nb = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.get("output_type") == "error"]
    assert errors == []
    # The comparison table came out: measured and model numbers side by side.
    text = "".join(str(o.get("data", {}).get("text/plain", "")) for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []))
    assert "percentScutoids" in text and "fitted tube" in "".join(
        o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
    )
