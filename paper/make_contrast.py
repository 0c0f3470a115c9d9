#!/usr/bin/python3
"""The report's section "Beyond the paper: a deformable substrate": its sentences and its table, every
number from the contrast sweep's table and the theory at its points.

    paper/make_contrast.py results/contrast/table/all_metrics.csv \\
        --theory results/contrast/theory/contrast_theory.csv \\
        --text generated/contrast_text.tex --table generated/contrast_table.tex

all_metrics.csv: one row per run (`python3 -m analysis aggregate`), the contrast in E_substrate_over_E
(empty: the rigid flat); the theory: `python3 -m analysis contrast-theory` at the same (nu, contrast, f).
The text says, per nu, for which f each contrast opens, where the backward pulses (c_p < 0) and the
inversion of T/N appear, the celerities, and how the runs sit against the theory: a cell is unstable
in theory when f exceeds the onset of either family of growing modes (on the rigid flat: inside the
flutter wedge or on its lower bound f = 1, where the paper's runs open too), and a measured celerity is
set against the phase speed of the growing mode that runs the same way. Nothing is measured here.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys

from analysis.core.atomic import write_file
from table_io import InputError, label, latex_number, read_rows

REQUIRED = ("nu", "f", "E_substrate_over_E", "category", "celerity_over_cs", "opening", "inversion", "min_T_over_N")
THEORY_REQUIRED = ("nu", "E_substrate_over_E", "f", "f_threshold_forward", "f_threshold_backward", "f_upper",
                   "forward_phase_speed_over_cs1", "backward_phase_speed_over_cs1")
#: Short marks of the table (the caption explains them); an opening wave prints its c_p / c_s instead.
MARKS = {"no_slip": "S", "no_opening": "F", "opening_without_front": "W"}


def finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def contrast_of(row) -> float | None:
    value = row["E_substrate_over_E"]
    return value if finite(value) else None


def contrast_text(contrast) -> str:
    if contrast is None:
        return "rigid"
    if contrast < 1 and abs(1 / contrast - round(1 / contrast)) < 1e-6:
        return f"1/{round(1 / contrast)}"
    return f"{contrast:g}"


def columns(rows) -> list:
    contrasts = {contrast_of(r) for r in rows}
    return ([None] if None in contrasts else []) + sorted((c for c in contrasts if c is not None), reverse=True)


def same_contrast(a, b) -> bool:
    return (a is None and b is None) or (a is not None and b is not None and math.isclose(a, b, rel_tol=1e-6))


def theory_row(theory, nu, contrast, f):
    for row in theory:
        if (math.isclose(row["nu"], nu, rel_tol=1e-9) and same_contrast(contrast_of(row), contrast)
                and math.isclose(row["f"], f, rel_tol=1e-9)):
            return row
    raise InputError(f"theory: no row for nu = {nu:g}, contrast {contrast_text(contrast)}, f = {f:g}")


def unstable_in_theory(t) -> bool:
    """f above the onset of either family; on the rigid flat strictly inside the flutter wedge."""
    f, forward, backward, upper = t["f"], t["f_threshold_forward"], t["f_threshold_backward"], t["f_upper"]
    if contrast_of(t) is None:
        return finite(forward) and forward < f < (upper if finite(upper) else math.inf)
    return (finite(forward) and f > forward) or (finite(backward) and f > backward)


def disagreement(t, contrast, f) -> str:
    """Why a run's opening (or its absence) differs from the theory: neutral on an onset, else stable or
    unstable (with the growth rate per unit wavenumber of the most unstable mode)."""
    where = f"{contrast_text(contrast)}, $f = {f:g}$: "
    onsets = (t["f_threshold_forward"], t["f_threshold_backward"])
    if any(finite(onset) and math.isclose(f, onset, rel_tol=1e-9) for onset in onsets):
        return where + "neutral in theory (on the onset), opens"
    if unstable_in_theory(t):
        growth = t.get("growth_rate_per_k_over_cs1")
        rate = f", growth ${latex_number(f'{growth:.2g}')}\\,c_s$ per unit $k$" if finite(growth) else ""
        return where + f"unstable in theory{rate}, no opening"
    return where + "stable in theory, opens"


def mode_speed(t, celerity):
    """The theory's phase speed (/ c_s) of the growing family that runs the way the measured front does."""
    for key in ("forward_phase_speed_over_cs1", "backward_phase_speed_over_cs1"):
        speed = t[key]
        if finite(speed) and finite(celerity) and speed * celerity > 0:
            return speed
    return None


def onset_text(value) -> str:
    """An onset f as LaTeX math: 3 digits, powers of ten as such; no onset (empty cell, inf) is infinity."""
    return f"${latex_number(f'{value:.3g}')}$" if finite(value) else "$\\infty$"


def fs_text(values) -> str:
    """'$f = 1$, $1.5$ and $2$'."""
    values = sorted(values)
    head = "$, $".join(f"{v:g}" for v in values[:-1])
    return "$f = " + head + ("$ and $" if len(values) > 1 else "") + f"{values[-1]:g}$"


def list_text(items) -> str:
    items = list(items)
    return ", ".join(items[:-1]) + (" and " if len(items) > 1 else "") + items[-1] if items else ""


def opening_words(rows, fs) -> str:
    """'from f = 1' / 'at f = 1 and 2' / 'at no f' for the runs of one column."""
    opened = sorted(r["f"] for r in rows if r["opening"] is True)
    if not opened:
        return "at no $f$"
    if opened == [f for f in fs if f >= opened[0]]:
        return f"from $f = {opened[0]:g}$" if opened[0] > fs[0] else "at every $f$"
        return f"at {fs_text(opened)}"


def nu_paragraph(nu, rows, theory) -> str:
    cols = columns(rows)
    fs = sorted({r["f"] for r in rows})
    groups: dict[str, list[str]] = {}
    for c in cols:
        groups.setdefault(opening_words([r for r in rows if same_contrast(contrast_of(r), c)], fs), []).append(
            contrast_text(c))
    opening = "; ".join(f"$E_s/E$ = {list_text(names)} {words}" for words, names in groups.items())
    text = [f"At $\\nu = {nu:g}$ the interface opens with {opening}."]
    steady = [r for r in rows if r["category"] == "no_slip"]
    if steady:
        where = sorted({contrast_text(contrast_of(r)) for r in steady})
        text.append(f"No node slips faster than the front threshold ($10\\,V_0$: steady sliding) in "
                    f"{len(steady)} runs, on $E_s/E$ = {list_text(where)}.")
    waves = [r for r in rows if finite(r["celerity_over_cs"])]
    for sign, name in ((1, "Forward opening waves (in the layer's sliding direction)"),
                       (-1, "Backward opening waves (against it)")):
        chosen = [r for r in waves if r["celerity_over_cs"] * sign > 0]
        if not chosen:
            text.append(f"{name}: none.")
            continue
        per = []
        for c in cols:
            here = [r for r in chosen if same_contrast(contrast_of(r), c)]
            speeds = [r["celerity_over_cs"] for r in here]
            if speeds:
                span = (f"${min(speeds):+.2f}$" if len(speeds) == 1 or math.isclose(min(speeds), max(speeds))
                        else f"${min(speeds):+.2f}$ to ${max(speeds):+.2f}$")
                per.append(f"{span} on {contrast_text(c)} ({fs_text([r['f'] for r in here])})")
        text.append(f"{name}, $c_p/c_s$: {'; '.join(per)}.")
    inverted = [r for r in rows if r["inversion"] is True]
    opened = [r for r in rows if r["opening"] is True]
    text.append(f"$T/N$ inverts in {len(inverted)} runs, {sum(r['opening'] is True for r in inverted)} of "
                f"them among the {len(opened)} that open"
                + (f" (min $T/N$ from ${min(r['min_T_over_N'] for r in inverted):.2f}$ to "
                   f"${max(r['min_T_over_N'] for r in inverted):.2f}$)." if inverted else "."))
    text.append(theory_sentence(rows, theory, nu))
    return " ".join(text)


def theory_sentence(rows, theory, nu) -> str:
    agree, against = 0, []
    gaps = []
    for r in rows:
        t = theory_row(theory, nu, contrast_of(r), r["f"])
        expected = unstable_in_theory(t)
        if expected == (r["opening"] is True):
            agree += 1
        else:
            against.append(f"({disagreement(t, contrast_of(r), r['f'])})")
        speed = mode_speed(t, r["celerity_over_cs"])
        if speed is not None:
            gaps.append((abs(r["celerity_over_cs"] / speed - 1), contrast_text(contrast_of(r)), r["f"]))
    onsets = []
    for c in columns(rows):
        if c is None:
            continue
        t = theory_row(theory, nu, c, rows[0]["f"])
        onsets.append(f"{contrast_text(c)}: {onset_text(t['f_threshold_forward'])} / "
                      f"{onset_text(t['f_threshold_backward'])}")
    text = (f"Theory (onset $f$ of the forward / backward growing modes, $E_s/E$: {'; '.join(onsets)}): "
            f"opening goes with instability of steady sliding in {agree} of {len(rows)} runs")
    text += (f"; not in {list_text(against)}." if against else ".")
    if gaps:
        median = statistics.median(g for g, _, _ in gaps)
        worst = max(gaps)
        runs = f"{len(gaps)} run{'s' if len(gaps) > 1 else ''}"
        text += (f" The measured celerity differs from the phase speed of the growing mode that runs the same "
                 f"way by {100 * median:.0f}\\,\\% (median of {runs}), at most {100 * worst[0]:.0f}\\,\\% "
                 f"($E_s/E$ = {worst[1]}, $f = {worst[2]:g}$).")
    return text


def cell(r) -> str:
    if finite(r["celerity_over_cs"]):
        text = f"${r['celerity_over_cs']:+.2f}$"
    else:
        text = MARKS.get(r["category"], label(r["category"]))
    return text + ("$^{*}$" if r["inversion"] is True else "")


def table(rows, theory) -> str:
    fs = sorted({r["f"] for r in rows})
    lines = ["\\begin{tabular}{ll" + "c" * len(fs) + "cc}", "\\toprule",
             "$\\nu$ & $E_s/E$ & " + " & ".join(f"$f = {f:g}$" for f in fs)
             + " & $f_c^{\\mathrm{fwd}}$ & $f_c^{\\mathrm{bwd}}$ \\\\", "\\midrule"]
    for nu in sorted({r["nu"] for r in rows}):
        of_nu = [r for r in rows if r["nu"] == nu]
        for c in columns(of_nu):
            cells = []
            for f in fs:
                found = [r for r in of_nu if same_contrast(contrast_of(r), c) and r["f"] == f]
                cells.append(cell(found[0]) if found else "--")
            t = theory_row(theory, nu, c, fs[0])
            onsets = ["--" if k == "f_threshold_backward" and c is None else onset_text(t[k])
                      for k in ("f_threshold_forward", "f_threshold_backward")]
            lines.append(f"{nu:g} & {contrast_text(c)} & " + " & ".join(cells + onsets) + " \\\\")
        lines.append("\\midrule" if nu != max(r["nu"] for r in rows) else "\\bottomrule")
    lines.append("\\end{tabular}")
    return "\n".join(lines) + "\n"


def render(rows, theory, sources) -> tuple[str, str]:
    head = f"% Generated by paper/make_contrast.py from: {', '.join(sources)}\n% Do not edit.\n"
    paragraphs = [nu_paragraph(nu, [r for r in rows if r["nu"] == nu], theory)
                  for nu in sorted({r["nu"] for r in rows})]
    return head + "\n\n".join(paragraphs) + "\n", head + table(rows, theory)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="all_metrics.csv of the contrast sweep")
    parser.add_argument("--theory", required=True, help="CSV of `python3 -m analysis contrast-theory`")
    parser.add_argument("--text", required=True, help="the section's sentences (.tex) to write")
    parser.add_argument("--table", required=True, help="the section's tabular (.tex) to write")
    args = parser.parse_args(argv)
    try:
        rows = read_rows(args.metrics, REQUIRED)
        theory = read_rows(args.theory, THEORY_REQUIRED)
        if not rows:
            raise InputError(f"{args.metrics}: no runs")
        text, tabular = render(rows, theory, [args.metrics, args.theory])
    except InputError as err:
        print(f"make_contrast.py: error: {err}", file=sys.stderr)
        return 2
    write_file(args.text, text)
    write_file(args.table, tabular)
    return 0


if __name__ == "__main__":
    sys.exit(main())
