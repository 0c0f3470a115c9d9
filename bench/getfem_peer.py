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
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spla  # noqa: E402

try:
    import getfem as gf  # noqa: E402
except ImportError:  # pragma: no cover
    sys.exit("getfem not importable: apt-get install -y --no-install-recommends python3-getfem, "
             "and run with /usr/bin/python3")

OPEN, STICK, SLIP = 0, 1, 2  # slidewave's /interface/state codes
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


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
        self.G = self.E / (2 * (1 + self.nu))
        self.lame = self.E * self.nu / ((1 + self.nu) * (1 - 2 * self.nu))
        self.c_s = np.sqrt(self.G / self.rho)
        self.dt = 0.5 / self.c_s  # dt_times_cs = 0.5
        self.p0 = 0.001 * self.E * (1 - self.nu) / ((1 + self.nu) * (1 - 2 * self.nu))
        self.uy_top = -0.001 * self.H
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
            "u_x_preshear": float(f.attrs["u_x_preshear"]),
            "dt": float(f.attrs["dt"]),
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
# GetFEM
# ----------------------------------------------------------------------------------------------
class GetfemLayer:
    """The periodic layer as a GetFEM model (reduced, periodic displacement field 'u')."""

    def __init__(self, prob, args):
        self.p = p = prob
        self.args = args
        gf.util_trace_level(0)
        xs = np.linspace(0.0, p.lam, p.n_x + 1)
        ys = np.linspace(0.0, p.H, p.n + 1)
        self.mesh = gf.Mesh("cartesian", xs, ys)
        self.mf = gf.MeshFem(self.mesh, 2)
        self.mf.set_fem(gf.Fem("FEM_QK(2,1)"))
        self.mim_k = gf.MeshIm(self.mesh, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,3)"))  # 2x2 points
        self.mim_m = gf.MeshIm(self.mesh, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,5)"))  # 3x3: exact mass
        self._periodic_reduction()
        self._model()

    # Periodicity: basic DOFs at x = lambda are copies of those at x = 0.
    def _periodic_reduction(self):
        p = self.p
        X = self.mf.basic_dof_nodes()
        nb = X.shape[1]
        assert np.allclose(X[:, 0::2], X[:, 1::2]), "expected (u_x, u_y) interleaved per node"
        i_node = np.rint(X[0] / p.h).astype(int)
        j_node = np.rint(X[1] / p.h).astype(int)
        comp = np.arange(nb) % 2
        keep = np.flatnonzero(i_node < p.n_x)
        red = -np.ones(nb, dtype=int)
        red[keep] = np.arange(keep.size)
        index = {(i_node[k], j_node[k], comp[k]): red[k] for k in keep}
        cols = np.array([red[k] if red[k] >= 0 else index[(0, j_node[k], comp[k])] for k in range(nb)])
        nr = keep.size
        E = gf.Spmat("empty", nb, nr)
        R = gf.Spmat("empty", nr, nb)
        for k in range(nb):
            E[k, cols[k]] = 1.0
        for k in keep:
            R[red[k], k] = 1.0
        self.mf.reduction_matrices(R, E)
        self.E_ext = sp.csr_matrix((np.ones(nb), (np.arange(nb), cols)), shape=(nb, nr))
        self.nr = nr
        self.i_red, self.j_red, self.c_red = i_node[keep], j_node[keep], comp[keep]
        self.key_red = {(i, j, c): k for k, (i, j, c) in enumerate(zip(self.i_red, self.j_red, self.c_red))}
        self.top = np.flatnonzero(self.j_red == p.n)
        self.top_is_x = self.c_red[self.top] == 0
        self.cx = np.array([self.key_red[(i, 0, 0)] for i in range(p.n_x)])  # contact node i: u_x
        self.cy = np.array([self.key_red[(i, 0, 1)] for i in range(p.n_x)])  # contact node i: u_y

    def _model(self):
        p, a = self.p, self.args
        md = self.md = gf.Model("real")
        md.add_fem_variable("u", self.mf)
        md.add_initialized_data("lambda", [p.lame])
        md.add_initialized_data("mu", [p.G])
        md.add_isotropic_linearized_elasticity_brick(self.mim_k, "u", "lambda", "mu")  # plane strain
        md.add_Newmark_scheme("u", 0.25, 0.5)
        md.add_initialized_data("rho", [p.rho])
        self.mass_brick = md.add_mass_brick(self.mim_m, "Dot2_u", "rho")
        md.set_time_step(p.dt)
        # Imposed top displacement, B u = L.
        ntop = self.top.size
        B = gf.Spmat("empty", ntop, self.nr)
        for k, dof in enumerate(self.top):
            B[k, dof] = 1.0
        md.add_variable("mult_top", ntop)
        md.add_initialized_data("L_top", np.zeros(ntop))
        md.add_constraint_with_multipliers("u", "mult_top", B, "L_top")
        # Nodal contact with the flat y = 0: BN u <= 0 with BN = -e_y (gap = u_y >= 0), BT = e_x.
        nc = p.n_x
        BN = gf.Spmat("empty", nc, self.nr)
        BT = gf.Spmat("empty", nc, self.nr)
        for k in range(nc):
            BN[k, self.cy[k]] = -1.0
            BT[k, self.cx[k]] = 1.0
        md.add_variable("lambda_n", nc)
        md.add_variable("lambda_t", nc)
        md.add_initialized_data("r_aug", [a.r_aug * p.E])
        md.add_initialized_data("friction_coeff", [p.f])
        md.add_initialized_data("gap", [0.0])
        md.add_initialized_data("alpha_aug", [1.0])
        md.add_initialized_data("gamma_wt", [-1.0])  # friction on BT (u - Previous_u)
        md.add_basic_contact_brick("u", "lambda_n", "lambda_t", "r_aug", BN, BT, "friction_coeff",
                                   "gap", "alpha_aug", 1, "gamma_wt", "Previous_u")
        # Newton stops when the residual norm is below tol x the total normal force p0 lambda (a
        # per-node scale, p0 h, falls under the round-off of the residual norm at H/64).
        self.max_res = a.tol * p.p0 * p.lam

    def top_values(self, ux, uy):
        return np.where(self.top_is_x, ux, uy)

    def solve(self, max_iter=100):
        its, converged = self.md.solve("max_res", self.max_res, "max_iter", max_iter)
        if not converged:
            raise RuntimeError("GetFEM Newton did not converge")
        return its

    def reactions(self):
        """Slidewave's convention: R_t (force on u_x), R_n (upward force, >= 0)."""
        return self.md.variable("lambda_t").copy(), -self.md.variable("lambda_n")

    def T_over_N(self):
        rt, rn = self.reactions()
        return -rt.sum() / rn.sum()

    def state(self, du_x):
        """open: no normal reaction; slip: friction saturated and the node moved over the step
        (both tests, so that a node stuck just below the bound, whose increment is at the level of
        the Newton residual, is not called slipping); stick otherwise."""
        rt, rn = self.reactions()
        eps = self.args.tol * self.p.force_scale
        saturated = np.abs(rt) >= self.p.f * rn * (1 - 1e-9)
        moved = self.args.r_aug * self.p.E * np.abs(du_x) > eps
        s = np.full(rn.size, STICK)
        s[saturated & moved] = SLIP
        s[rn <= eps] = OPEN
        return s

    def static_preload(self):
        p, md = self.p, self.md
        md.disable_bricks([self.mass_brick])
        md.set_variable("Previous_u", np.zeros(self.nr))
        md.set_variable("L_top", self.top_values(0.0, p.uy_top))
        self.solve()
        u1 = md.variable("u").copy()
        md.set_variable("Previous_u", u1)  # stage-2 slip measured from the end of stage 1
        md.set_variable("L_top", self.top_values(p.ux_pre, p.uy_top))
        self.solve()
        md.enable_bricks([self.mass_brick])
        return md.variable("u").copy()

    def consistent_acceleration(self, u):
        """M_ff a_f = C^T r - (K u)_f with the current reactions r; top DOFs a = 0 (as slidewave)."""
        K = self._assemble("lambda*Div_u*Div_Test_u + 2*mu*Sym(Grad_u):Grad_Test_u", self.mim_k)
        M = self._assemble("rho*u.Test_u", self.mim_m)
        rt, rn = self.reactions()
        rhs = -(K @ u)
        rhs[self.cx] += rt
        rhs[self.cy] += rn
        free = np.setdiff1d(np.arange(self.nr), self.top)
        acc = np.zeros(self.nr)
        acc[free] = spla.spsolve(M[free][:, free].tocsc(), rhs[free])
        return acc

    def _assemble(self, weak_form, mim):
        """Reduced (periodic) matrix of a bilinear weak form: E^T A_basic E, with A_basic assembled
        on a separate, unreduced MeshFem of the same mesh (same basic DOF numbering)."""
        mf = gf.MeshFem(self.mesh, 2)
        mf.set_fem(gf.Fem("FEM_QK(2,1)"))
        assert np.array_equal(mf.basic_dof_nodes(), self.mf.basic_dof_nodes())
        m = gf.Model("real")
        m.add_fem_variable("u", mf)
        m.add_initialized_data("lambda", [self.p.lame])
        m.add_initialized_data("mu", [self.p.G])
        m.add_initialized_data("rho", [self.p.rho])
        A = _to_scipy(gf.asm_generic(mim, 2, weak_form, -1, m))
        return (self.E_ext.T @ A @ self.E_ext).tocsr()

    def run(self, steps, start=None):
        """Stage 3. start: None (own static state, at rest) or slidewave's t = 0 snapshot."""
        p, md = self.p, self.md
        t_setup = time.perf_counter()
        u0 = self.static_preload()
        tn0_static = self.T_over_N()
        v0 = np.zeros(self.nr)
        v0[self.top[self.top_is_x]] = p.V0
        if start is not None:
            u0, v0 = self._from_snapshot(start)
        acc0 = self.consistent_acceleration(u0)
        md.set_variable("u", u0)
        md.set_variable("Previous_u", u0)
        md.set_variable("Previous_Dot_u", v0)
        md.set_variable("Previous_Dot2_u", acc0)
        setup = time.perf_counter() - t_setup

        nc = p.n_x
        tn = np.empty(steps + 1)
        state = np.empty((steps + 1, nc), dtype=int)
        tn[0] = tn0_static
        state[0] = self.state(np.zeros(nc))
        iterations = np.empty(steps, dtype=int)
        wall0, cpu0 = time.perf_counter(), time.process_time()
        for step in range(1, steps + 1):
            t = step * p.dt
            md.set_time(t)
            md.set_variable("L_top", self.top_values(p.ux_pre + p.V0 * t, p.uy_top))
            iterations[step - 1] = self.solve()
            u = md.variable("u")
            du_x = u[self.cx] - md.variable("Previous_u")[self.cx]
            tn[step] = self.T_over_N()
            state[step] = self.state(du_x)
            md.shift_variables_for_time_integration()
        wall = time.perf_counter() - wall0
        cpu = time.process_time() - cpu0
        return {"T_over_N": tn, "state": state, "wall_per_step": wall / steps, "cpu_per_step": cpu / steps,
                "newton_per_step": float(iterations.mean()), "setup_s": setup, "dofs": self.nr}

    def _from_snapshot(self, snap):
        coords, disp, vel = snap["coordinates"], snap["displacement"], snap["velocity"]
        u = np.zeros(self.nr)
        v = np.zeros(self.nr)
        for node in range(coords.shape[0]):
            i = int(round(coords[node, 0] / self.p.h))
            j = int(round(coords[node, 1] / self.p.h))
            if i == self.p.n_x:
                continue
            for c in (0, 1):
                k = self.key_red[(i, j, c)]
                u[k] = disp[node, c]
                v[k] = vel[node, c]
        return u, v


def _to_scipy(A):
    """gf.Spmat or ndarray -> scipy CSR."""
    if isinstance(A, np.ndarray):
        return sp.csr_matrix(A)
    A.to_csc()
    jc, ir = A.csc_ind()
    return sp.csc_matrix((A.csc_val(), ir, jc), shape=A.size()).tocsr()


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
