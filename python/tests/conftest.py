"""pytest set-up for the facet module's tests: they must test the build tree's package."""
import os
import pathlib

import facet


def pytest_configure(config):
    expected = os.environ.get("FACET_PYTHON_PACKAGE_DIR")
    if expected:
        found = pathlib.Path(facet.__file__).resolve().parent.parent
        if found != pathlib.Path(expected).resolve():
            raise RuntimeError(f"the tests import facet from {found}, not the build's {expected}")
