"""Readers against outputs the CLI wrote in this session, checked against the JSON read by hand."""

import csv
import json
import math
import re
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


def _damaged(source, tmp_path, edit, name="damaged.json"):
    """A copy of a CLI result with ``edit`` applied to its JSON."""
    result = json.loads(source.read_text())
    edit(result)
    path = tmp_path / name
    path.write_text(json.dumps(result))
    return path


def _drop(key, at=0):
    return lambda r: r["cells"][at].pop(key)


def _set(key, value, at=0):
    return lambda r: r["cells"][at].update({key: value})


@pytest.mark.parametrize(
    "damage, table, message",
    [
        (lambda r: r.update(cells="abc"), "cells", "cells is the string 'abc', not a list"),
        (lambda r: r.update(cells=[1, 2]), "cells", r"cells\[0\] is the number 1, not an object"),
        (_drop("sides"), "cells", r"cells\[0\] has no sides"),
        (_set("sides", [6]), "cells", r"cells\[0\].sides has 1 entries, not 2 \(one per layer\)"),
        (_set("areas", ["x", 1.0]), "cells", r"cells\[0\].areas\[0\] is the string 'x', not a number"),
        # A cell whose areas are gone or null used to vanish from the table.
        (_drop("areas", 5), "cells", r"cells\[5\] has no areas"),
        (_set("areas", None, 5), "cells", r"cells\[5\].areas is null, not a list"),
        (_set("valid", "yes"), "cells", r"cells\[0\].valid is the string 'yes', not true or false"),
        (_set("won", -1), "cells", r"cells\[0\].won is the number -1, not a whole number"),
        (_set("exclusion", 3), "cells", r"cells\[0\].exclusion is the number 3, not an object"),
        # The CLI refuses images with no labels, so a result with no cells is damaged.
        (lambda r: r.update(cells=[]), "cells", "cells is empty"),
        (lambda r: r.update(inputs="x"), "cells", "inputs is the string 'x', not an object"),
        (lambda r: r["inputs"].pop("layers"), "cells", "inputs has no layers"),
        (lambda r: r["inputs"].update(layers=[{"name": "basal"}]), "cells", "inputs.layers lists 1 layer"),
        (lambda r: r.update(analyses=5), "summary", "analyses is the number 5, not a list"),
        (lambda r: r.update(analyses=5), "cells", "analyses is the number 5, not a list"),
        (lambda r: r["analyses"][0].update(summary=[]), "summary", r"analyses\[0\].summary is a list, not an object"),
        (lambda r: r["analyses"][0]["summary"].update(perSurface=[1]), "summary", r"perSurface\[0\] is the number 1, not an object"),
        (lambda r: r.update(software="x"), "cells", "software is the string 'x', not an object"),
    ],
)
def test_damaged_measure_results_are_refused_by_name(measured, tmp_path, damage, table, message):
    path = _damaged(measured / "layers.json", tmp_path, damage)
    with pytest.raises(tissue_sheet.ResultFormatError, match=re.escape(str(path)) + ": .*" + message):
        tissue_sheet.read_measure(path, table)


@pytest.mark.parametrize(
    "damage, message",
    [
        (_set("centroids", [[1.0, 2.0, 3.0]]), r"cells\[0\].centroids has 1 entries, not 2 \(one per layer\)"),
        (_set("centroids", [[1.0, 2.0], None]), r"cells\[0\].centroids\[0\] has 2 entries, not 3"),
        (_set("height", "tall"), r"cells\[0\].height is the string 'tall', not a number"),
        (_drop("volume"), r"cells\[0\] has no volume"),
        (_set("lateralNeighbours", None), r"cells\[0\].lateralNeighbours is null, not a list"),
    ],
)
def test_damaged_volume_results_are_refused_by_name(measured, tmp_path, damage, message):
    path = _damaged(measured / "volume.json", tmp_path, damage)
    with pytest.raises(tissue_sheet.ResultFormatError, match=re.escape(str(path)) + ": " + message):
        tissue_sheet.read_measure(path)


def test_measure_tables_are_the_json(measured):
    for name in ("layers.json", "volume.json"):
        result = json.loads((measured / name).read_text())
        df = tissue_sheet.read_measure(measured / name)
        assert len(df) == 2 * len(result["cells"])
        rows = df.set_index(["layer", "label"])
        for c in result["cells"]:
            for k in range(2):
                row = rows.loc[(k, c["label"])]
                assert (row["area"], row["sides"], row["neighbours"]) == (c["areas"][k], c["sides"][k], len(c["neighbours"][k]))
                assert (row["valid"], row["scutoid"]) == (c["valid"], c["scutoid"])
                reason = (c["exclusion"] or {}).get("reason")
                assert row["excluded"] == reason if reason else pd.isna(row["excluded"])


def test_volume_summary_has_each_surface_min_contact(measured):
    # A volume's surfaces each have their own default min contact (scaled to their cells): the
    # apical row once showed the basal one (analyses[0].minContactLength).
    result = json.loads((measured / "volume.json").read_text())
    own = [layer["minContact"] for layer in result["inputs"]["layers"]]
    assert own[0] != own[1]
    summary = tissue_sheet.read_measure(measured / "volume.json", "summary")
    assert list(summary["surface_name"]) == ["basal", "apical"]
    assert list(summary["min_contact_length"]) == own
    assert summary.attrs["minContactLength"] == result["analyses"][0]["minContactLength"] == own[0]
    # Layers share one threshold: every row carries it.
    layers = tissue_sheet.read_measure(measured / "layers.json", "summary")
    threshold = json.loads((measured / "layers.json").read_text())["analyses"][0]["minContactLength"]
    assert list(layers["min_contact_length"]) == [threshold, threshold]


@pytest.mark.parametrize(
    "damage, table, message",
    [
        (lambda r: r.update(cells="abc"), "cells", "cells is the string 'abc', not a list"),
        (lambda r: r.update(cells="abc"), "contacts", "cells is the string 'abc', not a list"),
        (_set("area", "x"), "cells", r"cells\[0\].area is the string 'x', not a number"),
        (_set("position", [1.0, 2.0]), "cells", r"cells\[0\].position has 2 entries, not 3"),
        (_drop("touchesBorder"), "cells", r"cells\[0\] has no touchesBorder"),
        (lambda r: r["cells"][0]["neighbours"][0].update(id=999), "contacts", r"cells\[0\].neighbours\[0\].id is the number 999, not a cell of the 40"),
        # A short sides list used to be read as zeros for the missing surfaces.
        (lambda r: r["analyses"][0]["cells"][3].update(sides=[5]), "cells", r"analyses\[0\].cells\[3\].sides has 1 entries, not 3 \(one per surface\)"),
        (lambda r: r["surfaces"][0]["cells"].pop(), "cells", r"surfaces\[0\].cells"),
        (lambda r: r.update(analyses=5), "summary", "analyses is the number 5, not a list"),
        (lambda r: r.update(analyses=[5]), "summary", r"analyses\[0\] is the number 5, not an object"),
        (lambda r: r["analyses"][0]["summary"].update(perSurface=[1]), "summary", r"perSurface\[0\] is the number 1, not an object"),
        (lambda r: r.update(surfaces=[5]), "cells", r"surfaces\[0\] is the number 5, not an object"),
        (lambda r: r.update(config="x"), "cells", "config is the string 'x', not an object"),
        (lambda r: r.update(headline="x"), "summary", "headline is the string 'x', not an object"),
        (lambda r: r.update(lloyd="x"), "cells", "lloyd is the string 'x', not an object"),
        (lambda r: r.update(cellsFile="x"), "cells", "cellsFile is the string 'x', not an object"),
    ],
)
def test_damaged_run_results_are_refused_by_name(outputs, tmp_path, damage, table, message):
    path = _damaged(outputs / "plain.json", tmp_path, damage)
    with pytest.raises(tissue_sheet.ResultFormatError, match=re.escape(str(path)) + ": .*" + message):
        tissue_sheet.read_result(path, table)


@pytest.mark.parametrize(
    "edit, message",
    [
        (lambda r: r.update(tables="x"), "cellsFile.tables is the string 'x', not a list"),
        (lambda r: r["tables"][0].pop("columns"), r"cellsFile.tables\[0\].columns is null, not an object"),
        (lambda r: r["tables"][0]["columns"].update(area=[]), "cells.area is a list, not an object"),
        (lambda r: r["tables"][0]["columns"]["area"].update(type=["float64"]), "cells.area has type"),
        (lambda r: r["tables"][1].update(of="surfaces[x].cells"), r"the surfaces tables are numbered \[1\], not 0 to 0"),
        (lambda r: r["tables"].pop(2), "1 surface tables of cells where the result lists 2 surfaces"),
    ],
)
def test_damaged_side_file_records_are_refused_by_name(outputs, tmp_path, edit, message):
    for name in ("compact.json", "compact.cells.bin"):
        shutil.copy(outputs / name, tmp_path / name)
    _edit_record(tmp_path, edit)
    with pytest.raises(tissue_sheet.ResultFormatError, match=message):
        tissue_sheet.read_result(tmp_path / "compact.json")


@pytest.mark.parametrize("reader", [tissue_sheet.read_result, tissue_sheet.read_measure])
def test_files_that_are_no_results_are_refused_by_name(tmp_path, reader):
    image = ROOT / "examples" / "measure" / "basal.png"
    with pytest.raises(tissue_sheet.ResultFormatError, match=re.escape(str(image)) + ": not a result file but a PNG image"):
        reader(image)
    with pytest.raises(tissue_sheet.ResultFormatError, match=re.escape(str(tmp_path)) + ": a directory, not a result file"):
        reader(tmp_path)
    (tmp_path / "list.json").write_text("[1, 2]")
    with pytest.raises(tissue_sheet.ResultFormatError, match="list.json: "):
        reader(tmp_path / "list.json")


def test_damaged_sweep_files_are_refused_by_name(outputs, tmp_path):
    shutil.copytree(outputs / "sweep", tmp_path / "sweep")
    (tmp_path / "sweep" / "sweep.json").write_text("[1]")
    with pytest.raises(tissue_sheet.ResultFormatError, match="sweep.json is a list, not an object"):
        tissue_sheet.read_sweep(tmp_path / "sweep")
    shutil.copy(ROOT / "examples" / "measure" / "basal.png", tmp_path / "sweep" / "runs.csv")
    with pytest.raises(tissue_sheet.ResultFormatError, match="runs.csv: not runs.csv but a PNG image"):
        tissue_sheet.read_sweep(tmp_path / "sweep")
