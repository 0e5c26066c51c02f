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
import signal
import subprocess
import tempfile
from pathlib import Path
from typing import Any, Mapping, Sequence

import numpy as np
import pandas as pd

from .readers import read_measure, read_result, read_sweep
from .tiff import write_label_tiff, write_layer_tiff

INSTALL_HINT = (
    "install Node.js 20 or later (https://nodejs.org, or apt-get install nodejs) and the npm package "
    "(npm install -g tissue-sheet), or set TISSUE_SHEET_CLI to bin/tissue-sheet.mjs of a tissue-sheet checkout "
    "(built with npm ci)"
)


class TissueSheetCliNotFound(RuntimeError):
    """Node.js or the tissue-sheet CLI is not installed; the message says what to install."""


class TissueSheetCliError(RuntimeError):
    """The CLI failed: ``exit_code`` (2 bad input, 3 environment, 1 unexpected) and its ``stderr``."""

    def __init__(self, message: str, exit_code: int | None, stderr: str):
        super().__init__(message)
        self.exit_code = exit_code
        self.stderr = stderr


class TissueSheetInputError(TissueSheetCliError, ValueError):
    """The CLI refused its input (exit 2): the message is its one line naming the field or file."""


class TissueSheetTimeout(TissueSheetCliError, TimeoutError):
    """The CLI ran past ``timeout`` seconds and was stopped, with every process it had started;
    ``exit_code`` is None and ``stderr`` what it had written (its progress)."""


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


# How long a CLI asked to stop has before it is killed: on SIGTERM xvfb-run stops its X server
# and a sweep writes its finished rows and releases its lock.
_STOP_GRACE_S = 5.0


def _stop(process: subprocess.Popen) -> str:
    """Stops the CLI and what it started, and returns the rest of its stderr.

    Without a display the launcher re-runs itself under xvfb-run (an X server and a second
    node), which killing the first process alone would leave running: the CLI runs in its own
    process group (``start_new_session``), which gets SIGTERM, then SIGKILL if its processes
    still hold the output pipes after a grace time (the node doing the work may need a moment to
    write what it finished). Reading the pipes meanwhile keeps a chatty process from blocking.
    """
    if os.name != "posix":
        process.kill()
    elif _signal_group(process.pid, signal.SIGTERM):
        try:
            return process.communicate(timeout=_STOP_GRACE_S)[1]
        except subprocess.TimeoutExpired:
            _signal_group(process.pid, signal.SIGKILL)
    return process.communicate()[1]


def _signal_group(group: int, sig: int) -> bool:
    """Sends ``sig`` to a process group; False when it is gone."""
    try:
        os.killpg(group, sig)
        return True
    except (ProcessLookupError, PermissionError):
        return False


def _run(command: list[str], timeout: float | None) -> tuple[int, str, bool]:
    """Runs the CLI: its exit code, its stderr, and whether it ran past ``timeout`` (and was stopped)."""
    with subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=os.name == "posix"
    ) as process:
        try:
            _, stderr = process.communicate(timeout=timeout)
            return process.returncode, stderr, False
        except subprocess.TimeoutExpired:
            stderr = _stop(process)
            return process.returncode, stderr, True
        except BaseException:  # an interrupted kernel too: leave nothing running
            _stop(process)
            raise


def _named(message: str, names: Mapping[str, str] | None) -> str:
    """The CLI's message with the temporary files it read named as the user gave them ("the array")."""
    for path, name in (names or {}).items():
        message = message.replace(path, name)
    return message


def _call(args: Sequence[str], timeout: float | None = None, names: Mapping[str, str] | None = None) -> None:
    """Runs ``tissue-sheet ARGS``; ``names`` maps the temporary files made for it to what the messages call them."""
    if timeout is not None and not (isinstance(timeout, (int, float)) and timeout > 0):
        raise ValueError(f"timeout: seconds > 0 (or None for no limit), got {timeout!r}")
    command = [*find_cli(), *args]
    try:
        returncode, stderr, timed_out = _run(command, timeout)
    except FileNotFoundError as e:
        raise TissueSheetCliNotFound(f"{e.filename}: not found: {INSTALL_HINT}") from None
    lines = [line for line in (stderr or "").splitlines() if line.strip()]
    if timed_out:
        # Its own last line ("interrupted; finished runs are in ...") rather than the X server's.
        own = [line for line in lines if line.startswith("tissue-sheet:")] or lines
        said = f"; its last line: {own[-1]}" if own else ""
        raise TissueSheetTimeout(_named(f"tissue-sheet {args[0]} did not finish in {timeout:g} s (timeout) and was stopped{said}", names), None, stderr)
    if returncode != 0:
        # The CLI's own last line names the field or file (exit 2) or the environment (exit 3).
        last = lines[-1] if lines else f"exit code {returncode} with no message"
        if "dist/esm/cli.js is missing" in stderr:
            raise TissueSheetCliNotFound(f"{last} ({INSTALL_HINT})")
        kind = TissueSheetInputError if returncode == 2 else TissueSheetCliError
        raise kind(_named(f"tissue-sheet {args[0]} failed (exit {returncode}): {last}", names), returncode, stderr)


def _json_input(value: Any, what: str, directory: Path, names: dict[str, str]) -> str:
    """The JSON file the CLI reads: the path given, or a dict written to a temporary file (named "the WHAT dict" in messages)."""
    if isinstance(value, (str, os.PathLike)):
        path = Path(value)
        if not path.is_file():
            raise FileNotFoundError(f"{what}: {path} is not a file")
        return str(path)
    if not isinstance(value, Mapping):
        raise TypeError(f"{what}: a dict or the path of a JSON file, got {type(value).__name__}")
    path = directory / f"{what}.json"
    path.write_text(json.dumps(value), encoding="utf-8")
    names[str(path)] = f"the {what} dict"
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
    the headline's n (the CLI's default 5); ``cells_file``: write the compact side file;
    ``timeout``: seconds (None: no limit), past which the CLI is stopped and TissueSheetTimeout raised.
    """
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        tmp = Path(tmp)
        names: dict[str, str] = {}
        args = ["run", _json_input(config, "config", tmp, names), "--out", str(out if out is not None else tmp / "result.json")]
        if realizations is not None:
            args += ["--realizations", str(int(realizations))]
        if cells_file:
            args.append("--cells-file")
        _call(args, timeout, names)
        return read_result(args[3], table=table)


def sweep(
    spec: Mapping[str, Any] | str | os.PathLike,
    out: str | os.PathLike,
    table: str = "runs",
    workers: int | None = None,
    max_runs: int | None = None,
    timeout: float | None = None,
) -> pd.DataFrame:
    """``tissue-sheet sweep SPEC --out DIR``: returns ``read_sweep(out)`` (resumes a rerun, as the CLI does).

    ``timeout``: seconds (None: no limit), past which the CLI is stopped and TissueSheetTimeout
    raised; the runs finished so far stay in ``out``, and a rerun resumes from them.
    """
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        names: dict[str, str] = {}
        args = ["sweep", _json_input(spec, "sweep", Path(tmp), names), "--out", str(out)]
        if workers is not None:
            args += ["--workers", str(int(workers))]
        if max_runs is not None:
            args += ["--max-runs", str(int(max_runs))]
        _call(args, timeout, names)
    return read_sweep(out, table=table)


def measure(
    labels: np.ndarray | str | os.PathLike | Sequence[str | os.PathLike | np.ndarray],
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
    of a label volume TIFF (both measured with ``--volume``), or a list of 2D layers, basal
    first (the layers mode): each the path of a label image or a 2D numpy label array (y, x;
    up to 65,535 labels). ``voxel_size``: (x, y, z) µm of a volume (needed for an array; for a
    file it overrides the file's metadata). ``pixel_size``: µm of a layer's square pixel (needed
    for layer arrays). ``timeout``: seconds (None: no limit), past which the CLI is stopped and
    TissueSheetTimeout raised. The other arguments are the CLI's options (docs/measure.md).
    Messages name an array as the user gave it ("the array", "the array labels[1]"), not the
    temporary TIFF it was written to.
    """
    with tempfile.TemporaryDirectory(prefix="tissue-sheet-") as tmp:
        tmp = Path(tmp)
        names: dict[str, str] = {}  # temporary files -> how the CLI's messages should call them
        layers = isinstance(labels, (list, tuple))
        if isinstance(labels, np.ndarray):
            if voxel_size is None:
                raise ValueError("voxel_size: give (x, y, z) in µm for a numpy label volume")
            volume = tmp / "labels.tif"
            write_label_tiff(volume, labels, voxel_size)
            names[str(volume)] = "the array"
            args = ["measure", "--volume", str(volume)]
        elif layers:
            if voxel_size is not None:
                raise ValueError(
                    "voxel_size: is for a volume (a 3D array or a volume TIFF); a list of layer images takes "
                    "pixel_size (µm, the edge of a square pixel)"
                )
            args = ["measure", *_layer_files(labels, pixel_size, tmp, names)]
        elif isinstance(labels, (str, os.PathLike)):
            if not Path(labels).is_file():
                raise FileNotFoundError(f"labels: {labels} is not a file")
            args = ["measure", "--volume", str(labels)]
        else:
            raise TypeError(f"labels: a numpy 3D array, a volume TIFF path or a list of layer images, got {type(labels).__name__}")
        result = str(out if out is not None else tmp / "measure.json")
        args += ["--out", result]
        if voxel_size is not None:
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
        _call(args, timeout, names)
        return read_measure(result, table=table)


def _layer_files(labels: Sequence[Any], pixel_size: float | None, directory: Path, names: dict[str, str]) -> list[str]:
    """The layers' files, basal first: a path as given, a 2D array written to a one-page TIFF
    (the layers mode reads 2D TIFFs, of any width: an unrolled tube's apical layer is wider)."""
    # One 2D array alone would reach the CLI as a one-page TIFF, "a 3D stack with one page".
    if len(labels) == 1 and isinstance(labels[0], np.ndarray):
        raise ValueError("labels: one 2D layer; give two or more (basal first), or one 3D array (a label volume)")
    files = []
    for k, layer in enumerate(labels):
        if isinstance(layer, np.ndarray):
            if pixel_size is None:
                raise ValueError(f"pixel_size: give the pixel size in µm for the label array labels[{k}]")
            path = directory / f"layer-{k}.tif"
            try:
                write_layer_tiff(path, layer, pixel_size)
            except ValueError as e:
                message = str(e)
                raise ValueError(f"labels[{k}]: {message[len('labels: '):]}" if message.startswith("labels: ") else message) from None
            names[str(path)] = f"the array labels[{k}]"
        elif isinstance(layer, (str, os.PathLike)):
            path = Path(layer)
            if not path.is_file():
                raise FileNotFoundError(f"labels[{k}]: {path} is not a file")
        else:
            raise TypeError(f"labels[{k}]: a layer is the path of a label image or a 2D numpy label array, got {type(layer).__name__}")
        files.append(str(path))
    return files
