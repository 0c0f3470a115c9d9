"""The HTML report in a real browser (label `browser`: outside the default run).

    SLIDEWAVE_BROWSER_TESTS=1 /usr/bin/python3 -m pytest -q tests/browser
    /usr/bin/python3 -m pytest -q -m browser tests/browser

Headless Debian Chromium opens the report (SLIDEWAVE_REPORT, else results/report.html, else the
quick study's results/quick/report.html), in a 1400 px wide window: every <img> must have decoded
(complete, naturalWidth > 0), and no console error or uncaught exception may occur; no table cell
may end beyond the window (no horizontal scroll at 1400 px); and the phase diagram's legend counts
(its figure's data-legend, from the PNG) must be those of the Table-1 rows shown in the same section.
A full-page screenshot is written next to the report (report.png) for a person to look at; the
page's width and its widest table are printed.
"""
import json
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
# Cells whose right edge lies beyond the window (document coordinates, page not scrolled).
OUTSIDE = """Array.from(document.querySelectorAll('th, td')).filter(c =>
  c.getBoundingClientRect().right > window.innerWidth + 0.5).map(c => c.textContent.slice(0, 40))"""
# Per sweep section: the phase diagram's legend counts and the Table-1 rows beside it.
LEGENDS = """Array.from(document.querySelectorAll('h2')).map(h => {
  const items = []; let n = h.nextElementSibling;
  while (n && n.tagName !== 'H2') { items.push(n); n = n.nextElementSibling; }
  const inside = sel => items.flatMap(i => [...(i.matches(sel) ? [i] : []), ...i.querySelectorAll(sel)]);
  const legend = inside('figure[data-legend]').map(f => JSON.parse(f.dataset.legend));
  const rows = inside('table.table1 tr[data-cell]').map(r => ({cell: r.dataset.cell,
    published: parseFloat(r.dataset.published), match: r.dataset.categoryMatch === 'true'}));
  return {section: h.textContent, legend: legend, rows: rows};
})"""


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
        outside = page.evaluate(OUTSIDE)
        sections = page.evaluate(LEGENDS)
        page.screenshot(screenshot)
        errors = list(page.errors)
    print(f"\n{report}: {len(images)} images, page {widths['page']} px in a {widths['window']} px window, "
          f"widest table {widths['widest_table']} px; screenshot {screenshot}")
    assert images, f"{report}: no <img> at all"
    broken = [i["alt"] for i in images if not (i["complete"] and i["width"] > 0 and i["height"] > 0)]
    assert not broken, f"images that did not decode: {broken}"
    assert not errors, "console errors:\n" + "\n".join(errors)
    assert not outside, f"table cells beyond the {WINDOW_WIDTH} px window: {outside}"
    assert widths["page"] <= widths["window"], "the page scrolls horizontally"
    checked = 0
    for section in sections:
        for legend in section["legend"]:
            published = legend.get("published")
            if published is None or not section["rows"]:
                continue
            rows = section["rows"]
            assert published["published_forward"] == sum(r["published"] > 0 for r in rows), section["section"]
            assert published["published_backward"] == sum(r["published"] < 0 for r in rows), section["section"]
            assert published["differs"] == sum(not r["match"] for r in rows), section["section"]
            checked += 1
    assert checked, "no phase diagram with its legend counts beside a Table-1 block"
    print(f"legend counts checked in {checked} section(s): "
          + json.dumps([s["legend"] for s in sections if s["legend"]]))
    assert screenshot.stat().st_size > 50_000
