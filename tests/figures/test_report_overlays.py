"""What the reviewer asked to see on the report's figures, pinned: the paper's classification laid
over the phase diagram (Fig. 4a: one arrow per published Table-1 cell in its published direction, a
"not equal" sign where our category differs), and the celerity figure's friction coefficients told
apart by a distinct colour and marker each (it used near-identical shades of one colour map)."""
import csv

import matplotlib.colors
import pytest
from figure_support import GRID, call

import _style
import celerity_vs_nu


@pytest.fixture
def drawn(monkeypatch):
    """{name: figure} of the figures drawn in the test (captured instead of saved)."""
    figures = {}
    monkeypatch.setattr(_style, "save", lambda fig, prefix, **_: figures.__setitem__(str(prefix).rsplit("/", 1)[-1], fig))
    return figures


def table1(path):
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def points_with_marker(ax, marker):
    """(nu, f) of every point drawn with this marker."""
    return sorted((round(float(x), 6), round(float(y), 6)) for line in ax.get_lines()
                  if line.get_marker() == marker for x, y in zip(line.get_xdata(), line.get_ydata()))


def test_phase_diagram_marks_every_published_cell_by_direction(data, drawn, tmp_path):
    assert call("phase_diagram", data / "all_metrics.csv", "--flutter", data / "flutter.txt", "--published",
                data / "table1.csv", "--where", *GRID, "--out", tmp_path / "phase") == 0
    ax = drawn["phase"].axes[0]
    cells = table1(data / "table1.csv")
    cell = lambda r: (round(float(r["nu"]), 6), round(float(r["f"]), 6))  # noqa: E731
    forward = sorted(cell(r) for r in cells if float(r["published"]) > 0)
    backward = sorted(cell(r) for r in cells if float(r["published"]) < 0)
    differs = sorted(cell(r) for r in cells if r["category_match"].lower() != "true")
    assert forward and backward and differs, "the synthetic table has both directions and a mismatch"
    assert points_with_marker(ax, ">") == forward
    assert points_with_marker(ax, "<") == backward
    assert points_with_marker(ax, "$\\neq$") == differs
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert f"published: opening wave in the sliding direction ({len(forward)})" in labels
    assert f"published: opening wave against the sliding direction ({len(backward)})" in labels
    assert any(label.startswith("our category differs") and f"({len(differs)})" in label for label in labels)


def test_phase_diagram_of_a_few_runs_marks_and_counts_only_the_published_cells_run(data, drawn, tmp_path):
    """The quick study runs 4 points: the other published cells have no run, and say nothing."""
    rows = table1(data / "all_metrics.csv")
    published = table1(data / "table1.csv")
    ran = [r for r in published if r["category_match"].lower() != "true"][:1] + \
        [r for r in published if r["category_match"].lower() == "true"][:2]
    keep = {(float(r["nu"]), float(r["f"])) for r in ran}
    subset = tmp_path / "few.csv"
    with open(subset, "w", newline="") as stream:
        writer = csv.DictWriter(stream, list(rows[0]))
        writer.writeheader()
        writer.writerows(r for r in rows if (float(r["nu"]), float(r["f"])) in keep)
    assert call("phase_diagram", subset, "--flutter", data / "flutter.txt", "--published", data / "table1.csv",
                "--where", *GRID, "--out", tmp_path / "few") == 0
    ax = drawn["few"].axes[0]
    arrows = points_with_marker(ax, ">") + points_with_marker(ax, "<")
    assert sorted(arrows) == sorted((round(nu, 6), round(f, 6)) for nu, f in keep)
    assert len(points_with_marker(ax, "$\\neq$")) == 1
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    differs = [label for label in labels if label.startswith("our category differs")]
    assert differs and differs[0].endswith("(1)"), labels
    # Ticked at every swept nu and at the tenths between them.
    ticks = [round(t, 6) for t in ax.get_xticks()]
    nus = {round(nu, 6) for nu, _ in keep}
    assert nus <= set(ticks)
    assert {t / 10 for t in range(5) if all(abs(t / 10 - nu) >= 0.04 for nu in nus)} <= set(ticks)


def test_phase_diagram_without_published_has_no_overlay(data, drawn, tmp_path):
    assert call("phase_diagram", data / "all_metrics.csv", "--flutter", data / "flutter.txt",
                "--where", *GRID, "--out", tmp_path / "plain") == 0
    ax = drawn["plain"].axes[0]
    assert points_with_marker(ax, ">") == [] and points_with_marker(ax, "$\\neq$") == []


def test_celerity_styles_tell_every_friction_coefficient_apart():
    fs = [0.5, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2, 1.3, 1.4, 1.5, 1.8, 2.0]  # the paper's Table 1
    styles = celerity_vs_nu.styles_of(fs)
    assert len(set(styles.values())) == len(fs), "one (colour, marker) pair per f"
    assert len({marker for _, marker in styles.values()}) == len(fs), "a marker shape per f"
    # Neighbouring f values (the close ones near f = 1) differ clearly in colour, not in shade.
    rgb = [matplotlib.colors.to_rgb(styles[f][0]) for f in sorted(fs)]
    for a, b in zip(rgb, rgb[1:]):
        assert sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5 > 0.25, (a, b)


def test_celerity_figure_has_a_legend_entry_per_friction_coefficient(data, drawn, tmp_path):
    assert call("celerity_vs_nu", data / "table1.csv", "--out", tmp_path / "cel") == 0
    fig = drawn["cel"]
    fs = sorted({float(r["f"]) for r in table1(data / "table1.csv")})
    texts = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
    assert texts == [f"{f:g}" for f in fs]
