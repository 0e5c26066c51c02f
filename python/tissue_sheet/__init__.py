"""tissue-sheet in Python and Jupyter (docs/python.md).

- ``Sheet(config=...)``: the ``<tissue-sheet>`` element as a notebook widget (anywidget).
- ``read_result``, ``read_sweep``, ``read_measure``: the CLI's results as tidy pandas tables.
- ``run``, ``sweep``, ``measure``: headless runs through the CLI (needs Node.js and the npm package).
"""

from ._version import __version__
from .headless import (
    TissueSheetCliError,
    TissueSheetCliNotFound,
    TissueSheetInputError,
    TissueSheetTimeout,
    find_cli,
    measure,
    run,
    sweep,
)
from .readers import (
    ResultFormatError,
    cells_table,
    contacts_table,
    measure_table,
    read_csv_text,
    read_measure,
    read_result,
    read_result_json,
    read_sweep,
    summary_table,
)
from .tiff import write_label_tiff


def __getattr__(name):
    # The widget imports anywidget (and, through it, ipywidgets): only when asked for.
    if name in ("Sheet", "SweepJob", "FigureJob"):
        from . import widget

        return getattr(widget, name)
    raise AttributeError(f"module 'tissue_sheet' has no attribute {name!r}")


__all__ = [
    "__version__",
    "Sheet",
    "SweepJob",
    "FigureJob",
    "read_result",
    "read_sweep",
    "read_measure",
    "read_result_json",
    "read_csv_text",
    "cells_table",
    "contacts_table",
    "summary_table",
    "measure_table",
    "run",
    "sweep",
    "measure",
    "find_cli",
    "write_label_tiff",
    "TissueSheetCliError",
    "TissueSheetCliNotFound",
    "TissueSheetInputError",
    "TissueSheetTimeout",
    "ResultFormatError",
]
