#!/usr/bin/python3
"""Side-by-side peer comparison: slidewave against GetFEM 5.4 (Debian package python3-getfem).

Both codes solve the same discrete problem: the periodic elastic layer of Yastrebov (2016) on the
same structured Q4 mesh (plane strain, full 2x2 stiffness integration, consistent mass), pressed on a
rigid flat and sheared from its top, Newmark average acceleration (beta = 1/4, gamma = 1/2, i.e.
slidewave with hht_alpha = 0), nodal Signorini-Coulomb contact on the bottom nodes with the friction
law acting on the slip increment over the step and the contact forces taken at t(n+1).

GetFEM side (all standard GetFEM objects, its Newton solver and its default linear solver, which is
MUMPS here; forcing 'superlu' segfaults in the first dynamic step with this Debian build):
  - gf.Mesh('cartesian'), FEM_QK(2,1), IM_GAUSS_PARALLELEPIPED(2,3) (2x2) for the stiffness and
    IM_GAUSS_PARALLELEPIPED(2,5) (3x3, exact) for the consistent mass;
  - periodicity in x by MeshFem.reduction_matrices: the DOFs at x = lambda are tied to x = 0;
  - add_isotropic_linearized_elasticity_brick (plane strain), add_Newmark_scheme +
    add_mass_brick('Dot2_u');
  - top displacement by add_constraint_with_multipliers (one multiplier per top DOF);
  - contact by add_basic_contact_brick with nodal BN / BT matrices on the bottom nodes (the
    rigid-obstacle brick refuses reduced fems), Alart-Curnier augmented Lagrangian (version 1),
    friction on the increment u - Previous_u (dynamic friction term, gamma = -1, wt = Previous_u);
  - stage 1 (compression) and stage 2 (preshear to T/N = preshear_ratio * f) are static solves of
    the same model with the mass brick disabled; stage 3 starts from that state.

slidewave side: `slidewave run` with the equivalent JSON config (hht_alpha 0, integration full,
perturbation amplitude 0 by default, interface_stride 1).

Reported per mesh size: wall (and CPU) time per step of each and their ratio (GetFEM: its time loop
only; slidewave: a long run minus a 1-step run), max |T/N difference| over the common window, the
fraction of (node, step) pairs in the same contact state (open / stick / slip), and how many leading
steps stay identical in state / close in T/N. Documented with measured tables in bench/GETFEM.md.
Run with Debian's /usr/bin/python3 (numpy, scipy, h5py, python3-getfem):

    /usr/bin/python3 bench/getfem_peer.py                     # n = 8 16 32, 300 steps, ~20-30 s
    /usr/bin/python3 bench/getfem_peer.py --perturbation 1e-5 # same seeded perturbed start in both
    /usr/bin/python3 bench/getfem_peer.py --n 64 --json out.json   # ~3 min (GetFEM ~0.6 s/step)
"""
import argparse
import json
import os
import platform
import resource
import shutil
import subprocess
import sys
import tempfile
import time

# One core per run, as slidewave: keep BLAS / OpenMP inside MUMPS single-threaded.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402

try:
    import getfem as gf  # noqa: E402,F401  (its absence is the error below)
except ImportError:  # pragma: no cover
    sys.exit("getfem not importable: apt-get install -y --no-install-recommends python3-getfem, "
             "and run with /usr/bin/python3")

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
from analysis.theory import elastic  # noqa: E402  (run with PYTHONPATH=., bench/GETFEM.md)
from getfem_layer import OPEN, SLIP, GetfemLayer  # noqa: E402  (bench/, beside this file)


# ----------------------------------------------------------------------------------------------
# Problem parameters (the paper's, as slidewave's defaults)
# ----------------------------------------------------------------------------------------------
class Problem:
    def __init__(self, n, args):
        self.E, self.nu, self.rho = 1000.0, args.nu, 1000.0
        self.H, self.lambda_over_H = 25.0, 2.0
        self.f = args.f
        self.n = n
        self.h = self.H / n
        self.lam = self.lambda_over_H * self.H
        self.n_x = int(round(self.lambda_over_H * n))
        self.G = elastic.shear_modulus(self.E, self.nu)
        self.lame = self.E * self.nu / ((1 + self.nu) * (1 - 2 * self.nu))
        self.c_s = elastic.shear_wave_speed(self.E, self.nu, self.rho)
        self.dt = elastic.time_step(self.c_s, dt_times_cs=0.5)
        self.uy_top = -0.001 * self.H
        self.p0 = elastic.preload_pressure(self.uy_top, self.E, self.nu, self.H)
        self.preshear_ratio = args.preshear
        # All-stick interface: simple shear, T/N = G (u_x / H) / p0 (exact for the Q4 mesh too).
        self.ux_pre = self.preshear_ratio * self.f * self.p0 * self.H / self.G
        self.V0 = args.v0 * self.c_s
        self.force_scale = self.p0 * self.h  # slidewave's contact tolerance scale
        self.sw_tolerance = args.sw_tolerance

    def slidewave_config(self, steps, amplitude, snapshot0):
        config = {
            "material": {"E": self.E, "nu": self.nu, "rho": self.rho},
            "geometry": {"H": self.H, "lambda_over_H": self.lambda_over_H},
            "mesh": {"elements_per_H": self.n, "integration": "full", "mass": "consistent"},
            "loading": {"Uy_over_H": -0.001, "preshear_ratio": self.preshear_ratio,
                        "V0_over_cs": self.V0 / self.c_s},
            "friction": {"f": self.f},
            "time": {"dt_times_cs": 0.5, "t_end": steps * self.dt, "hht_alpha": 0.0},
            "perturbation": {"amplitude": amplitude, "seed": 1},
            "output": {"interface_stride": 1, "progress": "never",
                       "snapshot_times": [0.0] if snapshot0 else []},
        }
        if self.sw_tolerance is not None:
            config["contact"] = {"tolerance": self.sw_tolerance, "max_iterations": 100000}
        return config


# ----------------------------------------------------------------------------------------------
# slidewave
# ----------------------------------------------------------------------------------------------
def run_slidewave(exe, config, workdir, name):
    cfg_path = os.path.join(workdir, name + ".json")
    out_path = os.path.join(workdir, name + ".h5")
    with open(cfg_path, "w") as fh:
        json.dump(config, fh)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run([exe, "run", cfg_path, "-o", out_path], capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"slidewave failed ({proc.returncode}): {proc.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out_path, wall, cpu


def time_slidewave(exe, prob, args, workdir):
    """Per-step wall/CPU time: (run of S steps) - (run of 1 step), best of `repeats` each."""
    S = args.sw_timing_steps
    long_cfg = prob.slidewave_config(S, args.perturbation, False)
    one_cfg = prob.slidewave_config(1, args.perturbation, False)
    walls = {S: [], 1: []}
    cpus = {S: [], 1: []}
    for _ in range(args.repeats):
        for steps, cfg in ((S, long_cfg), (1, one_cfg)):
            path, wall, cpu = run_slidewave(exe, cfg, workdir, f"sw_timing_n{prob.n}_{steps}")
            walls[steps].append(wall)
            cpus[steps].append(cpu)
            os.remove(path)
    per_wall = (min(walls[S]) - min(walls[1])) / (S - 1)
    per_cpu = (min(cpus[S]) - min(cpus[1])) / (S - 1)
    if per_wall <= 0 or per_cpu <= 0:
        raise RuntimeError(f"timing lost in noise ({S} steps are too few): raise --sw-timing-steps")
    return per_wall, per_cpu


def read_slidewave(path):
    with h5py.File(path, "r") as f:
        out = {
            "T_over_N": f["/global/T_over_N"][:],
            "state": f["/interface/state"][:].astype(int),
            "x": f["/interface/x"][:],
            "n_steps": int(f.attrs["n_steps_done"]),
            "u_x_preshear": float(f["/setup"].attrs["u_x_preshear"]),  # run.h5 format 2: constants in /setup
            "dt": float(f["/setup"].attrs["dt"]),
        }
        if "/snapshots/coordinates" in f:
            snaps = [k for k in f["/snapshots"].keys() if k.isdigit()]
            s0 = f["/snapshots"][sorted(snaps)[0]]
            out["snapshot0"] = {
                "coordinates": f["/snapshots/coordinates"][:],
                "displacement": s0["displacement"][:],
                "velocity": s0["velocity"][:],
            }
    return out


# ----------------------------------------------------------------------------------------------
# Comparison
# ----------------------------------------------------------------------------------------------
def first_index(states, code):
    hits = np.flatnonzero((states == code).any(axis=1))
    return int(hits[0]) if hits.size else None


def compare_one(n, args, exe, workdir):
    prob = Problem(n, args)
    sw_path, _, _ = run_slidewave(exe, prob.slidewave_config(args.steps, args.perturbation,
                                                             args.perturbation > 0), workdir, f"sw_n{n}")
    sw = read_slidewave(sw_path)
    if sw["n_steps"] != args.steps:
        raise RuntimeError(f"slidewave did {sw['n_steps']} steps, expected {args.steps}")
    assert abs(sw["u_x_preshear"] - prob.ux_pre) <= 1e-9 * prob.ux_pre, (sw["u_x_preshear"], prob.ux_pre)
    assert abs(sw["dt"] - prob.dt) <= 1e-12 * prob.dt

    layer = GetfemLayer(prob, args)
    gfr = layer.run(args.steps, sw.get("snapshot0"))
    try:
        sw_wall, sw_cpu = time_slidewave(exe, prob, args, workdir)
    except RuntimeError as err:  # e.g. a tolerance at round-off level that a long run cannot hold
        print(f"# n={n}: slidewave timing run failed, no timing: {err}", file=sys.stderr)
        sw_wall = sw_cpu = float("nan")

    window = slice(1, args.steps + 1)  # the dynamic steps; t = 0 is the shared preload
    d_tn = np.abs(gfr["T_over_N"] - sw["T_over_N"])
    same = gfr["state"][window] == sw["state"][window]
    # Leading steps with every node in the same state (before round-off/tolerance differences,
    # amplified by the unstable sliding, make the two trajectories part).
    differs = np.flatnonzero(~same.all(axis=1))
    identical = int(differs[0]) if differs.size else args.steps
    # Leading steps with T/N within --close of each other.
    apart = np.flatnonzero(d_tn[window] > args.close)
    close = int(apart[0]) if apart.size else args.steps
    return {
        "n": n, "dofs": gfr["dofs"], "steps": args.steps,
        "gf_ms": 1e3 * gfr["wall_per_step"], "gf_cpu_ms": 1e3 * gfr["cpu_per_step"],
        "gf_newton": gfr["newton_per_step"], "gf_setup_s": gfr["setup_s"],
        "sw_ms": 1e3 * sw_wall, "sw_cpu_ms": 1e3 * sw_cpu,  # NaN: timing run failed
        "ratio_wall": gfr["wall_per_step"] / sw_wall, "ratio_cpu": gfr["cpu_per_step"] / sw_cpu,
        "tn0_diff": float(d_tn[0]),
        "max_dTN": float(d_tn[window].max()),
        "state_agree": float(same.mean()),
        "steps_all_agree": int(same.all(axis=1).sum()),
        "identical_steps": identical,
        "max_dTN_identical": float(d_tn[1:identical + 1].max()) if identical else None,
        "close_steps": close,
        "gf_first_slip": first_index(gfr["state"], SLIP), "sw_first_slip": first_index(sw["state"], SLIP),
        "gf_first_open": first_index(gfr["state"], OPEN), "sw_first_open": first_index(sw["state"], OPEN),
        "gf_state_counts": np.bincount(gfr["state"][window].ravel(), minlength=3).tolist(),
        "sw_state_counts": np.bincount(sw["state"][window].ravel(), minlength=3).tolist(),
        "TN_end": [float(gfr["T_over_N"][-1]), float(sw["T_over_N"][-1])],
    }


def getfem_version():
    try:
        return subprocess.run(["dpkg-query", "-W", "-f=${Version}", "python3-getfem"],
                              capture_output=True, text=True).stdout.strip() or "unknown"
    except OSError:
        return "unknown"


def print_table(rows, args, load_before, load_after):
    print(f"# slidewave vs GetFEM {getfem_version()} (python3-getfem), {platform.node()}, "
          f"{os.cpu_count()} cores, load average {load_before[0]:.2f} before / {load_after[0]:.2f} after")
    print(f"# nu={args.nu} f={args.f} preshear={args.preshear} V0/c_s={args.v0} perturbation={args.perturbation}"
          f" slidewave contact.tolerance={args.sw_tolerance or 'default (1e-10)'}, GetFEM Newton max_res={args.tol} p0 lambda,"
          f" dt=0.5/c_s, Newmark beta=1/4 gamma=1/2, full 2x2 Q4, {args.steps} steps;"
          f" slidewave timed over {args.sw_timing_steps} steps (best of {args.repeats}) minus 1 step")
    head = ("| H/h | DOFs | GetFEM ms/step | GetFEM Newton it/step | slidewave ms/step | ratio GF/SW (wall) | ratio GF/SW (CPU) "
            f"| max abs dT/N | same state | identical steps | max abs dT/N in those | steps abs dT/N <= {args.close:g} "
            "| first slip GF/SW "
            "| first open GF/SW |")
    print(head)
    print("|" + "---:|" * (head.count("|") - 1))
    for r in rows:
        fmt = lambda v: "-" if v is None else str(v)  # noqa: E731
        print(f"| {r['n']} | {r['dofs']} | {r['gf_ms']:.2f} | {r['gf_newton']:.2f} | {r['sw_ms']:.4f} "
              f"| {r['ratio_wall']:.0f} | {r['ratio_cpu']:.0f} | {r['max_dTN']:.2e} "
              f"| {100 * r['state_agree']:.2f} % | {r['identical_steps']} "
              f"| {'-' if r['max_dTN_identical'] is None else format(r['max_dTN_identical'], '.2e')} "
              f"| {r['close_steps']} | {fmt(r['gf_first_slip'])}/{fmt(r['sw_first_slip'])} "
              f"| {fmt(r['gf_first_open'])}/{fmt(r['sw_first_open'])} |")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32], help="elements per H (default 8 16 32)")
    ap.add_argument("--steps", type=int, default=300, help="dynamic steps compared (default 300)")
    ap.add_argument("--preshear", type=float, default=0.999, help="preshear_ratio (default 0.999: slip in the window)")
    ap.add_argument("--v0", type=float, default=1e-5, help="V0 / c_s (default 1e-5, the paper's)")
    ap.add_argument("--nu", type=float, default=0.2)
    ap.add_argument("--f", type=float, default=1.5)
    ap.add_argument("--perturbation", type=float, default=0.0,
                    help="slidewave perturbation amplitude (seed 1); > 0: GetFEM starts from slidewave's t = 0 "
                         "snapshot (same perturbed state). Default 0: seed-free uniform start")
    ap.add_argument("--close", type=float, default=1e-6,
                    help="T/N difference that counts as the trajectories parting (default 1e-6)")
    ap.add_argument("--r-aug", type=float, default=1.0, help="GetFEM augmentation parameter / E (default 1)")
    ap.add_argument("--tol", type=float, default=1e-10,
                    help="GetFEM Newton residual threshold relative to p0 lambda, and state thresholds "
                         "relative to p0 h (default 1e-10, slidewave's contact.tolerance)")
    ap.add_argument("--sw-tolerance", type=float, default=None,
                    help="slidewave contact.tolerance (default: slidewave's own, 1e-10)")
    ap.add_argument("--sw-timing-steps", type=int, default=3000,
                    help="length of the slidewave timing run (default 3000 steps)")
    ap.add_argument("--repeats", type=int, default=3, help="slidewave timing repeats, best taken (default 3)")
    ap.add_argument("--slidewave", default=os.path.join(REPO, "build", "slidewave"))
    ap.add_argument("--workdir", default=None, help="keep the slidewave runs here (default: a temporary dir)")
    ap.add_argument("--json", default=None, help="also write the results as JSON")
    args = ap.parse_args(argv)
    if args.tol <= 0 or args.steps < 1 or args.sw_timing_steps < 2:
        ap.error("need --tol > 0, --steps >= 1, --sw-timing-steps >= 2")
    if not os.access(args.slidewave, os.X_OK):
        ap.error(f"{args.slidewave} is not executable: build slidewave first (bash scripts/build.sh)")

    workdir = args.workdir or tempfile.mkdtemp(prefix="getfem_peer_")
    os.makedirs(workdir, exist_ok=True)
    load_before = os.getloadavg()
    rows = []
    try:
        for n in args.n:
            t0 = time.perf_counter()
            rows.append(compare_one(n, args, args.slidewave, workdir))
            print(f"# n={n} done in {time.perf_counter() - t0:.1f} s", file=sys.stderr, flush=True)
    finally:
        if args.workdir is None:
            shutil.rmtree(workdir, ignore_errors=True)
    load_after = os.getloadavg()
    print_table(rows, args, load_before, load_after)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"args": vars(args), "load_before": load_before, "load_after": load_after,
                       "getfem_version": getfem_version(), "rows": rows}, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
