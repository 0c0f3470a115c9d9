"""Helpers of the figure and paper tests: paths, the report's figure jobs, running a script
in-process (fast) or as a command (exit status, stderr), and the check of a written figure."""
import importlib
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FIGURES = ROOT / "figures"
PAPER = ROOT / "paper"
sys.path.insert(0, str(FIGURES))

GRID = ["elements_per_H=32", "lambda_over_H=2", "rho=1000", "V0_over_cs=1e-5", "dt_times_cs=0.5"]


def report_jobs(data):
    """The figures reproduction.tex expects (config `paper.figures`), as the pipeline would make them:
    {name: (script, args...)} with paths into the synthetic data folder."""
    jobs = {
        "fig2a_slip_velocity": ("spacetime", data / "run.h5", "--field", "slip_velocity",
                                "--metrics", data / "metrics.json", "--tmin", 600),
        "fig2b_opening": ("spacetime", data / "run.h5", "--field", "opening",
                          "--metrics", data / "metrics.json", "--tmin", 600, "--tmax", 1150),
        "fig2c_tn_shear_rate": ("tn_curves", data / "run_v1e-06.h5", data / "run.h5",
                                data / "run_v0.0001.h5", "--labels", "1e-6", "1e-5", "1e-4",
                                "--highlight", 1),
        "fig2e_tn_aligned": ("tn_aligned", data / "run_v1e-06.h5", data / "run.h5", data / "run_v0.0001.h5",
                             "--metrics", data / "metrics_v1e-06_drop.json", data / "metrics_drop.json",
                             data / "metrics_v0.0001_drop.json", "--labels", "1e-6", "1e-5", "1e-4",
                             "--highlight", 1),
        "fig2d_tn_long": ("tn_curves", data / "run.h5", "--tmax", 1100),
        "fig3_snapshots": ("snapshots", data / "run.h5"),
        "fig4a_phase_diagram": ("phase_diagram", data / "all_metrics.csv", "--flutter",
                                data / "flutter.txt", "--published", data / "table1.csv",
                                "--where", *GRID),
        "fig4b_celerity_vs_nu": ("celerity_vs_nu", data / "table1.csv"),
        "fig4g_deviation_map": ("deviation_map", data / "table1.csv"),
        "fig4c_state": ("spacetime", data / "run.h5", "--field", "state"),
        "fig4d_state": ("spacetime", data / "run.h5", "--field", "state", "--metrics",
                        data / "metrics.json"),
        "fig4e_state": ("spacetime", data / "run_v1e-06.h5", "--field", "state"),
        "fig4f_state": ("spacetime", data / "run_v0.0001.h5", "--field", "state"),
        "pulse_spacing": ("pulse_spacing", data / "all_metrics.csv", "--where", "nu=0.2",
                          "f=1.5", *GRID[:1], *GRID[2:]),
        "convergence_mesh": ("convergence", data / "all_metrics.csv", "--param",
                             "elements_per_H"),
        "convergence_density": ("convergence", data / "all_metrics.csv", "--param", "rho"),
        "convergence_shear_rate": ("convergence", data / "all_metrics.csv", "--param",
                                   "V0_over_cs"),
        "convergence_timestep": ("convergence", data / "all_metrics.csv", "--param", "dt_times_cs"),
        "regularized_fast_h128": ("spacetime", data / "run.h5", "--field", "slip_velocity"),
        "regularized_between_h128": ("spacetime", data / "run.h5", "--field", "state"),
        "regularized_mid_h128": ("spacetime", data / "run_v1e-06.h5", "--field", "slip_velocity"),
        "regularized_slow_h128": ("spacetime", data / "run_v0.0001.h5", "--field", "slip_velocity"),
        "contrast_phase_diagram": ("contrast_phase_diagram", data / "contrast_metrics.csv", "--theory",
                                   data / "contrast_theory.csv"),
    }
    return jobs


def call(script, *args):
    """Run figures/<script>.py main() in this process; returns its exit status."""
    module = importlib.import_module(script)
    return module.main([str(a) for a in args])


def command(path, *args):
    """Run a script as the pipeline does; returns the CompletedProcess."""
    return subprocess.run([sys.executable, str(path), *map(str, args)], capture_output=True,
                          text=True, cwd=ROOT, env=dict(os.environ, MPLBACKEND="Agg"))


def assert_figure(prefix):
    """PREFIX.png and PREFIX.pdf exist, are what they claim and are not blank."""
    import matplotlib.image

    png, pdf = Path(f"{prefix}.png"), Path(f"{prefix}.pdf")
    assert png.is_file() and pdf.is_file(), f"missing {png} or {pdf}"
    assert png.stat().st_size > 10_000, f"{png} is only {png.stat().st_size} bytes"
    assert pdf.stat().st_size > 5_000, f"{pdf} is only {pdf.stat().st_size} bytes"
    assert pdf.read_bytes()[:5] == b"%PDF-"
    pixels = matplotlib.image.imread(str(png))
    assert pixels.shape[0] > 300 and pixels.shape[1] > 300
    assert pixels[..., :3].std() > 0.05, f"{png} looks blank"
