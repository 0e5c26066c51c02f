"""``sheet.sweep(spec)`` waits in the running cell: the kernel's comm messages handled while it blocks.

Without a kernel (this pytest process: plain Python) it refuses at once with one message and
sends nothing. In a real kernel (ipykernel, started by jupyter_client as JupyterLab starts it),
a client plays the browser: it answers the widget's ``sweep`` message with the messages
widget_frontend.js sends (started, progress, done) while the cell is still running, and sends
the next cell meanwhile, which must run after the sweep's cell, in order. The browser itself is
tested in e2e/python-jupyter.spec.ts.
"""

import json
import queue
import sys
import time

import pytest

from tissue_sheet import Sheet
from tissue_sheet._wait import BlockingUnavailable

RUNS_CSV = "run,surfaceRatio,percentScutoids\n0,1.5,10.5\n1,2.5,31\n"


def test_without_a_kernel_sweep_refuses_at_once_and_sends_nothing():
    sheet = Sheet()
    sent = []
    sheet.send = lambda content, buffers=None: sent.append(content)
    start = time.monotonic()
    with pytest.raises(BlockingUnavailable, match=r"cannot wait for the browser here: no IPython kernel.*wait=False") as e:
        sheet.sweep({"base": {}, "vary": {"cells": [10]}})
    assert time.monotonic() - start < 1 and sent == [] and sheet.last_sweep is None
    assert "tissue_sheet.sweep(spec, out=...)" in str(e.value)
    assert isinstance(e.value, RuntimeError)
    # The non-blocking form works anywhere: a job at once.
    job = sheet.sweep({"base": {}, "vary": {"cells": [10]}}, wait=False)
    assert sent == [{"type": "sweep", "id": job.id, "spec": {"base": {}, "vary": {"cells": [10]}}}] and not job.done
    with pytest.raises(ValueError, match="timeout"):
        sheet.sweep({"base": {}}, timeout=0)


@pytest.fixture(scope="module")
def kernel():
    client = pytest.importorskip("jupyter_client")
    pytest.importorskip("ipykernel")
    km = client.KernelManager(kernel_name="python3")
    km.kernel_spec.argv[0] = sys.executable  # this venv's Python (where tissue_sheet is installed)
    km.start_kernel()
    kc = km.client()
    kc.start_channels()
    kc.wait_for_ready(timeout=60)
    kc.manager = km
    yield kc
    kc.stop_channels()
    km.shutdown_kernel(now=True)


def _execute(kc, code, wait=True, stop_on_error=True):
    msg_id = kc.execute(code, stop_on_error=stop_on_error)
    return _reply(kc, msg_id) if wait else msg_id


def _reply(kc, msg_id, timeout=30):
    while True:
        reply = kc.get_shell_msg(timeout=timeout)
        if reply["parent_header"].get("msg_id") == msg_id:
            return reply["content"]


def _iopub_until(kc, predicate, timeout=30):
    """IOPub messages up to the first one ``predicate`` accepts (returned last)."""
    seen = []
    deadline = time.monotonic() + timeout
    while True:
        try:
            msg = kc.get_iopub_msg(timeout=max(0.1, deadline - time.monotonic()))
        except queue.Empty:
            raise AssertionError(f"no such IOPub message; saw {[m['msg_type'] for m in seen]}") from None
        seen.append(msg)
        if predicate(msg):
            return seen


def _answer(kc, comm_id, content):
    """A message from the widget's front end, as the browser sends it (a custom widget message)."""
    msg = kc.session.msg("comm_msg", {"comm_id": comm_id, "data": {"method": "custom", "content": content}})
    kc.shell_channel.send(msg)


def _stream_text(msgs, parent):
    return "".join(m["content"]["text"] for m in msgs if m["msg_type"] == "stream" and m["parent_header"].get("msg_id") == parent)


def test_sweep_blocks_the_cell_and_returns_the_runs_the_browser_sends(kernel):
    kc = kernel
    reply = _execute(kc, "import tissue_sheet\nsheet = tissue_sheet.Sheet()\nCOMM = sheet.comm.comm_id")
    assert reply["status"] == "ok", reply
    reply = kc.execute_interactive("print(COMM)", timeout=30, output_hook=lambda m: setattr(kc, "_comm", m["content"].get("text", "").strip()) if m["msg_type"] == "stream" else None)
    comm_id = kc._comm
    spec = {"base": {"cells": 12}, "vary": {"sheet.surfaceRatio": [1.5, 2.5]}}
    sweep_cell = _execute(kc, f"runs = sheet.sweep({json.dumps(spec)}, timeout=60)\nprint('RUNS', runs.shape, list(runs.columns), runs.attrs['spec'] == {json.dumps(spec)})", wait=False)
    seen = _iopub_until(kc, lambda m: m["msg_type"] == "comm_msg" and m["content"]["data"].get("content", {}).get("type") == "sweep")
    request = seen[-1]["content"]["data"]["content"]
    assert request["spec"] == spec
    job = request["id"]
    # The next cell, sent while the sweep's cell waits: it runs after it (and sees `runs`).
    next_cell = _execute(kc, "print('NEXT', runs.shape)", wait=False)
    _answer(kc, comm_id, {"type": "sweep-started", "id": job})
    _answer(kc, comm_id, {"type": "sweep-progress", "id": job, "finished": 1, "total": 2})
    seen += _iopub_until(kc, lambda m: m["msg_type"] == "update_display_data" and "1 of 2 runs" in m["content"]["data"]["text/plain"])
    _answer(kc, comm_id, {"type": "sweep-done", "id": job, "runsCsv": RUNS_CSV, "aggregateCsv": "", "completed": 2, "aborted": False})
    assert _reply(kc, sweep_cell)["status"] == "ok"
    seen += _iopub_until(kc, lambda m: m["msg_type"] == "stream" and "NEXT" in m["content"]["text"])
    assert _reply(kc, next_cell)["status"] == "ok"
    assert "RUNS (2, 3) ['run', 'surfaceRatio', 'percentScutoids'] True" in _stream_text(seen, sweep_cell)
    assert "NEXT (2, 3)" in _stream_text(seen, next_cell)
    # The progress line in the sweep's cell: shown, then updated in place to the end.
    lines = [m["content"]["data"]["text/plain"] for m in seen if m["msg_type"] in ("display_data", "update_display_data") and m["parent_header"].get("msg_id") == sweep_cell]
    assert lines[0] == "sweep: waiting for the browser" and lines[-1].startswith("sweep: 2 runs done in "), lines
    # Nothing went to stderr.
    assert not [m for m in seen if m["msg_type"] == "stream" and m["content"]["name"] == "stderr"]


def test_sweep_times_out_with_a_clear_error_when_no_view_answers(kernel):
    kc = kernel
    reply = _execute(kc, "import tissue_sheet\nlonely = tissue_sheet.Sheet()\nlonely.sweep({'base': {}, 'vary': {'cells': [10]}}, timeout=1)", stop_on_error=False)
    assert reply["status"] == "error" and reply["ename"] == "TimeoutError", reply
    assert "did not finish in 1 s" in reply["evalue"] and "no view of the widget answered" in reply["evalue"]
    reply = _execute(kc, "assert lonely.last_sweep is not None and not lonely.last_sweep.done")
    assert reply["status"] == "ok", reply


def test_interrupting_the_kernel_stops_the_wait(kernel):
    kc = kernel
    msg_id = _execute(kc, "import tissue_sheet\nhalted = tissue_sheet.Sheet()\nhalted.sweep({'base': {}, 'vary': {'cells': [10]}})", wait=False, stop_on_error=False)
    _iopub_until(kc, lambda m: m["msg_type"] == "display_data" and m["parent_header"].get("msg_id") == msg_id)
    kc.manager.interrupt_kernel()
    reply = _reply(kc, msg_id)
    assert reply["status"] == "error" and reply["ename"] == "KeyboardInterrupt", reply
    assert _execute(kc, "assert not halted.last_sweep.done")["status"] == "ok"
