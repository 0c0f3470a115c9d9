"""Reading a run file (`run.h5`, format_version 1, docs/contracts.md section 2).

This is the only module of the package that imports h5py. `load_run` checks `format_version` before
anything else, then that every attribute and dataset the analysis needs is present, has the promised
shape and holds finite numbers; any problem is a `RunFormatError` naming the file and the problem.
Snapshots are not read (the analysis needs only the interface and the global series).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from analysis.errors import RunFormatError

__all__ = ["FORMAT_VERSION", "GlobalSeries", "InterfaceFields", "RunData", "RunFormatError",
           "load_run"]

#: The one run-file format this reader knows.
FORMAT_VERSION = 1

#: Root attributes that docs/contracts.md promises (besides format_version).
REQUIRED_ATTRIBUTES = (
    "creator", "slidewave_version", "git_commit", "call", "created_utc", "config", "complete",
    "end_reason", "E", "nu", "rho", "H", "lambda", "h", "f", "c_s", "c_l", "p0", "V0", "dt",
    "t_end", "hht_alpha", "n_steps_done", "t_onset_estimate", "u_x_preshear",
)
_NUMERIC_ATTRIBUTES = ("E", "nu", "rho", "H", "lambda", "h", "f", "c_s", "c_l", "p0", "V0", "dt",
                       "t_end", "hht_alpha", "n_steps_done", "t_onset_estimate", "u_x_preshear",
                       "complete")
_INTERFACE_FIELDS = ("slip_velocity", "slip", "opening", "normal_traction", "tangential_traction",
                     "state")
_GLOBAL_SERIES = ("t", "T", "N", "T_over_N", "energy_kinetic", "energy_elastic", "work_external",
                  "dissipation_friction", "energy_balance_residual", "contact_iterations",
                  "contact_residual")


@dataclass(frozen=True)
class InterfaceFields:
    """Interface output: node positions, output times and (n_out, n_c) fields, SI units.

    x (m), t (s, stage-3 clock), slip_velocity (m/s), slip (m), opening (m, u_y >= 0),
    normal_traction (Pa, compression positive), tangential_traction (Pa, positive when it resists
    sliding in +x), state (int8: 0 open, 1 stick, 2 slip).
    """

    x: np.ndarray
    t: np.ndarray
    slip_velocity: np.ndarray
    slip: np.ndarray
    opening: np.ndarray
    normal_traction: np.ndarray
    tangential_traction: np.ndarray
    state: np.ndarray


@dataclass(frozen=True)
class GlobalSeries:
    """Per-step series (n_steps + 1 values from t = 0): t (s); T, N (N/m, per unit depth);
    T_over_N (-); energies, work, dissipation and balance residual (J/m); contact_iterations (-);
    contact_residual (-, relative)."""

    t: np.ndarray
    T: np.ndarray
    N: np.ndarray
    T_over_N: np.ndarray
    energy_kinetic: np.ndarray
    energy_elastic: np.ndarray
    work_external: np.ndarray
    dissipation_friction: np.ndarray
    energy_balance_residual: np.ndarray
    contact_iterations: np.ndarray
    contact_residual: np.ndarray


@dataclass(frozen=True)
class RunData:
    """One run: root attributes (decoded to Python values), the resolved config (parsed JSON),
    the interface fields and the global series."""

    path: str
    attrs: dict[str, Any]
    config: dict[str, Any]
    interface: InterfaceFields
    global_series: GlobalSeries

    def attr(self, name: str) -> float:
        """A numeric root attribute as float."""
        return float(self.attrs[name])


def _decode(value: Any) -> Any:
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray) and value.shape == ():
        return _decode(value[()])
    return value


def _fail(path: str, message: str) -> RunFormatError:
    return RunFormatError(f"{path}: {message}")


def _read_array(file: Any, path: str, name: str, allow_nan: bool = False) -> np.ndarray:
    if name not in file:
        raise _fail(path, f"dataset '{name}' is missing (malformed run file)")
    node = file[name]
    if not hasattr(node, "shape"):
        raise _fail(path, f"'{name}' is a group, expected a dataset")
    data = np.asarray(node[()])
    if not np.issubdtype(data.dtype, np.number):
        raise _fail(path, f"dataset '{name}' is not numeric (dtype {data.dtype})")
    finite = np.isfinite(data) | (np.isnan(data) if allow_nan else False)
    if not np.all(finite):
        raise _fail(path, f"dataset '{name}' holds non-finite values")
    return data


def _check_version(path: str, attrs: Any) -> None:
    if "format_version" not in attrs:
        raise _fail(path, "no 'format_version' root attribute: not a slidewave run file, or one "
                          f"older than format_version {FORMAT_VERSION} (docs/contracts.md)")
    version = _decode(attrs["format_version"])
    if isinstance(version, bool) or not isinstance(version, (int, np.integer)):
        raise _fail(path, f"format_version is {version!r} ({type(version).__name__}); expected "
                          f"the integer {FORMAT_VERSION}")
    if version != FORMAT_VERSION:
        raise _fail(path, f"format_version {version} is not supported: this reader knows only "
                          f"format_version {FORMAT_VERSION}")


def load_run(path: str | Path) -> RunData:
    """Read and check a run file.

    Parameters
    ----------
    path
        A `run.h5` written by `slidewave run` (format_version 1).

    Returns
    -------
    RunData
        Attributes, config and arrays (float64, `state` int8), fully in memory.

    Raises
    ------
    RunFormatError
        Missing or unreadable file, not HDF5, unknown or absent `format_version`, a missing
        attribute or dataset, inconsistent shapes, non-finite data, unparsable `config`.
    """
    import h5py

    path = str(path)
    if not Path(path).is_file():
        raise _fail(path, "no such file")
    try:
        file = h5py.File(path, "r")
    except OSError as err:
        raise _fail(path, f"not a readable HDF5 file ({err})") from None
    with file:
        # 1. The format version, before anything else.
        _check_version(path, file.attrs)
        # 2. Root attributes.
        missing = [name for name in REQUIRED_ATTRIBUTES if name not in file.attrs]
        if missing:
            raise _fail(path, f"root attribute(s) missing: {', '.join(missing)}")
        attrs = {name: _decode(value) for name, value in file.attrs.items()}
        if attrs["creator"] != "slidewave":
            raise _fail(path, f"creator is {attrs['creator']!r}, expected 'slidewave'")
        for name in _NUMERIC_ATTRIBUTES:
            value = attrs[name]
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise _fail(path, f"root attribute '{name}' = {value!r} is not a finite number")
        try:
            config = json.loads(attrs["config"])
        except (TypeError, json.JSONDecodeError) as err:
            raise _fail(path, f"root attribute 'config' is not valid JSON ({err})") from None
        if not isinstance(config, dict):
            raise _fail(path, "root attribute 'config' is not a JSON object")
        # 3. Interface fields.
        x = _read_array(file, path, "/interface/x").astype(float)
        t = _read_array(file, path, "/interface/t").astype(float)
        if x.ndim != 1 or x.size < 3:
            raise _fail(path, f"/interface/x has shape {x.shape}, expected (n_c,) with n_c >= 3")
        if t.ndim != 1 or t.size < 1:
            raise _fail(path, f"/interface/t has shape {t.shape}, expected (n_out,) with n_out >= 1")
        steps = np.diff(x)
        if np.any(steps <= 0) or np.max(np.abs(steps - steps.mean())) > 1e-6 * steps.mean():
            raise _fail(path, "/interface/x is not uniformly spaced and increasing")
        period = steps.mean() * x.size
        if abs(period - float(attrs["lambda"])) > 1e-6 * period:
            raise _fail(path, f"/interface/x spans a period of {period:g} m, but lambda = "
                              f"{attrs['lambda']:g} m (x = lambda must be the node x = 0)")
        if np.any(np.diff(t) <= 0):
            raise _fail(path, "/interface/t is not strictly increasing")
        fields = {}
        for name in _INTERFACE_FIELDS:
            data = _read_array(file, path, f"/interface/{name}")
            if data.shape != (t.size, x.size):
                raise _fail(path, f"/interface/{name} has shape {data.shape}, expected "
                                  f"(n_out, n_c) = ({t.size}, {x.size})")
            fields[name] = data.astype(np.int8) if name == "state" else data.astype(float)
        interface = InterfaceFields(x=x, t=t, **fields)
        # 4. Global series.
        # T/N is NaN (undefined) exactly where the whole interface is open (N = 0), nowhere else.
        series = {name: _read_array(file, path, f"/global/{name}", allow_nan=name == "T_over_N").astype(float)
                  for name in _GLOBAL_SERIES}
        undefined = np.isnan(series["T_over_N"])
        if series["N"].shape == undefined.shape and np.any(series["N"][undefined] != 0):
            raise _fail(path, "dataset '/global/T_over_N' is NaN where N != 0")
        n_steps = series["t"].size
        bad = [name for name, data in series.items() if data.shape != (n_steps,)]
        if bad or n_steps < 1:
            raise _fail(path, f"/global series of unequal or non-1-D shape: {', '.join(bad)} "
                              f"(/global/t has {n_steps} values)")
    return RunData(path=path, attrs=attrs, config=config, interface=interface,
                   global_series=GlobalSeries(**series))
