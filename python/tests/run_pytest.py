#!/usr/bin/env python3
"""Runs test files of the facet Python module with pytest (ctest runs one file per test).

`make test` installs numpy and pytest (the Makefile's PACKAGES), so a missing one means a broken
set-up: the run fails saying which package to install, rather than passing with nothing tested.
"""
import importlib.util
import sys

REQUIRED = (("numpy", "python3-numpy"), ("pytest", "python3-pytest"))


def main() -> int:
    missing = [package for module, package in REQUIRED if importlib.util.find_spec(module) is None]
    if missing:
        them = "them" if len(missing) > 1 else "it"
        print(f"run_pytest: install {' and '.join(missing)} (`make deps` installs {them})")
        return 1
    import pytest

    # No cache folder in the source tree; report skips (there should be none).
    return pytest.main(["-p", "no:cacheprovider", "-q", "-rs", *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
