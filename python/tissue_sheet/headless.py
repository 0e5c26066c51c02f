"""Headless runs from Python through the project's CLI (Node), returning what the readers return.

The CLI is found, first found wins:
1. ``TISSUE_SHEET_CLI``: the path of ``bin/tissue-sheet.mjs`` (a checkout or an npm install), or
   of a ``tissue-sheet`` executable;
2. a checkout around this package (``python/`` beside ``bin/tissue-sheet.mjs``: ``pip install -e``
   or running from the source tree);
3. a checkout or an ``npm install tissue-sheet`` in the working directory or one above it (a
   notebook next to the project: ``bin/tissue-sheet.mjs`` of a package.json named tissue-sheet, or
   ``node_modules/tissue-sheet/bin/tissue-sheet.mjs``);
4. ``tissue-sheet`` on PATH (``npm install -g tissue-sheet``).
Where Node or the CLI is missing, ``TissueSheetCliNotFound`` says what to install. There is no
fallback: nothing is computed in Python.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path
from typing import Any, Mapping, Sequence

import numpy as np
import pandas as pd

from .readers import read_measure, read_result, read_sweep
from .tiff import write_label_tiff

INSTALL_HINT = (
    "install Node.js 20 or later (https://nodejs.org, or apt-get install nodejs) and the npm package "
    "(npm install -g tissue-sheet), or set TISSUE_SHEET_CLI to bin/tissue-sheet.mjs of a tissue-sheet checkout "
    "(built with npm ci)"
)


class TissueSheetCliNotFound(RuntimeError):
    """Node.js or the tissue-sheet CLI is not installed; the message says what to install."""


class TissueSheetCliError(RuntimeError):
    """The CLI failed: ``exit_code`` (2 bad input, 3 environment, 1 unexpected) and its ``stderr``."""

    def __init__(self, message: str, exit_code: int, stderr: str):
        super().__init__(message)
        self.exit_code = exit_code
        self.stderr = stderr


class TissueSheetInputError(TissueSheetCliError, ValueError):
    """The CLI refused its input (exit 2): the message is its one line naming the field or file."""


_checked_nodes: set[str] = set()


def _node() -> str:
    node = shutil.which("node")
    if node is None:
        raise TissueSheetCliNotFound(f"tissue-sheet needs Node.js to run headless, and `node` is not on PATH: {INSTALL_HINT}")
    if node not in _checked_nodes:
        try:
            version = subprocess.run([node, "--version"], capture_output=True, text=True, timeout=30).stdout.strip()
            major = int(version.lstrip("v").split(".")[0])
        except (OSError, ValueError, subprocess.SubprocessError):
            raise TissueSheetCliNotFound(f"{node} does not answer --version: {INSTALL_HINT}") from None
        if major < 20:
            raise TissueSheetCliNotFound(f"{node} is Node.js {version}; tissue-sheet needs 20 or later: {INSTALL_HINT}")
        _checked_nodes.add(node)
    return node


def _checkout_above(start: Path) -> Path | None:
    """bin/tissue-sheet.mjs of a tissue-sheet checkout or npm install in ``start`` or a folder above it."""
    for folder in (start, *start.parents):
        installed = folder / "node_modules" / "tissue-sheet" / "bin" / "tissue-sheet.mjs"
        if installed.is_file():
            return installed
        package = folder / "package.json"
        launcher = folder / "bin" / "tissue-sheet.mjs"
        if launcher.is_file() and package.is_file():
            try:
                if json.loads(package.read_text(encoding="utf-8")).get("name") == "tissue-sheet":
                    return launcher
            except (OSError, ValueError):
                pass
    return None


def find_cli() -> list[str]:
    """The command that runs the CLI (a list for subprocess), or TissueSheetCliNotFound."""
    env = os.environ.get("TISSUE_SHEET_CLI")
    if env:
        path = Path(env)
        if not path.is_file():
            raise TissueSheetCliNotFound(f"TISSUE_SHEET_CLI={env} is not a file: {INSTALL_HINT}")
        return [_node(), str(path)] if path.suffix in (".mjs", ".js") else [str(path)]
    checkout = Path(__file__).resolve().parent.parent.parent / "bin" / "tissue-sheet.mjs"
    if checkout.is_file():
        return [_node(), str(checkout)]
    above = _checkout_above(Path.cwd().resolve())
    if above is not None:
        return [_node(), str(above)]
    on_path = shutil.which("tissue-sheet")
    if on_path:
        _node()
        return [on_path]
    raise TissueSheetCliNotFound(f"the tissue-sheet CLI was not found (no TISSUE_SHEET_CLI, no checkout, no tissue-sheet on PATH): {INSTALL_HINT}")


def _call(args: Sequence[str], timeout: float | None = None) -> subprocess.CompletedProcess:
    command = [*find_cli(), *args]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except FileNotFoundError as e:
        raise TissueSheetCliNotFound(f"{e.filename}: not found: {INSTALL_HINT}") from None
    if done.returncode != 0:
        lines = [line for line in done.stderr.splitlines() if line.strip()]
        # The CLI's own last line names the field or file (exit 2) or the environment (exit 3).
        last = lines[-1] if lines else f"exit code {done.returncode} with no message"
        if "dist/esm/cli.js is missing" in done.stderr:
            raise TissueSheetCliNotFound(f"{last} ({INSTALL_HINT})")
        kind = TissueSheetInputError if done.returncode == 2 else TissueSheetCliError
        raise kind(f"tissue-sheet {args[0]} failed (exit {done.returncode}): {last}", done.returncode, done.stderr)
    return done


def _json_input(value: Any, what: str, directory: Path) -> str:
    if isinstance(value, (str, os.PathLike)):
        path = Path(value)
        if not path.is_file():
            raise FileNotFoundError(f"{what}: {path} is not a file")
        return str(path)
    if not isinstance(value, Mapping):
        raise TypeError(f"{what}: a dict or the path of a JSON file, got {type(value).__name__}")
    path = directory / f"{what}.json"
    path.write_text(json.dumps(value), encoding="utf-8")
    return str(path)


def run(
    config: Mapping[str, Any] | str | os.PathLike,
    out: str | os.PathLike | None = None,
    realizations: int | None = None,
    cells_file: bool = False,
    table: str = "cells",
    timeout: float | None = None,
) -> pd.DataFrame:
    """``tissue-sheet run``: one sheet from a config (a dict or a JSON file); returns ``read_result``'s table.

    ``out``: where to keep RESULT.json (default: a temporary file, removed); ``realizations``:
    the headline's n (the CLI's default 5); ``cells_file``: write the compact side file.
    """
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        tmp = Path(tmp)
        args = ["run", _json_input(config, "config", tmp), "--out", str(out if out is not None else tmp / "result.json")]
        if realizations is not None:
            args += ["--realizations", str(int(realizations))]
        if cells_file:
            args.append("--cells-file")
        _call(args, timeout)
        return read_result(args[3], table=table)


def sweep(
    spec: Mapping[str, Any] | str | os.PathLike,
    out: str | os.PathLike,
    table: str = "runs",
    workers: int | None = None,
    max_runs: int | None = None,
    timeout: float | None = None,
) -> pd.DataFrame:
    """``tissue-sheet sweep SPEC --out DIR``: returns ``read_sweep(out)`` (resumes a rerun, as the CLI does)."""
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        args = ["sweep", _json_input(spec, "sweep", Path(tmp)), "--out", str(out)]
        if workers is not None:
            args += ["--workers", str(int(workers))]
        if max_runs is not None:
            args += ["--max-runs", str(int(max_runs))]
        _call(args, timeout)
    return read_sweep(out, table=table)


def measure(
    labels: np.ndarray | str | os.PathLike | Sequence[str | os.PathLike],
    voxel_size: Sequence[float] | None = None,
    out: str | os.PathLike | None = None,
    apical: str | None = None,
    lumen_label: int | None = None,
    min_contact: float | None = None,
    quartet_filter: bool = False,
    compare: bool = False,
    realizations: int | None = None,
    seed: int | None = None,
    pixel_size: float | None = None,
    periodic_x: bool = False,
    table: str = "cells",
    timeout: float | None = None,
) -> pd.DataFrame:
    """``tissue-sheet measure``: a segmented tissue; returns ``read_measure``'s table.

    ``labels``: a numpy 3D label array (z, y, x; 0 background, one integer per cell) or the path
    of a label volume TIFF (both measured with ``--volume``), or a list of 2D layer image paths,
    basal first (the layers mode). ``voxel_size``: (x, y, z) µm (needed for an array; for a
    file it overrides the file's metadata). The other arguments are the CLI's options
    (docs/measure.md).
    """
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        tmp = Path(tmp)
        layers = isinstance(labels, (list, tuple)) and not isinstance(labels, np.ndarray)
        if isinstance(labels, np.ndarray):
            if voxel_size is None:
                raise ValueError("voxel_size: give (x, y, z) in µm for a numpy label volume")
            volume = tmp / "labels.tif"
            write_label_tiff(volume, labels, voxel_size)
            args = ["measure", "--volume", str(volume)]
        elif layers:
            files = [str(Path(p)) for p in labels]
            for f in files:
                if not Path(f).is_file():
                    raise FileNotFoundError(f"labels: {f} is not a file")
            args = ["measure", *files]
        elif isinstance(labels, (str, os.PathLike)):
            if not Path(labels).is_file():
                raise FileNotFoundError(f"labels: {labels} is not a file")
            args = ["measure", "--volume", str(labels)]
        else:
            raise TypeError(f"labels: a numpy 3D array, a volume TIFF path or a list of layer images, got {type(labels).__name__}")
        result = str(out if out is not None else tmp / "measure.json")
        args += ["--out", result]
        if voxel_size is not None and not layers:
            if len(voxel_size) != 3:
                raise ValueError(f"voxel_size: three numbers (x, y, z) in µm, got {voxel_size!r}")
            args += ["--voxel-size", ",".join(repr(float(v)) for v in voxel_size)]
        options = {
            "--apical": apical,
            "--lumen-label": lumen_label,
            "--min-contact": min_contact,
            "--realizations": realizations,
            "--seed": seed,
            "--pixel-size": pixel_size,
        }
        for flag, value in options.items():
            if value is not None:
                args += [flag, str(value)]
        if quartet_filter:
            args.append("--quartet-filter")
        if compare:
            args.append("--compare")
        if periodic_x:
            args.append("--periodic-x")
        _call(args, timeout)
        return read_measure(result, table=table)
