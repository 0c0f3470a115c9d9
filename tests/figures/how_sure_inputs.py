"""A small made-up ensemble (three published cells, three seeds, one mesh variant) run through
analysis.confidence.ensemble and analysis.confidence.envelope, and the generated inputs of paper/how_sure.tex made from
it: for tests/figures/test_how_sure.py and the full report build of test_paper.py."""
import csv
import json

from figure_support import PAPER, call, command

from analysis import cli

REFERENCE = "nu,f,celerity_m_per_s\n0.2,1.5,0.882\n0.45,1.0,-2.523\n0.0,1.1,0.861\n"
SEEDS = {(0.2, 1.5): [0.86, 0.85, 0.87], (0.45, 1.0): [-2.68, -2.66, 1.0], (0.0, 1.1): [0.99, 1.01, 0.97]}
CATEGORY = {(0.2, 1.5): "intersonic_opening_inversion", (0.45, 1.0): "supersonic_backward_opening",
            (0.0, 1.1): "supersonic_forward_opening"}


def write_csv(path, rows):
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return path


def write_tables(folder):
    """all_metrics.csv, ensemble.*, envelope.*, flutter.txt in `folder`."""
    (folder / "ref.csv").write_text(REFERENCE)
    runs = [{"nu": nu, "f": f, "seed": seed, "celerity": c, "celerity_reason": "ok",
             "category": CATEGORY[(nu, f)] if c * SEEDS[(nu, f)][0] > 0 else "supersonic_forward_opening",
             "elements_per_H": 64}
            for (nu, f), values in SEEDS.items() for seed, c in enumerate(values, start=1)]
    write_csv(folder / "all_metrics.csv", runs)
    assert cli.main(["ensemble", str(folder / "all_metrics.csv"), "--reference", str(folder / "ref.csv"),
                                 "-o", str(folder)]) == 0
    write_csv(folder / "h32.csv", [{"nu": nu, "f": f, "celerity": values[0] * 1.08, "celerity_reason": "ok"}
                                   for (nu, f), values in SEEDS.items()])
    write_csv(folder / "h64.csv", [{"nu": nu, "f": f, "celerity": values[0], "celerity_reason": "ok"}
                                   for (nu, f), values in SEEDS.items()])
    spec = {"variants": [{"factor": "mesh", "label": "H/32", "table": str(folder / "h32.csv"),
                          "base": str(folder / "h64.csv")}]}
    assert cli.main(["envelope", "--ensemble", str(folder / "ensemble.csv"), "--spec", json.dumps(spec),
                                 "-o", str(folder)]) == 0
    (folder / "flutter.txt").write_text("0 nan nan\n0.2 1.0 inf\n0.45 1.0 inf\n")
    return folder


def write_generated(folder, generated):
    """The files rule paper_how_sure puts in paper/generated/, from write_tables(folder)."""
    # The finer ensemble (config paper.envelope.finer_ensemble) stands in as the same made-up ensemble.
    assert command(PAPER / "make_how_sure.py", "--ensemble", folder / "ensemble_summary.json", "--envelope",
                   folder / "envelope_summary.json", "--finer-ensemble", folder / "ensemble_summary.json",
                   "--finer-mesh", 128, "-o", generated / "how_sure_numbers.tex").returncode == 0
    (generated / "ensemble.tex").write_text((folder / "ensemble.tex").read_text())
    (generated / "envelope.tex").write_text((folder / "envelope.tex").read_text())
    assert call("envelope", folder / "envelope.csv", "--tolerance", 0.05, "--out", generated / "envelope") == 0
    assert call("phase_diagram", folder / "ensemble.csv", "--ensemble", "--flutter", folder / "flutter.txt",
                "--out", generated / "phase_diagram_ensemble") == 0
    # The measurement rules' scores come from `analysis score-rules` (not this section's code): a stand-in.
    (generated / "rule_scores.tex").write_text("\\begin{tabular}{l}rule scores (stand-in)\\end{tabular}\n")
