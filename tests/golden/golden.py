"""Golden regression of the solver (tests/golden/README.md): each config of configs/ is run, its run.h5
is reduced to one digest per dataset and attribute, and the digests are compared with digests.json.

    python3 tests/golden/golden.py check [NAME ...]   compare the current build with digests.json
    python3 tests/golden/golden.py bless [NAME ...]   rewrite digests.json from the current build

A digest is the sha256 of the dataset's values as numpy bytes in a fixed dtype and byte order (floats
'<f8', integers '<i8'), with its shape, its stored dtype and a small summary (max |value|, 8 sampled
values) that lets a mismatch say how far the values moved. `bless` also keeps each run.h5 under
build/golden/ (not committed): while those files match digests.json, a mismatch is reported with the
exact largest differences and the first row that differs.

The solver is build/slidewave or $SLIDEWAVE_BIN. Not a test module: test_golden.py imports it."""

import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
CONFIGS = HERE / "configs"
DIGESTS = HERE / "digests.json"
LOCAL_RUNS = REPO / "build" / "golden"
FORMAT = 1
N_SAMPLES = 8

# What run.h5 holds that is not a result. Every dataset is digested; these attributes are not.
EXCLUDED = {
    "/@call": "the command line: holds the paths of this run",
    "/@created_utc": "the creation time",
    "/@run_id": "a random id unique to each run (it names the run's temporary files)",
    "/@git_commit": "the commit of the build (with -dirty): equal results come from many commits",
    "/@slidewave_version": "a release label, not a result",
    "/setup@config_input": "the verbatim input file; its resolved form, /@config, is digested",
    "*@unit": "documentation text of each dataset (its wording is not a result)",
    "*@description": "documentation text of each dataset (its wording is not a result)",
}
# Digested after a normalization.
NORMALIZED = {
    "/@config": "numerics.threads removed: the resolved config records the thread count, which must not change "
                "the results (test_golden.py checks --threads 2)",
}


def solver():
    """The solver binary: $SLIDEWAVE_BIN or build/slidewave."""
    return Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))


def config_names():
    return sorted(p.stem for p in CONFIGS.glob("*.json"))


def solver_environment():
    """The environment of the runs: OpenMP threads that sleep while they wait (OMP_WAIT_POLICY=PASSIVE,
    unless set), since spinning threads make --threads 2 some 50x slower on a busy 2-core machine; the
    wait policy does not change results."""
    return {**os.environ, "OMP_WAIT_POLICY": os.environ.get("OMP_WAIT_POLICY", "PASSIVE")}


def run_config(name, folder, *extra, timeout=300):
    """Runs configs/NAME.json into folder/NAME.h5 and returns that path; raises with the solver's stderr."""
    output = Path(folder) / f"{name}.h5"
    result = subprocess.run([str(solver()), "run", str(CONFIGS / f"{name}.json"), "-o", str(output), *extra],
                            capture_output=True, text=True, timeout=timeout, env=solver_environment())
    if result.returncode != 0:
        raise RuntimeError(f"slidewave run {name} exited {result.returncode}: {result.stderr.strip()}")
    return output


# --- digests -------------------------------------------------------------------------------------

def _canonical(value):
    """numpy array in the fixed dtype and byte order of the digest."""
    array = np.asarray(value)
    if array.dtype.kind == "f":
        return array.astype("<f8")
    if array.dtype.kind in "iub":
        return array.astype("<i8")
    raise TypeError(f"no canonical dtype for {array.dtype}")


def _summary(array):
    flat = array.ravel().astype(float)
    if flat.size == 0:
        return {"max_abs": 0.0, "samples": []}
    index = np.unique(np.linspace(0, flat.size - 1, N_SAMPLES).round().astype(int))
    finite = flat[np.isfinite(flat)]
    return {"max_abs": float(np.abs(finite).max()) if finite.size else 0.0,
            "samples": [[int(i), float(flat[i])] for i in index]}


def _dataset_entry(dataset):
    array = _canonical(dataset[()])
    return {"sha256": hashlib.sha256(np.ascontiguousarray(array).tobytes()).hexdigest(),
            "shape": list(array.shape), "dtype": dataset.dtype.str, **_summary(array)}


def _attribute_value(key, value):
    if isinstance(value, bytes):
        value = value.decode()
    if key == "/@config":
        config = json.loads(value)
        config.get("numerics", {}).pop("threads", None)
        return config
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def _excluded(key):
    return key in EXCLUDED or any(key.endswith(pattern[1:]) for pattern in EXCLUDED if pattern.startswith("*"))


def digest(path):
    """Digests of one run.h5: "/group/dataset" -> {sha256, shape, dtype, max_abs, samples},
    "/group@attribute" -> {value}; without the EXCLUDED attributes."""
    entries = {}
    with h5py.File(path, "r") as f:
        def add_attributes(name, obj):
            for attribute, value in obj.attrs.items():
                key = f"/{name}@{attribute}" if name else f"/@{attribute}"
                if not _excluded(key):
                    entries[key] = {"value": _attribute_value(key, value)}

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                entries[f"/{name}"] = _dataset_entry(obj)
            add_attributes(name, obj)

        add_attributes("", f)
        f.visititems(visit)
    return dict(sorted(entries.items()))


# --- comparison ----------------------------------------------------------------------------------

def _sampled_difference(old, new):
    """Largest absolute and relative difference of the sampled values and max |value| (a lower bound)."""
    if old.get("shape") != new.get("shape"):
        return None
    pairs = [(a[1], b[1]) for a, b in zip(old["samples"], new["samples"])] + [(old["max_abs"], new["max_abs"])]
    absolute = max(abs(a - b) for a, b in pairs)
    relative = max(abs(a - b) / max(abs(a), abs(b), 1e-300) for a, b in pairs)
    return absolute, relative


def _exact_difference(reference_file, actual_file, key):
    """Exact largest differences of one dataset, and the first row that differs (with its time when the
    group has a `t` series of that length)."""
    with h5py.File(reference_file, "r") as fa, h5py.File(actual_file, "r") as fb:
        a, b = np.asarray(fa[key][()], dtype=float), np.asarray(fb[key][()], dtype=float)
        parent = fa[key].parent
        t = parent["t"][()] if "t" in parent and isinstance(parent["t"], h5py.Dataset) else None
    text = ""
    if a.shape != b.shape:
        n = min(len(a), len(b)) if a.ndim and b.ndim else 0
        if n == 0 or a.shape[1:] != b.shape[1:]:
            return f"shape {list(a.shape)} -> {list(b.shape)}"
        text = f"shape {list(a.shape)} -> {list(b.shape)}; on the first {n} rows: "
        a, b = a[:n], b[:n]
    difference = np.abs(a - b)
    largest = difference.max(initial=0.0)
    text += f"max |diff| {largest:.3e}, relative to max |value| {largest / max(np.abs(a).max(initial=0.0), 1e-300):.3e}"
    if a.ndim and a.size:
        rows = np.flatnonzero(difference.reshape(len(a), -1).any(axis=1))
        if rows.size:
            text += f", first differing row {rows[0]}"
            if t is not None and t.ndim == 1 and len(t) >= len(a):
                text += f" (t = {t[rows[0]]:.6g} s)"
    return text


def _value_difference(old, new):
    """old -> new of an attribute; for dictionaries (the resolved config) only the keys that differ."""
    if isinstance(old, dict) and isinstance(new, dict):
        def flat(d, prefix=""):
            out = {}
            for k, v in d.items():
                out.update(flat(v, f"{prefix}{k}.") if isinstance(v, dict) else {f"{prefix}{k}": v})
            return out
        a, b = flat(old), flat(new)
        return "; ".join(f"{k}: {json.dumps(a.get(k))} -> {json.dumps(b.get(k))}"
                         for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k))
    return f"{json.dumps(old)} -> {json.dumps(new)}"


def compare(expected, actual, reference_file=None, actual_file=None):
    """Lines that describe how `actual` differs from `expected` (digests of one run); empty if equal.
    With reference_file (a run.h5 whose digests are `expected`) differences are exact."""
    lines = []
    for key in sorted(set(expected) | set(actual)):
        old, new = expected.get(key), actual.get(key)
        if old == new:
            continue
        if old is None:
            lines.append(f"  {key}: new")
        elif new is None:
            lines.append(f"  {key}: gone")
        elif "value" in old or "value" in new:
            lines.append(f"  {key}: {_value_difference(old.get('value'), new.get('value'))}")
        elif old["sha256"] == new["sha256"] and old["shape"] == new["shape"]:
            lines.append(f"  {key}: stored dtype {old['dtype']} -> {new['dtype']} (same values)")
        elif reference_file is not None and actual_file is not None:
            lines.append(f"  {key}: {_exact_difference(reference_file, actual_file, key.lstrip('/'))}")
        else:
            sampled = _sampled_difference(old, new)
            if sampled is None:
                lines.append(f"  {key}: shape {old['shape']} -> {new['shape']}")
            else:
                lines.append(f"  {key}: values differ; sampled max |diff| {sampled[0]:.3e}, relative {sampled[1]:.3e} "
                             f"(a lower bound)")
    return lines


def dumps(digests):
    """digests.json text with one line per dataset or attribute, so that a re-bless diffs line by line."""
    head = {key: value for key, value in digests.items() if key != "runs"}
    lines = json.dumps(head, indent=1)[:-2].splitlines()
    lines[-1] += ","
    lines.append(' "runs": {')
    for i, (name, entries) in enumerate(digests["runs"].items()):
        lines.append(f'  {json.dumps(name)}: {{')
        rows = [f"   {json.dumps(key)}: {json.dumps(entry)}" for key, entry in entries.items()]
        lines.append(",\n".join(rows))
        lines.append("  }" + ("," if i + 1 < len(digests["runs"]) else ""))
    lines += [" }", "}"]
    return "\n".join(lines) + "\n"


def load():
    """digests.json: {"format", "blessed_with", "excluded", "normalized", "runs": {name: digests}}."""
    return json.loads(DIGESTS.read_text()) if DIGESTS.exists() else {"runs": {}}


def local_reference(name, expected):
    """build/golden/NAME.h5 if it is there and its digests are the committed ones."""
    path = LOCAL_RUNS / f"{name}.h5"
    if expected is not None and path.exists() and digest(path) == expected:
        return path
    return None


def report(name, expected, run_file):
    """Mismatch lines of one run against the committed digests (exact where build/golden/ allows)."""
    actual = digest(run_file)
    reference = local_reference(name, expected)
    lines = compare(expected or {}, actual, reference, run_file if reference else None)
    if lines and reference is None:
        lines.append(f"  (sampled differences: bless an earlier build to keep {LOCAL_RUNS}/{name}.h5 for exact ones)")
    return lines


# --- command line --------------------------------------------------------------------------------

def version():
    return subprocess.run([str(solver()), "--version"], capture_output=True, text=True, check=True).stdout.strip()


def check(names):
    runs = load()["runs"]
    failed = False
    with tempfile.TemporaryDirectory() as folder:
        for name in names:
            lines = report(name, runs.get(name), run_config(name, folder))
            print(f"{name}: {'differs' if lines else 'same'}")
            for line in lines:
                print(line)
            failed |= bool(lines)
    return 1 if failed else 0


def bless(names):
    old = load()
    runs = dict(old.get("runs", {}))
    LOCAL_RUNS.mkdir(parents=True, exist_ok=True)
    changed = []
    with tempfile.TemporaryDirectory() as folder:
        for name in names:
            run_file = run_config(name, folder)
            if name not in runs:
                runs[name] = digest(run_file)
                shutil.copy(run_file, LOCAL_RUNS / f"{name}.h5")
                print(f"{name}: new")
                changed.append(name)
                continue
            lines = report(name, runs[name], run_file)
            runs[name] = digest(run_file)
            shutil.copy(run_file, LOCAL_RUNS / f"{name}.h5")
            print(f"{name}: {'changed' if lines else 'unchanged'}")
            if lines:
                print("\n".join(lines))
                changed.append(name)
    for name in sorted(set(runs) - set(config_names())):
        print(f"{name}: dropped (no configs/{name}.json)")
        del runs[name]
        changed.append(name)
    new = {"format": FORMAT, "blessed_with": version(), "excluded": EXCLUDED, "normalized": NORMALIZED,
           "runs": dict(sorted(runs.items()))}
    if not changed and {**old, "blessed_with": None} == {**new, "blessed_with": None}:
        print(f"no result moved: {DIGESTS.relative_to(REPO)} left as it is")
        return 0
    DIGESTS.write_text(dumps(new))
    print(f"wrote {DIGESTS.relative_to(REPO)} ({new['blessed_with']})")
    if changed:
        print(f"results moved in: {', '.join(changed)}.\n"
              "REMINDER: the commit that re-blesses must say why the results moved (what changed in the solver "
              "and why that is intended).")
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=["check", "bless"])
    parser.add_argument("names", nargs="*", help="config names (default: every configs/*.json)")
    args = parser.parse_args(argv)
    names = args.names or config_names()
    unknown = sorted(set(names) - set(config_names()))
    if unknown:
        parser.error(f"no configs/NAME.json for: {', '.join(unknown)}")
    if not solver().is_file():
        parser.error(f"solver {solver()} not built (bash scripts/build.sh)")
    return bless(names) if args.command == "bless" else check(names)


if __name__ == "__main__":
    sys.exit(main())
