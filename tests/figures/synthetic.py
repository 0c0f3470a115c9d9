"""Small synthetic inputs that follow docs/contracts.md: a run.h5 with interface fields, global
series and snapshots; all_metrics.csv, table1.csv, flutter.txt, metrics.json, summary.json, and a
tiny contrast sweep (contrast_inputs.py).

The fields look like the paper's nu=0.2, f=1.5 case (a pulse at c_p = 0.85 m/s that opens the
interface and drops T/N below zero) so that the figures made from them can be judged by eye.
`PYTHONPATH=.:tests/support python3 tests/figures/synthetic.py DIR` writes them all to DIR.
"""
import csv
import json
import math
import sys
from pathlib import Path

import numpy as np

from analysis.metrics import pulses
from analysis.tables import aggregate
from analysis.tables.reference import ReferenceCell
from analysis.theory import elastic, flutter
from contrast_inputs import write_contrast
from synthetic_run import write_run_file

E, RHO, H = 1000.0, 1000.0, 25.0
PUBLISHED = {  # a few cells of the paper's Table 1, (nu, f): c_p in m/s
    (0.0, 1.5): 0.982, (0.0, 2.0): 1.213, (0.2, 1.5): 0.882, (0.2, 1.2): 0.875,
    (0.3, 1.5): 0.774, (0.45, 1.0): -2.523, (0.45, 1.5): 0.656, (0.49, 0.5): -5.250,
    (0.49, 2.0): 0.607, (0.4, 1.05): 0.825,
}
NUS = [0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.49]
FS = [0.5, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2, 1.3, 1.4, 1.5, 1.8, 2.0]


def speeds(nu):
    c_s = math.sqrt(E / (2 * (1 + nu) * RHO))
    c_l = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * RHO))
    return c_s, c_l


def _stamp(dataset, unit, description):
    dataset.attrs["unit"] = unit
    dataset.attrs["description"] = description


def write_run(path, nu=0.2, f=1.5, v0_over_cs=1e-5, elements_per_H=16, lambda_over_H=2.0,
              c_p=0.85, format_version=2, snapshots=True, periodic_connectivity=False,
              t_end=1200.0):
    """A run file (tests/support/synthetic_run.py: write_run_file) of a pulse like the paper's case."""
    c_s, c_l = speeds(nu)
    lam, h = lambda_over_H * H, H / elements_per_H
    dt = 0.5 / c_s
    p0 = 0.001 * E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    n_c = int(round(lam / h))
    x = np.arange(n_c) * h
    t = np.arange(0.0, t_end + 1e-9, 4 * dt)
    onset = 740.0

    # A pulse that wraps around the period, grows after onset and opens after t = 850 s.
    xp = (10.0 + c_p * (t - onset))[:, None]
    dist = (x[None, :] - xp + lam / 2) % lam - lam / 2
    active = ((t > onset) & (t < 1100.0))[:, None]
    slip_velocity = 0.02 * np.exp(-(dist / 3.0) ** 2) * active
    grow = np.clip((t - 850.0) / 100.0, 0.0, 1.0)[:, None] * (t < 1100.0)[:, None]
    opening = 0.01 * grow * np.exp(-((dist + 1.0) / 2.0) ** 2)
    state = np.where(opening > 1e-4, 0, np.where(slip_velocity > 1e-3, 2, 1)).astype(np.int8)

    tg = np.arange(0.0, t_end + 1e-9, dt)
    rise = 0.95 * f + 0.05 * f * np.clip(tg / onset, 0.0, 1.0)
    drop = np.where(tg > onset, (f + 0.3) * (1 - np.exp(-np.clip(tg - onset, 0, None) / 80.0)), 0)
    t_over_n = rise - drop + np.where(tg > 1000.0, 0.001 * (tg - 1000.0), 0.0)
    n_force = p0 * lam * np.ones_like(tg)

    config = {"material": {"E": E, "nu": nu, "rho": RHO},
              "geometry": {"H": H, "lambda_over_H": lambda_over_H},
              "mesh": {"elements_per_H": elements_per_H, "integration": "reduced"},
              "loading": {"V0_over_cs": v0_over_cs}, "friction": {"f": f}}
    attrs = dict(format_version=format_version, creator="slidewave",
                 slidewave_version="0.0.0-test", git_commit="synthetic", call="synthetic",
                 created_utc="2024-01-01T00:00:00Z", config=json.dumps(config), complete=1,
                 end_reason="t_end", n_steps_done=len(tg) - 1)
    # format_version 2: the derived constants and the verbatim input are /setup attributes.
    setup = dict(config_input=json.dumps(config), E=E, nu=nu, rho=RHO, H=H, h=h, f=f, c_s=c_s,
                 c_l=c_l, p0=p0, V0=v0_over_cs * c_s, dt=dt, t_end=t_end, hht_alpha=0.1,
                 t_onset_estimate=onset, u_x_preshear=0.09, opening_threshold=0.01 * 0.001 * H)
    setup["lambda"] = lam
    interface = {"x": (x, "m", "node positions"), "t": (t, "s", "output times"),
                 "slip_velocity": (slip_velocity, "m/s", "slip rate"),
                 "slip": (np.cumsum(slip_velocity, axis=0) * 4 * dt, "m", "slip"),
                 "opening": (opening, "m", "u_y"),
                 "normal_traction": (p0 * (1 - 5 * slip_velocity), "Pa", "pressure"),
                 "tangential_traction": (f * p0 * np.ones_like(opening), "Pa", "traction"),
                 "state": (state, "1", "0 open, 1 stick, 2 slip")}
    series = {"t": tg, "T": t_over_n * n_force, "N": n_force, "T_over_N": t_over_n,
              "energy_kinetic": 0 * tg, "energy_elastic": 0 * tg, "work_external": 0 * tg,
              "dissipation_friction": 0 * tg, "energy_balance_residual": 0 * tg,
              "contact_iterations": 0 * tg + 5, "contact_residual": 0 * tg + 1e-12}

    def add_snapshots(file):
        _write_snapshots(file, lam, h, elements_per_H, c_p, onset, periodic_connectivity)

    write_run_file(path, attrs, setup, interface, {name: (data, "-", name) for name, data in series.items()},
                   extend=add_snapshots if snapshots else None)


def _write_snapshots(file, lam, h, n_y, c_p, onset, periodic):
    n_x = int(round(lam / h))
    columns = n_x if periodic else n_x + 1  # periodic: the x = lambda column is x = 0
    i, j = np.meshgrid(np.arange(columns), np.arange(n_y + 1), indexing="ij")
    coordinates = np.column_stack([i.ravel() * h, j.ravel() * h])
    node = lambda a, b: (a % columns) * (n_y + 1) + b  # noqa: E731
    connectivity = np.array([[node(a, b), node(a + 1, b), node(a + 1, b + 1), node(a, b + 1)]
                             for a in range(n_x) for b in range(n_y)])
    _stamp(file.create_dataset("/snapshots/coordinates", data=coordinates), "m", "nodes")
    _stamp(file.create_dataset("/snapshots/connectivity", data=connectivity), "1", "quads")
    X, Y = coordinates[:, 0], coordinates[:, 1]
    for k, time in enumerate([700.0, 840.0, 890.0, 960.0, 1010.0, 1077.0]):
        xp = 10.0 + c_p * (time - onset)
        dist = (X - xp + lam / 2) % lam - lam / 2
        amplitude = 0.0 if time < onset else 1.0
        pulse = amplitude * np.exp(-(dist / 4.0) ** 2 - Y / 10.0)
        displacement = np.column_stack([0.09 * Y / H + 0.01 * pulse, 0.005 * pulse * (Y < h)])
        displacement[:, 1] += -0.025 * Y / H
        velocity = np.column_stack([0.02 * pulse, 0.008 * pulse * np.sin(dist / 3.0)])
        group = file.create_group(f"/snapshots/{k:04d}")
        group.attrs["t"] = time
        _stamp(group.create_dataset("displacement", data=displacement), "m", "u")
        _stamp(group.create_dataset("velocity", data=velocity), "m/s", "v")


def category_of(nu, f):
    c = PUBLISHED.get((nu, f))
    if c is None:
        return "no_opening" if f < 1.1 or nu > 0.4 else "intersonic_opening"
    if c < 0:
        return "supersonic_backward_opening"
    if c > speeds(nu)[1]:
        return "supersonic_forward_opening"
    return "intersonic_opening_inversion" if f >= 1.3 else "intersonic_opening"


def metrics_rows():
    base = dict(V0_over_cs=1e-5, lambda_over_H=2.0, elements_per_H=32, rho=1000.0,
                integration="reduced", Uy_over_H=-0.001, preshear_ratio=0.95, hht_alpha=0.1)

    def row(nu, f, **over):
        c_s, c_l = speeds(nu)
        r = dict(nu=nu, f=f, **base)
        r.update(over)
        published = PUBLISHED.get((nu, f), 1.3 * c_s)
        scale = 1.0 + 0.02 * math.sin(7 * nu + 3 * f) + 0.01 * math.log2(r["elements_per_H"] / 32)
        celerity = published * scale
        category = category_of(nu, f)
        opening = category != "no_opening"
        count = max(1, round(r["lambda_over_H"] * H / (2 * H * math.sqrt(
            max(celerity ** 2 / c_s ** 2 - 1, 0.25)))))
        r.update(onset_time=700.0 + 300 * nu, celerity=celerity,
                 regime="supersonic" if abs(celerity) > c_l else "intersonic",
                 opening=opening, max_opening=0.01 if opening else 1e-13,
                 min_T_over_N=-0.3 if "inversion" in category else 0.6, inversion=("inversion" in
                                                                                category),
                 category=category, pulse_count=count,
                 pulse_spacing=r["lambda_over_H"] * H / count,
                 energy_balance_error=1e-4 * (1 + nu), c_s=c_s, E=E, H=H,
                 dissipative_friction_opening=0.2 * f if opening else None,
                 dissipative_friction_before_opening=0.9 * f,
                 friction_energy_share_opening=0.5 if opening else None,
                 dt=r.setdefault("dt_times_cs", 0.5) / c_s, metrics_file=f"nu{nu}_f{f}/metrics.json",
                 below_sqrt2_cs=abs(celerity) < math.sqrt(2.0) * c_s, complete=True,
                 pulse_spacing_theory=elastic.pulse_spacing(celerity, c_s, H), end_reason="stop_after_opening",
                 localization_time=760.0 + 300 * nu, first_opening_time=(900.0 + 300 * nu) if opening else None,
                 first_drop_start_time=950.0 + 300 * nu, first_drop_bottom_time=990.0 + 300 * nu,
                 first_drop_bottom_T_over_N=-0.3 if "inversion" in category else 0.6,
                 later_drops_start_T_over_N_median=0.9 * f, n_drops=2, pulse_count_all=count + 1,
                 # the slowest shear rate stops during its second drop; the first one is complete
                 n_complete_drops=1 if r["V0_over_cs"] == 1e-6 else 2)
        if not opening:  # the default rule measures the pulse that opens: none here
            r.update(celerity=None, regime=None, below_sqrt2_cs=None, pulse_count=None, pulse_spacing=None,
                     pulse_spacing_theory=math.nan)
        r["pulse_count_theory"] = pulses.expected_pulse_count(r["lambda_over_H"] * H, r["pulse_spacing_theory"])
        # The metrics measure derives from the others (analysis.metrics.measure), as it writes them.
        c = r["celerity"]
        r.update(celerity_over_cs=None if c is None else c / c_s,
                 first_drop_start_after_onset=r["first_drop_start_time"] - r["onset_time"],
                 first_drop_duration=r["first_drop_bottom_time"] - r["first_drop_start_time"],
                 first_drop_complete=r["n_complete_drops"] >= 1, inside_flutter_wedge=flutter.inside_wedge(nu, f))
        return r

    return [row(nu, f, **{parameter: value} if parameter else {})
            for parameter, values in SWEEPS.items() for value in values for nu, f in
            (((nu, f) for nu in NUS for f in FS) if parameter is None else [(0.2, 1.5)])]


# The grid (parameter None), then one-parameter sweeps at nu = 0.2, f = 1.5: parameter -> values
# besides the grid's (the roles of paper/make_numbers.py).
SWEEPS = {None: [None], "lambda_over_H": (4.0, 6.0), "elements_per_H": (16, 64, 128), "rho": (0.1, 10.0),
          "V0_over_cs": (1e-6, 5e-6, 5e-5, 1e-4), "dt_times_cs": (0.25, 1.0)}
ROLES = {"period": "lambda_over_H", "mesh": "elements_per_H", "density": "rho", "shear_rate": "V0_over_cs",
         "timestep": "dt_times_cs"}


def write_sweeps(folder, rows):
    """grid_metrics.csv (one run per (nu, f)) and sweep_<role>.csv (the grid's nu = 0.2, f = 1.5 run
    and the runs varying the role's parameter), as `analysis aggregate` writes each sweep's table."""
    n_grid = len(NUS) * len(FS)
    write_csv(folder / "grid_metrics.csv", rows[:n_grid])
    reference = [r for r in rows[:n_grid] if (r["nu"], r["f"]) == (0.2, 1.5)]
    start = n_grid
    for parameter, values in list(SWEEPS.items())[1:]:
        role = next(name for name, p in ROLES.items() if p == parameter)
        write_csv(folder / f"sweep_{role}.csv", reference + rows[start:start + len(values)])
        start += len(values)


def write_csv(path, rows, drop=()):
    columns = [c for c in rows[0] if c not in drop]
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


def table1_rows():
    """Like `analysis aggregate`'s table1.csv: one row per published cell (here PUBLISHED)."""
    rows = []
    for (nu, f), published in sorted(PUBLISHED.items()):
        c_s, c_l = speeds(nu)
        regenerated = None if (nu, f) == (0.49, 2.0) else published * (1 + 0.03 * math.cos(5 * nu + f))
        regime = lambda c: "supersonic" if abs(c) > c_l else "intersonic"  # noqa: E731
        row = dict(nu=nu, f=f, celerity=regenerated, published=published, deviation_rel=None,
                   regime=None, published_regime=regime(published), sign_match=None,
                   regime_match=None, within_tol=None, category=category_of(nu, f), end_reason=None,
                   published_category=aggregate.published_category(ReferenceCell(nu, f, published)),
                   category_match=None, reproduced=None, celerity_quality="ok", celerity_window_sensitivity=0.02)
        if regenerated is not None:
            deviation = (regenerated - published) / abs(published)
            row.update(deviation_rel=deviation, regime=regime(regenerated),
                       sign_match=regenerated * published > 0,
                       regime_match=regime(regenerated) == regime(published),
                       within_tol=abs(deviation) <= 0.05,
                       category_match=aggregate.category_matches(row["category"], row["published_category"]))
            row["reproduced"] = row["within_tol"] and row["sign_match"] and row["regime_match"] and row["category_match"]
        else:
            row["category"] = None
        if (nu, f) == (0.3, 1.5):  # one regime mismatch, as a real table may have
            row.update(regime="subsonic", regime_match=False)
        rows.append(row)
    return rows


FLUTTER = """# nu f_lower f_upper
0.0 1.00 inf
0.1 1.00 inf
0.2 1.02 5.0
0.3 1.08 2.6
0.35 1.20 1.9
0.4 nan nan
0.45 nan nan
"""



#: The three runs of paper/make_energy_evidence.py: option -> (hht_alpha, contact weighting).
ENERGY_RUNS = {"alpha_zero": (0.0, "alpha"), "alpha": (0.1, "alpha"), "alpha_end": (0.1, "end")}


def write_energy_run(path, alpha, weighting, decomposition=True, t_end=1200.0):
    """A run as `output.energy_decomposition = hht` writes it: the energy series of a run that takes
    in work W(t) and dissipates by friction, its residual exactly -(HHT dissipation), the three terms."""
    import h5py

    write_run(path, snapshots=False, t_end=t_end)
    with h5py.File(path, "a") as file:
        config = json.loads(file.attrs["config"])
        config["time"] = {"hht_alpha": alpha, "contact_weighting": weighting, "t_end": t_end, "dt_times_cs": 0.5}
        file.attrs["config"] = json.dumps(config)
        tg = file["/global/t"][()]
        work = 1e-3 * tg
        dissipation = alpha * 0.25 * work  # 0 at alpha = 0
        series = {"work_external": work, "energy_elastic": 0.5 * work, "dissipation_friction": 0.25 * work,
                  "energy_kinetic": 0.25 * work - dissipation, "energy_balance_residual": -dissipation}
        if alpha == 0:
            series["energy_balance_residual"] = 1e-16 * np.sin(tg)  # round-off
        for name, data in series.items():
            file[f"/global/{name}"][...] = data
        if decomposition:
            terms = {"gamma": 8.0 * dissipation, "beta": 1e-4 * dissipation, "shift": -7.0001 * dissipation}
            _stamp(file.create_dataset("/global/dissipation_hht", data=dissipation), "J/m", "HHT")
            for term, data in terms.items():
                _stamp(file.create_dataset(f"/global/dissipation_hht_{term}", data=data), "J/m", term)


def write_all(folder):
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    write_run(folder / "run.h5")
    for v in (1e-6, 1e-4):
        write_run(folder / f"run_v{v:g}.h5", v0_over_cs=v, snapshots=False)
    write_csv(folder / "all_metrics.csv", metrics_rows())
    write_sweeps(folder, metrics_rows())
    write_csv(folder / "table1.csv", table1_rows())
    for name, (alpha, weighting) in ENERGY_RUNS.items():
        write_energy_run(folder / f"energy_{name}.h5", alpha, weighting)
    (folder / "flutter.txt").write_text(FLUTTER)
    write_contrast(folder)
    for name, start, complete in (("v1e-06", 1000.0, 1), ("", 950.0, 1), ("v0.0001", 900.0, 0)):
        (folder / f"metrics{'_' + name if name else ''}_drop.json").write_text(json.dumps(
            {"first_drop_start_time": start, "n_complete_drops": complete}))
    (folder / "metrics.json").write_text(json.dumps(
        {"celerity": 0.85, "celerity_window": [800.0, 1000.0], "regime": "intersonic"}))
    (folder / "summary.json").write_text(json.dumps(  # keys of `analysis aggregate`
        {"cells_total": 38, "cells_compared": 36, "cells_missing": 2, "within_tolerance": 21,
         "sign_matches": 35, "regime_matches": 34, "median_abs_deviation": 0.041,
         "max_abs_deviation": 0.19, "tolerance": 0.05, "missing_cells": ["nu=0.49 f=2"],
         "category_matches": 35, "reproduced": 19, "category_mismatches": ["nu=0.45 f=0.9"]}))
    return folder


if __name__ == "__main__":
    print(write_all(sys.argv[1] if len(sys.argv) > 1 else "synthetic"))
