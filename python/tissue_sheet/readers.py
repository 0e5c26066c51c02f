"""Readers of every result form the tissue-sheet CLI writes, as tidy pandas tables.

- ``read_result(path)``: a ``tissue-sheet run`` result (plain JSON, or JSON with its compact
  side file ``RESULT.cells.bin``): one row per cell and surface.
- ``read_sweep(dir)``: a ``tissue-sheet sweep`` directory: ``runs.csv`` (one row per run) or
  ``aggregate.csv`` (one row per grid point), read generically (whatever its columns).
- ``read_measure(path)``: a ``tissue-sheet measure`` result (layer images or ``--volume``): one
  row per cell and layer.

Every table carries its provenance in ``DataFrame.attrs`` (software version, config or inputs,
seed, engine, method, spec). Column meanings: docs/python.md.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
from pathlib import Path
from typing import Any, Mapping

import numpy as np
import pandas as pd

CELLS_FILE_FORMAT = "tissue-sheet cells 1"
CELLS_FILE_MAGIC = b"TSCELLS1"
_HEADER_BYTES = 16
_DTYPES = {"float64": np.dtype("<f8"), "int32": np.dtype("<i4"), "uint8": np.dtype("u1")}
_CELL_COLUMNS = ("position", "surface", "area", "touchesBorder", "neighbourOffsets", "neighbourIds", "neighbourLengths")
_ANALYSIS_COLUMNS = ("valid", "scutoid", "won", "lost", "transitions", "neighbours3D", "sides")


class ResultFormatError(ValueError):
    """A file that is not the result form it was read as; the message names the file and what is wrong."""


# --------------------------------------------------------------------------- run results


def _load_json(path: Path) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise FileNotFoundError(f"{path}: no such file") from None
    try:
        return json.loads(text)
    except json.JSONDecodeError as e:
        raise ResultFormatError(f"{path}: not JSON ({e.msg} at line {e.lineno} column {e.colno})") from None


def decode_cells_file(record: Mapping[str, Any], data: bytes, name: str = "cells file") -> dict:
    """The side file's columns as numpy arrays, checked against the JSON's ``cellsFile`` record.

    Returns ``{"cells": {column: array}, "surfaces": [...], "analyses": [...]}`` in the JSON's
    order (the layout of README, "Large results: the cells side file").
    """
    if record.get("format") != CELLS_FILE_FORMAT:
        raise ResultFormatError(f'{name}: cellsFile.format {record.get("format")!r} is not "{CELLS_FILE_FORMAT}"')
    if record.get("byteOrder", "little-endian") != "little-endian":
        raise ResultFormatError(f"{name}: byte order {record.get('byteOrder')!r} is not little-endian")
    if len(data) != record.get("bytes"):
        raise ResultFormatError(f"{name}: {len(data)} bytes where the result says {record.get('bytes')}")
    if data[: len(CELLS_FILE_MAGIC)] != CELLS_FILE_MAGIC:
        raise ResultFormatError(f"{name}: not a tissue-sheet cells file (no TSCELLS1 header)")
    buffer = memoryview(data)

    def read(table: Mapping[str, Any], column: str) -> np.ndarray:
        c = table["columns"].get(column)
        if c is None:
            raise ResultFormatError(f"{name}: {table['of']} has no column {column}")
        dtype = _DTYPES.get(c.get("type"))
        if dtype is None:
            raise ResultFormatError(f"{name}: {table['of']}.{column} has type {c.get('type')!r}")
        offset, length = c.get("offset"), c.get("length")
        if not (
            isinstance(offset, int)
            and isinstance(length, int)
            and offset >= _HEADER_BYTES
            and length >= 0
            and offset % dtype.itemsize == 0
            and offset + length * dtype.itemsize <= len(data)
        ):
            raise ResultFormatError(f"{name}: {table['of']}.{column} lies outside the file")
        return np.frombuffer(buffer, dtype=dtype, count=length, offset=offset)

    tables = {t.get("of"): t for t in record.get("tables", [])}

    def find(of: str) -> Mapping[str, Any]:
        if of not in tables:
            raise ResultFormatError(f"{name}: no table for {of}")
        return tables[of]

    def ordered(prefix: str) -> list[str]:
        keys = [k for k in tables if isinstance(k, str) and k.startswith(prefix + "[") and k.endswith("].cells")]
        return sorted(keys, key=lambda k: int(k[len(prefix) + 1 : k.index("]")]))

    def columns(of: str, names: tuple[str, ...]) -> dict:
        t = find(of)
        out = {column: read(t, column) for column in names}
        count = t.get("count")
        if not isinstance(count, int) or isinstance(count, bool) or count < 0:
            raise ResultFormatError(f"{name}: {of}: count {count!r} is not a whole number of cells")
        out["count"] = count
        return out

    out = {
        "cells": columns("cells", _CELL_COLUMNS),
        "surfaces": [columns(of, _CELL_COLUMNS) for of in ordered("surfaces")],
        "analyses": [columns(of, _ANALYSIS_COLUMNS) for of in ordered("analyses")],
    }
    _check_tables(name, out, ["cells"] + ordered("surfaces"), ordered("analyses"))
    return out


_CELL_TYPES = {
    "position": "<f8",
    "surface": "<f8",
    "area": "<f8",
    "touchesBorder": "u1",
    "neighbourOffsets": "<i4",
    "neighbourIds": "<i4",
    "neighbourLengths": "<f8",
}
_ANALYSIS_TYPES = {"valid": "u1", "scutoid": "u1", "won": "<i4", "lost": "<i4", "transitions": "<i4", "neighbours3D": "<i4", "sides": "<i4"}


def _check_tables(name: str, tables: dict, cell_names: list[str], analysis_names: list[str]) -> None:
    """Refuses a side file whose tables break their structure (as the JavaScript readers do,
    src/run/cellsFileCheck.ts): types and lengths from each table's count, neighbour lists as
    CSR with ids of cells of the table, every table of one count. A side file is data from anyone."""
    count = tables["cells"]["count"]

    def column(of: str, table: dict, column_name: str, dtype: str, length: int) -> np.ndarray:
        values = table[column_name]
        if values.dtype != np.dtype(dtype):
            raise ResultFormatError(f"{name}: {of}.{column_name} must be {_TYPE_NAMES[np.dtype(dtype).str]}")
        if len(values) != length:
            raise ResultFormatError(f"{name}: {of}.{column_name} holds {len(values)} values where {length} are expected")
        return values

    for of, table in zip(cell_names, [tables["cells"], *tables["surfaces"]]):
        if table["count"] != count:
            raise ResultFormatError(f"{name}: {of} has {table['count']} cells where the file's cells table has {count}")
        lengths = {"position": 3 * count, "surface": 2 * count, "area": count, "touchesBorder": count, "neighbourOffsets": count + 1}
        for column_name, length in lengths.items():
            column(of, table, column_name, _CELL_TYPES[column_name], length)
        offsets = table["neighbourOffsets"]
        if offsets[0] != 0:
            raise ResultFormatError(f"{name}: {of}.neighbourOffsets starts at {offsets[0]}, not 0")
        decreasing = np.flatnonzero(np.diff(offsets.astype(np.int64)) < 0)
        if len(decreasing):
            raise ResultFormatError(f"{name}: {of}.neighbourOffsets decreases at cell {decreasing[0]}")
        ids = column(of, table, "neighbourIds", _CELL_TYPES["neighbourIds"], int(offsets[-1]))
        column(of, table, "neighbourLengths", _CELL_TYPES["neighbourLengths"], int(offsets[-1]))
        outside = np.flatnonzero((ids < 0) | (ids >= count))
        if len(outside):
            k = outside[0]
            raise ResultFormatError(f"{name}: {of}.neighbourIds[{k}] is {ids[k]}, not a cell of the {count}")
    for of, table in zip(analysis_names, tables["analyses"]):
        if table["count"] != count:
            raise ResultFormatError(f"{name}: {of} has {table['count']} cells where the file's cells table has {count}")
        for column_name in ("valid", "scutoid", "won", "lost", "transitions", "neighbours3D"):
            column(of, table, column_name, _ANALYSIS_TYPES[column_name], count)
        sides = table["sides"]
        if sides.dtype != np.dtype("<i4") or (len(sides) % count != 0 if count > 0 else len(sides) != 0):
            raise ResultFormatError(f"{name}: {of}.sides holds {len(sides)} values, not a whole number of surfaces of {count} cells")


_TYPE_NAMES = {"<f8": "float64", "<i4": "int32", "|u1": "uint8"}


def _cell_columns_from_records(cells: list) -> dict:
    """The side file's columns built from a JSON cell list (so both forms share one table builder)."""
    n = len(cells)
    offsets = np.zeros(n + 1, dtype=np.int64)
    for i, c in enumerate(cells):
        offsets[i + 1] = offsets[i] + len(c["neighbours"])
    return {
        "count": n,
        "position": np.array([c["position"] for c in cells], dtype=float).reshape(-1),
        "surface": np.array([c["surface"] for c in cells], dtype=float).reshape(-1),
        "area": np.array([c["area"] for c in cells], dtype=float),
        "touchesBorder": np.array([bool(c["touchesBorder"]) for c in cells], dtype=np.uint8),
        "neighbourOffsets": offsets,
        "neighbourIds": np.array([nb["id"] for c in cells for nb in c["neighbours"]], dtype=np.int64),
        "neighbourLengths": np.array([nb["length"] for c in cells for nb in c["neighbours"]], dtype=float),
    }


def _analysis_columns_from_records(cells: list) -> dict:
    n = len(cells)
    surfaces = len(cells[0]["sides"]) if n else 0
    sides = np.zeros(surfaces * n, dtype=np.int64)
    for i, c in enumerate(cells):
        for k, s in enumerate(c["sides"]):
            sides[k * n + i] = s
    return {
        "count": n,
        "valid": np.array([bool(c["valid"]) for c in cells], dtype=np.uint8),
        "scutoid": np.array([bool(c["scutoid"]) for c in cells], dtype=np.uint8),
        "won": np.array([c["won"] for c in cells], dtype=np.int64),
        "lost": np.array([c["lost"] for c in cells], dtype=np.int64),
        "transitions": np.array([c["transitions"] for c in cells], dtype=np.int64),
        "neighbours3D": np.array([c["neighbours3D"] for c in cells], dtype=np.int64),
        "sides": sides,
    }


def _result_tables(result: Mapping[str, Any], tables: dict | None) -> dict:
    if tables is not None:
        return tables
    try:
        return {
            "cells": _cell_columns_from_records(result["cells"]),
            "surfaces": [_cell_columns_from_records(s["cells"]) for s in result["surfaces"]],
            "analyses": [_analysis_columns_from_records(a["cells"]) for a in result["analyses"]],
        }
    except (KeyError, TypeError) as e:
        raise ResultFormatError(f"the result has no per-cell lists ({e}) and no cellsFile") from None


def _is_result(result: Any) -> bool:
    return isinstance(result, Mapping) and all(k in result for k in ("config", "surfaces", "analyses", "headline"))


def result_provenance(result: Mapping[str, Any], source: str | None = None) -> dict:
    """What made a result: software version, config, seed, engine, method, headline."""
    headline = result.get("headline") or {}
    lloyd = result.get("lloyd") or {}
    return {
        "kind": "result",
        "source": source,
        "software": result.get("software"),
        "version": (result.get("software") or {}).get("version"),
        "config": result.get("config"),
        "seed": result.get("seed"),
        "engine": result.get("engine"),
        "gpu": result.get("gpu"),
        "grid": result.get("grid"),
        "adjacency": result.get("adjacency"),
        "method": headline.get("method"),
        "protocol": headline.get("protocol"),
        "headline": headline,
        "byConstruction": result.get("byConstruction"),
        "lloyd": {"converged": lloyd.get("converged"), "finalEnergy": lloyd.get("finalEnergy"), "iterations": len(lloyd.get("iterations") or [])},
    }


def _stack(result: Mapping[str, Any]) -> list[dict]:
    """The surfaces in stack order: the seeded one (the JSON's ``cells``), then ``surfaces``."""
    seeded = ((result.get("config") or {}).get("sheet") or {}).get("seeded", "seeded")
    stack = [{"name": seeded, "role": "seeded", "offset": 0.0, "ratio": 1.0}]
    for s in result["surfaces"]:
        stack.append({"name": s.get("name"), "role": s.get("role"), "offset": s.get("offset"), "ratio": s.get("ratio")})
    return stack


def cells_table(result: Mapping[str, Any], tables: dict | None = None, source: str | None = None) -> pd.DataFrame:
    """One row per cell and surface of a run's result (a dict as the CLI or the widget gives it).

    Columns: surface (0 = seeded, then the stack's order), surface_name, role (seeded, layer,
    other), offset (µm), ratio, cell (id), x, y, z (µm), u, v (unrolled, µm), area (µm²),
    touches_border, neighbours (count), contact_length (µm, summed over the neighbours), and per
    analysis METHOD (``exact``, ``labels``): METHOD.valid, METHOD.scutoid, METHOD.won,
    METHOD.lost, METHOD.transitions, METHOD.neighbours3D (per cell, the same on every surface)
    and METHOD.sides (on this surface).
    """
    if not _is_result(result):
        raise ResultFormatError(f"{source or 'result'}: not a tissue-sheet run result (needs config, surfaces, analyses, headline)")
    t = _result_tables(result, tables)
    stack = _stack(result)
    per_surface = [t["cells"], *t["surfaces"]]
    frames = []
    for k, (meta, cols) in enumerate(zip(stack, per_surface)):
        n = cols["count"]
        offsets = np.asarray(cols["neighbourOffsets"], dtype=np.int64)
        lengths = np.asarray(cols["neighbourLengths"], dtype=float)
        summed = np.add.reduceat(lengths, offsets[:-1]) if len(lengths) else np.zeros(n)
        summed = np.where(np.diff(offsets) > 0, summed, 0.0) if n else summed
        position = np.asarray(cols["position"]).reshape(n, 3)
        coords = np.asarray(cols["surface"]).reshape(n, 2)
        frame = {
            "surface": np.full(n, k, dtype=np.int64),
            "surface_name": [meta["name"]] * n,
            "role": [meta["role"]] * n,
            "offset": np.full(n, meta["offset"], dtype=float),
            "ratio": np.full(n, meta["ratio"], dtype=float),
            "cell": np.arange(n, dtype=np.int64),
            "x": position[:, 0],
            "y": position[:, 1],
            "z": position[:, 2],
            "u": coords[:, 0],
            "v": coords[:, 1],
            "area": np.asarray(cols["area"], dtype=float),
            "touches_border": np.asarray(cols["touchesBorder"]).astype(bool),
            "neighbours": np.diff(offsets).astype(np.int64),
            "contact_length": summed[:n],
        }
        for analysis, a in zip(result["analyses"], t["analyses"]):
            m = analysis.get("method")
            if a["count"] != n:
                raise ResultFormatError(f"{source or 'result'}: analysis {m} has {a['count']} cells, surface {k} has {n}")
            frame[f"{m}.valid"] = np.asarray(a["valid"]).astype(bool)
            frame[f"{m}.scutoid"] = np.asarray(a["scutoid"]).astype(bool)
            for name in ("won", "lost", "transitions", "neighbours3D"):
                frame[f"{m}.{name}"] = np.asarray(a[name]).astype(np.int64)
            frame[f"{m}.sides"] = np.asarray(a["sides"])[k * n : (k + 1) * n].astype(np.int64)
        frames.append(pd.DataFrame(frame))
    df = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()
    df.attrs.update(result_provenance(result, source))
    return df


def contacts_table(result: Mapping[str, Any], tables: dict | None = None, source: str | None = None) -> pd.DataFrame:
    """One row per contact of a run's result: surface, cell, neighbour, length (µm); both directions."""
    if not _is_result(result):
        raise ResultFormatError(f"{source or 'result'}: not a tissue-sheet run result")
    t = _result_tables(result, tables)
    frames = []
    for k, cols in enumerate([t["cells"], *t["surfaces"]]):
        offsets = np.asarray(cols["neighbourOffsets"], dtype=np.int64)
        counts = np.diff(offsets)
        frames.append(
            pd.DataFrame(
                {
                    "surface": np.full(int(offsets[-1]), k, dtype=np.int64),
                    "cell": np.repeat(np.arange(cols["count"], dtype=np.int64), counts),
                    "neighbour": np.asarray(cols["neighbourIds"], dtype=np.int64)[: offsets[-1]],
                    "length": np.asarray(cols["neighbourLengths"], dtype=float)[: offsets[-1]],
                }
            )
        )
    df = pd.concat(frames, ignore_index=True)
    df.attrs.update(result_provenance(result, source))
    return df


def summary_table(result: Mapping[str, Any], source: str | None = None) -> pd.DataFrame:
    """One row per analysis (adjacency method) and surface: the analysis's summary.

    Columns: method, protocol, min_contact_length (µm), then the summary's numbers (cells,
    validCells, excludedCells, scutoids, percentScutoids, percentScutoidsEnds, meanTransitions,
    meanWon, meanLost, meanNeighbours3D), and per surface: surface (stack index), surface_name,
    meanSides, meanArea, polygons.3 ... polygons.10+ (fractions of the valid cells).
    """
    if not isinstance(result, Mapping) or "analyses" not in result:
        raise ResultFormatError(f"{source or 'result'}: no analyses")
    rows = []
    classes = ["3", "4", "5", "6", "7", "8", "9", "10+"]
    for a in result["analyses"]:
        summary = a.get("summary") or {}
        base = {"method": a.get("method"), "protocol": a.get("protocol"), "min_contact_length": a.get("minContactLength")}
        for key, value in summary.items():
            if not isinstance(value, (list, dict)):
                base[key] = value
        for k, surface in enumerate(summary.get("perSurface") or [{}]):
            row = dict(base)
            row["surface"] = k
            row["surface_name"] = surface.get("label")
            row["meanSides"] = surface.get("meanSides")
            row["meanArea"] = surface.get("meanArea")
            for c, f in zip(classes, surface.get("polygonDistribution") or []):
                row[f"polygons.{c}"] = f
            rows.append(row)
    df = pd.DataFrame(rows)
    if result.get("kind") == "measured":
        df.attrs.update(measure_provenance(result, source))
    else:
        df.attrs.update(result_provenance(result, source))
    return df


def read_result_json(path: str | os.PathLike) -> tuple[dict, dict | None]:
    """A run result's JSON and, where it names a side file, that file's columns (else None)."""
    path = Path(path)
    result = _load_json(path)
    if not isinstance(result, dict):
        raise ResultFormatError(f"{path}: not a tissue-sheet result (a JSON object)")
    record = result.get("cellsFile")
    if not record:
        return result, None
    name = record.get("path")
    # The side file is named relative to the JSON and never leaves its directory.
    if not isinstance(name, str) or os.path.basename(name) != name or name.startswith("."):
        raise ResultFormatError(f"{path}: cellsFile.path {name!r} is not a file name in the result's directory")
    side = path.parent / name
    try:
        data = side.read_bytes()
    except FileNotFoundError:
        raise FileNotFoundError(f"{path}: its side file {side} is missing (copy RESULT.json and RESULT.cells.bin together)") from None
    return result, decode_cells_file(record, data, str(side))


def read_result(path: str | os.PathLike, table: str = "cells") -> pd.DataFrame:
    """A ``tissue-sheet run`` result as a table (``table``: "cells", "contacts" or "summary").

    Reads the plain JSON and the compact form (JSON + ``RESULT.cells.bin``) alike.
    """
    result, tables = read_result_json(path)
    if result.get("kind") == "measured":
        raise ResultFormatError(f"{path}: a measure result; read it with read_measure")
    if table == "cells":
        return cells_table(result, tables, str(path))
    if table == "contacts":
        return contacts_table(result, tables, str(path))
    if table == "summary":
        return summary_table(result, str(path))
    raise ValueError(f'table: {table!r} is not one of "cells", "contacts", "summary"')


# --------------------------------------------------------------------------- sweeps


def _number(text: str) -> Any:
    """A CSV cell as the CLI wrote it: a number where it is one, NaN where empty, else the text."""
    if text == "":
        return math.nan
    try:
        value = float(text)
    except ValueError:
        return text
    return value


def read_csv_text(text: str, name: str = "csv") -> pd.DataFrame:
    """A tidy CSV the CLI writes (RFC 4180 quoting), whatever its columns: numeric columns as numbers.

    The header is taken as written (units or renamed columns need no change here); a column whose
    every non-empty cell is a number becomes float64 (int64 where all are whole and none is
    empty), the others stay text.
    """
    reader = csv.reader(io.StringIO(text, newline=""))
    try:
        header = next(reader)
    except StopIteration:
        raise ResultFormatError(f"{name}: empty (no header)") from None
    if len(set(header)) != len(header):
        raise ResultFormatError(f"{name}: repeated column names in the header")
    rows = []
    for line, row in enumerate(reader, start=2):
        if not row:
            continue
        if len(row) != len(header):
            raise ResultFormatError(f"{name}: line {line} has {len(row)} cells where the header has {len(header)}")
        rows.append(row)
    columns = {}
    for j, column in enumerate(header):
        cells = [r[j] for r in rows]
        values = [_number(c) for c in cells]
        if all(isinstance(v, float) for v in values):
            arr = np.array(values, dtype=float)
            finite = arr[~np.isnan(arr)]
            if len(finite) == len(arr) and len(arr) and np.all(finite == np.round(finite)) and np.all(np.abs(finite) < 2**53):
                columns[column] = arr.astype(np.int64)
            else:
                columns[column] = arr
        else:
            columns[column] = pd.array(cells, dtype=object)
    return pd.DataFrame(columns, columns=header)


def sweep_provenance(sweep: Mapping[str, Any] | None, source: str | None) -> dict:
    sweep = sweep or {}
    return {
        "kind": "sweep",
        "source": source,
        "software": sweep.get("software"),
        "version": (sweep.get("software") or {}).get("version"),
        "spec": sweep.get("spec"),
        "renderer": sweep.get("renderer"),
        "runs": sweep.get("runs"),
        "started": sweep.get("started"),
        "ended": sweep.get("ended"),
        "sweep": dict(sweep),
    }


def read_sweep(directory: str | os.PathLike, table: str = "runs") -> pd.DataFrame:
    """A ``tissue-sheet sweep`` directory: ``runs.csv`` (one row per run) or ``aggregate.csv``.

    ``table``: "runs" or "aggregate". The columns are the file's own; ``attrs`` holds sweep.json
    (the spec, software version, renderer, start and end).
    """
    directory = Path(directory)
    if table not in ("runs", "aggregate"):
        raise ValueError(f'table: {table!r} is not "runs" or "aggregate"')
    if not directory.is_dir():
        raise FileNotFoundError(f"{directory}: not a directory (give the --out directory of tissue-sheet sweep)")
    csv_path = directory / f"{table}.csv"
    if not csv_path.is_file():
        raise FileNotFoundError(f"{csv_path}: missing; {directory} is not a finished tissue-sheet sweep directory")
    sweep_json = directory / "sweep.json"
    sweep = _load_json(sweep_json) if sweep_json.is_file() else None
    df = read_csv_text(csv_path.read_text(encoding="utf-8"), str(csv_path))
    df.attrs.update(sweep_provenance(sweep, str(directory)))
    return df


# --------------------------------------------------------------------------- measure results


def measure_provenance(result: Mapping[str, Any], source: str | None) -> dict:
    inputs = result.get("inputs") or {}
    analysis = (result.get("analyses") or [{}])[0]
    return {
        "kind": "measured",
        "mode": "volume" if "volume" in inputs else "layers",
        "source": source,
        "software": result.get("software"),
        "version": (result.get("software") or {}).get("version"),
        "inputs": inputs,
        "method": analysis.get("method"),
        "minContactLength": analysis.get("minContactLength"),
        "summary": {k: v for k, v in (analysis.get("summary") or {}).items() if not isinstance(v, (list, dict))},
        "exclusions": result.get("exclusions"),
        "surfaceRatio": result.get("surfaceRatio"),
        "quartetFilter": result.get("quartetFilter"),
        "comparison": result.get("comparison"),
        "warnings": result.get("warnings"),
    }


def measure_table(result: Mapping[str, Any], source: str | None = None) -> pd.DataFrame:
    """One row per measured cell and layer (a measure result as a dict).

    Columns: layer (0 = basal first), layer_name, cell (dense id), label (the segmentation's),
    valid, scutoid, area (µm²), sides, neighbours (count on the layer), won, lost, transitions,
    neighbours3D, excluded (the reason, or None); a volume adds volume (µm³), height (µm),
    cx, cy, cz (the cell's face centroid on the layer, µm) and lateral_neighbours.
    """
    if not isinstance(result, Mapping) or result.get("kind") != "measured" or "cells" not in result:
        raise ResultFormatError(f'{source or "result"}: not a tissue-sheet measure result (kind "measured")')
    inputs = result.get("inputs") or {}
    layers = inputs.get("layers") or []
    volume = "volume" in inputs
    rows = []
    for c in result["cells"]:
        for k in range(len(c.get("areas") or [])):
            row = {
                "layer": k,
                "layer_name": layers[k].get("name") if k < len(layers) else None,
                "cell": c.get("id"),
                "label": c.get("label"),
                "valid": bool(c.get("valid")),
                "scutoid": bool(c.get("scutoid")),
                "area": c["areas"][k],
                "sides": c["sides"][k],
                "neighbours": len(c["neighbours"][k]) if c.get("neighbours") else 0,
                "won": c.get("won"),
                "lost": c.get("lost"),
                "transitions": c.get("transitions"),
                "neighbours3D": c.get("neighbours3D"),
                "excluded": (c.get("exclusion") or {}).get("reason"),
            }
            if volume:
                centroid = (c.get("centroids") or [None] * (k + 1))[k] or [None, None, None]
                row.update(
                    {
                        "volume": c.get("volume"),
                        "height": c.get("height"),
                        "cx": centroid[0],
                        "cy": centroid[1],
                        "cz": centroid[2],
                        "lateral_neighbours": len(c.get("lateralNeighbours") or []),
                    }
                )
            rows.append(row)
    df = pd.DataFrame(rows)
    for column in ("area", "volume", "height", "cx", "cy", "cz"):
        if column in df:
            df[column] = df[column].astype(float)
    df.attrs.update(measure_provenance(result, source))
    return df


def read_measure(path: str | os.PathLike, table: str = "cells") -> pd.DataFrame:
    """A ``tissue-sheet measure`` result (layers or ``--volume``): ``table`` "cells" or "summary"."""
    result = _load_json(Path(path))
    if table == "cells":
        return measure_table(result, str(path))
    if table == "summary":
        if not isinstance(result, Mapping) or result.get("kind") != "measured":
            raise ResultFormatError(f'{path}: not a tissue-sheet measure result (kind "measured")')
        return summary_table(result, str(path))
    raise ValueError(f'table: {table!r} is not "cells" or "summary"')
