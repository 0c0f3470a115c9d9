"""The verdict on each of the paper's claims (rendered by paper/make_claims.py): one function per claim, its rule in its
docstring, the numbers in the reason; `verdicts` runs those of claims.json."""
from __future__ import annotations

import math
import statistics
from collections import Counter

from analysis.core.errors import InputError
from analysis.metrics.regime import outcome_label
from analysis.tables.claim_support import (BACKWARD_OPENING, FORWARD_OPENING, Missing, Tables, Verdict, cell,
                                          finite, g, grade, mesh_number, pct, same, sci, spread, tt)


# ---------------------------------------------------------------- Table 1, the headline count

def window_position(r, tolerance: float) -> str:
    """Where the cell's deviation interval (deviation +- the celerity's window sensitivity, in units
    of the published value) lies against the tolerance: 'inside' (whole interval within),
    'straddles', 'outside', or 'unknown' without a sensitivity."""
    if not finite(r["celerity_window_sensitivity"]):
        return "unknown"
    half = abs(r["celerity_window_sensitivity"] * r["celerity"]) / abs(r["published"])
    low, high = r["deviation_rel"] - half, r["deviation_rel"] + half
    nearest = 0.0 if low <= 0 <= high else min(abs(low), abs(high))
    farthest = max(abs(low), abs(high))
    return "inside" if farthest <= tolerance else "outside" if nearest > tolerance else "straddles"


def flips_at_other_meshes(r, meshes) -> list[str]:
    flips = []
    for mesh, rows in meshes:
        other = next((o for o in rows if same(o["nu"], r["nu"]) and same(o["f"], r["f"])), None)
        if other and finite(other["celerity"]) and finite(r["celerity"]) and \
                (other["celerity"] > 0) != (r["celerity"] > 0):
            flips.append(mesh)
    return flips


def headline(tables: Tables, tolerance: float, steps: list[float]) -> dict:
    """The counts behind the headline: within the tolerance (and at each step), reproduced, and by
    each cell's window sensitivity."""
    rows = [r for r in tables.need("table1") if finite(r["published"])]
    measured = [r for r in rows if finite(r["celerity"])]

    def within(r, tol):
        return abs(r["deviation_rel"]) <= tol

    def reproduced(r, tol):
        return (within(r, tol) and r["sign_match"] is True and r["regime_match"] is True
                and r["category_match"] is True)

    positions = Counter(window_position(r, tolerance) for r in measured)
    stable = [r for r in measured if reproduced(r, tolerance) and not flips_at_other_meshes(r, tables.meshes)]
    return {"cells": len(rows), "measured": len(measured),
            "within": {f"{t:g}": sum(within(r, t) for r in measured) for t in sorted({tolerance, *steps})},
            "reproduced": {f"{t:g}": sum(reproduced(r, t) for r in measured) for t in sorted({tolerance, *steps})},
            "reproduced_sign_stable": len(stable),
            "window": {k: positions.get(k, 0) for k in ("inside", "straddles", "outside", "unknown")}}


def claim_table1(tables: Tables, spec, tolerance, steps):
    """Reproduced when every published cell is reproduced (within the tolerance with the published
    sign, regime and outcome, and its sign at the other meshes); not reproduced when none is."""
    h = headline(tables, tolerance, steps)
    tol = f"{tolerance:g}"
    counts = ", ".join(f"{h['within'][f'{t:g}']} at {pct(t, 0)}" for t in steps)
    meshes = ", ".join(m for m, _ in tables.meshes)
    reason = (f"{h['reproduced'][tol]} of {h['cells']} published cells reproduced (within {pct(tolerance, 0)} with "
              f"the published sign, regime and outcome), {h['reproduced_sign_stable']} of them with the same sign "
              f"at {meshes or 'the other meshes (none given)'}; {h['measured']} have a measured front. "
              f"Within {pct(tolerance, 0)} whatever the outcome: {h['within'][tol]} ({counts}): the count moves "
              f"with the tolerance. With each cell's window sensitivity, {h['window']['inside']} cells are within "
              f"{pct(tolerance, 0)} over their whole interval, {h['window']['straddles']} straddle the line, "
              f"{h['window']['outside']} lie outside it.")
    if tables.missing_meshes:
        reason += f" Not built: {', '.join(tables.missing_meshes)}."
    return grade(h["reproduced_sign_stable"], h["cells"]), reason


# ---------------------------------------------------------------- the other claims

def claim_intersonic(tables, spec, tolerance, steps):
    """Graded by the share of the grid's forward opening waves that run at c_s < c_p < sqrt(2) c_s."""
    forward = [r for r in tables.need("grid") if r["category"] in FORWARD_OPENING and finite(r["celerity"])
               and r["celerity"] > 0]
    inside = [r for r in forward if r["below_sqrt2_cs"] is True and r["celerity_over_cs"] > 1]
    others = [r for r in forward if r not in inside]
    reason = f"{len(inside)} of the grid's {len(forward)} forward opening waves run at $c_s < c_p < \\sqrt2\\,c_s$"
    if others:
        reason += ("; the others, at $c_p/c_s$: " + ", ".join(f"{g(r['celerity_over_cs'])} at {cell(r)}"
                                                              for r in others))
    return grade(len(inside), len(forward)), reason + "."


def claim_backward(tables, spec, tolerance, steps):
    """Reproduced when every published cell at these nu has the published direction at the paper's
    mesh and at the other meshes; partly when some hold."""
    rows = [r for r in tables.need("table1") if finite(r["published"]) and any(same(r["nu"], n) for n in spec["nus"])]
    held, notes = 0, []
    for r in rows:
        if not finite(r["celerity"]):
            notes.append(f"{cell(r)} no front ({outcome_label(r['category'])})")
            continue
        flips = flips_at_other_meshes(r, tables.meshes)
        if r["sign_match"] is True and not flips:
            held += 1
        elif flips:
            notes.append(f"{cell(r)} changes direction at {' and '.join(flips)}")
        else:
            notes.append(f"{cell(r)} runs the other way")
    backward = sum(1 for r in rows if r["published"] < 0)
    reason = (f"{held} of the {len(rows)} published cells at $\\nu = {', '.join(f'{n:g}' for n in spec['nus'])}$ "
              f"({backward} published backward) keep the published direction at every mesh")
    reason += ("; " + "; ".join(notes)) if notes else ""
    return grade(held, len(rows)), reason + "."


def claim_nu0_f2(tables, spec, tolerance, steps):
    """Reproduced when the cell has the published regime at every mesh; not reproduced when it misses
    it at the paper's mesh; partly otherwise."""
    nu, f = spec["cell"]
    r = next((r for r in tables.need("table1") if same(r["nu"], nu) and same(r["f"], f)), None)
    if r is None:
        raise Missing(f"cell ({nu:g}, {f:g}) not in table {tt('table1')}")
    grid = tables.optional("grid") or []
    own = {o["elements_per_H"] for o in grid if finite(o.get("elements_per_H"))}
    own_label = f"H/{own.pop():g}" if len(own) == 1 else "the paper's mesh"
    per_mesh = [(own_label, r)] + [(m, o) for m, rows in tables.meshes
                                          for o in rows if same(o["nu"], nu) and same(o["f"], f)]
    text = "; ".join(f"{m}: $c_p =$ {g(o['celerity'])} m/s, {o['regime'] if isinstance(o['regime'], str) else 'no front'}"
                     for m, o in per_mesh)
    celerities = [(mesh_number(m), o["celerity"]) for m, o in per_mesh if finite(o["celerity"])
                  and finite(mesh_number(m))]
    reason = (f"published {g(r['published'])} m/s, {r['published_regime']}; {text}. At $\\nu = 0$, "
              "$c_l = \\sqrt2\\,c_s$: intersonic and supersonic are told apart by $c_l$")
    meshes = sorted(celerities)
    if len(meshes) >= 2 and finite(r["celerity"]):
        values = [c for _, c in meshes]
        if not (values == sorted(values) or values == sorted(values, reverse=True)):
            reason += "; the celerity is not monotone in the mesh"
    if r["regime_match"] is not True:
        return "not reproduced", reason + f"; deviation {pct(r['deviation_rel'])} at {own_label}."
    ok = all(o["regime"] == r["published_regime"] for _, o in per_mesh)
    return ("reproduced" if ok else "partly"), reason + "."


def claim_opening(tables, spec, tolerance, steps):
    """Graded by the share of published cells (all published as opening waves) whose run shows the
    published outcome; the grid's opening and inversion counts are quoted."""
    rows = [r for r in tables.need("table1") if finite(r["published"])]
    kept = [r for r in rows if r["category_match"] is True]
    other = [f"{cell(r)}: {outcome_label(r['category'])}" for r in rows if r["category_match"] is not True]
    grid = tables.need("grid")
    reason = (f"{len(kept)} of {len(rows)} published cells show the published opening wave"
              + (f" (not: {'; '.join(other)})" if other else "")
              + f"; over the grid, {sum(r['opening'] is True for r in grid)} of {len(grid)} runs open and "
              f"{sum(r['inversion'] is True for r in grid)} invert $T/N$.")
    return grade(len(kept), len(rows)), reason


def claim_pulses(tables, spec, tolerance, steps):
    """Reproduced when every run (every seed) has the published number of major pulses; partly when
    the most frequent count over seeds matches at every period; not reproduced otherwise."""
    expected = {float(k): v for k, v in spec["major_pulses"].items()}
    rows = tables.optional("period_ensemble") or tables.need("period")
    by_period = {p: [int(r["pulse_count"]) for r in rows if same(r["lambda_over_H"], p) and finite(r["pulse_count"])]
                 for p in expected}
    if not any(by_period.values()):
        raise Missing("no run of the period sweeps at the published lambda/H")
    source = "period_ensemble" if tables.optional("period_ensemble") else "period"
    parts, modes_match, all_match = [], True, True
    for p, counts in by_period.items():
        mode = Counter(counts).most_common(1)[0][0] if counts else None
        modes_match &= mode == expected[p]
        all_match &= bool(counts) and all(c == expected[p] for c in counts)
        parts.append(f"$\\lambda/H = {p:g}$: {', '.join(str(c) for c in counts) or 'no run'} (paper {expected[p]})")
    reason = f"major pulses per run ({tt(source)}): " + "; ".join(parts)
    single = tables.optional("period")
    if single and source != "period":
        counts = [f"{int(r['pulse_count'])}" for r in sorted(single, key=lambda r: r["lambda_over_H"])
                  if finite(r["pulse_count"])]
        reason += f"; the period sweep alone gives {', '.join(counts)}"
    mesh = tables.optional("mesh")
    if mesh:
        counts = [f"{int(r['pulse_count'])} at H/{r['elements_per_H']:g}" for r in
                  sorted(mesh, key=lambda r: r["elements_per_H"]) if finite(r["pulse_count"])]
        reason += f"; at the reference point across meshes: {', '.join(counts)}"
    reason += tables.not_built_note("period_ensemble", "mesh") + "."
    return ("reproduced" if all_match else "partly" if modes_match else "not reproduced"), reason


def claim_shear_rate(tables, spec, tolerance, steps):
    """Reproduced when the start of the first drop varies by at most the tolerance over the sweep;
    partly when every run still inverts T/N; not reproduced otherwise."""
    rows = sorted(tables.need("shear_rate"), key=lambda r: r["V0_over_cs"])
    starts = [r["first_drop_start_after_onset"] for r in rows]
    inverted = sum(r["inversion"] is True for r in rows)
    s = spread(starts)
    reason = (f"the first drop starts {g(min(starts))}--{g(max(starts))} s after the slip onset for "
              f"$V_0/c_s$ = {sci(rows[0]['V0_over_cs'])}--{sci(rows[-1]['V0_over_cs'])} (spread {pct(s)} of "
              f"the mean, tolerance {pct(tolerance, 0)}); {inverted} of {len(rows)} runs invert $T/N$ "
              f"(minimum {g(min(r['min_T_over_N'] for r in rows), 2)} to {g(max(r['min_T_over_N'] for r in rows), 2)})")
    if finite(s) and s <= tolerance:
        return "reproduced", reason + "."
    return ("partly" if inverted == len(rows) else "not reproduced"), reason + "."


def claim_density(tables, spec, tolerance, steps):
    """Not testable here: with dt proportional to sqrt(rho) the discrete problems are the same problem
    in scaled time, so agreement is no evidence; the numbers are quoted."""
    rows = tables.need("density")
    reason = (f"$c_p/c_s$ varies by {pct(spread([r['celerity_over_cs'] for r in rows]))} over "
              f"$\\rho$ = {', '.join(g(r['rho']) for r in sorted(rows, key=lambda r: r['rho']))} kg/m$^3$. "
              "With $\\Delta t \\propto \\sqrt\\rho$ the runs solve one problem in scaled time: the invariance holds "
              "by construction and is no evidence for the claim.")
    return "not testable here", reason


def claim_mesh(tables, spec, tolerance, steps):
    """Reproduced when the mesh sweep keeps its category with a celerity spread within the tolerance and
    no published cell changes sign between meshes; not reproduced when the category changes; partly
    otherwise."""
    rows = sorted(tables.need("mesh"), key=lambda r: r["elements_per_H"])
    s = spread([r["celerity"] for r in rows])
    categories = {r["category"] for r in rows}
    reason = ("at the reference point $c_p$ = " + ", ".join(f"{g(r['celerity'])} (H/{r['elements_per_H']:g})" for r in rows)
              + f" m/s, spread {pct(s)} (tolerance {pct(tolerance, 0)}), categories: "
              + ", ".join(sorted(outcome_label(c) for c in categories)))
    flips = [cell(r) for r in tables.optional("table1") or [] if finite(r["published"])
             and flips_at_other_meshes(r, tables.meshes)]
    if tables.meshes:
        reason += f"; published cells whose sign changes between meshes: {', '.join(flips) or 'none'}"
    reason += tables.not_built_note("table1") + "."
    if len(categories) > 1:
        return "not reproduced", reason
    return ("reproduced" if finite(s) and s <= tolerance and not flips else "partly"), reason


def claim_timestep(tables, spec, tolerance, steps):
    """Per cell of the time-step sweep: stable when its category holds at every dt and its celerity
    varies by at most the tolerance; graded by the share of stable cells. Small-dt seeds of the
    backward cells are counted when built."""
    rows = tables.need("timestep")
    cells = sorted({(r["nu"], r["f"]) for r in rows})
    stable, parts = 0, []
    for nu, f in cells:
        runs = sorted((r for r in rows if same(r["nu"], nu) and same(r["f"], f)), key=lambda r: r["dt_times_cs"])
        s = spread([r["celerity"] for r in runs if r["category"] == runs[0]["category"]])
        kinds = {r["category"] for r in runs}
        ok = len(kinds) == 1 and finite(s) and s <= tolerance
        stable += ok
        text = f"({nu:g}, {f:g}): $c_p$ = " + ", ".join(f"{g(r['celerity'])}" for r in runs) + \
            " at $\\Delta t\\,c_s$ = " + ", ".join(f"{r['dt_times_cs']:g}" for r in runs) + f" m (spread {pct(s)})"
        if len(kinds) > 1:
            text += ", category " + " / ".join(outcome_label(r["category"]) for r in runs)
        parts.append(text)
    reason = "; ".join(parts)
    small = tables.optional("timestep_backward")
    if small:
        finest = sorted({r["dt_times_cs"] for r in small})[:2]
        for nu, f in sorted({(r["nu"], r["f"]) for r in small}):
            runs = [r for r in small if same(r["nu"], nu) and same(r["f"], f) and r["dt_times_cs"] in finest]
            kept = sum(r["category"] == BACKWARD_OPENING for r in runs)
            reason += (f"; at $\\Delta t\\,c_s$ = {', '.join(f'{d:g}' for d in finest)} m the backward opening pulse "
                       f"of ({nu:g}, {f:g}) survives in {kept} of {len(runs)} runs (seeds)")
    reason += tables.not_built_note("timestep_backward") + "."
    return grade(stable, len(cells)), reason


def claim_long(tables, spec, tolerance, steps):
    """Not reproduced without repeated drops; reproduced when the later drops start within the
    tolerance of the published T/N in every seed; partly otherwise."""
    rows = tables.optional("long_ensemble") or tables.need("long")
    drops = [int(r["n_drops"]) for r in rows if finite(r["n_drops"])]
    starts = [r["later_drops_start_T_over_N_median"] for r in rows]
    target = spec["later_drop_start_T_over_N"]
    reason = (f"drops per run: {', '.join(str(d) for d in drops)}; the later drops start at $T/N$ = "
              f"{', '.join(g(s, 2) for s in starts)} (median per run; paper {g(target, 2)})"
              + tables.not_built_note("long_ensemble") + ".")
    if not drops or max(drops) < 2:
        return "not reproduced", reason
    near = all(finite(s) and abs(s - target) <= tolerance * target for s in starts)
    return ("reproduced" if near else "partly"), reason


def claim_dissipation(tables, spec, tolerance, steps):
    """Median dissipative friction coefficient during opening, in units of f: reproduced when below the
    tolerance (marginal), partly when lower than before the opening, not reproduced otherwise."""
    opened = [r for r in tables.need("grid") if r["opening"] is True and finite(r["dissipative_friction_opening"])
              and r["f"] > 0]
    if not opened:
        raise Missing(f"no opening run with a dissipation in table {tt('grid')}")
    during = statistics.median(r["dissipative_friction_opening"] / r["f"] for r in opened)
    before = [r["dissipative_friction_before_opening"] / r["f"] for r in opened
              if finite(r["dissipative_friction_before_opening"])]
    before = statistics.median(before) if before else math.nan
    reason = (f"over {len(opened)} opening runs of the grid, friction dissipates a median {g(during, 2)}\\,$f$ per "
              f"unit mean slip while the interface opens, against {g(before, 2)}\\,$f$ before the first opening "
              f"($f$ for uniform Coulomb sliding; marginal here: below {pct(tolerance, 0)} of $f$)")
    if during <= tolerance:
        return "reproduced", reason + "."
    return ("partly" if finite(before) and during < before else "not reproduced"), reason + "."


CLAIMS = {"table1": claim_table1, "intersonic": claim_intersonic, "backward": claim_backward,
          "nu0_f2": claim_nu0_f2, "opening": claim_opening, "pulses": claim_pulses,
          "shear_rate": claim_shear_rate, "density": claim_density, "mesh": claim_mesh,
          "timestep": claim_timestep, "long": claim_long, "dissipation": claim_dissipation}


def verdicts(tables: Tables, reference: dict, tolerance: float) -> list[Verdict]:
    out = []
    steps = reference["tolerance_steps"]
    for key, spec in reference["claims"].items():
        if key not in CLAIMS:
            raise InputError(f"claims: no verdict rule for claim {key!r} (paper/make_claims.py CLAIMS)")
        try:
            verdict, reason = CLAIMS[key](tables, spec, tolerance, steps)
        except Missing as missing:
            verdict, reason = "not testable here", f"{missing}."
        out.append(Verdict(key, spec["statement"], verdict, reason))
    return out
