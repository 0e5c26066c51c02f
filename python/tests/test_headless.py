"""Headless calls through the CLI: the same tables as the readers, numpy volumes, bad input, no CLI."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import tissue_sheet
from tissue_sheet.tiff import read_label_tiff
from conftest import ROOT, SWEEP, TUBE, VOXEL, shell_volume


def test_label_tiff_round_trip(tmp_path):
    labels = shell_volume()
    tissue_sheet.write_label_tiff(tmp_path / "v.tif", labels, VOXEL)
    back, tags = read_label_tiff(tmp_path / "v.tif")
    assert back.dtype == np.uint8 and np.array_equal(back, labels)  # the smallest type that holds them
    assert "unit=micron" in tags[270] and "spacing=0.75" in tags[270]
    big = (labels.astype(np.uint32) * 7000) % 100_000
    tissue_sheet.write_label_tiff(tmp_path / "b.tif", big, VOXEL)
    back, _ = read_label_tiff(tmp_path / "b.tif")
    assert back.dtype == np.uint32 and np.array_equal(back, big)


def test_measure_numpy_volume_against_the_labels():
    labels = shell_volume()
    df = tissue_sheet.measure(labels, voxel_size=VOXEL)
    found = np.unique(labels[labels > 0])
    seeded = df[df["layer"] == 0].set_index("label")
    assert sorted(seeded.index) == list(found)
    # Volume: the cell's voxel count times the voxel's volume, counted here by numpy.
    counts = np.bincount(labels.ravel())
    for label, row in seeded.iterrows():
        assert row["volume"] == pytest.approx(counts[label] * np.prod(VOXEL), rel=1e-12)
    # Valid: cells touching no face of the volume: the middle ring only (z faces cut the others).
    middle = set(range(1 + 10, 1 + 20))
    assert set(seeded.index[seeded["valid"]]) == middle
    # Straight sectors: the same neighbours on both sides, so no scutoid.
    assert not seeded["scutoid"].any()
    assert df.attrs["mode"] == "volume"
    assert df.attrs["inputs"]["voxelSize"]["x"] == VOXEL[0] and df.attrs["inputs"]["voxelSize"]["z"] == VOXEL[2]
    assert df.attrs["version"] == tissue_sheet.__version__


def test_measure_file_reads_our_voxel_size_and_equals_the_array_call(tmp_path):
    labels = shell_volume(twist=1.2)
    path = tmp_path / "twisted.tif"
    tissue_sheet.write_label_tiff(path, labels, VOXEL)
    from_file = tissue_sheet.measure(path)  # no voxel_size: the CLI reads our ImageJ metadata
    assert from_file.attrs["inputs"]["voxelSize"]["source"] == "imagej"
    assert [from_file.attrs["inputs"]["voxelSize"][a] for a in "xyz"] == pytest.approx(list(VOXEL))
    from_array = tissue_sheet.measure(labels, voxel_size=VOXEL)
    pd.testing.assert_frame_equal(from_file, from_array)
    summary = tissue_sheet.measure(labels, voxel_size=VOXEL, table="summary")
    valid = from_array[(from_array["layer"] == 0) & from_array["valid"]]
    assert summary["percentScutoids"].iloc[0] == pytest.approx(100 * valid["scutoid"].mean())


def test_measure_layers(tmp_path):
    layers = [ROOT / "examples" / "measure" / "basal.png", ROOT / "examples" / "measure" / "apical.png"]
    out = tmp_path / "m.json"
    df = tissue_sheet.measure(layers, pixel_size=0.5, periodic_x=True, out=out)
    result = json.loads(out.read_text())
    assert df.attrs["mode"] == "layers"
    assert len(df) == 2 * len(result["cells"])
    assert list(df["layer_name"].unique()) == ["basal", "apical"]
    pd.testing.assert_frame_equal(df, tissue_sheet.read_measure(out), check_like=True)


def test_run_and_sweep_return_the_readers_tables(outputs, tmp_path):
    df = tissue_sheet.run(TUBE, realizations=1, out=tmp_path / "r.json")
    pd.testing.assert_frame_equal(df, tissue_sheet.read_result(outputs / "plain.json"), check_exact=True, check_dtype=False)
    assert df.attrs["source"].endswith("r.json")
    compact = tissue_sheet.run(TUBE, realizations=1, cells_file=True, out=tmp_path / "c.json")
    assert (tmp_path / "c.cells.bin").is_file()
    pd.testing.assert_frame_equal(df, compact, check_dtype=False)
    runs = tissue_sheet.sweep(SWEEP, out=tmp_path / "sweep", workers=1)
    pd.testing.assert_frame_equal(runs, tissue_sheet.read_sweep(outputs / "sweep"))
    assert runs.attrs["spec"]["seed"] == SWEEP["seed"]


def test_bad_input_is_named():
    with pytest.raises(tissue_sheet.TissueSheetInputError, match="cells") as e:
        tissue_sheet.run({**TUBE, "cells": -3})
    assert e.value.exit_code == 2
    with pytest.raises(ValueError, match="3D array"):
        tissue_sheet.measure(np.zeros((4, 4), dtype=np.uint8), voxel_size=VOXEL)
    with pytest.raises(ValueError, match="negative"):
        tissue_sheet.measure(-shell_volume().astype(np.int32), voxel_size=VOXEL)
    with pytest.raises(ValueError, match="voxel_size"):
        tissue_sheet.measure(shell_volume())
    with pytest.raises(ValueError, match="whole numbers"):
        tissue_sheet.measure(shell_volume() + 0.5, voxel_size=VOXEL)
    with pytest.raises(ValueError, match="boolean mask"):
        tissue_sheet.measure(shell_volume() > 0, voxel_size=VOXEL)
    with pytest.raises(FileNotFoundError, match="not a file"):
        tissue_sheet.measure("/nonexistent/volume.tif", voxel_size=VOXEL)
    # A volume the CLI refuses (no lumen): its own message, exit 2.
    solid = np.ones((3, 8, 8), dtype=np.uint8)
    solid[1, 2:6, 2:6] = 2
    with pytest.raises(tissue_sheet.TissueSheetInputError, match="lumen"):
        tissue_sheet.measure(solid, voxel_size=VOXEL)


def test_missing_node_or_cli_says_what_to_install(monkeypatch, tmp_path):
    monkeypatch.setenv("TISSUE_SHEET_CLI", str(tmp_path / "nowhere" / "tissue-sheet.mjs"))
    with pytest.raises(tissue_sheet.TissueSheetCliNotFound, match="install Node.js.*npm install -g tissue-sheet"):
        tissue_sheet.run(TUBE)
    script = tmp_path / "tissue-sheet.mjs"
    script.write_text("")
    monkeypatch.setenv("TISSUE_SHEET_CLI", str(script))
    monkeypatch.setenv("PATH", str(tmp_path))  # no node on PATH
    with pytest.raises(tissue_sheet.TissueSheetCliNotFound, match="needs Node.js"):
        tissue_sheet.run(TUBE)


def test_cli_found_from_a_folder_of_the_checkout(monkeypatch):
    monkeypatch.delenv("TISSUE_SHEET_CLI", raising=False)
    monkeypatch.chdir(ROOT / "docs")  # a notebook beside the project
    assert tissue_sheet.find_cli()[-1] == str(ROOT / "bin" / "tissue-sheet.mjs")


def test_old_node_is_named(monkeypatch, tmp_path):
    # A Node.js older than 20 on PATH (a stand-in script answering --version as node 18 does).
    node = tmp_path / "node"
    node.write_text("#!/bin/sh\necho v18.19.1\n")
    node.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.setenv("TISSUE_SHEET_CLI", str(ROOT / "bin" / "tissue-sheet.mjs"))
    with pytest.raises(tissue_sheet.TissueSheetCliNotFound, match="Node.js v18.19.1; tissue-sheet needs 20 or later"):
        tissue_sheet.run(TUBE)


def test_an_array_the_cli_refuses_is_named_as_the_array():
    # The CLI reads a temporary TIFF, gone by the time the message is read: name the array.
    with pytest.raises(tissue_sheet.TissueSheetInputError) as e:
        tissue_sheet.measure(np.zeros((3, 8, 8), dtype=np.uint8), voxel_size=VOXEL)
    assert "the array: no cell labels" in str(e.value)
    assert "labels.tif" not in str(e.value) and "tissue-sheet-" not in str(e.value)
    with pytest.raises(tissue_sheet.TissueSheetInputError, match=r"the array labels\[0\]: no labels"):
        tissue_sheet.measure([np.zeros((8, 8), dtype=np.uint8), np.ones((8, 8), dtype=np.uint8)], pixel_size=1)


def write_png16(path, labels):
    """A 16-bit grey PNG (no filter, one zlib stream): what a segmentation tool saves as a layer."""
    import struct
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    h, w = labels.shape
    rows = b"".join(b"\0" + labels[y].astype(">u2").tobytes() for y in range(h))
    ihdr = struct.pack(">IIBBBBB", w, h, 16, 0, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def brick_layers(rows=6, cols=8, size=12):
    """An unrolled tube of brick cells: the apical layer twice as wide, its rows offset the other way (scutoids)."""
    y, x = np.mgrid[0 : rows * size, 0 : cols * size]
    row = y // size
    basal = 1 + row * cols + ((x + (row % 2) * size // 2) // size) % cols
    y, x = np.mgrid[0 : rows * size, 0 : 2 * cols * size]
    row = y // size
    apical = 1 + row * cols + ((x // 2 + ((row + 1) % 2) * size // 2) // size) % cols
    return [basal.astype(np.uint16), apical.astype(np.uint16)]


def test_measure_layer_arrays_equal_the_same_layers_as_images(tmp_path):
    layers = brick_layers()
    df = tissue_sheet.measure(layers, pixel_size=0.5, periodic_x=True)
    for k, layer in enumerate(layers):
        write_png16(tmp_path / f"{k}.png", layer)
    files = tissue_sheet.measure([tmp_path / "0.png", tmp_path / "1.png"], pixel_size=0.5, periodic_x=True)
    pd.testing.assert_frame_equal(df, files)
    assert df.attrs["mode"] == "layers" and df.attrs["surfaceRatio"]["value"] == 2
    assert list(df["layer_name"].unique()) == ["basal", "apical"]
    for k, layer in enumerate(layers):
        counts = np.bincount(layer.ravel())
        rows = df[df["layer"] == k].set_index("label")
        assert sorted(rows.index) == list(np.unique(layer))
        for label, row in rows.iterrows():
            assert row["area"] == counts[label] * 0.25
    assert df["scutoid"].any()
    # A path and an array mixed: the same measurement.
    mixed = tissue_sheet.measure([tmp_path / "0.png", layers[1]], pixel_size=0.5, periodic_x=True)
    pd.testing.assert_frame_equal(df, mixed)


def test_layer_arrays_refused_with_what_is_accepted():
    layers = brick_layers()
    with pytest.raises(ValueError, match="voxel_size: is for a volume .* layer images takes pixel_size"):
        tissue_sheet.measure(layers, voxel_size=VOXEL, pixel_size=0.5)
    with pytest.raises(ValueError, match=r"pixel_size: give the pixel size in µm for the label array labels\[0\]"):
        tissue_sheet.measure(layers)
    with pytest.raises(ValueError, match=r"labels\[1\]: value 70048 is over 65,535"):
        tissue_sheet.measure([layers[0], layers[1].astype(np.uint32) + 70000], pixel_size=0.5)
    with pytest.raises(ValueError, match=r"labels\[0\]: a 2D array"):
        tissue_sheet.measure([shell_volume(), layers[1]], pixel_size=0.5)
    with pytest.raises(TypeError, match=r"labels\[1\]: a layer is the path of a label image or a 2D numpy label array, got int"):
        tissue_sheet.measure([layers[0], 3], pixel_size=0.5)
    with pytest.raises(ValueError, match=r"labels: one 2D layer; give two or more \(basal first\)"):
        tissue_sheet.measure([layers[0]], pixel_size=0.5)


def _processes_naming(text):
    """Processes whose command line holds ``text`` (Linux /proc)."""
    found = []
    for proc in Path("/proc").iterdir():
        try:
            if proc.name.isdigit() and text in (proc / "cmdline").read_bytes().decode(errors="replace"):
                found.append(proc.name)
        except OSError:
            pass
    return found


def test_timeout_raises_our_error():
    with pytest.raises(tissue_sheet.TissueSheetTimeout, match="tissue-sheet measure did not finish in 0.05 s") as e:
        tissue_sheet.measure(shell_volume(), voxel_size=VOXEL, timeout=0.05)
    assert isinstance(e.value, TimeoutError) and isinstance(e.value, tissue_sheet.TissueSheetCliError)
    assert e.value.exit_code is None
    with pytest.raises(ValueError, match="timeout: seconds > 0"):
        tissue_sheet.run(TUBE, timeout=0)


@pytest.mark.skipif(not Path("/proc/self/cmdline").exists(), reason="needs Linux /proc to look for processes left running")
def test_timeout_stops_the_cli_and_what_it_started(monkeypatch, tmp_path):
    # Without a display the launcher waits on xvfb-run and a second node: a stand-in CLI that
    # waits on a child shell (named by tmp_path) as the launcher does. Both must be stopped.
    cli = tmp_path / "tissue-sheet"
    cli.write_text(f'#!/bin/sh\necho "tissue-sheet: started" >&2\nsh -c "sleep 300; echo {tmp_path}"\n')
    cli.chmod(0o755)
    monkeypatch.setenv("TISSUE_SHEET_CLI", str(cli))
    with pytest.raises(tissue_sheet.TissueSheetTimeout, match="tissue-sheet run did not finish in 1 s .*its last line: tissue-sheet: started") as e:
        tissue_sheet.run(TUBE, timeout=1)
    assert "started" in e.value.stderr
    assert _processes_naming(str(tmp_path)) == []
