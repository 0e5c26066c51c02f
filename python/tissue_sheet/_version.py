# Equal to the npm package's version (package.json): hatch_build.py refuses to build a wheel
# that differs, and tests/test_package.py checks it.
__version__ = "0.1.0"
