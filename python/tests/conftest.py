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
    (d / "tube.json").write_text(json.dumps(TUBE))
    (d / "sweep.json").write_text(json.dumps(SWEEP))
    cli = cli_command()
    subprocess.run([*cli, "run", str(d / "tube.json"), "--out", str(d / "plain.json"), "--realizations", "1"], check=True, capture_output=True)
    subprocess.run(
        [*cli, "run", str(d / "tube.json"), "--out", str(d / "compact.json"), "--realizations", "1", "--cells-file"], check=True, capture_output=True
    )
    subprocess.run([*cli, "sweep", str(d / "sweep.json"), "--out", str(d / "sweep"), "--workers", "1"], check=True, capture_output=True)
    return d
