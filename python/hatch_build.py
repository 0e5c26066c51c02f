"""Build hook: bundles the element's JavaScript into the wheel and keeps the version equal to npm's.

In a checkout (package.json one level up) every build writes tissue_sheet/static/widget.js with
scripts/bundle-python-widget.mjs from dist/lib (running `npm run build:lib` first when dist/lib is
missing) and refuses a version that differs from package.json's. Built from an sdist (no
checkout), the sdist's own widget.js is used.
"""

import json
import re
import shutil
import subprocess
from pathlib import Path

from hatchling.builders.hooks.plugin.interface import BuildHookInterface

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
WIDGET = HERE / "tissue_sheet" / "static" / "widget.js"


def _lib_is_stale() -> bool:
    """dist/lib/tissue-sheet.js is missing, or a source of it is newer."""
    built = ROOT / "dist" / "lib" / "tissue-sheet.js"
    if not built.is_file():
        return True
    at = built.stat().st_mtime
    sources = [ROOT / "package.json", ROOT / "vite.lib.config.ts", *(p for p in (ROOT / "src").rglob("*") if p.is_file())]
    return any(p.is_file() and p.stat().st_mtime > at for p in sources)


class CustomBuildHook(BuildHookInterface):
    def initialize(self, version, build_data):
        package_json = ROOT / "package.json"
        bundler = ROOT / "scripts" / "bundle-python-widget.mjs"
        if package_json.is_file() and bundler.is_file():
            npm_version = json.loads(package_json.read_text(encoding="utf-8"))["version"]
            text = (HERE / "tissue_sheet" / "_version.py").read_text(encoding="utf-8")
            py_version = re.search(r'__version__ = "([^"]+)"', text).group(1)
            if py_version != npm_version:
                raise RuntimeError(
                    f"python/tissue_sheet/_version.py says {py_version}, package.json {npm_version}: make them equal"
                )
            node = shutil.which("node")
            if node is None:
                raise RuntimeError("building the tissue-sheet wheel needs Node.js (>= 20) to bundle the element: install it")
            if _lib_is_stale():
                npm = shutil.which("npm")
                if npm is None:
                    raise RuntimeError("dist/lib is missing or older than src and npm is not installed: run `npm ci && npm run build:lib` in the checkout")
                subprocess.run([npm, "run", "build:lib"], cwd=ROOT, check=True)
            subprocess.run([node, str(bundler)], cwd=ROOT, check=True)
        if not WIDGET.is_file():
            raise RuntimeError(f"{WIDGET} is missing: build from a tissue-sheet checkout (it runs scripts/bundle-python-widget.mjs)")
