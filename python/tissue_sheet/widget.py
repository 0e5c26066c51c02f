"""``tissue_sheet.Sheet``: the ``<tissue-sheet>`` element as an anywidget.

The element's JavaScript (three.js, the engine and its workers, inlined) ships in the wheel as
``static/widget.js``; nothing is fetched at run time. Runs compute in the browser (a Web Worker
with WebGL2). A notebook kernel receives the browser's messages between cells, not while a cell
runs: ``sweep()`` and ``save_figure()`` return a job at once, whose result is there in a later
cell (``job.done``; ``job.runs``).
"""

from __future__ import annotations

import itertools
import json
import os
import time
from pathlib import Path
from typing import Any, Callable, Mapping

import anywidget
import pandas as pd
import traitlets

from .readers import cells_table, read_csv_text, summary_table, sweep_provenance
from ._version import __version__
from ._wait import BlockingUnavailable, KernelPump

_STATIC = Path(__file__).resolve().parent / "static" / "widget.js"
_ids = itertools.count(1)


_esm_text: str | None = None


def _esm() -> str:
    """The widget module's text (read once; anywidget sends it to the browser as a string)."""
    global _esm_text
    if _esm_text is not None:
        return _esm_text
    if not _STATIC.is_file():
        raise RuntimeError(
            f"{_STATIC} is missing: this tissue_sheet was not built with its widget (install the wheel, "
            "or in a checkout run `node scripts/bundle-python-widget.mjs` after `npm run build:lib`)"
        )
    _esm_text = _STATIC.read_text(encoding="utf-8")
    return _esm_text


class BrowserJob:
    """A request the widget's browser side answers (a sweep, a figure): done in a later cell."""

    def __init__(self, kind: str, on_done: Callable[["BrowserJob"], None] | None = None):
        self.id = next(_ids)
        self.kind = kind
        self.done = False
        self.started = False  # a view of the widget answered
        self.error: str | None = None
        self.finished = 0
        self.total: int | None = None
        self._on_done = on_done

    def _finish(self, error: str | None = None) -> None:
        self.done = True
        self.error = error
        if self._on_done is not None:
            self._on_done(self)

    def _check(self) -> None:
        if not self.done:
            total = "?" if self.total is None else self.total
            raise RuntimeError(
                f"the {self.kind} is still running in the browser ({self.finished} of {total}); a notebook hears "
                "back between cells: read it in a later cell (job.done says when). The browser computes it only "
                "while the widget is shown"
            )
        if self.error is not None:
            raise RuntimeError(f"the {self.kind} failed in the browser: {self.error}")

    def __repr__(self) -> str:
        state = "failed: " + self.error if self.error else ("done" if self.done else f"running, {self.finished} of {self.total or '?'}")
        return f"<tissue-sheet {self.kind} {self.id}: {state}>"


class SweepJob(BrowserJob):
    """``Sheet.sweep(spec)``: ``runs`` (runs.csv as a DataFrame) and ``aggregate`` once ``done``."""

    def __init__(self, spec: Mapping[str, Any], on_done=None):
        super().__init__("sweep", on_done)
        self.spec = dict(spec)
        self.runs_csv: str | None = None
        self.aggregate_csv: str | None = None
        self.aborted = False

    def _table(self, text: str | None, name: str) -> pd.DataFrame:
        self._check()
        df = read_csv_text(text or "", name)
        df.attrs.update(sweep_provenance({"software": {"name": "tissue-sheet", "version": __version__}, "spec": self.spec}, "browser"))
        df.attrs["aborted"] = self.aborted
        return df

    @property
    def runs(self) -> pd.DataFrame:
        """One row per run: the text of runs.csv the element computed, read as ``read_sweep`` reads the file."""
        return self._table(self.runs_csv, "runs.csv")

    @property
    def aggregate(self) -> pd.DataFrame:
        return self._table(self.aggregate_csv, "aggregate.csv")


class FigureJob(BrowserJob):
    """``Sheet.save_figure(path)``: the PNG of the 3D view, written to ``path`` once ``done``."""

    def __init__(self, path: Path, on_done=None):
        super().__init__("figure", on_done)
        self.path = path

    @property
    def bytes(self) -> int:
        self._check()
        return self.path.stat().st_size


# After this long with no answer from a view, the progress line says the sheet may not be shown.
_NO_VIEW_HINT_S = 10.0


def _progress_text(job: "SweepJob", elapsed: float) -> str:
    if job.done:
        if job.error is not None:
            return f"sweep failed in the browser after {elapsed:.1f} s: {job.error}"
        return f"sweep: {job.finished} runs done in {elapsed:.1f} s" + (" (aborted)" if job.aborted else "")
    if not job.started:
        return "sweep: waiting for the browser"
    return f"sweep: {job.finished} of {job.total if job.total is not None else '?'} runs, {elapsed:.0f} s"


class _ProgressLine:
    """One line of text in the running cell's output, updated in place (a display with an id)."""

    def __init__(self) -> None:
        self.hint = ""
        self._handle = None

    def show(self, text: str) -> None:
        try:
            from IPython.display import display
        except ImportError:  # pragma: no cover - a kernel always has IPython
            return
        bundle = {"text/plain": text + self.hint}
        if self._handle is None:
            self._handle = display(bundle, raw=True, display_id=True)
        else:
            self._handle.update(bundle, raw=True)


class Sheet(anywidget.AnyWidget):
    """The ``<tissue-sheet>`` element in a notebook.

    ``config`` (synced both ways): set it and the sheet re-runs; after each run it holds the
    configuration that ran, every default filled in (so a change made in the widget is seen in
    Python). ``result``: the last result (the CLI's JSON shape); ``cells`` and ``summary``: it
    as DataFrames. ``realizations``: the headline's n (the element's default 5 when None).
    """

    _esm = traitlets.Unicode().tag(sync=True)
    config = traitlets.Dict().tag(sync=True)
    result = traitlets.Dict(allow_none=True, default_value=None).tag(sync=True)
    error = traitlets.Unicode("").tag(sync=True)
    compute_site = traitlets.Dict().tag(sync=True)
    realizations = traitlets.Int(allow_none=True, default_value=None).tag(sync=True)
    height = traitlets.Unicode("480px").tag(sync=True)

    def __init__(self, config: Mapping[str, Any] | None = None, **kwargs: Any):
        super().__init__(_esm=_esm(), config=dict(config or {}), **kwargs)
        self._jobs: dict[int, BrowserJob] = {}
        self.last_sweep: SweepJob | None = None
        self.on_msg(self._handle_message)

    @traitlets.validate("config")
    def _validate_config(self, proposal):
        value = proposal["value"]
        try:
            json.dumps(value)
        except (TypeError, ValueError) as e:
            raise traitlets.TraitError(f"config: not JSON ({e})") from None
        return value

    @property
    def cells(self) -> pd.DataFrame:
        """The last result's cells: one row per cell and surface (read_result's columns)."""
        return cells_table(self._result(), source="widget")

    @property
    def summary(self) -> pd.DataFrame:
        """The last result's summary: one row per analysis and surface (read_result(..., 'summary')'s columns)."""
        return summary_table(self._result(), source="widget")

    def _result(self) -> dict:
        if not self.result:
            why = f" (the last run failed: {self.error})" if self.error else ""
            raise RuntimeError(
                f"no result yet{why}: show the widget (put it last in a cell) and read it in a later cell once it has run"
            )
        return self.result

    def sweep(
        self,
        spec: Mapping[str, Any],
        wait: bool = True,
        timeout: float | None = None,
        progress: bool = True,
        on_done: Callable[[SweepJob], None] | None = None,
    ) -> pd.DataFrame | SweepJob:
        """Runs a sweep (the CLI's spec, docs/sweep.md) in the browser's workers; progress shows under the view.

        ``wait=True`` (the default): blocks until the browser has run it, handling the kernel's
        messages meanwhile (a Jupyter kernel, ipykernel 6 or 7), and returns runs.csv as a
        DataFrame (equal to what ``tissue-sheet sweep`` writes for the spec; the job, with
        ``aggregate``, is ``sheet.last_sweep``). ``timeout`` (s; None: no limit) raises
        ``TimeoutError`` (``.job``: the sweep, still running in the browser). ``progress``: a
        line in the cell's output says how far it is. Where no kernel can be waited on (plain
        Python, marimo, ...) it raises at once, before anything is sent.

        ``wait=False``: returns a SweepJob at once; in a later cell ``job.runs`` is the runs.csv
        DataFrame and ``job.aggregate`` aggregate.csv.
        """
        if not isinstance(spec, Mapping):
            raise TypeError(f"spec: a dict (docs/sweep.md), got {type(spec).__name__}")
        json.dumps(spec)
        if timeout is not None and not timeout > 0:
            raise ValueError(f"timeout: seconds > 0 (or None), got {timeout!r}")
        pump = None
        if wait:
            try:
                pump = KernelPump()
            except BlockingUnavailable as e:
                raise BlockingUnavailable(
                    f"sheet.sweep(spec) cannot wait for the browser here: {e}. It needs a Jupyter kernel "
                    "(JupyterLab, Notebook, VS Code); use sheet.sweep(spec, wait=False) and read job.runs in a "
                    "later cell, or the headless tissue_sheet.sweep(spec, out=...)"
                ) from None
        job = SweepJob(spec, on_done)
        self._jobs[job.id] = job
        self.last_sweep = job
        self.send({"type": "sweep", "id": job.id, "spec": dict(spec)})
        if pump is None:
            return job
        return self._wait(job, pump, timeout, progress)

    def _wait(self, job: SweepJob, pump: KernelPump, timeout: float | None, progress: bool) -> pd.DataFrame:
        start = time.monotonic()
        line = _ProgressLine() if progress else None
        shown = [None]

        def tick() -> None:
            if line is None:
                return
            if job.started:
                line.hint = ""
            state = (job.started, job.finished, job.total, job.done, line.hint)
            if state == shown[0]:
                return
            shown[0] = state
            line.show(_progress_text(job, time.monotonic() - start))

        if line is not None:
            tick()
        deadline = None if timeout is None else start + timeout
        while not job.done:
            now = time.monotonic()
            if deadline is not None and now >= deadline:
                if line is not None:
                    line.show(_progress_text(job, now - start) + f": timed out after {timeout:g} s")
                err = TimeoutError(
                    f"the sweep did not finish in {timeout:g} s ({job.finished} of {job.total or '?'} runs"
                    + ("" if job.started else "; no view of the widget answered: is the sheet shown?")
                    + "); it goes on in the browser while the widget is shown: sheet.last_sweep is its job"
                )
                err.job = job  # type: ignore[attr-defined]
                raise err
            if not job.started and now - start > _NO_VIEW_HINT_S and line is not None:
                line.hint = " (no view of the widget has answered yet: show the sheet, e.g. `sheet` last in a cell)"
            pump.pump(0.05 if deadline is None else max(0.0, min(0.05, deadline - now)))
            tick()
        pump.pump(0)
        if line is not None:
            line.show(_progress_text(job, time.monotonic() - start))
        return job.runs

    def save_figure(self, path: str | os.PathLike, on_done: Callable[[FigureJob], None] | None = None) -> FigureJob:
        """Saves the 3D view as PNG (the element's ``toBlob()``); the file is written once the browser answers."""
        path = Path(path)
        if path.suffix.lower() != ".png":
            raise ValueError(f"path: {path} should end in .png (the element exports PNG)")
        job = FigureJob(path, on_done)
        self._jobs[job.id] = job
        self.send({"type": "figure", "id": job.id, "mime": "image/png"})
        return job

    def _handle_message(self, _widget: Any, content: Mapping[str, Any], buffers: list) -> None:
        job = self._jobs.get(content.get("id")) if isinstance(content, Mapping) else None
        if job is None:
            return
        kind = content.get("type")
        if kind in ("sweep-started", "sweep-progress", "sweep-done"):
            job.started = True
        if kind == "sweep-progress":
            job.finished = int(content.get("finished") or 0)
            job.total = content.get("total")
        elif kind == "sweep-done" and isinstance(job, SweepJob):
            job.runs_csv = content.get("runsCsv")
            job.aggregate_csv = content.get("aggregateCsv")
            job.aborted = bool(content.get("aborted"))
            if job.total is None:
                job.total = int(content.get("completed") or 0)
            job.finished = job.total
            job._finish()
        elif kind == "figure-done" and isinstance(job, FigureJob):
            data = bytes(buffers[0]) if buffers else b""
            if data[:8] != b"\x89PNG\r\n\x1a\n":
                job._finish("the browser sent no PNG")
            else:
                job.path.write_bytes(data)
                job._finish()
        elif kind in ("sweep-error", "figure-error"):
            job._finish(str(content.get("message")))
        if job.done:
            self._jobs.pop(job.id, None)
