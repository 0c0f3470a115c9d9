#include "model/simulation.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <random>
#include <stdexcept>

#include "contact/delassus.hpp"
#include "contact/gauss_seidel.hpp"
#include "time/hht.hpp"

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
                   StepProfile* profile, RunObserver* observer) {
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
  const double a = hht.alpha, dt = hht.dt;
  const bool alpha_weighted = c.time.contact_weighting == ContactWeighting::alpha;
  const double w = alpha_weighted ? 1 - a : 1.0;        // weight of r(n+1)
  const double w_previous = alpha_weighted ? a : 0.0;   // weight of r(n)
  const Eigen::SparseMatrix<double> K_eff_matrix = hht.mass_factor() * m.M_ff + (1 - a) * m.K_ff;
  const auto K_eff = m.factorize(K_eff_matrix);
  const Eigen::MatrixXd W = w * delassus_operator_periodic(*K_eff, n_nodes_c);

  // 2. Initial state: the preload, plus the seeded perturbation that breaks translation invariance.
  //    The normal DOFs of the contact nodes are not perturbed (no initial gap or penetration).
  Eigen::VectorXd u = pre.u, v = Eigen::VectorXd::Zero(n_f + n_t), acc = Eigen::VectorXd::Zero(n_f + n_t);
  for (int i = 0; i < m.mesh.n_x; ++i) v(n_f + 2 * i) = d.V0;  // the top moves at V0 from t = 0
  {
    std::mt19937_64 generator(static_cast<std::uint64_t>(c.perturbation.seed));
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const double amplitude = c.perturbation.amplitude * std::fabs(pre.u_x_top);
    for (int dof = 0; dof < n_f; ++dof) {
      const double xi = uniform(generator);
      if (dof < n_c && dof % 2 == 1) continue;
      u(dof) += amplitude * xi;
    }
  }
  Eigen::VectorXd r = pre.r;
  Eigen::VectorXd Ku = m.K * u;
  {  // consistent initial acceleration: M_ff a_f = C^T r - (K u)_f
    Eigen::VectorXd rhs = -Ku.head(n_f);
    rhs.head(n_c) += r;
    acc.head(n_f) = m.factorize(m.M_ff)->solve(rhs);
  }
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

  // 3. Mass products of the free rows, M_ff u, M_ff v, M_ff a, carried through the step by the Newmark
  //    relations and the equation of motion (M_ff a(n+1) follows from K u, K u(n) and the contact forces),
  //    so that K u is the only full sparse product of a step. The top velocity is the constant V0.
  Eigen::VectorXd Mu_f = m.M_ff_rows * u.head(n_f), Mv_f = m.M_ff_rows * v.head(n_f);
  Eigen::VectorXd Ma_f = -Ku.head(n_f);
  Ma_f.head(n_c) += r;
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

  // 5. Time loop.
  const GaussSeidelSettings settings{c.contact.tolerance, c.contact.max_iterations, d.p0 * d.h};
  const double threshold_open = opening_threshold(c);
  double t_end = c.time.t_end;
  const int n_steps_max = static_cast<int>(std::ceil(t_end / dt - 1e-9));
  rec.end_reason = "t_end";
  rec.complete = true;

  // The evolving state, for checkpoints (--resume continues from it bit for bit).
  std::vector<Eigen::VectorXd*> carried = {&u, &v, &acc, &r, &Ku, &Mu_f, &Mv_f, &Ma_f, &F_top};
  const char* carried_names[] = {"u", "v", "acc", "r", "Ku", "Mu_f", "Mv_f", "Ma_f", "F_top"};
  const RunObserver::Capture capture = [&]() {
    LoopState out;
    for (size_t i = 0; i < carried.size(); ++i)
      out.reals[carried_names[i]].assign(carried[i]->data(), carried[i]->data() + carried[i]->size());
    out.reals["regularized_normal"] = regularized_normal;
    out.reals["scalars"] = {work_external, dissipation, work_normal, t_end, rec.t_first_opening};
    auto& contact_state = out.integers["contact_state"];
    for (auto s : state) contact_state.push_back(static_cast<std::int64_t>(s));
    out.integers["counters"] = {rec.n_steps_done, static_cast<std::int64_t>(next_snapshot),
                                rec.end_reason == "stop_after_opening" ? 1 : 0};
    return out;
  };
  int first_step = 1;
  if (const LoopState* start = observer ? observer->start_state() : nullptr) {
    for (size_t i = 0; i < carried.size(); ++i) {
      const auto& values = start->reals.at(carried_names[i]);
      if (static_cast<Eigen::Index>(values.size()) != carried[i]->size())
        throw std::runtime_error(std::string("checkpoint: ") + carried_names[i] + " has the wrong size");
      std::copy(values.begin(), values.end(), carried[i]->data());
    }
    regularized_normal = start->reals.at("regularized_normal");
    const auto& scalars = start->reals.at("scalars");
    work_external = scalars.at(0), dissipation = scalars.at(1), work_normal = scalars.at(2), t_end = scalars.at(3);
    rec.t_first_opening = scalars.at(4);
    const auto& contact_state = start->integers.at("contact_state");
    std::transform(contact_state.begin(), contact_state.end(), state.begin(),
                   [](std::int64_t s) { return static_cast<ContactState>(s); });
    const auto& counters = start->integers.at("counters");
    rec.n_steps_done = static_cast<int>(counters.at(0));
    next_snapshot = static_cast<size_t>(counters.at(1));
    if (counters.at(2)) rec.end_reason = "stop_after_opening";
    first_step = rec.n_steps_done + 1;
    // The rows up to that state are already in the output.
    rec.snapshots.clear();
    RunRecord empty_rows;
    rec.global = empty_rows.global;
    rec.interface.t.clear();
    for (auto* series : {&rec.interface.slip_velocity, &rec.interface.slip, &rec.interface.opening,
                         &rec.interface.normal_traction, &rec.interface.tangential_traction})
      series->data.clear();
    rec.interface.state.data.clear();
  } else if (observer) {
    observer->after_step(rec, capture);
  }

  watch.lap(&StepProfile::setup);
  auto wall_last = std::chrono::steady_clock::now();
  int steps_since_report = 0;
  Eigen::VectorXd u_tilde(n_f), Mu_tilde(n_f), rhs(n_f), u_free(n_f), q(n_c), y(n_c), r_new(n_c), Ku_next(n_f + n_t),
      Ma_next(n_f);
  for (int step = first_step; step <= n_steps_max; ++step) {
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
    u_tilde = u.head(n_f) + dt * v.head(n_f) + dt * dt * (0.5 - hht.beta) * acc.head(n_f);
    Mu_tilde = Mu_f + dt * Mv_f + dt * dt * (0.5 - hht.beta) * Ma_f;
    rhs.noalias() = hht.mass_factor() * Mu_tilde;
    rhs.noalias() -= (1 - a) * (m.K_fd * u_d);
    rhs.noalias() -= a * Ku.head(n_f);
    if (w_previous != 0) rhs.head(n_c) += w_previous * r;
    watch.lap(&StepProfile::predictor);
    K_eff->solve_into(rhs, u_free);
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
    rhs.head(n_c) += w * r_new;
    Eigen::VectorXd u_next(n_f + n_t);
    K_eff->solve_into(rhs, u_next.head(n_f));
    u_next.tail(n_t) = u_d;
    const Eigen::VectorXd acc_f_next = hht.mass_factor() * (u_next.head(n_f) - u_tilde);
    v.head(n_f) += dt * ((1 - hht.gamma) * acc.head(n_f) + hht.gamma * acc_f_next);
    acc.head(n_f) = acc_f_next;

    watch.lap(&StepProfile::correction);
    const Eigen::VectorXd du_contact = u_next.head(n_c) - u.head(n_c);
    // Work of the contact forces over the step, booked with the trapezoid: the discrete energy identity
    // of the trapezoidal rule (exact at hht_alpha = 0, either weighting). For hht_alpha > 0 no exact
    // identity exists; with "end" weighting the booked residual can then be slightly positive (2e-6 of
    // the energy scale measured at H/8), with "alpha" weighting it stays negative (HHT dissipation).
    for (int k = 0; k < n_nodes_c; ++k) {
      dissipation -= 0.5 * (r(2 * k) + r_new(2 * k)) * du_contact(2 * k);
      work_normal -= 0.5 * (r(2 * k + 1) + r_new(2 * k + 1)) * du_contact(2 * k + 1);
    }
    if (!bounds.empty())
      for (int k = 0; k < n_nodes_c; ++k) {
        const double theta = (std::fabs(du_contact(2 * k)) + c.friction.pc_velocity * dt) / c.friction.pc_length;
        regularized_normal[k] = (regularized_normal[k] + theta * r_new(2 * k + 1)) / (1 + theta);
      }
    const Eigen::VectorXd u_contact_prev = u.head(n_c);
    const Eigen::VectorXd u_top_prev = u.tail(n_t);
    Ku_next.noalias() = m.K * u_next;
    Ma_next = -(1 - a) * Ku_next.head(n_f) - a * Ku.head(n_f);
    Ma_next.head(n_c) += w * r_new + w_previous * r;
    Mv_f += dt * ((1 - hht.gamma) * Ma_f + hht.gamma * Ma_next);
    Mu_f = Mu_tilde + hht.beta * dt * dt * Ma_next;
    Ma_f = Ma_next;
    u = u_next;
    r = r_new;
    Ku.swap(Ku_next);
    const Eigen::VectorXd F_top_next = Ku.tail(n_t) + m.M_top_rows * acc;
    work_external += 0.5 * (F_top + F_top_next).dot(u_d - u_top_prev);
    F_top = F_top_next;
    record_global(t, report.iterations, report.residual);
    const double T_over_N_last = g.T_over_N.back();  // the observer may drain the record
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

    if (observer) observer->after_step(rec, capture);
    watch.lap(&StepProfile::diagnostics);
    if (profile) profile->steps = step;
    ++steps_since_report;
    if (progress) {
      const auto now = std::chrono::steady_clock::now();
      const double elapsed = std::chrono::duration<double>(now - wall_last).count();
      if (elapsed >= 1.0) {
        int n_slip = 0;
        for (auto s : state) n_slip += s == ContactState::slip;
        progress(t, t_end, steps_since_report / elapsed, T_over_N_last, n_slip);
        wall_last = now;
        steps_since_report = 0;
      }
    }
  }
  if (observer) observer->at_end(rec, capture);
  return rec;
}

}  // namespace slidewave
