"""Made-up inputs of the limits subsections of paper/how_sure.tex (three published cells at three
meshes, one backward cell at four time steps and two seeds, a Fig. 3 timeline, pulse counts) run
through analysis.confidence.mesh_limit, timestep_limit, timeline and pulse_seeds: for
tests/figures/test_how_sure_limits.py and the full report build of test_paper.py."""

from figure_support import PAPER, call, command
from how_sure_inputs import write_csv

from analysis import cli
from analysis.confidence import timeline

REFERENCE = "nu,f,celerity_m_per_s\n0.2,1.5,0.882\n0.45,1.0,-2.523\n0.0,1.1,0.861\n"
MESHES = {32: {(0.2, 1.5): 0.84, (0.45, 1.0): -2.68, (0.0, 1.1): 0.99},
          64: {(0.2, 1.5): 0.86, (0.45, 1.0): -2.66, (0.0, 1.1): 1.01},
          128: {(0.2, 1.5): 0.87, (0.45, 1.0): -2.65, (0.0, 1.1): 0.97}}
DT_MEANS = {0.5: -2.66, 0.25: -2.40, 0.125: -2.30, 0.0625: -2.25}


def write_limits(folder):
    """Every file of results/limits/ that rule paper_how_sure_limits reads, in `folder`."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "ref.csv").write_text(REFERENCE)
    args = []
    for n, cells in MESHES.items():
        rows = [{"nu": nu, "f": f, "seed": 1, "celerity": c, "celerity_reason": "ok"} for (nu, f), c in cells.items()]
        args += ["--mesh", f"{n}={write_csv(folder / f'h{n}.csv', rows)}"]
    assert cli.main(["mesh-limit"] + args + ["--reference", str(folder / "ref.csv"), "-o", str(folder)]) == 0
    runs = [{"nu": 0.45, "f": 1.0, "dt_times_cs": dt, "seed": seed, "elements_per_H": 64,
             "celerity": mean + (seed - 1.5) * 0.02, "celerity_reason": "ok"}
            for dt, mean in DT_MEANS.items() for seed in (1, 2)]
    assert cli.main(["timestep-limit", str(write_csv(folder / "dt.csv", runs)), "--reference", str(folder / "ref.csv"),
                                "-o", str(folder)]) == 0
    events = dict(onset_time=744.0, localization_time=908.0, celerity_window_start=909.0, first_opening_time=1018.0,
                  slip_velocity_max_time=1064.0, first_drop_start_time=839.0, min_T_over_N_time=1301.0)
    base = {"nu": 0.2, "f": 1.5}
    sets = {"seeds, H/64": [dict(base, run=f"s{s}", elements_per_H=64, seed=s, **events) for s in (1, 2, 3)],
            "meshes": [dict(base, run=f"m{n}", elements_per_H=n, seed=1, **events) for n in (32, 64, 128)]}
    for name, text in timeline.timeline_files(sets).items():
        (folder / name).write_text(text)
    pulses = [{"nu": 0.2, "f": 1.5, "seed": s, "lambda_over_H": lam, "elements_per_H": 64, "pulse_count": count,
               "pulse_count_theory": lam / 2 + 1, "pulse_next_strength": 0.3,
               "later_drops_start_T_over_N_median": 0.65 if s == 1 else "", "end_reason": "stop_after_opening"}
              for lam, count in ((2.0, 1), (4.0, 2), (6.0, 3)) for s in (1, 2)]
    assert cli.main(["pulse-seeds", str(write_csv(folder / "pulses.csv", pulses)), "-o", str(folder)]) == 0
    return folder


def write_generated_limits(folder, generated):
    """The files rule paper_how_sure_limits puts in paper/generated/, from write_limits(folder)."""
    result = command(PAPER / "make_how_sure_limits.py", "--mesh", folder / "mesh_limit_summary.json",
                     "--timestep", folder / "timestep_limit_summary.json", "--timeline",
                     folder / "timeline_summary.json", "--pulses", folder / "pulse_seeds_summary.json",
                     "-o", generated / "how_sure_limits.tex")
    assert result.returncode == 0, result.stderr
    for name in ("mesh_limit", "timestep_limit", "timeline", "pulse_seeds"):
        (generated / f"{name}.tex").write_text((folder / f"{name}.tex").read_text())
    assert call("mesh_limit", folder / "mesh_limit.csv", "--tolerance", 0.05, "--out", generated / "mesh_limit") == 0
    assert call("timestep_backward", folder / "timestep_limit.csv", "--out", generated / "timestep_backward") == 0
    results = folder / "committed"
    for sweep in ("table1_h32", "variant_seed2", "table1", "table1_h128", "timestep", "variant_dt1"):
        (results / sweep).mkdir(parents=True, exist_ok=True)
        write_csv(results / sweep / "all_metrics.csv", [dict(
            nu=0.45, f=1.0, celerity=-2.6, integration="reduced", regularization="none", lambda_over_H=2,
            E=1000.0, rho=1000.0, V0_over_cs=1e-5, elements_per_H=64, dt_times_cs=0.5, seed=1)])
    assert call("backward_celerity", "--results", results, "--out", generated) == 0
