"""Write one run's solver configuration (docs/contracts.md, section 1) from a point of the study.

    /usr/bin/python3 -m study.make_run_config --spec SPEC_JSON -o results/<sweep>/<point>/config.json

SPEC_JSON (built by the Snakefile from the validated study config) holds
`point` (study/sweeps.py POINT_KEYS), `model` (E, H, Uy_over_H, preshear_ratio), `run_length`
(duration_transits, stop_after_opening_transits, t_end), `snapshot_offsets_transits` (bulk snapshots,
in transit times after the onset estimate) and `solver` (extra solver keys, merged last; they may not
redefine a key set here).

A point with a contrast `E_substrate_over_E` gets the solver group `substrate` (docs/substrate.md):
E = E_substrate_over_E E, and the layer's nu, rho and H (a substrate of another nu, rho or thickness is
a sweep's full `solver: {substrate: {E, nu, rho, H}}` instead; both at once is an error). A point
without one (or with None) writes no `substrate` group: the rigid flat, the config text of before.

The interface is written every `output.interface_stride` steps by the rule of docs/output-sampling.md
(study/output_sampling.py): written only where it departs from the solver's default 4 (nu = 0.49 at
lambda = 2H), and not where the sweep's `solver.output` sets the stride itself.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from study.output_sampling import SOLVER_DEFAULT_STRIDE, interface_stride
from study.run_length import RunLength, run_length
from study.sweeps import CONTRAST


def _merge_new_keys(base: dict, extra: dict, path: str = "") -> None:
    """Adds the keys of `extra` to `base` (recursively); a key that `base` already sets is an error."""
    for key, value in extra.items():
        where = f"{path}{key}"
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            _merge_new_keys(base[key], value, where + ".")
        elif key in base:
            raise ValueError(f"solver override {where} redefines a value the study sets; "
                             "change the point, the model or the run_length instead")
        else:
            base[key] = value


def substrate_of(point: dict, model: dict, solver: dict) -> dict | None:
    """The solver's `substrate` group of a point: from its contrast, else the sweep's `solver.substrate`,
    else None (the rigid flat)."""
    contrast = point.get(CONTRAST)
    if contrast is None:
        return solver.get("substrate")
    if "substrate" in solver:
        raise ValueError(f"point {CONTRAST} = {contrast:g} and solver.substrate both set the substrate; "
                         "give one of them")
    return {"E": contrast * model["E"], "nu": point["nu"], "rho": point["rho"], "H": model["H"]}


def run_times(spec: dict) -> RunLength:
    """The times that bound one point's run (study/run_length.py): onset estimate, transit, t_end."""
    point, model, length = spec["point"], spec["model"], spec["run_length"]
    return run_length(E=model["E"], nu=point["nu"], rho=point["rho"], H=model["H"], f=point["f"],
                      Uy_over_H=model["Uy_over_H"], preshear_ratio=model["preshear_ratio"],
                      V0_over_cs=point["V0_over_cs"], duration_transits=length["duration_transits"],
                      stop_after_opening_transits=length.get("stop_after_opening_transits"),
                      t_end=length.get("t_end"), substrate=substrate_of(point, model, spec.get("solver", {})))


def study_interface_stride(point: dict, model: dict, substrate: dict | None) -> int:
    """The point's interface output stride (study/output_sampling.py, docs/output-sampling.md)."""
    return interface_stride(E=model["E"], nu=point["nu"], rho=point["rho"], f=point["f"], H=model["H"],
                            lambda_over_H=point["lambda_over_H"], dt_times_cs=point["dt_times_cs"],
                            substrate=substrate)


def run_config(spec: dict) -> dict:
    """The solver configuration of one point (a dict ready for json.dump)."""
    point, model = spec["point"], spec["model"]
    substrate = substrate_of(point, model, spec.get("solver", {}))
    times = run_times(spec)
    snapshots = sorted(times.t_onset_estimate + offset * times.transit_time
                       for offset in spec.get("snapshot_offsets_transits", []))
    if snapshots and (snapshots[0] < 0 or snapshots[-1] > times.t_end):
        raise ValueError(f"snapshot times {snapshots} fall outside [0, t_end = {times.t_end}]")
    config = {
        "material": {"E": model["E"], "nu": point["nu"], "rho": point["rho"]},
        "geometry": {"H": model["H"], "lambda_over_H": point["lambda_over_H"]},
        "mesh": {"elements_per_H": point["elements_per_H"], "integration": point["integration"]},
        "loading": {"Uy_over_H": model["Uy_over_H"], "preshear_ratio": model["preshear_ratio"],
                    "V0_over_cs": point["V0_over_cs"]},
        "friction": {"f": point["f"]},
        "time": {"t_end": times.t_end, "stop_after_opening": times.stop_after_opening,
                 "dt_times_cs": point["dt_times_cs"]},
        "perturbation": {"seed": point["seed"]},
    }
    output = {"snapshot_times": snapshots} if snapshots else {}
    stride = study_interface_stride(point, model, substrate)
    if stride != SOLVER_DEFAULT_STRIDE and "interface_stride" not in spec.get("solver", {}).get("output", {}):
        output["interface_stride"] = stride
    if output:
        config["output"] = output
    if point.get(CONTRAST) is not None:
        config["substrate"] = substrate
    _merge_new_keys(config, spec.get("solver", {}))
    return config


def config_json_text(config: dict) -> str:
    """config.json's text: what the solver reads and what names a run's folder (study/rules/common.smk)."""
    return json.dumps(config, indent=2) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--spec", required=True, help="the point's specification (JSON text)")
    parser.add_argument("-o", "--output", required=True, type=Path, help="config.json to write")
    args = parser.parse_args(argv)
    config = run_config(json.loads(args.spec))
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(config_json_text(config))
    print(f"wrote {args.output}: t_end = {config['time']['t_end']:.1f} s, "
          f"stop_after_opening = {config['time']['stop_after_opening']}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
