"""Every figure script on synthetic inputs that follow docs/contracts.md: PNG and PDF written and
not blank; bad inputs rejected with a clear message and exit status 2."""
import csv
import json

import numpy as np
import pytest

from pathlib import Path

from figure_support import FIGURES, GRID, assert_figure, call, command, report_jobs
import synthetic


# ---------------------------------------------------------------- figures are drawn

REPORT_FIGURES = sorted(report_jobs(Path("data")))


@pytest.mark.parametrize("name", REPORT_FIGURES)
def test_report_figure(rendered, name):
    status, prefix = rendered[name]
    assert status == 0
    assert_figure(prefix)


def test_spacetime_without_metrics_or_window(data, tmp_path):
    assert call("spacetime", data / "run.h5", "--field", "slip_velocity", "--out",
                tmp_path / "st") == 0
    assert_figure(tmp_path / "st")


def test_snapshots_periodic_connectivity(tmp_path):
    """Elements that close the period on the x = 0 nodes are drawn unwrapped, not across."""
    synthetic.write_run(tmp_path / "run.h5", periodic_connectivity=True)
    assert call("snapshots", tmp_path / "run.h5", "--columns", 2, "--scale", 50,
                "--out", tmp_path / "snap") == 0
    assert_figure(tmp_path / "snap")


def test_element_corners_unwraps_the_closing_column():
    import snapshots

    coordinates = np.array([[0.0, 0.0], [8.0, 0.0], [8.0, 1.0], [0.0, 1.0]])
    corners = snapshots.element_corners(coordinates, np.array([[1, 0, 3, 2]]), lam=10.0)
    assert corners[0, :, 0].tolist() == [8.0, 10.0, 10.0, 8.0]


def test_pulse_spacing_without_c_s_column(tmp_path):
    where = ["nu=0.2", "f=1.5", "elements_per_H=32", "rho=1000", "V0_over_cs=1e-5"]
    synthetic.write_csv(tmp_path / "no_cs.csv", synthetic.metrics_rows(), drop=("c_s",))
    assert call("pulse_spacing", tmp_path / "no_cs.csv", "--where", *where,
                "--out", tmp_path / "b") == 0
    assert_figure(tmp_path / "b")


def test_scripts_run_as_commands(data, tmp_path):
    """The pipeline calls the scripts as programs from the repository root."""
    result = command(FIGURES / "celerity_vs_nu.py", data / "table1.csv",
                     "--out", tmp_path / "sub" / "cel")
    assert result.returncode == 0, result.stderr
    assert_figure(tmp_path / "sub" / "cel")


# ---------------------------------------------------------------- bad inputs

def expect_error(script, *args, says):
    result = command(FIGURES / f"{script}.py", *args)
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert f"{script}.py: error:" in result.stderr
    for text in ([says] if isinstance(says, str) else says):
        assert text in result.stderr, result.stderr
    assert "Traceback" not in result.stderr
    return result


@pytest.mark.parametrize("script,extra", [("spacetime", ["--field", "opening"]),
                                          ("tn_curves", []), ("snapshots", [])])
def test_unknown_format_version_is_refused(tmp_path, script, extra):
    synthetic.write_run(tmp_path / "old.h5", format_version=99, snapshots=False)
    expect_error(script, tmp_path / "old.h5", *extra, "--out", tmp_path / "x",
                 says=["format_version 99 is not supported", "only format_version 2 and 3"])
    assert not (tmp_path / "x.png").exists()


def test_not_hdf5(tmp_path):
    (tmp_path / "run.h5").write_text("not hdf5")
    expect_error("spacetime", tmp_path / "run.h5", "--field", "state", "--out", tmp_path / "x",
                 says="not a readable HDF5 file")


def test_missing_dataset_is_named(tmp_path):
    import h5py

    synthetic.write_run(tmp_path / "run.h5", snapshots=False)
    with h5py.File(tmp_path / "run.h5", "a") as file:
        del file["/interface/opening"]
    expect_error("spacetime", tmp_path / "run.h5", "--field", "opening", "--out", tmp_path / "x",
                 says="dataset '/interface/opening' is missing")


def test_time_window_outside_the_run(data, tmp_path):
    expect_error("spacetime", data / "run.h5", "--field", "state", "--tmin", 5000,
                 "--out", tmp_path / "x", says="no interface output in [5000.0, None] s")


def test_run_without_snapshots(data, tmp_path):
    expect_error("snapshots", data / "run_v1e-06.h5", "--out", tmp_path / "x",
                 says="'/snapshots' is missing")


def test_labels_must_match_runs(data, tmp_path):
    expect_error("tn_curves", data / "run.h5", "--labels", "a", "b", "--out", tmp_path / "x",
                 says="--labels has 2 entries for 1 runs")


def drop_column(source, target, column):
    rows = list(csv.DictReader(open(source)))
    synthetic.write_csv(target, rows, drop=(column,))


@pytest.mark.parametrize("script,source,column,extra", [
    ("phase_diagram", "all_metrics.csv", "category", ["--flutter", "flutter.txt"]),
    ("celerity_vs_nu", "table1.csv", "published", []),
    ("deviation_map", "table1.csv", "category_match", []),
    ("pulse_spacing", "all_metrics.csv", "pulse_spacing", []),
    ("convergence", "all_metrics.csv", "max_opening", ["--param", "rho"]),
    ("convergence", "all_metrics.csv", "rho", ["--param", "rho"]),
])
def test_missing_column_is_named(data, tmp_path, script, source, column, extra):
    drop_column(data / source, tmp_path / source, column)
    extra = [data / e if e.endswith(".txt") else e for e in extra]
    expect_error(script, tmp_path / source, *extra, "--out", tmp_path / "x",
                 says=f"missing required column(s) {column}")


def test_phase_diagram_needs_one_row_per_point(data, tmp_path):
    expect_error("phase_diagram", data / "all_metrics.csv", "--flutter", data / "flutter.txt",
                 "--out", tmp_path / "x", says=["appear more than once", "--where"])


def test_where_on_unknown_column(data, tmp_path):
    expect_error("phase_diagram", data / "all_metrics.csv", "--flutter", data / "flutter.txt",
                 "--where", "mesh=64", "--out", tmp_path / "x", says="column 'mesh' does not exist")


def test_bad_flutter_line(data, tmp_path):
    (tmp_path / "flutter.txt").write_text("0.0 1.0 inf\n0.1 one\n")
    expect_error("phase_diagram", data / "all_metrics.csv", "--flutter", tmp_path / "flutter.txt",
                 "--where", *GRID, "--out", tmp_path / "x", says="flutter.txt:2: expected")


def test_convergence_without_a_series(data, tmp_path):
    expect_error("convergence", data / "all_metrics.csv", "--param", "rho", "--where", "nu=0",
                 "--out", tmp_path / "x", says="no set of runs differs only in 'rho'")


def test_bad_metrics_json(data, tmp_path):
    (tmp_path / "m.json").write_text("{celerity: 1}")
    expect_error("spacetime", data / "run.h5", "--field", "state", "--metrics",
                 tmp_path / "m.json", "--out", tmp_path / "x", says="not valid JSON")


def test_metrics_json_is_read(data, tmp_path):
    """The measured celerity is what the c_p line uses (shown in the title)."""
    import matplotlib.pyplot as plt
    import spacetime

    (tmp_path / "m.json").write_text(json.dumps({"celerity": -2.5}))
    captured = {}
    original = plt.Figure.savefig

    def spy(fig, *args, **kwargs):
        captured["title"] = fig.axes[0].get_title()
        captured["labels"] = fig.axes[0].get_legend_handles_labels()[1]
        return original(fig, *args, **kwargs)

    plt.Figure.savefig = spy
    try:
        assert spacetime.main([str(data / "run.h5"), "--field", "state", "--metrics",
                               str(tmp_path / "m.json"), "--out", str(tmp_path / "x")]) == 0
    finally:
        plt.Figure.savefig = original
    assert "-2.500 m/s" in captured["title"]
    assert any("$c_p$ = -2.500" in label for label in captured["labels"])
    assert any("$c_l$ = -1.054" in label for label in captured["labels"])


def test_tn_aligned_needs_the_first_drop_of_every_run(data, tmp_path):
    expect_error("tn_aligned", data / "run.h5", "--metrics", data / "metrics.json", "--out", tmp_path / "x",
                 says="no first_drop_start_time")
    expect_error("tn_aligned", data / "run.h5", "--metrics", data / "metrics_drop.json", data / "metrics.json",
                 "--out", tmp_path / "x", says="--metrics has 2 entries for 1 runs")
