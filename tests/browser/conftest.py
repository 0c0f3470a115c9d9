"""The `browser` marker: tests that drive Debian's headless Chromium. They stay out of the default
run (skipped) and run with `-m browser` or SLIDEWAVE_BROWSER_TESTS=1."""
import os

import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "browser: renders a page in headless Chromium (Debian `chromium`); "
                                       "skipped unless selected with -m browser or SLIDEWAVE_BROWSER_TESTS=1")


def pytest_collection_modifyitems(config, items):
    if "browser" in (config.getoption("markexpr") or "") or os.environ.get("SLIDEWAVE_BROWSER_TESTS") == "1":
        return
    skip = pytest.mark.skip(reason="browser test: run with -m browser or SLIDEWAVE_BROWSER_TESTS=1")
    for item in items:
        if "browser" in item.keywords:
            item.add_marker(skip)
