"""Synthetic run files (docs/contracts.md section 2, format_version 2) with known answers.

A run has the paper's time line: stick until `t_onset`, sub-threshold uniform slip until the pulses
appear at `t_pulses`, slip pulses of prescribed celerity (each a plateau of slip velocity with
smooth edges, moving rigidly, optionally decaying, decelerating and opening), stick again after
`t_stop`. T/N follows piecewise-linear knots; the energy series carry a prescribed balance error.
Used by the analysis tests and reusable by pipeline tests (`write_run(path, Scenario(...))`).

The derived constants (c_s, c_l, p0, dt, the onset estimate, the opening threshold) are the
solver's formulas written out here on purpose: a synthetic file stands in for the solver, and
tests/analysis/theory/test_elastic.py checks analysis.theory.elastic against the real solver.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, replace

import numpy as np

from analysis.theory.elastic import n_steps

E, RHO, H = 1000.0, 1000.0, 25.0
UY_OVER_H = -1e-3
PRESHEAR = 0.95
#: The solver's opening threshold / |Uy| (the one of stop_after_opening).
OPENING_THRESHOLD_REL = 1e-2


def wave_speeds(nu: float) -> tuple[float, float]:
    return (math.sqrt(E / (2 * (1 + nu) * RHO)),
            math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * RHO)))


@dataclass
class Pulse:
    """A slip pulse. Front at x_front (m) at t_start (s), moving at celerity (m/s); slip velocity
    `amplitude` (m/s) over `length` (m) behind the front, edges of tanh width front_width and
    tail_width (m); amplitude decays as exp(-(t - t_start)/decay_time); |speed| falls by
    `deceleration` (m/s^2) down to 0; it disappears after t_end. The interface opens by `opening`
    (m) in the middle of the pulse from `opening_start` (s) on."""

    celerity: float
    x_front: float = 10.0
    t_start: float = 800.0
    t_end: float = math.inf
    amplitude: float = 3e-3
    length: float = 10.0
    front_width: float = 1.0
    tail_width: float = 2.0
    decay_time: float = math.inf
    deceleration: float = 0.0
    opening: float = 0.0
    opening_start: float = math.inf

    def front(self, t: np.ndarray) -> np.ndarray:
        """Unwrapped front position (m) at times t >= t_start."""
        tau = np.maximum(t - self.t_start, 0.0)
        c0, a = abs(self.celerity), self.deceleration
        if a > 0:
            t_stop = c0 / a
            tau_c = np.minimum(tau, t_stop)
            distance = c0 * tau_c - 0.5 * a * tau_c ** 2
        else:
            distance = c0 * tau
        return self.x_front + math.copysign(1.0, self.celerity) * distance


@dataclass
class Scenario:
    """Everything a synthetic run needs; defaults are the paper's nu = 0.2, f = 1.5 case."""

    nu: float = 0.2
    f: float = 1.5
    lambda_over_H: float = 2.0
    elements_per_H: int = 32
    V0_over_cs: float = 1e-5
    interface_stride: int = 4
    t_end: float = 1500.0
    t_onset: float = 740.0
    t_pulses: float = 800.0
    t_stop: float = 1150.0
    uniform_level: float = 2.0     # slip velocity / V0 between onset and the pulses
    pulses: list[Pulse] = field(default_factory=list)
    noise: float = 0.0             # std of Gaussian noise on the slip velocity (m/s)
    seed: int = 0
    ratio_knots: list[tuple[float, float]] | None = None  # (t, T/N); None = drop to -0.2
    ratio_chatter: float = 0.0     # T/N alternates by +-this from step to step (as the solver's does)
    energy_error: float = 1e-4     # max |residual| / max work
    format_version: object = 2
    creator: str = "slidewave"
    complete: int = 1
    end_reason: str = "t_end"
    drop_attributes: tuple[str, ...] = ()
    drop_datasets: tuple[str, ...] = ()
    config_text: str | None = None


def default_config(s: Scenario) -> dict:
    """The resolved config of docs/contracts.md section 1 for a scenario."""
    return {
        "material": {"E": E, "nu": s.nu, "rho": RHO},
        "geometry": {"H": H, "lambda_over_H": s.lambda_over_H},
        "mesh": {"elements_per_H": s.elements_per_H, "integration": "reduced", "mass": "consistent"},
        "loading": {"Uy_over_H": UY_OVER_H, "preshear_ratio": PRESHEAR, "V0_over_cs": s.V0_over_cs},
        "friction": {"f": s.f, "regularization": "none", "pc_length": 0.5, "pc_velocity": 0.0},
        "time": {"dt_times_cs": 0.5, "dt": None, "t_end": s.t_end, "hht_alpha": 0.1,
                 "contact_weighting": "alpha", "stop_after_opening": None},
        "contact": {"tolerance": 1e-10, "max_iterations": 2000},
        "perturbation": {"amplitude": 1e-5, "seed": 1},
        "numerics": {"linear_solver": "spectral"},
        "output": {"interface_stride": s.interface_stride, "snapshot_times": [], "progress": "never"},
    }


def _sigma(z: np.ndarray) -> np.ndarray:
    return 0.5 * (1.0 + np.tanh(z))


def pulse_fields(x: np.ndarray, t: np.ndarray, pulse: Pulse, period: float) -> tuple[np.ndarray, np.ndarray]:
    """(slip velocity, opening) of one pulse on the grid, shape (n_t, n_x)."""
    alive = ((t >= pulse.t_start) & (t <= pulse.t_end))[:, None]
    s = math.copysign(1.0, pulse.celerity)
    front = pulse.front(t)[:, None]
    xi = s * ((x[None, :] - front + 0.5 * period) % period - 0.5 * period)  # > 0 ahead of the front
    decay = np.exp(-np.maximum(t - pulse.t_start, 0.0) / pulse.decay_time)[:, None]
    profile = _sigma(-xi / pulse.front_width) * _sigma((xi + pulse.length) / pulse.tail_width)
    v = pulse.amplitude * decay * profile * alive  # slip is in +x whatever the direction
    opened = ((t >= pulse.opening_start) & alive[:, 0])[:, None]
    u_y = pulse.opening * np.exp(-((xi + 0.5 * pulse.length) / (0.2 * pulse.length)) ** 2) * opened
    return v, u_y


def build_fields(s: Scenario) -> dict:
    """All arrays and constants of a scenario (no file I/O)."""
    c_s, c_l = wave_speeds(s.nu)
    lam = s.lambda_over_H * H
    h = H / s.elements_per_H
    n_c = int(round(lam / h))
    dt = 0.5 / c_s
    V0 = s.V0_over_cs * c_s
    p0 = -UY_OVER_H * H * E * (1 - s.nu) / (H * (1 + s.nu) * (1 - 2 * s.nu))
    x = np.arange(n_c) * h
    tg = np.arange(n_steps(s.t_end, dt) + 1) * dt  # the solver's steps, t = 0 included
    t = tg[:: s.interface_stride]
    v = np.zeros((t.size, n_c))
    u_y = np.zeros((t.size, n_c))
    uniform = (t >= s.t_onset) & (t < s.t_pulses)
    v[uniform] = s.uniform_level * V0
    for pulse in s.pulses:
        pv, pu = pulse_fields(x, t, pulse, lam)
        v += pv
        u_y = np.maximum(u_y, pu)
    v[t >= s.t_stop] = 0.0
    u_y[t >= s.t_stop] = 0.0
    state = np.where(u_y > 1e-9, 0, np.where(v > 0, 2, 1)).astype(np.int8)
    u_y = u_y + 1e-13  # round-off where closed
    if s.noise > 0:
        v = v + np.random.default_rng(s.seed).normal(0.0, s.noise, v.shape)
    kt, kr = zip(*ratio_knots(s))
    ratio = np.interp(tg, kt, kr) + s.ratio_chatter * (-1.0) ** np.arange(tg.size)
    n_force = p0 * lam * np.ones_like(tg)
    work = 1e-4 * tg
    dissipation = 0.5 * work
    kinetic = 0.01 * work * (1 + np.sin(tg / 50.0)) / 2
    eps = s.energy_error * work.max() * np.sin(tg / 100.0) ** 2
    elastic0 = 0.5 * p0 ** 2 / E * H * lam
    elastic = elastic0 + work - dissipation - kinetic + eps
    residual = kinetic + elastic + dissipation - (kinetic[0] + elastic[0]) - work
    return dict(c_s=c_s, c_l=c_l, lam=lam, h=h, dt=dt, V0=V0, p0=p0, x=x, t=t, tg=tg, v=v,
                u_y=u_y, state=state, ratio=ratio, n_force=n_force, work=work,
                dissipation=dissipation, kinetic=kinetic, elastic=elastic, residual=residual)


def write_run_file(path, attrs: dict, setup: dict, interface: dict, series: dict, *, drop_attributes=(),
                   drop_datasets=(), compression=None, extend=None) -> None:
    """The one writer of synthetic run files (docs/contracts.md section 2) for every test folder:
    root `attrs`, `/setup` attributes, `/interface/<name>` and `/global/<name>` datasets given as
    {name: (data, unit, description)}; the attributes and datasets named in `drop_*` are left out
    (a broken file), None values are not written; `extend(file)` adds more (e.g. snapshots)."""
    import h5py

    with h5py.File(path, "w") as file:
        for key, value in attrs.items():
            if key not in drop_attributes and value is not None:
                file.attrs[key] = value
        group = file.create_group("setup")
        for key, value in setup.items():
            if key not in drop_attributes:
                group.attrs[key] = value
        for group, items in (("interface", interface), ("global", series)):
            for name, (data, unit, description) in items.items():
                if f"/{group}/{name}" in drop_datasets:
                    continue
                ds = file.create_dataset(f"/{group}/{name}", data=data, compression=compression)
                ds.attrs["unit"] = unit
                ds.attrs["description"] = description
        if extend is not None:
            extend(file)


def write_run(path, s: Scenario) -> dict:
    """Write the run file of a scenario (write_run_file); returns build_fields(s)."""
    d = build_fields(s)
    config = default_config(s)
    dt_out = s.interface_stride * d["dt"]
    G = E / (2 * (1 + s.nu))
    attrs = {
        "format_version": s.format_version, "creator": s.creator, "slidewave_version": "0.0.0-synthetic",
        "git_commit": "synthetic", "call": "synthetic_run.py", "created_utc": "2024-01-01T00:00:00Z",
        "config": s.config_text if s.config_text is not None else json.dumps(config),
        "complete": s.complete, "end_reason": s.end_reason, "n_steps_done": d["tg"].size - 1,
    }
    setup = {
        "config_input": json.dumps(config), "E": E, "nu": s.nu, "rho": RHO, "H": H,
        "lambda": d["lam"], "h": d["h"], "f": s.f, "c_s": d["c_s"], "c_l": d["c_l"], "p0": d["p0"],
        "V0": d["V0"], "dt": d["dt"], "t_end": s.t_end, "hht_alpha": 0.1,
        "t_onset_estimate": (1 - PRESHEAR) * s.f * d["p0"] * H / G / d["V0"],
        "u_x_preshear": PRESHEAR * s.f * d["p0"] * H / G,
        "opening_threshold": OPENING_THRESHOLD_REL * abs(UY_OVER_H) * H,
    }
    interface = {
        "x": (d["x"], "m"), "t": (d["t"], "s"), "slip_velocity": (d["v"], "m/s"),
        "slip": (np.cumsum(d["v"], axis=0) * dt_out, "m"), "opening": (d["u_y"], "m"),
        "normal_traction": (np.where(d["state"] == 0, 0.0, d["p0"]), "Pa"),
        "tangential_traction": (np.where(d["state"] == 2, s.f * d["p0"], PRESHEAR * s.f * d["p0"]), "Pa"),
        "state": (d["state"], "1"),
    }
    series = {
        "t": (d["tg"], "s"), "T": (d["ratio"] * d["n_force"], "N/m"), "N": (d["n_force"], "N/m"),
        "T_over_N": (d["ratio"], "1"), "energy_kinetic": (d["kinetic"], "J/m"),
        "energy_elastic": (d["elastic"], "J/m"), "work_external": (d["work"], "J/m"),
        "dissipation_friction": (d["dissipation"], "J/m"),
        "energy_balance_residual": (d["residual"], "J/m"),
        "contact_iterations": (np.full(d["tg"].size, 12), "1"),
        "contact_residual": (np.full(d["tg"].size, 3e-11), "1"),
    }
    write_run_file(path, attrs, setup,
                   {name: (data, unit, f"synthetic {name}") for name, (data, unit) in interface.items()},
                   {name: (data, unit, f"synthetic {name}") for name, (data, unit) in series.items()},
                   drop_attributes=s.drop_attributes, drop_datasets=s.drop_datasets, compression="gzip")
    return d


def ratio_knots(s: Scenario) -> list[tuple[float, float]]:
    """(t, T/N) knots of the scenario's piecewise-linear T/N (before the chatter): its own, or
    preshear -> f at the onset, held until 50 s after the pulses appear, down to -0.2 150 s later,
    back to 0.6 at t_end."""
    return s.ratio_knots or [(0.0, PRESHEAR * s.f), (s.t_onset, s.f), (s.t_pulses + 50, s.f),
                             (s.t_pulses + 200, -0.2), (s.t_end, 0.6)]


def paper_case(**changes) -> Scenario:
    """nu = 0.2, f = 1.5: one pulse at +0.882 m/s from t = 800 s that opens and inverts T/N."""
    base = Scenario(pulses=[Pulse(celerity=0.882, x_front=10.0, t_start=800.0, opening=0.01,
                                  opening_start=880.0)])
    return replace(base, **changes)


def store_with_filters(path, name: str, **filters) -> None:
    """Rewrite dataset `name` of a run file as one chunk with HDF5 filters (e.g. fletcher32=True)."""
    import h5py

    with h5py.File(path, "a") as file:
        data = file[name][()]
        del file[name]
        file.create_dataset(name, data=data, chunks=data.shape, **filters)


def corrupt_stored_chunk(path, name: str, at: int = 7) -> None:
    """Flip one byte of the first stored chunk of a dataset, behind HDF5's back (a damaged disk)."""
    import h5py

    with h5py.File(path, "r") as file:
        offset = file[name].id.get_chunk_info(0).byte_offset + at
    with open(path, "r+b") as stream:
        stream.seek(offset)
        byte = stream.read(1)
        stream.seek(offset)
        stream.write(bytes([byte[0] ^ 0xFF]))
