"""Reading a run file (`run.h5`, format_version 2, docs/contracts.md section 2).

This is the only module of the package that imports h5py. `load_run` checks `format_version` before
anything else (format 1 is refused: rerun the solver), then that every root attribute, every
derived constant in the `/setup` attributes and every dataset the analysis needs is present, has
the promised shape and holds finite numbers; any problem is an `InputError` naming the file and the
problem, and so is a dataset whose HDF5 checksum (Fletcher32) does not match, a damaged HDF5
structure (h5py's KeyError, RuntimeError, OSError, ... on a broken object header or link) and a
dataset whose declared shape is not the run's or would not fit in memory: shapes are checked before
any data is read. Snapshots are not read (the analysis needs only the interface and the global series).
Limit: a few damaged object headers crash the HDF5 library itself (a segmentation fault), which no
reader in this process can catch.

The constants are read, never recomputed: c_s, c_l, p0, dt, the onset estimate and the opening
threshold are what the solver used (one definition, in the solver).

A run that ended on `contact_not_converged` may hold non-finite values (a blow-up): such a run is
read, and the names of the datasets concerned are in `RunData.non_finite`, so that `measure` can
call it non-physical. In a complete run a non-finite value is a malformed file.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from analysis.core.errors import InputError

__all__ = ["FORMAT_VERSION", "FORMAT_VERSIONS", "SUBSTRATE_FORMAT_VERSION", "GlobalSeries", "InputError", "InterfaceFields", "RunData", "load_run"]

#: The run-file format of a rigid-flat run.
FORMAT_VERSION = 2
#: The format of a run with a deformable substrate (docs/substrate.md): format 2, with relative interface
#: fields (layer minus substrate), /substrate_snapshots and the substrate's constants in /setup.
SUBSTRATE_FORMAT_VERSION = 3
#: Every format this reader knows.
FORMAT_VERSIONS = (FORMAT_VERSION, SUBSTRATE_FORMAT_VERSION)

#: Root attributes (provenance and outcome) besides format_version.
ROOT_ATTRIBUTES = ("creator", "slidewave_version", "git_commit", "call", "created_utc", "config",
                   "complete", "end_reason", "n_steps_done")
_NUMERIC_ROOT = ("complete", "n_steps_done")
#: Derived constants of the solver, attributes of `/setup` (SI units).
SETUP_CONSTANTS = ("E", "nu", "rho", "H", "lambda", "h", "f", "c_s", "c_l", "p0", "V0", "dt",
                   "t_end", "hht_alpha", "t_onset_estimate", "u_x_preshear", "opening_threshold")
#: `/setup` attributes of format 3 only: the substrate's constants (SI units; the return time 2 H_s / c_l,s).
SUBSTRATE_CONSTANTS = ("substrate_E", "substrate_nu", "substrate_rho", "substrate_H", "substrate_c_s",
                       "substrate_c_l", "substrate_return_time")
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
    """One run: root attributes (decoded to Python values), the solver's derived constants (the
    `/setup` attributes, floats), the verbatim input, the resolved config (parsed JSON), the
    interface fields, the global series, and the datasets holding non-finite values (only ever
    non-empty for an incomplete run)."""

    path: str
    attrs: dict[str, Any]
    setup: dict[str, float]
    config_input: str
    config: dict[str, Any]
    interface: InterfaceFields
    global_series: GlobalSeries
    non_finite: tuple[str, ...] = ()

    @property
    def has_substrate(self) -> bool:
        """A deformable substrate below the interface (format 3): interface fields are then relative."""
        return int(self.attrs["format_version"]) == SUBSTRATE_FORMAT_VERSION

    def attr(self, name: str) -> float:
        """A derived constant of `/setup` (e.g. "c_s") or a numeric root attribute, as float."""
        if name in self.setup:
            return self.setup[name]
        return float(self.attrs[name])

    @property
    def complete(self) -> bool:
        return bool(self.attrs["complete"])

    @property
    def end_reason(self) -> str:
        return str(self.attrs["end_reason"])


def _decode(value: Any) -> Any:
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray) and value.shape == ():
        return _decode(value[()])
    return value


def _fail(path: str, message: str) -> InputError:
    return InputError(f"{path}: {message}")


def _is_number(value: Any) -> bool:
    return not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(value)


def _available_bytes() -> int:
    """Memory this process may still fill (MemAvailable of /proc/meminfo, else the physical memory)."""
    try:
        with open("/proc/meminfo") as stream:
            for line in stream:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")


def _dataset(file: Any, path: str, name: str) -> Any:
    """The dataset node `name` (no data read)."""
    if name not in file:
        raise _fail(path, f"dataset '{name}' is missing (malformed run file)")
    node = file[name]
    if not hasattr(node, "shape"):
        raise _fail(path, f"'{name}' is a group, expected a dataset")
    return node


def _check_shapes(file: Any, path: str, n_c: int) -> None:
    """Declared shapes (metadata only) against the run's: x (n_c,), t (n_out,), the interface fields
    (n_out, n_c), the global series (n_steps,) with n_out <= n_steps, and all of them together within
    the memory available, so that a file declaring a huge dataset is refused before it is read."""
    shapes = {name: _dataset(file, path, name).shape
              for name in [f"/interface/{n}" for n in ("x", "t") + _INTERFACE_FIELDS]
              + [f"/global/{n}" for n in _GLOBAL_SERIES]}
    if shapes["/interface/x"] != (n_c,):
        raise _fail(path, f"/interface/x has shape {shapes['/interface/x']}, expected (n_c,) = ({n_c},) "
                          "(lambda / h)")
    n_out, n_steps = shapes["/interface/t"], shapes["/global/t"]
    if len(n_out) != 1 or len(n_steps) != 1 or n_out[0] > n_steps[0]:
        raise _fail(path, f"/interface/t has shape {n_out} and /global/t {n_steps}, expected (n_out,) and "
                          "(n_steps,) with n_out <= n_steps")
    for name in _INTERFACE_FIELDS:
        if shapes[f"/interface/{name}"] != (n_out[0], n_c):
            raise _fail(path, f"/interface/{name} has shape {shapes[f'/interface/{name}']}, expected "
                              f"(n_out, n_c) = ({n_out[0]}, {n_c})")
    bad = [name for name in _GLOBAL_SERIES if shapes[f"/global/{name}"] != n_steps]
    if bad:
        raise _fail(path, f"/global series of unequal or non-1-D shape: {', '.join(bad)} "
                          f"(/global/t has shape {n_steps})")
    needed = 8 * sum(math.prod(shape) for shape in shapes.values())  # read as float64
    available = _available_bytes()
    if needed > available:
        raise _fail(path, f"its datasets declare {needed / 1e9:.3g} GB ({n_steps[0]} steps, {n_out[0]} "
                          f"interface outputs x {n_c} nodes), more than the {available / 1e9:.3g} GB of "
                          "memory available (a damaged file, or a run too large for this machine)")


def _read_dataset(file: Any, path: str, name: str) -> np.ndarray:
    """The data of a dataset; a failing checksum (Fletcher32) or filter is an InputError."""
    node = _dataset(file, path, name)
    try:
        return np.asarray(node[()])
    except OSError as err:
        text = str(err)
        if any(word in text.lower() for word in ("checksum", "filter", "inflate")):
            raise _fail(path, f"dataset '{name}' is corrupt: its HDF5 checksum does not match "
                              f"(the file was damaged after it was written; rerun or restore it) "
                              f"[{text}]") from None
        raise _fail(path, f"dataset '{name}' cannot be read ({text})") from None


def _read_array(file: Any, path: str, name: str, finite_required: bool, allow_nan: bool = False
                ) -> tuple[np.ndarray, bool]:
    """(data, whether it holds values that are neither finite nor an allowed NaN)."""
    data = _read_dataset(file, path, name)
    if not np.issubdtype(data.dtype, np.number):
        raise _fail(path, f"dataset '{name}' is not numeric (dtype {data.dtype})")
    finite = np.isfinite(data) | (np.isnan(data) if allow_nan else False)
    bad = not bool(np.all(finite))
    if bad and finite_required:
        raise _fail(path, f"dataset '{name}' holds non-finite values")
    return data, bad


def _check_version(path: str, attrs: Any) -> None:
    if "format_version" not in attrs:
        raise _fail(path, "no 'format_version' root attribute: not a slidewave run file, or one "
                          f"older than format_version {FORMAT_VERSION} (docs/contracts.md)")
    version = _decode(attrs["format_version"])
    if isinstance(version, bool) or not isinstance(version, (int, np.integer)):
        raise _fail(path, f"format_version is {version!r} ({type(version).__name__}); expected "
                          f"the integer {FORMAT_VERSION}")
    if version == 1:
        raise _fail(path, "format_version 1 is an older run-file format (derived constants as "
                          "root attributes) that this reader no longer reads: rerun the solver "
                          "(slidewave run) to write format_version 2")
    if version not in FORMAT_VERSIONS:
        raise _fail(path, f"format_version {version} is not supported: this reader knows only "
                          f"format_version {' and '.join(str(v) for v in FORMAT_VERSIONS)}")


def _read_attributes(file: Any, path: str) -> tuple[dict[str, Any], dict[str, float], str, dict]:
    """(root attributes, /setup constants, verbatim input, resolved config), all checked."""
    missing = [name for name in ROOT_ATTRIBUTES if name not in file.attrs]
    if missing:
        raise _fail(path, f"root attribute(s) missing: {', '.join(missing)}")
    attrs = {name: _decode(value) for name, value in file.attrs.items()}
    if attrs["creator"] != "slidewave":
        raise _fail(path, f"creator is {attrs['creator']!r}, expected 'slidewave'")
    for name in _NUMERIC_ROOT:
        if not _is_number(attrs[name]):
            raise _fail(path, f"root attribute '{name}' = {attrs[name]!r} is not a finite number")
    if "setup" not in file or hasattr(file["setup"], "shape"):
        raise _fail(path, "group '/setup' is missing (malformed run file)")
    setup_attrs = {name: _decode(value) for name, value in file["setup"].attrs.items()}
    constants = SETUP_CONSTANTS + (
        SUBSTRATE_CONSTANTS if _decode(file.attrs["format_version"]) == SUBSTRATE_FORMAT_VERSION else ())
    missing = [name for name in constants + ("config_input",) if name not in setup_attrs]
    if missing:
        raise _fail(path, f"/setup attribute(s) missing: {', '.join(missing)}")
    for name in constants:
        if not _is_number(setup_attrs[name]):
            raise _fail(path, f"/setup attribute '{name}' = {setup_attrs[name]!r} is not a finite number")
    config_input = setup_attrs["config_input"]
    if not isinstance(config_input, str):
        raise _fail(path, "/setup attribute 'config_input' is not a string")
    try:
        config = json.loads(attrs["config"])
    except (TypeError, json.JSONDecodeError) as err:
        raise _fail(path, f"root attribute 'config' is not valid JSON ({err})") from None
    if not isinstance(config, dict):
        raise _fail(path, "root attribute 'config' is not a JSON object")
    setup = {name: float(setup_attrs[name]) for name in constants}
    return attrs, setup, config_input, config


def load_run(path: str | Path) -> RunData:
    """Read and check a run file.

    Parameters
    ----------
    path
        A `run.h5` written by `slidewave run` (format_version 2, or 3 with a substrate).

    Returns
    -------
    RunData
        Attributes, constants, config and arrays (float64, `state` int8), fully in memory.

    Raises
    ------
    InputError
        Missing or unreadable file, not HDF5, unknown or absent `format_version` (format 1: rerun
        the solver), a missing attribute or dataset, inconsistent shapes, non-finite data in a
        complete run, unparsable `config`, a dataset whose checksum does not match.
    """
    import h5py

    path = str(path)
    if not Path(path).is_file():
        raise _fail(path, "no such file")
    try:
        file = h5py.File(path, "r")
    except OSError as err:
        raise _fail(path, f"not a readable HDF5 file ({err})") from None
    try:
        with file:
            return _read_run(file, path)
    except (KeyError, RuntimeError, OSError, TypeError, ValueError) as err:
        # h5py's errors on a broken object header, link or attribute message.
        raise _fail(path, f"damaged HDF5 structure ({type(err).__name__}: {err}); rerun the run or "
                          "restore the file") from None


def _read_run(file: Any, path: str) -> RunData:
    """load_run's checks and reads on the open file."""
    # 1. The format version, before anything else.
    _check_version(path, file.attrs)
    # 2. Root attributes, /setup constants, config.
    attrs, setup, config_input, config = _read_attributes(file, path)
    finite_required = bool(attrs["complete"])
    _check_shapes(file, path, round(setup["lambda"] / setup["h"]))
    # 3. Interface fields.
    x = _read_array(file, path, "/interface/x", True)[0].astype(float)
    t = _read_array(file, path, "/interface/t", True)[0].astype(float)
    if x.size < 3:
        raise _fail(path, f"/interface/x has shape {x.shape}, expected (n_c,) with n_c >= 3")
    if t.size < 1:
        raise _fail(path, f"/interface/t has shape {t.shape}, expected (n_out,) with n_out >= 1")
    steps = np.diff(x)
    if np.any(steps <= 0) or np.max(np.abs(steps - steps.mean())) > 1e-6 * steps.mean():
        raise _fail(path, "/interface/x is not uniformly spaced and increasing")
    period = steps.mean() * x.size
    if abs(period - setup["lambda"]) > 1e-6 * period:
        raise _fail(path, f"/interface/x spans a period of {period:g} m, but lambda = "
                          f"{setup['lambda']:g} m (x = lambda must be the node x = 0)")
    if np.any(np.diff(t) <= 0):
        raise _fail(path, "/interface/t is not strictly increasing")
    fields, non_finite = {}, []
    for name in _INTERFACE_FIELDS:
        data, bad = _read_array(file, path, f"/interface/{name}", finite_required)
        fields[name] = data.astype(np.int8) if name == "state" else data.astype(float)
        if bad:
            non_finite.append(f"/interface/{name}")
    interface = InterfaceFields(x=x, t=t, **fields)
    # 4. Global series.
    # T/N is NaN (undefined) exactly where the whole interface is open (N = 0), nowhere else.
    series = {}
    for name in _GLOBAL_SERIES:
        data, bad = _read_array(file, path, f"/global/{name}", finite_required or name == "t",
                                allow_nan=name == "T_over_N")
        series[name] = data.astype(float)
        if bad:
            non_finite.append(f"/global/{name}")
    if series["t"].size < 1:
        raise _fail(path, "/global/t is empty")
    undefined = np.isnan(series["T_over_N"])
    if not non_finite and np.any(series["N"][undefined] != 0):
        raise _fail(path, "dataset '/global/T_over_N' is NaN where N != 0")
    return RunData(path=path, attrs=attrs, setup=setup, config_input=config_input, config=config,
                   interface=interface, global_series=GlobalSeries(**series),
                   non_finite=tuple(non_finite))


#: The optional term-by-term HHT dissipation of a run made with `output.energy_decomposition = hht`.
HHT_DISSIPATION = ("dissipation_hht", "dissipation_hht_gamma", "dissipation_hht_beta", "dissipation_hht_shift")


def load_hht_dissipation(path: str | Path) -> dict[str, np.ndarray]:
    """{name: series (J/m)} of HHT_DISSIPATION under /global of a run file that `load_run` accepts.

    Raises InputError naming the file when the run was made without the decomposition.
    """
    import h5py

    path = str(path)
    with h5py.File(path, "r") as file:
        if "global/dissipation_hht" not in file:
            raise _fail(path, "no /global/dissipation_hht: run it with output.energy_decomposition = hht")
        return {name: _read_array(file, path, f"/global/{name}", True)[0].astype(float) for name in HHT_DISSIPATION}
