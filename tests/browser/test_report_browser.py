"""The HTML report in a real browser (label `browser`: outside the default run).

    SLIDEWAVE_BROWSER_TESTS=1 /usr/bin/python3 -m pytest -q tests/browser
    /usr/bin/python3 -m pytest -q -m browser tests/browser

Headless Debian Chromium opens the report (SLIDEWAVE_REPORT, else results/report.html, else the
quick study's results/quick/report.html), in a 1400 px wide window: every <img> must have decoded
(complete, naturalWidth > 0), and no console error or uncaught exception may occur. A full-page
screenshot is written next to the report (report.png) for a person to look at; the page's width
and its widest table are printed.
"""
import os
from pathlib import Path

import pytest

from chromium import Page, chromium_binary

REPO = Path(__file__).resolve().parents[2]
WINDOW_WIDTH = 1400

IMAGES = """Array.from(document.images).map(i => ({alt: i.alt, complete: i.complete,
  width: i.naturalWidth, height: i.naturalHeight, shown: i.getBoundingClientRect().width}))"""
WIDTHS = """({page: document.documentElement.scrollWidth, window: window.innerWidth,
  widest_table: Math.max(0, ...Array.from(document.querySelectorAll('table')).map(t => t.scrollWidth))})"""


def report_path():
    if os.environ.get("SLIDEWAVE_REPORT"):
        return Path(os.environ["SLIDEWAVE_REPORT"]).resolve()
    for candidate in ("results/report.html", "results/quick/report.html"):
        if (REPO / candidate).is_file():
            return REPO / candidate
    pytest.fail("no report: build one (snakemake -c2 quick) or name it in SLIDEWAVE_REPORT")


@pytest.mark.browser
def test_report_renders_with_every_figure_and_no_console_error(tmp_path):
    if not chromium_binary():
        pytest.fail("chromium not installed (Debian: apt-get install chromium; scripts/setup.sh)")
    report = report_path()
    screenshot = report.with_suffix(".png")
    with Page(tmp_path / "profile", width=WINDOW_WIDTH) as page:
        page.open(report.as_uri())
        images = page.evaluate(IMAGES)
        widths = page.evaluate(WIDTHS)
        page.screenshot(screenshot)
        errors = list(page.errors)
    print(f"\n{report}: {len(images)} images, page {widths['page']} px in a {widths['window']} px window, "
          f"widest table {widths['widest_table']} px; screenshot {screenshot}")
    assert images, f"{report}: no <img> at all"
    broken = [i["alt"] for i in images if not (i["complete"] and i["width"] > 0 and i["height"] > 0)]
    assert not broken, f"images that did not decode: {broken}"
    assert not errors, "console errors:\n" + "\n".join(errors)
    assert screenshot.stat().st_size > 50_000
