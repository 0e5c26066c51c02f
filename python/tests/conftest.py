"""Shared fixtures: the checkout's root, and small CLI outputs made once per test session."""

import json
import os
import shutil
import subprocess
from pathlib import Path

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
