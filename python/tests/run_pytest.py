#!/usr/bin/env python3
"""Runs test files of the facet Python module with pytest (ctest runs one file per test).

`make test` installs numpy, pytest and what single test files need (the Makefile's PACKAGES), so
a missing one means a broken set-up: the run fails saying which package to install, rather than
passing with nothing tested.
"""
import importlib.util
import os
import sys

REQUIRED = (("numpy", "python3-numpy"), ("pytest", "python3-pytest"))
# What a test file needs besides: {file name: ((module, Debian package), ...)}.
# (docs/python.md's facet.dask block starts a cluster.)
DASK = (("distributed", "python3-distributed"),)
REQUIRED_BY_FILE = {"test_dask.py": DASK, "test_docs.py": DASK}


def main() -> int:
    required = list(REQUIRED)
    for argument in sys.argv[1:]:
        required += REQUIRED_BY_FILE.get(os.path.basename(argument), ())
    missing = [package for module, package in required if importlib.util.find_spec(module) is None]
    if missing:
        them = "them" if len(missing) > 1 else "it"
        print(f"run_pytest: install {' and '.join(missing)} (`make deps` installs {them})")
        return 1
    import pytest

    # No cache folder in the source tree; report skips (there should be none).
    return pytest.main(["-p", "no:cacheprovider", "-q", "-rs", *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
