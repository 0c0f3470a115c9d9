#include "model/simulation.hpp"

#include <chrono>
#include <cmath>
#include <random>

#include "contact/delassus.hpp"
#include "contact/gauss_seidel.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

double opening_threshold(const RunConfig& config) {
  return 1e-2 * std::fabs(config.loading.Uy_over_H) * config.geometry.H;
}

namespace {

/// Appends one row of interface output at time t.
void record_interface(RunRecord& rec, double t, const LayerModel& m, const Eigen::VectorXd& u,
                      const Eigen::VectorXd& u_contact_prev, const Eigen::VectorXd& u_contact_start,
                      const Eigen::VectorXd& r, const std::vector<ContactState>& state, double dt) {
  auto& s = rec.interface;
  s.t.push_back(t);
  const double h = m.d.h;
  for (int k = 0; k < m.mesh.n_contact(); ++k) {
    s.slip_velocity.data.push_back((u(2 * k) - u_contact_prev(2 * k)) / dt);
    s.slip.data.push_back(u(2 * k) - u_contact_start(2 * k));
    s.opening.data.push_back(u(2 * k + 1));
    s.normal_traction.data.push_back(r(2 * k + 1) / h);
    s.tangential_traction.data.push_back(-r(2 * k) / h);
    s.state.data.push_back(static_cast<std::int8_t>(state[k]));
  }
}

void record_snapshot(RunRecord& rec, double t, const LayerModel& m, const Eigen::VectorXd& u,
                     const Eigen::VectorXd& v) {
  Snapshot snap{t, {}, {}};
  const int n_x = m.mesh.n_x;
  for (int j = 0; j <= m.mesh.n_y; ++j)
    for (int i = 0; i <= n_x; ++i) {  // i = n_x repeats i = 0 so that the file mesh is not periodic
      const int node = m.mesh.node(i, j);
      for (int c = 0; c < 2; ++c) {
        snap.displacement.push_back(u(2 * node + c));
        snap.velocity.push_back(v(2 * node + c));
      }
    }
  rec.snapshots.push_back(std::move(snap));
}

SnapshotMesh snapshot_mesh(const LayerMesh& mesh) {
  SnapshotMesh out;
  const int n_x = mesh.n_x;
  for (int j = 0; j <= mesh.n_y; ++j)
    for (int i = 0; i <= n_x; ++i) {
      out.coordinates.push_back(i * mesh.h);
      out.coordinates.push_back(j * mesh.h);
    }
  for (int j = 0; j < mesh.n_y; ++j)
    for (int i = 0; i < n_x; ++i) {
      const std::int64_t n0 = j * (n_x + 1) + i;
      for (std::int64_t n : {n0, n0 + 1, n0 + n_x + 2, n0 + n_x + 1}) out.connectivity.push_back(n);
    }
  return out;
}

}  // namespace

namespace {
/// Adds the time since the last call to one field of the profile (no-op without a profile).
class Stopwatch {
 public:
  explicit Stopwatch(StepProfile* p) : profile_(p), last_(std::chrono::steady_clock::now()) {}
  void lap(double StepProfile::*field) {
    if (!profile_) return;
    const auto now = std::chrono::steady_clock::now();
    profile_->*field += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  StepProfile* profile_;
  std::chrono::steady_clock::time_point last_;
};
}  // namespace

RunRecord simulate(const LayerModel& m, const ProgressCallback& progress, const std::atomic<bool>* stop_requested,
                   StepProfile* profile) {
  Stopwatch watch(profile);
  const auto& c = m.config;
  const auto& d = m.d;
  const int n_f = m.n_free, n_t = m.n_top, n_c = m.n_contact_dofs, n_nodes_c = n_c / 2;

  RunRecord rec;
  const PreloadState pre = solve_preload(m);
  rec.u_x_preshear = pre.u_x_top;
  rec.static_contact_iterations = pre.contact_iterations;

  // 1. Effective matrix, factorized once, and its condensation on the contact DOFs.
  const HHTCoefficients hht(c.time.hht_alpha, d.dt);
  const double dt = hht.dt;
  const PartitionedSystem system{m.K, m.K_ff, m.M_ff, m.M_ff_rows, m.K_fd, n_f, n_t, n_c};
  HHTStepper stepper(system, hht, c.time.contact_weighting == ContactWeighting::alpha,
                     m.factorize(effective_matrix(hht, system)));
  const Eigen::MatrixXd W = stepper.contact_weight() * delassus_operator_periodic(stepper.K_eff(), n_nodes_c);

  // 2. Initial state: the preload, plus the seeded perturbation that breaks translation invariance.
  //    The normal DOFs of the contact nodes are not perturbed (no initial gap or penetration).
  Eigen::VectorXd u0 = pre.u, v0 = Eigen::VectorXd::Zero(n_f + n_t);
  for (int i = 0; i < m.mesh.n_x; ++i) v0(n_f + 2 * i) = d.V0;  // the top moves at V0 from t = 0
  {
    std::mt19937_64 generator(static_cast<std::uint64_t>(c.perturbation.seed));
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const double amplitude = c.perturbation.amplitude * std::fabs(pre.u_x_top);
    for (int dof = 0; dof < n_f; ++dof) {
      const double xi = uniform(generator);
      if (dof < n_c && dof % 2 == 1) continue;
      u0(dof) += amplitude * xi;
    }
  }
  HHTState s = stepper.initial_state(u0, v0, pre.r, *m.factorize(m.M_ff));
  Eigen::VectorXd &u = s.u, &v = s.v, &acc = s.acc, &r = s.r, &Ku = s.Ku, &Mv_f = s.Mv_f;
  const Eigen::VectorXd u_contact_start = u.head(n_c);
  const double u_y_top = c.loading.Uy_over_H * d.H;
  std::vector<ContactState> state = pre.state;
  std::vector<double> bounds;            // Prakash–Clifton friction bounds (empty: Coulomb)
  std::vector<double> regularized_normal;
  if (c.friction.regularization == Regularization::prakash_clifton) {
    regularized_normal.resize(n_nodes_c);
    for (int k = 0; k < n_nodes_c; ++k) regularized_normal[k] = r(2 * k + 1);
    bounds.resize(n_nodes_c);
  }

  // 3. Kinetic energy from the carried M_ff v (the top velocity is the constant V0).
  const Eigen::VectorXd M_fd_v_top = m.M_fd * v.tail(n_t);
  const double kinetic_top = v.tail(n_t).dot(m.M.bottomRightCorner(n_t, n_t) * v.tail(n_t));
  const auto kinetic = [&]() { return 0.5 * (v.head(n_f).dot(Mv_f + 2 * M_fd_v_top) + kinetic_top); };

  // 4. Diagnostics at t = 0.
  Eigen::VectorXd F_top = Ku.tail(n_t) + m.M_top_rows * acc;
  const double energy_start = kinetic() + 0.5 * u.dot(Ku);
  double work_external = 0, dissipation = 0, work_normal = 0;
  auto& g = rec.global;
  const auto record_global = [&](double t, int iterations, double residual) {
    double T = 0, N = 0;
    for (int k = 0; k < n_nodes_c; ++k) {
      T -= r(2 * k);
      N += r(2 * k + 1);
    }
    const double e_kin = kinetic(), e_el = 0.5 * u.dot(Ku);
    g.t.push_back(t);
    g.T.push_back(T);
    g.N.push_back(N);
    g.T_over_N.push_back(N > 0 ? T / N : std::nan(""));
    g.energy_kinetic.push_back(e_kin);
    g.energy_elastic.push_back(e_el);
    g.work_external.push_back(work_external);
    g.dissipation_friction.push_back(dissipation);
    g.work_contact_normal.push_back(work_normal);
    g.energy_balance_residual.push_back(e_kin + e_el + dissipation + work_normal - energy_start - work_external);
    g.contact_iterations.push_back(iterations);
    g.contact_residual.push_back(residual);
  };
  for (auto* series : {&rec.interface.slip_velocity, &rec.interface.slip, &rec.interface.opening,
                       &rec.interface.normal_traction, &rec.interface.tangential_traction})
    series->n_cols = n_nodes_c;
  rec.interface.state.n_cols = n_nodes_c;
  for (int k = 0; k < n_nodes_c; ++k) rec.interface.x.push_back(k * d.h);
  rec.snapshot_mesh = snapshot_mesh(m.mesh);
  std::vector<double> snapshot_times = c.output.snapshot_times;
  std::sort(snapshot_times.begin(), snapshot_times.end());
  size_t next_snapshot = 0;
  const auto maybe_snapshot = [&](double t) {
    while (next_snapshot < snapshot_times.size() && t >= snapshot_times[next_snapshot] - 0.5 * dt) {
      record_snapshot(rec, t, m, u, v);
      ++next_snapshot;
    }
  };
  record_global(0, pre.contact_iterations, 0);
  record_interface(rec, 0, m, u, u.head(n_c), u_contact_start, r, state, dt);
  maybe_snapshot(0);

  watch.lap(&StepProfile::setup);

  // 5. Time loop.
  const GaussSeidelSettings settings{c.contact.tolerance, c.contact.max_iterations, d.p0 * d.h};
  const double threshold_open = opening_threshold(c);
  double t_end = c.time.t_end;
  const int n_steps_max = static_cast<int>(std::ceil(t_end / dt - 1e-9));
  rec.end_reason = "t_end";
  rec.complete = true;
  auto wall_last = std::chrono::steady_clock::now();
  int steps_since_report = 0;
  Eigen::VectorXd q(n_c), y(n_c), r_new(n_c);
  for (int step = 1; step <= n_steps_max; ++step) {
    const double t = step * dt;
    // The run ends with the first step that reaches t_end (t_end may have been shortened by
    // stop_after_opening): the last time is in [t_end, t_end + dt).
    if ((step - 1) * dt >= t_end - 1e-9 * dt) break;
    if (stop_requested && stop_requested->load()) {
      rec.complete = false;
      rec.end_reason = "interrupted";
      break;
    }
    const Eigen::VectorXd u_d = m.top_displacement(pre.u_x_top + d.V0 * t, u_y_top);

    // Predictor and free solve.
    stepper.predict(s, u_d);
    watch.lap(&StepProfile::predictor);
    const Eigen::VectorXd& u_free = stepper.solve_free();
    watch.lap(&StepProfile::free_solve);

    // Contact: y = (du_x, u_y) at the contact nodes.
    q = u_free.head(n_c);
    for (int k = 0; k < n_nodes_c; ++k) q(2 * k) -= u(2 * k);
    if (!bounds.empty())
      for (int k = 0; k < n_nodes_c; ++k) bounds[k] = c.friction.f * regularized_normal[k];
    r_new = r;
    const auto report = solve_contact_gauss_seidel(W, q, c.friction.f, bounds, settings, r_new, y, state);
    if (!report.converged) {
      rec.complete = false;
      rec.end_reason = "contact_not_converged";
      break;
    }

    watch.lap(&StepProfile::contact);
    if (profile) profile->contact_sweeps += report.iterations;

    // Correction, Newmark update, diagnostics.
    const Eigen::VectorXd u_top_prev = u.tail(n_t);
    stepper.correct(r_new, s);
    watch.lap(&StepProfile::correction);
    const Eigen::VectorXd& u_prev = stepper.u_previous();
    const Eigen::VectorXd& r_prev = stepper.r_previous();
    const Eigen::VectorXd du_contact = u.head(n_c) - u_prev.head(n_c);
    // Work of the contact forces over the step, booked with the trapezoid: the discrete energy identity
    // of the trapezoidal rule (exact at hht_alpha = 0, either weighting). For hht_alpha > 0 no exact
    // identity exists; with "end" weighting the booked residual can then be slightly positive (2e-6 of
    // the energy scale measured at H/8), with "alpha" weighting it stays negative (HHT dissipation).
    for (int k = 0; k < n_nodes_c; ++k) {
      dissipation -= 0.5 * (r_prev(2 * k) + r(2 * k)) * du_contact(2 * k);
      work_normal -= 0.5 * (r_prev(2 * k + 1) + r(2 * k + 1)) * du_contact(2 * k + 1);
    }
    if (!bounds.empty())
      for (int k = 0; k < n_nodes_c; ++k) {
        const double theta = (std::fabs(du_contact(2 * k)) + c.friction.pc_velocity * dt) / c.friction.pc_length;
        regularized_normal[k] = (regularized_normal[k] + theta * r(2 * k + 1)) / (1 + theta);
      }
    const Eigen::VectorXd u_contact_prev = u_prev.head(n_c);
    const Eigen::VectorXd F_top_next = Ku.tail(n_t) + m.M_top_rows * acc;
    work_external += 0.5 * (F_top + F_top_next).dot(u_d - u_top_prev);
    F_top = F_top_next;
    record_global(t, report.iterations, report.residual);
    rec.n_steps_done = step;
    if (step % c.output.interface_stride == 0)
      record_interface(rec, t, m, u, u_contact_prev, u_contact_start, r, state, dt);
    maybe_snapshot(t);

    if (rec.t_first_opening < 0) {
      for (int k = 0; k < n_nodes_c; ++k)
        if (u(2 * k + 1) > threshold_open) {
          rec.t_first_opening = t;
          if (c.time.stop_after_opening && t + *c.time.stop_after_opening < t_end) {
            t_end = t + *c.time.stop_after_opening;
            rec.end_reason = "stop_after_opening";
          }
          break;
        }
    }

    watch.lap(&StepProfile::diagnostics);
    if (profile) profile->steps = step;
    ++steps_since_report;
    if (progress) {
      const auto now = std::chrono::steady_clock::now();
      const double elapsed = std::chrono::duration<double>(now - wall_last).count();
      if (elapsed >= 1.0) {
        int n_slip = 0;
        for (auto s : state) n_slip += s == ContactState::slip;
        progress(t, t_end, steps_since_report / elapsed, g.T_over_N.back(), n_slip);
        wall_last = now;
        steps_since_report = 0;
      }
    }
  }
  return rec;
}

}  // namespace slidewave
