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
import re
from collections import abc
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


# --------------------------------------------------------------------------- checking shapes
# A result file is data from anyone (edited, truncated, another program's): every reader checks
# each field it reads, so damage raises ResultFormatError naming the file and the field, never a
# bare KeyError or TypeError from deep inside pandas.

# What a file that is not JSON text starts with, to say what it is.
_MAGIC = {b"\x89PNG": "a PNG image", b"II*\0": "a TIFF image", b"MM\0*": "a TIFF image", b"TSCELLS1": "a cells side file"}


def _json_type(value: Any) -> str:
    """A JSON value's kind, as a message names it."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, (int, float)):
        return f"the number {value!r}"
    if isinstance(value, str):
        return f"the string {value[:40]!r}"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, Mapping):
        return "an object"
    return type(value).__name__


def _bad(name: str, what: str, value: Any, wanted: str) -> ResultFormatError:
    return ResultFormatError(f"{name}: {what} is {_json_type(value)}, not {wanted}")


def _field(obj: Mapping[str, Any], key: str, name: str, what: str) -> Any:
    if key not in obj:
        raise ResultFormatError(f"{name}: {what} has no {key}")
    return obj[key]


def _object(value: Any, name: str, what: str) -> Mapping[str, Any]:
    # collections.abc, not typing: typing's isinstance is slow, and this runs once per cell.
    if type(value) is not dict and not isinstance(value, abc.Mapping):
        raise _bad(name, what, value, "an object")
    return value


def _optional_object(parent: Mapping[str, Any], key: str, name: str, what: str | None = None) -> Mapping[str, Any]:
    """``parent[key]`` as an object; {} where it is missing or null (provenance the CLI may leave out)."""
    value = parent.get(key)
    return {} if value is None else _object(value, name, what or key)


def _list(value: Any, name: str, what: str, length: int | None = None, per: str = "") -> list:
    """A list; of ``length`` entries where given (``per`` says what each is for: "layer", "surface")."""
    if not isinstance(value, list):
        raise _bad(name, what, value, "a list")
    if length is not None and len(value) != length:
        raise ResultFormatError(f"{name}: {what} has {len(value)} entries, not {length}" + (f" (one per {per})" if per else ""))
    return value


def _objects(value: Any, name: str, what: str) -> list:
    """A list of objects (surfaces, analyses, layers): each checked, so later ``.get`` is safe."""
    for i, item in enumerate(_list(value, name, what)):
        _object(item, name, f"{what}[{i}]")
    return value


def _is_number(value: Any) -> bool:
    return type(value) in (int, float) or (isinstance(value, (int, float)) and not isinstance(value, bool))


def _float(value: Any, name: str, what: str, null: bool = False) -> float:
    """A number; null read as NaN where ``null`` (JSON writes a NaN as null)."""
    if null and value is None:
        return math.nan
    if not _is_number(value):
        raise _bad(name, what, value, "a number")
    return float(value)


def _floats(value: Any, name: str, what: str, length: int | None = None, null: bool = False, per: str = "") -> list:
    return [_float(v, name, f"{what}[{i}]", null) for i, v in enumerate(_list(value, name, what, length, per))]


def _count(value: Any, name: str, what: str, below: int = 2**31, wanted: str = "a whole number >= 0") -> int:
    """A whole number in [0, below): counts, ids, labels (int32 columns hold them)."""
    if not (_is_number(value) and math.isfinite(value) and value == int(value) and 0 <= value < below):
        raise _bad(name, what, value, wanted)
    return int(value)


def _boolean(value: Any, name: str, what: str) -> bool:
    if not isinstance(value, bool):
        raise _bad(name, what, value, "true or false")
    return value


def _read_text(path: Path, what: str = "a result file") -> str:
    """A file's UTF-8 text; a directory or a binary file is a ResultFormatError naming it."""
    if path.is_dir():
        raise ResultFormatError(f"{path}: a directory, not {what}")
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise FileNotFoundError(f"{path}: no such file") from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        kind = next((k for magic, k in _MAGIC.items() if data.startswith(magic)), "binary data")
        raise ResultFormatError(f"{path}: not {what} but {kind} (not UTF-8 text at byte {e.start})") from None


# --------------------------------------------------------------------------- run results


def _load_json(path: Path) -> Any:
    text = _read_text(path)
    try:
        return json.loads(text)
    except json.JSONDecodeError as e:
        raise ResultFormatError(f"{path}: not JSON ({e.msg} at line {e.lineno} column {e.colno})") from None


def decode_cells_file(record: Mapping[str, Any], data: bytes, name: str = "cells file") -> dict:
    """The side file's columns as numpy arrays, checked against the JSON's ``cellsFile`` record.

    Returns ``{"cells": {column: array}, "surfaces": [...], "analyses": [...]}`` in the JSON's
    order (the layout of README, "Large results: the cells side file").
    """
    record = _object(record, name, "cellsFile")
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
        c = _object(c, name, f"{table['of']}.{column}")
        dtype = _DTYPES.get(c.get("type")) if isinstance(c.get("type"), str) else None
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

    tables = {}
    for i, t in enumerate(_objects(record.get("tables", []), name, "cellsFile.tables")):
        if not isinstance(t.get("of"), str):
            raise _bad(name, f"cellsFile.tables[{i}].of", t.get("of"), "a table name")
        _object(t.get("columns"), name, f"cellsFile.tables[{i}].columns")
        tables[t["of"]] = t

    def find(of: str) -> Mapping[str, Any]:
        if of not in tables:
            raise ResultFormatError(f"{name}: no table for {of}")
        return tables[of]

    def ordered(prefix: str) -> list[str]:
        numbered = {int(m.group(1)): k for k in tables for m in [re.fullmatch(re.escape(prefix) + r"\[(\d+)\]\.cells", k)] if m}
        if sorted(numbered) != list(range(len(numbered))):
            raise ResultFormatError(f"{name}: the {prefix} tables are numbered {sorted(numbered)}, not 0 to {len(numbered) - 1}")
        return [numbered[i] for i in range(len(numbered))]

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


def _cell_columns_from_records(cells: Any, name: str, of: str) -> dict:
    """The side file's columns built from a JSON cell list, each field checked as it is read (so
    both forms share one table builder, and ``_check_tables`` checks both)."""
    cells = _list(cells, name, of)
    n = len(cells)
    position: list = []
    surface: list = []
    area, border, ids, lengths, offsets = [], [], [], [], [0]
    for i, c in enumerate(cells):
        what = f"{of}[{i}]"
        c = _object(c, name, what)
        # JSON writes a NaN as null: read it back as the side file holds it.
        position += _floats(_field(c, "position", name, what), name, f"{what}.position", 3, null=True)
        surface += _floats(_field(c, "surface", name, what), name, f"{what}.surface", 2, null=True)
        area.append(_float(_field(c, "area", name, what), name, f"{what}.area", null=True))
        border.append(_boolean(_field(c, "touchesBorder", name, what), name, f"{what}.touchesBorder"))
        for j, nb in enumerate(_list(_field(c, "neighbours", name, what), name, f"{what}.neighbours")):
            at = f"{what}.neighbours[{j}]"
            nb = _object(nb, name, at)
            ids.append(_count(_field(nb, "id", name, at), name, f"{at}.id", n, f"a cell of the {n} (0 to {n - 1})"))
            lengths.append(_float(_field(nb, "length", name, at), name, f"{at}.length", null=True))
        offsets.append(len(ids))
    return {
        "count": n,
        "position": np.array(position, dtype="<f8"),
        "surface": np.array(surface, dtype="<f8"),
        "area": np.array(area, dtype="<f8"),
        "touchesBorder": np.array(border, dtype="u1"),
        "neighbourOffsets": np.array(offsets, dtype="<i4"),
        "neighbourIds": np.array(ids, dtype="<i4"),
        "neighbourLengths": np.array(lengths, dtype="<f8"),
    }


def _analysis_columns_from_records(cells: Any, name: str, of: str, surfaces: int) -> dict:
    """An analysis's per-cell columns from its JSON list; ``sides`` has one entry per surface of the stack."""
    cells = _list(cells, name, of)
    n = len(cells)
    flags: dict = {"valid": [], "scutoid": []}
    counts: dict = {"won": [], "lost": [], "transitions": [], "neighbours3D": []}
    sides = np.zeros(surfaces * n, dtype="<i4")
    for i, c in enumerate(cells):
        what = f"{of}[{i}]"
        c = _object(c, name, what)
        for key, values in flags.items():
            values.append(_boolean(_field(c, key, name, what), name, f"{what}.{key}"))
        for key, values in counts.items():
            values.append(_count(_field(c, key, name, what), name, f"{what}.{key}"))
        for k, value in enumerate(_list(_field(c, "sides", name, what), name, f"{what}.sides", surfaces, "surface")):
            sides[k * n + i] = _count(value, name, f"{what}.sides[{k}]")
    out = {key: np.array(values, dtype="u1") for key, values in flags.items()}
    out.update({key: np.array(values, dtype="<i4") for key, values in counts.items()})
    out.update(count=n, sides=sides)
    return out


def _result_tables(result: Mapping[str, Any], tables: dict | None, name: str) -> dict:
    """The per-cell columns: the side file's (checked when decoded), else built from the JSON's lists and checked alike."""
    if tables is not None:
        return tables
    if result.get("cells") is None:
        raise ResultFormatError(f"{name}: the result has no per-cell lists (cells is null) and no cellsFile")
    surfaces, analyses = result["surfaces"], result["analyses"]
    cell_names = ["cells"] + [f"surfaces[{k}].cells" for k in range(len(surfaces))]
    analysis_names = [f"analyses[{k}].cells" for k in range(len(analyses))]
    out = {
        "cells": _cell_columns_from_records(result["cells"], name, "cells"),
        "surfaces": [_cell_columns_from_records(_field(s, "cells", name, f"surfaces[{k}]"), name, cell_names[k + 1]) for k, s in enumerate(surfaces)],
        "analyses": [
            _analysis_columns_from_records(_field(a, "cells", name, f"analyses[{k}]"), name, analysis_names[k], len(cell_names))
            for k, a in enumerate(analyses)
        ],
    }
    _check_tables(name, out, cell_names, analysis_names)
    return out


def _is_result(result: Any) -> bool:
    return isinstance(result, Mapping) and all(k in result for k in ("config", "surfaces", "analyses", "headline"))


def _check_result(result: Any, name: str, what: str = "not a tissue-sheet run result (needs config, surfaces, analyses, headline)") -> None:
    """A run result's frame: the objects and lists every table reads (the cells are checked where they are read)."""
    if not _is_result(result):
        raise ResultFormatError(f"{name}: {what}")
    _optional_object(_object(result["config"], name, "config"), "sheet", name, "config.sheet")
    _object(result["headline"], name, "headline")
    _objects(result["surfaces"], name, "surfaces")
    _objects(result["analyses"], name, "analyses")


def result_provenance(result: Mapping[str, Any], source: str | None = None) -> dict:
    """What made a result: software version, config, seed, engine, method, headline."""
    name = source or "result"
    headline = _optional_object(result, "headline", name)
    lloyd = _optional_object(result, "lloyd", name)
    iterations = lloyd.get("iterations")
    return {
        "kind": "result",
        "source": source,
        "software": result.get("software"),
        "version": _optional_object(result, "software", name).get("version"),
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
        "lloyd": {
            "converged": lloyd.get("converged"),
            "finalEnergy": lloyd.get("finalEnergy"),
            "iterations": 0 if iterations is None else len(_list(iterations, name, "lloyd.iterations")),
        },
    }


def _stack(result: Mapping[str, Any], name: str) -> list[dict]:
    """The surfaces in stack order: the seeded one (the JSON's ``cells``), then ``surfaces``."""
    seeded = (result.get("config") or {}).get("sheet", {}) or {}
    stack = [{"name": seeded.get("seeded", "seeded"), "role": "seeded", "offset": 0.0, "ratio": 1.0}]
    for k, s in enumerate(result["surfaces"]):
        offset = _float(s.get("offset"), name, f"surfaces[{k}].offset", null=True)
        ratio = _float(s.get("ratio"), name, f"surfaces[{k}].ratio", null=True)
        stack.append({"name": s.get("name"), "role": s.get("role"), "offset": offset, "ratio": ratio})
    return stack


def _check_stack(result: Mapping[str, Any], t: dict, stack: list, name: str) -> None:
    """The side file's tables against the JSON: one per surface and analysis, sides for every surface (else zip truncates)."""
    if len(t["surfaces"]) != len(result["surfaces"]):
        raise ResultFormatError(f"{name}: {len(t['surfaces'])} surface tables of cells where the result lists {len(result['surfaces'])} surfaces")
    if len(t["analyses"]) != len(result["analyses"]):
        raise ResultFormatError(f"{name}: {len(t['analyses'])} analysis tables of cells where the result lists {len(result['analyses'])} analyses")
    for k, a in enumerate(t["analyses"]):
        if len(a["sides"]) != len(stack) * a["count"]:
            raise ResultFormatError(f"{name}: analyses[{k}] sides hold {len(a['sides'])} values, not one per cell on each of the {len(stack)} surfaces")


def cells_table(result: Mapping[str, Any], tables: dict | None = None, source: str | None = None) -> pd.DataFrame:
    """One row per cell and surface of a run's result (a dict as the CLI or the widget gives it).

    Columns: surface (0 = seeded, then the stack's order), surface_name, role (seeded, layer,
    other), offset (µm), ratio, cell (id), x, y, z (µm), u, v (unrolled, µm), area (µm²),
    touches_border, neighbours (count), contact_length (µm, summed over the neighbours), and per
    analysis METHOD (``exact``, ``labels``): METHOD.valid, METHOD.scutoid, METHOD.won,
    METHOD.lost, METHOD.transitions, METHOD.neighbours3D (per cell, the same on every surface)
    and METHOD.sides (on this surface).
    """
    name = source or "result"
    _check_result(result, name)
    t = _result_tables(result, tables, name)
    stack = _stack(result, name)
    _check_stack(result, t, stack, name)
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
                raise ResultFormatError(f"{name}: analysis {m} has {a['count']} cells, surface {k} has {n}")
            frame[f"{m}.valid"] = np.asarray(a["valid"]).astype(bool)
            frame[f"{m}.scutoid"] = np.asarray(a["scutoid"]).astype(bool)
            for stat in ("won", "lost", "transitions", "neighbours3D"):
                frame[f"{m}.{stat}"] = np.asarray(a[stat]).astype(np.int64)
            frame[f"{m}.sides"] = np.asarray(a["sides"])[k * n : (k + 1) * n].astype(np.int64)
        frames.append(pd.DataFrame(frame))
    df = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()
    df.attrs.update(result_provenance(result, source))
    return df


def contacts_table(result: Mapping[str, Any], tables: dict | None = None, source: str | None = None) -> pd.DataFrame:
    """One row per contact of a run's result: surface, cell, neighbour, length (µm); both directions."""
    name = source or "result"
    _check_result(result, name, "not a tissue-sheet run result")
    t = _result_tables(result, tables, name)
    _check_stack(result, t, _stack(result, name), name)
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


def _layer_min_contacts(result: Mapping[str, Any], name: str) -> list | None:
    """Each surface's own min contact where a result has one per surface: a measured volume
    (``inputs.layers[k].minContact``, the default scaled to that surface's cells, so apical and
    basal differ; ``minContactLength`` is the basal one). None where one threshold serves every
    surface (a run, measured layers): ``analyses[].minContactLength``."""
    if result.get("kind") != "measured":
        return None
    inputs = _optional_object(result, "inputs", name)
    if "volume" not in inputs:
        return None
    layers = _objects(_field(inputs, "layers", name, "inputs"), name, "inputs.layers")
    return [_float(_field(layer, "minContact", name, f"inputs.layers[{k}]"), name, f"inputs.layers[{k}].minContact") for k, layer in enumerate(layers)]


def summary_table(result: Mapping[str, Any], source: str | None = None) -> pd.DataFrame:
    """One row per analysis (adjacency method) and surface: the analysis's summary.

    Columns: method, protocol, min_contact_length (µm; a measured volume's per surface), then the
    summary's numbers (cells, validCells, excludedCells, scutoids, percentScutoids,
    percentScutoidsEnds, meanTransitions, meanWon, meanLost, meanNeighbours3D), and per surface:
    surface (stack index), surface_name, meanSides, meanArea, polygons.3 ... polygons.10+
    (fractions of the valid cells).
    """
    name = source or "result"
    if not isinstance(result, Mapping) or "analyses" not in result:
        raise ResultFormatError(f"{name}: no analyses")
    min_contacts = _layer_min_contacts(result, name)
    rows = []
    classes = ["3", "4", "5", "6", "7", "8", "9", "10+"]
    for i, a in enumerate(_objects(result["analyses"], name, "analyses")):
        what = f"analyses[{i}].summary"
        summary = _optional_object(a, "summary", name, what)
        base = {"method": a.get("method"), "protocol": a.get("protocol"), "min_contact_length": a.get("minContactLength")}
        for key, value in summary.items():
            if not isinstance(value, (list, dict)):
                base[key] = value
        per_surface = summary.get("perSurface")
        per_surface = _objects(per_surface, name, f"{what}.perSurface") if per_surface is not None else []
        for k, surface in enumerate(per_surface or [{}]):
            row = dict(base)
            if min_contacts is not None and k < len(min_contacts):
                row["min_contact_length"] = min_contacts[k]
            row["surface"] = k
            row["surface_name"] = surface.get("label")
            row["meanSides"] = surface.get("meanSides")
            row["meanArea"] = surface.get("meanArea")
            distribution = surface.get("polygonDistribution")
            if distribution is not None:
                distribution = _floats(distribution, name, f"{what}.perSurface[{k}].polygonDistribution", null=True)
            for c, f in zip(classes, distribution or []):
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
    record = _object(record, str(path), "cellsFile")
    name = record.get("path")
    # The side file is named relative to the JSON and never leaves its directory.
    if not isinstance(name, str) or os.path.basename(name) != name or name.startswith("."):
        raise ResultFormatError(f"{path}: cellsFile.path {name!r} is not a file name in the result's directory")
    side = path.parent / name
    if side.is_dir():
        raise ResultFormatError(f"{path}: its side file {side} is a directory")
    try:
        data = side.read_bytes()
    except FileNotFoundError:
        raise FileNotFoundError(f"{path}: its side file {side} is missing (copy RESULT.json and RESULT.cells.bin together)") from None
    return result, decode_cells_file(record, data, str(side))


def read_result(path: str | os.PathLike, table: str = "cells") -> pd.DataFrame:
    """A ``tissue-sheet run`` result as a table (``table``: "cells", "contacts" or "summary").

    Reads the plain JSON and the compact form (JSON + ``RESULT.cells.bin``) alike.
    """
    if table not in ("cells", "contacts", "summary"):
        raise ValueError(f'table: {table!r} is not one of "cells", "contacts", "summary"')
    result, tables = read_result_json(path)
    if result.get("kind") == "measured":
        raise ResultFormatError(f"{path}: a measure result; read it with read_measure")
    if table == "cells":
        return cells_table(result, tables, str(path))
    if table == "contacts":
        return contacts_table(result, tables, str(path))
    _check_result(result, str(path))
    return summary_table(result, str(path))


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
        if len(set(header)) != len(header):
            raise ResultFormatError(f"{name}: repeated column names in the header")
        rows = []
        for line, row in enumerate(reader, start=2):
            if not row:
                continue
            if len(row) != len(header):
                raise ResultFormatError(f"{name}: line {line} has {len(row)} cells where the header has {len(header)}")
            rows.append(row)
    except StopIteration:
        raise ResultFormatError(f"{name}: empty (no header)") from None
    except csv.Error as e:
        raise ResultFormatError(f"{name}: not CSV ({e} at line {reader.line_num})") from None
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
    sweep = _object(sweep or {}, source or "sweep", "sweep.json")
    return {
        "kind": "sweep",
        "source": source,
        "software": sweep.get("software"),
        "version": _optional_object(sweep, "software", source or "sweep", "sweep.json's software").get("version"),
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
    df = read_csv_text(_read_text(csv_path, f"{table}.csv"), str(csv_path))
    df.attrs.update(sweep_provenance(sweep, str(directory)))
    return df


# --------------------------------------------------------------------------- measure results


def _check_measure(result: Any, name: str) -> tuple[list, bool]:
    """A measure result's frame: returns its layers (``inputs.layers``, two or more) and whether it is a volume."""
    if not isinstance(result, Mapping) or result.get("kind") != "measured":
        raise ResultFormatError(f'{name}: not a tissue-sheet measure result (kind "measured")')
    inputs = _object(_field(result, "inputs", name, "the result"), name, "inputs")
    layers = _objects(_field(inputs, "layers", name, "inputs"), name, "inputs.layers")
    if len(layers) < 2:
        raise ResultFormatError(f"{name}: inputs.layers lists {len(layers)} layer(s); a measure result has two or more")
    _objects(_field(result, "analyses", name, "the result"), name, "analyses")
    return layers, "volume" in inputs


def measure_provenance(result: Mapping[str, Any], source: str | None) -> dict:
    name = source or "result"
    inputs = _optional_object(result, "inputs", name)
    analyses = _objects(result.get("analyses") or [], name, "analyses")
    analysis = analyses[0] if analyses else {}
    return {
        "kind": "measured",
        "mode": "volume" if "volume" in inputs else "layers",
        "source": source,
        "software": result.get("software"),
        "version": _optional_object(result, "software", name).get("version"),
        "inputs": inputs,
        "method": analysis.get("method"),
        "minContactLength": analysis.get("minContactLength"),
        "summary": {k: v for k, v in _optional_object(analysis, "summary", name, "analyses[0].summary").items() if not isinstance(v, (list, dict))},
        "exclusions": result.get("exclusions"),
        "surfaceRatio": result.get("surfaceRatio"),
        "quartetFilter": result.get("quartetFilter"),
        "comparison": result.get("comparison"),
        "warnings": result.get("warnings"),
    }


def _volume_columns(c: Mapping[str, Any], what: str, layers: int, name: str) -> list[dict]:
    """A volume cell's added columns, per layer: volume, height, its face centroid there, lateral neighbours."""
    volume = _float(_field(c, "volume", name, what), name, f"{what}.volume")
    # null: the cell misses a surface (no face there, so no centroid and no height).
    height = _float(_field(c, "height", name, what), name, f"{what}.height", null=True)
    lateral = len(_list(_field(c, "lateralNeighbours", name, what), name, f"{what}.lateralNeighbours"))
    out = []
    for k, point in enumerate(_list(_field(c, "centroids", name, what), name, f"{what}.centroids", layers, "layer")):
        x, y, z = [math.nan] * 3 if point is None else _floats(point, name, f"{what}.centroids[{k}]", 3)
        out.append({"volume": volume, "height": height, "cx": x, "cy": y, "cz": z, "lateral_neighbours": lateral})
    return out


def _measure_rows(c: Mapping[str, Any], what: str, layers: list, volume: bool, name: str) -> list[dict]:
    """One measured cell's rows, one per layer: every per-layer list must hold one entry per layer
    (a short or missing one would drop or shift the cell's rows silently)."""
    K = len(layers)

    def get(key: str) -> Any:
        return _field(c, key, name, what)

    areas = _floats(get("areas"), name, f"{what}.areas", K, per="layer")
    sides = [_count(v, name, f"{what}.sides[{k}]") for k, v in enumerate(_list(get("sides"), name, f"{what}.sides", K, "layer"))]
    neighbours = [len(_list(v, name, f"{what}.neighbours[{k}]")) for k, v in enumerate(_list(get("neighbours"), name, f"{what}.neighbours", K, "layer"))]
    exclusion = c.get("exclusion")
    cell = {
        "cell": _count(get("id"), name, f"{what}.id"),
        "label": _count(get("label"), name, f"{what}.label", 2**32, "a label (a whole number >= 0)"),
        "valid": _boolean(get("valid"), name, f"{what}.valid"),
        "scutoid": _boolean(get("scutoid"), name, f"{what}.scutoid"),
    }
    stats = {key: _count(get(key), name, f"{what}.{key}") for key in ("won", "lost", "transitions", "neighbours3D")}
    stats["excluded"] = None if exclusion is None else _object(exclusion, name, f"{what}.exclusion").get("reason")
    extra = _volume_columns(c, what, K, name) if volume else [{}] * K
    return [
        {"layer": k, "layer_name": layers[k].get("name"), **cell, "area": areas[k], "sides": sides[k], "neighbours": neighbours[k], **stats, **extra[k]}
        for k in range(K)
    ]


def measure_table(result: Mapping[str, Any], source: str | None = None) -> pd.DataFrame:
    """One row per measured cell and layer (a measure result as a dict).

    Columns: layer (0 = basal first), layer_name, cell (dense id), label (the segmentation's),
    valid, scutoid, area (µm²), sides, neighbours (count on the layer), won, lost, transitions,
    neighbours3D, excluded (the reason, or None); a volume adds volume (µm³), height (µm),
    cx, cy, cz (the cell's face centroid on the layer, µm) and lateral_neighbours.
    """
    name = source or "result"
    layers, volume = _check_measure(result, name)
    cells = _list(_field(result, "cells", name, "the result"), name, "cells")
    if not cells:
        # The CLI refuses images and volumes without labels, so a result it wrote has cells.
        raise ResultFormatError(f"{name}: cells is empty; a measure result lists every labelled cell")
    rows = []
    for i, c in enumerate(cells):
        rows += _measure_rows(_object(c, name, f"cells[{i}]"), f"cells[{i}]", layers, volume, name)
    df = pd.DataFrame(rows)
    for column in ("area", "volume", "height", "cx", "cy", "cz"):
        if column in df:
            df[column] = df[column].astype(float)
    df.attrs.update(measure_provenance(result, source))
    return df


def read_measure(path: str | os.PathLike, table: str = "cells") -> pd.DataFrame:
    """A ``tissue-sheet measure`` result (layers or ``--volume``): ``table`` "cells" or "summary"."""
    if table not in ("cells", "summary"):
        raise ValueError(f'table: {table!r} is not "cells" or "summary"')
    result = _load_json(Path(path))
    if table == "cells":
        return measure_table(result, str(path))
    _check_measure(result, str(path))
    return summary_table(result, str(path))
