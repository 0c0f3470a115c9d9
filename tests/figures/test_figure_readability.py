"""Figure defects a reviewer saw at page size, pinned: the convergence panels label nearly equal
values with distinct ticks, the T/N legend stays off the inversion T/N < 0 and prints symbols, not
the pipeline's raw strings, and the snapshot colour scale is logarithmic so that slow snapshots
are not black beside fast ones."""
import csv

import pytest
from figure_support import call

import _style


@pytest.fixture
def drawn(monkeypatch):
    """{script: figure} of the figures drawn in the test (captured instead of closed)."""
    figures = {}

    def keep(fig, prefix, **_):
        figures[str(prefix).rsplit("/", 1)[-1]] = fig

    monkeypatch.setattr(_style, "save", keep)
    return figures


def tick_texts(ax):
    """The y tick labels a reader sees: major and minor, inside the axis range."""
    ax.figure.canvas.draw()
    lo, hi = sorted(ax.get_ylim())
    ticks = ax.yaxis.get_major_ticks() + ax.yaxis.get_minor_ticks()
    return [t.label1.get_text() for t in ticks
            if t.label1.get_visible() and t.label1.get_text() and lo <= t.get_loc() <= hi]


def test_density_convergence_ticks_are_distinct_for_nearly_equal_values(data, tmp_path, drawn):
    # What the density sweep gives: openings equal to 6 digits (a log axis labelled every tick
    # "4.81644e-3"), celerities and T/N equal to 4.
    with open(data / "all_metrics.csv", newline="") as stream:
        reader = csv.DictReader(stream)
        rows = [r for r in reader if (r["nu"], r["f"], r["elements_per_H"], r["V0_over_cs"], r["dt_times_cs"],
                                      r["lambda_over_H"]) == ("0.2", "1.5", "32", "1e-05", "0.5", "2.0")]
    assert sorted(float(r["rho"]) for r in rows) == [0.1, 10.0, 1000.0]
    for k, r in enumerate(rows):
        r.update(max_opening=4.81644e-3 + k * 2e-9, celerity=0.85 + k * 1e-5, min_T_over_N=-0.3 + k * 1e-5)
    with open(tmp_path / "density.csv", "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    assert call("convergence", tmp_path / "density.csv", "--param", "rho", "--out", tmp_path / "density") == 0
    for ax in drawn["density"].axes:
        texts = tick_texts(ax)
        assert len(texts) >= 3 and len(set(texts)) == len(texts), texts
        assert ax.get_yaxis().get_offset_text().get_text() == ""


def test_tn_legend_stays_off_the_inversion_and_prints_symbols(data, tmp_path, drawn):
    assert call("tn_curves", data / "run_v1e-06.h5", data / "run.h5", "--labels", "V0/c_s=1e-06",
                "V0/c_s=1e-05", "--highlight", 1, "--out", tmp_path / "tn") == 0
    fig = drawn["tn"]
    ax = fig.axes[0]
    fig.canvas.draw()
    legend = ax.get_legend()
    box, axes_box = legend.get_window_extent(), ax.get_window_extent()
    beside = box.x0 >= axes_box.x1
    above_zero = ax.transData.inverted().transform(box)[0][1] >= 0.0
    assert beside or above_zero
    assert [t.get_text() for t in legend.get_texts()] == ["$V_0/c_s$ = $10^{-6}$", "$V_0/c_s$ = $10^{-5}$"]


def test_single_tn_curve_has_no_legend(data, tmp_path, drawn):
    assert call("tn_curves", data / "run.h5", "--labels", "nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced",
                "--out", tmp_path / "one") == 0
    assert drawn["one"].axes[0].get_legend() is None


def test_snapshot_colours_are_logarithmic_from_v0(data, tmp_path, drawn):
    from matplotlib.colors import LogNorm

    assert call("snapshots", data / "run.h5", "--out", tmp_path / "snap") == 0
    images = [c for ax in drawn["snap"].axes for c in ax.collections if c.get_array() is not None]
    norms = {id(c.norm): c.norm for c in images}
    assert len(norms) == 1  # one scale shared by every block
    (norm,) = norms.values()
    assert isinstance(norm, LogNorm) and norm.vmax / norm.vmin >= 10


def test_titles_name_the_run_parameters(data, tmp_path, drawn):
    # Format 2 keeps nu, f, c_s, ... in /setup: the title must still name them.
    assert call("tn_curves", data / "run.h5", "--out", tmp_path / "titled") == 0
    title = drawn["titled"].axes[0].get_title()
    assert "$\\nu$ = 0.2" in title and "$f$ = 1.5" in title and "$H$/16" in title
