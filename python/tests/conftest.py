"""Shared fixtures: the checkout's root, and small CLI outputs made once per test session."""

import json
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tissue_sheet

ROOT = Path(__file__).resolve().parents[2]

# A small curved sheet: a tube with a surface ratio and a layer, so scutoids and transitions occur.
TUBE = {
    "surface": {"kind": "tube", "radius": 30, "length": 240},
    "cells": 40,
    "seed": 5,
    "lloyd": {"maxIterations": 4},
    "sheet": {"surfaceRatio": 2, "layers": 1},
}
# The GPU engine (on headless-gl's software renderer here) with both adjacency methods, and a
# closed surface (a sphere on a cube map): the other result layouts the readers meet.
GPU_TUBE = {**TUBE, "resolution": 128, "engine": "gpu", "sheet": {"surfaceRatio": 2, "adjacency": "both"}}
SPHERE = {"surface": {"kind": "sphere", "radius": 40}, "resolution": 64, "cells": 40, "seed": 2, "lloyd": {"maxIterations": 2}, "sheet": {"thickness": 10}}
CONFIGS = {"tube": TUBE, "gpu": GPU_TUBE, "sphere": SPHERE}
SWEEP = {
    "base": {"surface": {"kind": "tube", "radius": 30, "length": 240}, "cells": 30, "lloyd": {"maxIterations": 2}},
    "vary": {"sheet.surfaceRatio": [1.5, 2.5]},
    "realizations": 2,
    "seed": 7,
}


VOXEL = (0.5, 0.5, 0.75)


def shell_volume(sectors=10, rings=3, slices=6, size=44, inner=8.0, outer=17.0, twist=0.0):
    """A tube cut open by the volume: a cylindrical shell along z in sectors x rings of cells.

    ``twist`` turns the sector boundaries with the radius (radians across the shell), so cells
    change neighbours between the lumen and the outside side.
    """
    z, y, x = np.mgrid[0 : rings * slices, 0:size, 0:size]
    dx, dy = x + 0.5 - size / 2, y + 0.5 - size / 2
    r = np.hypot(dx, dy)
    angle = (np.arctan2(dy, dx) + 2 * np.pi + twist * (r - inner) / (outer - inner)) % (2 * np.pi)
    sector = np.floor(angle / (2 * np.pi / sectors)).astype(int) % sectors
    ring = z // slices
    labels = (1 + sector + sectors * ring) * ((r >= inner) & (r < outer))
    return labels.astype(np.uint16)


def cli_command():
    """The CLI as the tests call it directly (the same one tissue_sheet finds)."""
    return tissue_sheet.find_cli()


@pytest.fixture(scope="session")
def outputs(tmp_path_factory):
    """CLI outputs made by the CLI itself (not through tissue_sheet): plain JSON, side file, sweep."""
    d = tmp_path_factory.mktemp("cli")
    (d / "sweep.json").write_text(json.dumps(SWEEP))
    cli = cli_command()
    # NAME-plain.json (cells in the JSON) and NAME-compact.json (+ NAME-compact.cells.bin); the
    # tube's also as plain.json and compact.json.
    for name, config in CONFIGS.items():
        (d / f"{name}.json").write_text(json.dumps(config))
        for form, extra in (("plain", []), ("compact", ["--cells-file"])):
            out = d / f"{name}-{form}.json"
            subprocess.run([*cli, "run", str(d / f"{name}.json"), "--out", str(out), "--realizations", "1", *extra], check=True, capture_output=True)
        if name == "tube":
            for form in ("plain", "compact"):
                result = json.loads((d / f"tube-{form}.json").read_text())
                if result.get("cellsFile"):
                    shutil.copy(d / result["cellsFile"]["path"], d / "compact.cells.bin")
                    result["cellsFile"]["path"] = "compact.cells.bin"
                (d / f"{form}.json").write_text(json.dumps(result, indent=2))
    subprocess.run([*cli, "sweep", str(d / "sweep.json"), "--out", str(d / "sweep"), "--workers", "1"], check=True, capture_output=True)
    return d


@pytest.fixture(scope="session")
def measured(tmp_path_factory):
    """Measure results written by the CLI itself: layers.json (the example's two PNG layers) and
    volume.json (a twisted shell volume, so its surfaces differ and have their own min contact)."""
    d = tmp_path_factory.mktemp("measured")
    cli = cli_command()
    layers = [str(ROOT / "examples" / "measure" / f"{name}.png") for name in ("basal", "apical")]
    subprocess.run([*cli, "measure", *layers, "--out", str(d / "layers.json"), "--pixel-size", "0.5", "--periodic-x"], check=True, capture_output=True)
    tissue_sheet.write_label_tiff(d / "volume.tif", shell_volume(twist=1.2), VOXEL)
    subprocess.run([*cli, "measure", "--volume", str(d / "volume.tif"), "--out", str(d / "volume.json")], check=True, capture_output=True)
    return d
