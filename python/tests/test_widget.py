"""The Sheet's Python side: traits, tables from a real result, and the browser's answers as it sends them.

The browser side is tested in a real JupyterLab (e2e/python-jupyter.spec.ts); here the messages
are the ones widget_frontend.js sends (the same keys), fed to the handler.
"""

import json

import pandas as pd
import pytest

import tissue_sheet
from tissue_sheet.widget import Sheet


def test_sheet_carries_the_bundled_module_and_config():
    sheet = Sheet(config={"cells": 12}, realizations=1)
    assert "export default __tissueSheetWidget" in sheet._esm
    assert sheet.config == {"cells": 12} and sheet.realizations == 1
    with pytest.raises(RuntimeError, match="no result yet"):
        sheet.cells
    with pytest.raises(Exception, match="not JSON"):
        sheet.config = {"cells": object()}


def test_cells_and_summary_are_the_readers_tables(outputs):
    result = json.loads((outputs / "plain.json").read_text())
    sheet = Sheet(config=result["config"])
    sheet.result = result  # as the browser sets it after a run
    expected = tissue_sheet.read_result(outputs / "plain.json")
    pd.testing.assert_frame_equal(sheet.cells, expected)
    pd.testing.assert_frame_equal(sheet.summary, tissue_sheet.read_result(outputs / "plain.json", "summary"))
    assert sheet.cells.attrs["seed"] == result["seed"] and sheet.cells.attrs["source"] == "widget"


def test_sweep_job_reads_the_runs_csv_the_browser_sends(outputs):
    sheet = Sheet()
    sent = []
    sheet.send = lambda content, buffers=None: sent.append(content)
    spec = json.loads((outputs / "sweep.json").read_text())
    job = sheet.sweep(spec, wait=False)
    assert sent == [{"type": "sweep", "id": job.id, "spec": spec}]
    with pytest.raises(RuntimeError, match="still running in the browser"):
        job.runs
    sheet._handle_message(sheet, {"type": "sweep-progress", "id": job.id, "finished": 1, "total": 4}, [])
    assert (job.finished, job.total, job.done) == (1, 4, False)
    runs_csv = (outputs / "sweep" / "runs.csv").read_text()
    aggregate_csv = (outputs / "sweep" / "aggregate.csv").read_text()
    sheet._handle_message(sheet, {"type": "sweep-done", "id": job.id, "runsCsv": runs_csv, "aggregateCsv": aggregate_csv, "completed": 4, "aborted": False}, [])
    assert job.done
    pd.testing.assert_frame_equal(job.runs, tissue_sheet.read_sweep(outputs / "sweep"))
    pd.testing.assert_frame_equal(job.aggregate, tissue_sheet.read_sweep(outputs / "sweep", "aggregate"))
    assert job.runs.attrs["spec"] == spec
    failed = sheet.sweep(spec, wait=False)
    sheet._handle_message(sheet, {"type": "sweep-error", "id": failed.id, "message": 'vary["x"]: "x" is not a field'}, [])
    with pytest.raises(RuntimeError, match="failed in the browser: vary"):
        failed.runs
    with pytest.raises(TypeError, match="spec: a dict"):
        sheet.sweep("sweep.json", wait=False)


def test_figure_job_writes_the_png(tmp_path):
    sheet = Sheet()
    sheet.send = lambda content, buffers=None: None
    with pytest.raises(ValueError, match=r"\.png"):
        sheet.save_figure(tmp_path / "view.jpg")
    job = sheet.save_figure(tmp_path / "view.png")
    png = b"\x89PNG\r\n\x1a\n" + bytes(2000)
    sheet._handle_message(sheet, {"type": "figure-done", "id": job.id, "mime": "image/png"}, [memoryview(png)])
    assert job.done and (tmp_path / "view.png").read_bytes() == png and job.bytes == len(png)
    bad = sheet.save_figure(tmp_path / "bad.png")
    sheet._handle_message(sheet, {"type": "figure-done", "id": bad.id}, [b"GIF89a"])
    with pytest.raises(RuntimeError, match="no PNG"):
        bad.bytes
