"""A tiny synthetic contrast sweep: its all_metrics.csv (the columns the contrast figure and
paper/make_contrast.py read) and the theory CSV of `python3 -m analysis contrast-theory` at its points,
written by hand so that the expected sentences are known. Not a test module."""
import math

from analysis.core.table_csv import csv_text
from analysis.theory.contrast_theory import COLUMNS

METRIC_COLUMNS = ("nu", "f", "E_substrate_over_E", "elements_per_H", "category", "celerity_over_cs", "opening",
                  "inversion", "min_T_over_N")
# (nu, contrast or None, f): (category, c_p / c_s or nan, opening, inversion, min T/N)
RUNS = {
    (0.2, None, 0.5): ("no_opening", math.nan, False, False, 0.47),
    (0.2, None, 1.5): ("intersonic_opening_inversion", 1.33, True, True, -0.53),
    (0.2, 3.0, 0.5): ("no_opening", math.nan, False, False, 0.45),
    (0.2, 3.0, 1.5): ("intersonic_opening_inversion", 1.08, True, True, -0.25),
    (0.2, 1.0, 0.5): ("no_slip", math.nan, False, False, 0.47),
    (0.2, 1.0, 1.5): ("no_slip", math.nan, False, False, 1.42),
    (0.45, None, 0.5): ("no_opening", math.nan, False, False, 0.47),
    (0.45, None, 1.5): ("intersonic_opening_inversion", 1.29, True, True, -0.51),
    (0.45, 3.0, 0.5): ("no_opening", math.nan, False, False, 0.47),
    (0.45, 3.0, 1.5): ("intersonic_backward_opening", -3.01, True, True, -0.64),
    (0.45, 1.0, 0.5): ("no_slip", math.nan, False, False, 0.47),
    (0.45, 1.0, 1.5): ("no_slip", math.nan, False, False, 1.42),
}
# (nu, contrast): onsets forward, backward, f_upper, and per f the forward / backward phase speeds (/ c_s1)
THEORY = {
    (0.2, None): (1.0, math.inf, 6.19, {}),
    (0.2, 3.0): (0.665, 3.31, math.nan, {1.5: (1.144, math.nan)}),
    (0.2, 1.0): (math.inf, math.inf, math.nan, {}),
    (0.45, None): (1.0, math.inf, math.inf, {}),
    (0.45, 3.0): (0.917, 0.719, math.nan, {0.5: (math.nan, math.nan), 1.5: (1.159, -3.362)}),
    (0.45, 1.0): (math.inf, math.inf, math.nan, {}),
}


def metrics_rows():
    return [dict(zip(METRIC_COLUMNS, (nu, f, contrast, 32, *values))) for (nu, contrast, f), values in RUNS.items()]


def theory_rows():
    rows = []
    for nu, contrast, f in RUNS:
        forward, backward, upper, speeds = THEORY[(nu, contrast)]
        fwd, bwd = speeds.get(f, (math.nan, math.nan))
        unstable = (contrast is None and forward < f < upper) or (contrast is not None and f > min(forward, backward))
        rows.append({"nu": nu, "E_substrate_over_E": contrast, "f": f, "f_threshold": min(forward, backward),
                     "f_threshold_forward": forward, "f_threshold_backward": backward,
                     "f_upper": upper if contrast is None else None, "unstable": unstable,
                     "growth_rate_per_k_over_cs1": 0.1 if unstable and contrast is not None else None,
                     "forward_phase_speed_over_cs1": fwd, "backward_phase_speed_over_cs1": bwd})
    return rows


def write_contrast(folder):
    """contrast_metrics.csv and contrast_theory.csv in `folder`; returns their paths."""
    metrics, theory = folder / "contrast_metrics.csv", folder / "contrast_theory.csv"
    metrics.write_text(csv_text(METRIC_COLUMNS, metrics_rows()))
    theory.write_text(csv_text(COLUMNS, theory_rows()))
    return metrics, theory
