import json
import os
import re
from importlib import metadata
from pathlib import Path

import pytest

import tissue_sheet
from conftest import ROOT


def test_version_equals_package_json():
    npm = json.loads((ROOT / "package.json").read_text())["version"]
    assert tissue_sheet.__version__ == npm
    assert metadata.version("tissue-sheet") == npm


def test_dependencies_are_the_four_named():
    requires = metadata.requires("tissue-sheet") or []
    names = sorted(re.split(r"[ <>=!;\[]", r, maxsplit=1)[0].lower() for r in requires)
    assert names == ["anywidget", "numpy", "pandas", "traitlets"]


def test_widget_module_is_bundled_with_its_workers_inlined():
    widget = Path(tissue_sheet.__file__).parent / "static" / "widget.js"
    text = widget.read_text(encoding="utf-8")
    # The element, its workers (no file next to the module is needed: no assets/ URL is left)
    # and the anywidget front end, in one module.
    assert 'customElements.get("tissue-sheet")' in text
    assert not re.search(r'new URL\("assets/', text)
    assert "__tissueSheetWorkerSources" in text and text.count("three.js") >= 1
    assert "export default __tissueSheetWidget" in text
    sources = json.loads(re.search(r"const __tissueSheetWorkerSources = (\{.*?\});\n", text, re.S).group(1))
    assert len(sources) >= 1 and all(len(code) > 10_000 for code in sources.values())
    # Every worker the build wrote is inlined.
    assets = ROOT / "dist" / "lib" / "assets"
    if assets.is_dir():
        assert sorted(sources) == sorted(p.name for p in assets.glob("*.js"))


def test_installed_from_the_wheel_when_asked():
    # scripts/test-python.sh runs these tests against the wheel installed in a fresh venv.
    if os.environ.get("TISSUE_SHEET_EXPECT_WHEEL") != "1":
        pytest.skip("TISSUE_SHEET_EXPECT_WHEEL=1 is set by scripts/test-python.sh, which installs the wheel")
    installed = Path(tissue_sheet.__file__).resolve()
    assert "site-packages" in installed.parts, installed
    assert not installed.is_relative_to(ROOT / "python" / "tissue_sheet")
