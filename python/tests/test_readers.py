"""Readers against outputs the CLI wrote in this session, checked against the JSON read by hand."""

import csv
import json
import math
import shutil

import numpy as np
import pandas as pd
import pytest

import tissue_sheet
from conftest import CONFIGS, ROOT, SWEEP, TUBE


@pytest.mark.parametrize("name", list(CONFIGS))
def test_cells_table_is_the_json_cell_by_cell(outputs, name):
    result = json.loads((outputs / f"{name}-plain.json").read_text())
    df = tissue_sheet.read_result(outputs / f"{name}-plain.json")
    stack = [result["cells"]] + [s["cells"] for s in result["surfaces"]]
    assert len(df) == sum(len(cells) for cells in stack) == CONFIGS[name]["cells"] * len(stack)
    assert list(df["surface_name"].unique()) == [result["config"]["sheet"]["seeded"]] + [s["name"] for s in result["surfaces"]]
    methods = [a["method"] for a in result["analyses"]]
    for k, cells in enumerate(stack):
        rows = df[df["surface"] == k].set_index("cell")
        for c in cells:
            row = rows.loc[c["id"]]
            assert [row["x"], row["y"], row["z"]] == c["position"]
            assert [row["u"], row["v"]] == c["surface"]
            assert row["area"] == c["area"]
            assert row["touches_border"] == c["touchesBorder"]
            assert row["neighbours"] == len(c["neighbours"])
            assert row["contact_length"] == pytest.approx(sum(n["length"] for n in c["neighbours"]), rel=1e-12)
        for m, analysis in zip(methods, result["analyses"]):
            for a in analysis["cells"]:
                row = rows.loc[a["id"]]
                assert row[f"{m}.sides"] == a["sides"][k]
                assert (row[f"{m}.valid"], row[f"{m}.scutoid"]) == (a["valid"], a["scutoid"])
                assert (row[f"{m}.won"], row[f"{m}.lost"], row[f"{m}.transitions"], row[f"{m}.neighbours3D"]) == (
                    a["won"],
                    a["lost"],
                    a["transitions"],
                    a["neighbours3D"],
                )


def test_headline_follows_from_the_table(outputs):
    df = tissue_sheet.read_result(outputs / "plain.json")
    method = df.attrs["method"]
    seeded = df[df["surface"] == 0]
    valid = seeded[f"{method}.valid"]
    percent = 100 * (seeded[f"{method}.scutoid"] & valid).sum() / valid.sum()
    assert df.attrs["headline"]["percentScutoids"] == pytest.approx(percent, abs=1e-9)
    assert 0 < percent < 100  # a tube with s = 2 has scutoids and non-scutoids


@pytest.mark.parametrize("name", list(CONFIGS))
def test_side_file_and_json_read_the_same(outputs, name):
    plain = tissue_sheet.read_result(outputs / f"{name}-plain.json")
    compact = tissue_sheet.read_result(outputs / f"{name}-compact.json")
    assert (outputs / f"{name}-compact.cells.bin").read_bytes()[:8] == b"TSCELLS1"
    assert json.loads((outputs / f"{name}-compact.json").read_text())["cells"] is None
    pd.testing.assert_frame_equal(plain, compact, check_dtype=False, check_exact=True)
    for table in ("contacts", "summary"):
        pd.testing.assert_frame_equal(
            tissue_sheet.read_result(outputs / f"{name}-plain.json", table),
            tissue_sheet.read_result(outputs / f"{name}-compact.json", table),
            check_dtype=False,
        )


def test_both_methods_are_columns(outputs):
    df = tissue_sheet.read_result(outputs / "gpu-compact.json")
    assert df.attrs["engine"]["name"] == "gpu"
    for method in ("labels", "exact"):
        assert {f"{method}.valid", f"{method}.scutoid", f"{method}.sides"} <= set(df.columns)
    summary = tissue_sheet.read_result(outputs / "gpu-compact.json", "summary")
    assert sorted(summary["method"].unique()) == ["exact", "labels"]


def test_contacts_are_symmetric(outputs):
    contacts = tissue_sheet.read_result(outputs / "compact.json", "contacts")
    forward = {(r.surface, r.cell, r.neighbour): r.length for r in contacts.itertuples()}
    assert forward and all(forward[(s, b, a)] == pytest.approx(length) for (s, a, b), length in forward.items())


def test_provenance(outputs):
    df = tissue_sheet.read_result(outputs / "compact.json")
    npm = json.loads((ROOT / "package.json").read_text())["version"]
    assert df.attrs["version"] == npm == tissue_sheet.__version__
    assert df.attrs["seed"] == TUBE["seed"]
    assert df.attrs["config"]["cells"] == TUBE["cells"]
    assert df.attrs["engine"]["name"] in ("exact", "gpu")
    assert df.attrs["method"] in ("exact", "labels")
    assert df.attrs["source"].endswith("compact.json")


def test_summary_table_is_the_json_summary(outputs):
    result = json.loads((outputs / "plain.json").read_text())
    summary = tissue_sheet.read_result(outputs / "plain.json", "summary")
    for a in result["analyses"]:
        rows = summary[summary["method"] == a["method"]]
        assert len(rows) == len(a["summary"]["perSurface"])
        for k, surface in enumerate(a["summary"]["perSurface"]):
            row = rows[rows["surface"] == k].iloc[0]
            assert row["percentScutoids"] == a["summary"]["percentScutoids"]
            assert row["meanSides"] == surface["meanSides"]
            assert [row[f"polygons.{c}"] for c in ("3", "4", "5", "6", "7", "8", "9", "10+")] == surface["polygonDistribution"]


def test_sweep_table_is_runs_csv_whatever_its_columns(outputs):
    directory = outputs / "sweep"
    runs = tissue_sheet.read_sweep(directory)
    with open(directory / "runs.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert list(runs.columns) == rows[0]
    assert len(runs) == len(rows) - 1 == len(SWEEP["vary"]["sheet.surfaceRatio"]) * SWEEP["realizations"]
    for i, row in enumerate(rows[1:]):
        for column, text in zip(rows[0], row):
            value = runs[column].iloc[i]
            if text == "":
                assert isinstance(value, float) and math.isnan(value)
            else:
                try:
                    assert value == float(text)
                except ValueError:
                    assert value == text
    assert runs.attrs["spec"]["vary"] == SWEEP["vary"]
    assert runs.attrs["version"] == tissue_sheet.__version__
    aggregate = tissue_sheet.read_sweep(directory, "aggregate")
    assert len(aggregate) == len(SWEEP["vary"]["sheet.surfaceRatio"])
    # Renamed headers (units, base geometry) read as they are: nothing is hard-coded.
    renamed = outputs / "renamed"
    shutil.copytree(directory, renamed, dirs_exist_ok=True)
    text = (renamed / "runs.csv").read_text().replace("sheet.surfaceRatio", "sheet.surfaceRatio (1)", 1)
    (renamed / "runs.csv").write_text(text)
    again = tissue_sheet.read_sweep(renamed)
    assert "sheet.surfaceRatio (1)" in again.columns
    assert list(again["sheet.surfaceRatio (1)"]) == list(runs["sheet.surfaceRatio"])


def _poke_int32(directory, of, column, index, value):
    """Writes one int32 of a side-file column in place (the column found from the JSON's record)."""
    record = json.loads((directory / "compact.json").read_text())["cellsFile"]
    entry = next(t for t in record["tables"] if t["of"] == of)["columns"][column]
    data = bytearray((directory / "compact.cells.bin").read_bytes())
    data[entry["offset"] + 4 * index : entry["offset"] + 4 * index + 4] = int(value).to_bytes(4, "little", signed=True)
    (directory / "compact.cells.bin").write_bytes(bytes(data))


def _edit_record(directory, edit):
    result = json.loads((directory / "compact.json").read_text())
    edit(result["cellsFile"])
    (directory / "compact.json").write_text(json.dumps(result))


@pytest.mark.parametrize(
    "damage, message",
    [
        (lambda d: _poke_int32(d, "cells", "neighbourIds", 0, 10**6), r"cells.neighbourIds\[0\] is 1000000, not a cell of the"),
        (lambda d: _poke_int32(d, "cells", "neighbourOffsets", 2, 2**31 - 1), "cells.neighbourOffsets decreases at cell 2"),
        (lambda d: _poke_int32(d, "cells", "neighbourOffsets", 0, 1), "cells.neighbourOffsets starts at 1, not 0"),
        (lambda d: _edit_record(d, lambda r: r["tables"][0]["columns"]["area"].update(type="int32")), "cells.area must be float64"),
        (lambda d: _edit_record(d, lambda r: r["tables"][-1].update(count=1)), "cells where the file's cells table has"),
        (lambda d: _edit_record(d, lambda r: r["tables"][0].update(count=1.5)), "count 1.5 is not a whole number of cells"),
        (lambda d: (d / "compact.cells.bin").write_bytes((d / "compact.cells.bin").read_bytes()[:-8]), "bytes where the result says"),
        (lambda d: (d / "compact.cells.bin").write_bytes(b"XXXXXXXX" + (d / "compact.cells.bin").read_bytes()[8:]), "no TSCELLS1 header"),
        (lambda d: (d / "compact.cells.bin").unlink(), "side file"),
        (
            lambda d: (d / "compact.json").write_text((d / "compact.json").read_text().replace('"path": "compact.cells.bin"', '"path": "../x.bin"')),
            "is not a file name in the result's directory",
        ),
        (lambda d: (d / "compact.json").write_text("{ not json"), "not JSON"),
    ],
)
def test_damaged_results_are_refused_by_name(outputs, tmp_path, damage, message):
    for name in ("compact.json", "compact.cells.bin"):
        shutil.copy(outputs / name, tmp_path / name)
    # The JSON's own spacing: match both compact and pretty forms of the path.
    text = (tmp_path / "compact.json").read_text()
    (tmp_path / "compact.json").write_text(json.dumps(json.loads(text)))
    damage(tmp_path)
    with pytest.raises((ValueError, FileNotFoundError), match=message.replace("(", r"\(")):
        tissue_sheet.read_result(tmp_path / "compact.json")


def test_wrong_kinds_are_refused(outputs, tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        tissue_sheet.read_result(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="not a tissue-sheet measure result"):
        tissue_sheet.read_measure(outputs / "plain.json")
    with pytest.raises(FileNotFoundError, match="not a directory"):
        tissue_sheet.read_sweep(outputs / "plain.json")
    with pytest.raises(FileNotFoundError, match="runs.csv: missing"):
        tissue_sheet.read_sweep(tmp_path)
    with pytest.raises(ValueError, match="table"):
        tissue_sheet.read_result(outputs / "plain.json", "cell")
    bad = tmp_path / "bad.csv"
    with pytest.raises(ValueError, match="line 2 has 1 cells where the header has 2"):
        tissue_sheet.read_csv_text("a,b\n1\n", str(bad))
