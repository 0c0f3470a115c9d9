"""The periodic layer of bench/getfem_peer.py as a GetFEM 5.4 model (see that file's docstring for
what both codes solve). Kept apart from the comparison driver so that each file holds one concept."""
import time

import getfem as gf
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

OPEN, STICK, SLIP = 0, 1, 2  # slidewave's /interface/state codes
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
