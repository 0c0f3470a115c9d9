#include "model/recorder.hpp"

#include <algorithm>
#include <cmath>

#include "model/substrate.hpp"

namespace slidewave {

double opening_threshold(const RunConfig& config) {
  return 1e-2 * std::fabs(config.loading.Uy_over_H) * config.geometry.H;
}

namespace {

/// The unwrapped mesh of the snapshots: the column i = n_x repeats i = 0, so that the file mesh is not periodic.
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

Recorder::Recorder(const LayerModel& m, const EnergyLedger& ledger, const PreloadState& preload)
    : model_(m),
      ledger_(ledger),
      dt_(m.d.dt),
      opening_threshold_(opening_threshold(m.config)),
      snapshot_times_(m.config.output.snapshot_times) {
  std::sort(snapshot_times_.begin(), snapshot_times_.end());
  const int n_nodes_c = m.mesh.n_contact();
  auto& s = record_.interface;
  for (auto* series : {&s.slip_velocity, &s.slip, &s.opening, &s.normal_traction, &s.tangential_traction})
    series->n_cols = n_nodes_c;
  s.state.n_cols = n_nodes_c;
  for (int k = 0; k < n_nodes_c; ++k) s.x.push_back(k * m.d.h);
  record_.snapshot_mesh = snapshot_mesh(m.mesh);
  record_.u_x_preshear = preload.u_x_top;
  record_.static_contact_iterations = preload.contact_iterations;
  record_.opening_threshold = opening_threshold_;
}

void Recorder::attach_substrate(const EnergyLedger& substrate_ledger) {
  substrate_ledger_ = &substrate_ledger;
  record_.substrate_snapshot_mesh = snapshot_mesh(model_.substrate->mesh);
  // Physical coordinates: the mirrored body's y' = j h is y = -j h.
  for (std::size_t k = 1; k < record_.substrate_snapshot_mesh.coordinates.size(); k += 2)
    record_.substrate_snapshot_mesh.coordinates[k] = -record_.substrate_snapshot_mesh.coordinates[k];
}

RowSource Recorder::layer_source(const LoopState& loop) const {
  RowSource source{loop, loop.energy, ledger_.kinetic(loop.dynamics), ledger_.elastic(loop.dynamics)};
  if (substrate_ledger_) {
    source.substrate_sums = &loop.substrate_energy;
    source.e_kin_substrate = substrate_ledger_->kinetic(loop.substrate);
    source.e_el_substrate = substrate_ledger_->elastic(loop.substrate);
  }
  return source;
}

void Recorder::record_start(LoopState& loop, int contact_iterations) {
  const Eigen::VectorXd& u = loop.dynamics.u;
  loop.recording = RecorderState{u.head(model_.n_contact_dofs), 0, -1};
  if (substrate_ledger_)
    loop.recording.u_contact_start = relative_contact_displacement(u, loop.substrate.u, model_.n_contact_dofs);
  const RowSource source = layer_source(loop);
  record_global(0, source, contact_iterations, 0);
  record_interface(0, source, u, substrate_ledger_ ? &loop.substrate.u : nullptr);
  record_due_snapshots(0, source, loop.recording);
}

void Recorder::record_step(LoopState& loop, const Eigen::VectorXd& u_previous, const GaussSeidelReport& report,
                           const Eigen::VectorXd* u_previous_substrate) {
  const double t = loop.step * dt_;
  const RowSource source = layer_source(loop);
  record_global(t, source, report.iterations, report.residual);
  if (loop.step % model_.config.output.interface_stride == 0)
    record_interface(t, source, u_previous, u_previous_substrate);
  record_due_snapshots(t, source, loop.recording);
}

void Recorder::record_wavenumber_step(LoopState& view, double e_kin, double e_el,
                                      const Eigen::VectorXd& u_contact_previous, const GaussSeidelReport& report,
                                      const std::function<LoopState()>& full) {
  const double t = view.step * dt_;
  const RowSource source{view, view.energy, e_kin, e_el};
  record_global(t, source, report.iterations, report.residual);
  if (view.step % model_.config.output.interface_stride == 0) record_interface(t, source, u_contact_previous);
  const auto& next = view.recording.next_snapshot;
  if (next < snapshot_times_.size() && t >= snapshot_times_[next] - 0.5 * dt_) {
    LoopState state = full();
    state.recording = view.recording;
    const RowSource full_source{state, view.energy, e_kin, e_el};
    record_due_snapshots(t, full_source, view.recording);
  }
}

bool Recorder::detect_first_opening(LoopState& loop) {
  if (loop.recording.t_first_opening >= 0) return false;
  const Eigen::VectorXd& u = loop.dynamics.u;
  for (int k = 0; k < model_.mesh.n_contact(); ++k)
    if ((substrate_ledger_ ? u(2 * k + 1) + loop.substrate.u(2 * k + 1) : u(2 * k + 1)) > opening_threshold_) {
      loop.recording.t_first_opening = loop.step * dt_;
      return true;
    }
  return false;
}

RunRecord Recorder::finish(const LoopState& loop, bool complete, const std::string& end_reason) {
  record_.complete = complete;
  record_.end_reason = end_reason;
  record_.n_steps_done = loop.step;
  record_.t_first_opening = loop.recording.t_first_opening;
  return std::move(record_);
}

void Recorder::record_global(double t, const RowSource& source, int contact_iterations, double contact_residual) {
  const Eigen::VectorXd& r = source.state.dynamics.r;
  double T = 0, N = 0;
  for (int k = 0; k < model_.mesh.n_contact(); ++k) {
    T -= r(2 * k);
    N += r(2 * k + 1);
  }
  double e_kin = source.e_kin, e_el = source.e_el;
  const EnergySums& e = source.sums;
  double work_external = e.work_external, dissipation = e.dissipation_friction, work_normal = e.work_contact_normal;
  double residual = ledger_.balance_residual(e_kin, e_el, e);
  double hht_total = e.hht.total(), hht_gamma = e.hht.gamma, hht_beta = e.hht.beta, hht_shift = e.hht.shift;
  if (source.substrate_sums) {  // the pair: the sums of both bodies' ledgers (docs/substrate.md)
    const EnergySums& es = *source.substrate_sums;
    residual += substrate_ledger_->balance_residual(source.e_kin_substrate, source.e_el_substrate, es);
    e_kin += source.e_kin_substrate;
    e_el += source.e_el_substrate;
    work_external += es.work_external;
    dissipation += es.dissipation_friction;
    work_normal += es.work_contact_normal;
    hht_total += es.hht.total();
    hht_gamma += es.hht.gamma;
    hht_beta += es.hht.beta;
    hht_shift += es.hht.shift;
  }
  auto& g = record_.global;
  g.t.push_back(t);
  g.T.push_back(T);
  g.N.push_back(N);
  last_T_over_N_ = N > 0 ? T / N : std::nan("");
  g.T_over_N.push_back(last_T_over_N_);
  g.energy_kinetic.push_back(e_kin);
  g.energy_elastic.push_back(e_el);
  g.work_external.push_back(work_external);
  g.dissipation_friction.push_back(dissipation);
  g.work_contact_normal.push_back(work_normal);
  g.energy_balance_residual.push_back(residual);
  if (e.hht.on()) {
    g.dissipation_hht.push_back(hht_total);
    g.dissipation_hht_gamma.push_back(hht_gamma);
    g.dissipation_hht_beta.push_back(hht_beta);
    g.dissipation_hht_shift.push_back(hht_shift);
  }
  g.contact_iterations.push_back(contact_iterations);
  g.contact_residual.push_back(contact_residual);
}

void Recorder::record_interface(double t, const RowSource& source, const Eigen::VectorXd& u_previous,
                                const Eigen::VectorXd* u_previous_substrate) {
  const Eigen::VectorXd &u = source.state.dynamics.u, &r = source.state.dynamics.r;
  const Eigen::VectorXd& u_contact_start = source.state.recording.u_contact_start;
  const double h = model_.d.h;
  auto& s = record_.interface;
  s.t.push_back(t);
  for (int k = 0; k < model_.mesh.n_contact(); ++k) {
    const int x = 2 * k, y = 2 * k + 1;
    if (u_previous_substrate) {  // relative: layer minus substrate (model/substrate.hpp)
      const Eigen::VectorXd &u_s = source.state.substrate.u, &u_s_previous = *u_previous_substrate;
      const double rel_x = u(x) - u_s(x), rel_x_previous = u_previous(x) - u_s_previous(x);
      s.slip_velocity.data.push_back((rel_x - rel_x_previous) / dt_);
      s.slip.data.push_back(rel_x - u_contact_start(x));
      s.opening.data.push_back(u(y) + u_s(y));
    } else {
      s.slip_velocity.data.push_back((u(x) - u_previous(x)) / dt_);
      s.slip.data.push_back(u(x) - u_contact_start(x));
      s.opening.data.push_back(u(y));
    }
    s.normal_traction.data.push_back(r(y) / h);
    s.tangential_traction.data.push_back(-r(x) / h);
    s.state.data.push_back(static_cast<std::int8_t>(source.state.contact[x / 2]));
  }
}

void Recorder::record_due_snapshots(double t, const RowSource& source, RecorderState& recording) {
  auto& next = recording.next_snapshot;
  while (next < snapshot_times_.size() && t >= snapshot_times_[next] - 0.5 * dt_) {
    Snapshot snap{t, {}, {}};
    const Eigen::VectorXd &u = source.state.dynamics.u, &v = source.state.dynamics.v;
    for (int j = 0; j <= model_.mesh.n_y; ++j)
      for (int i = 0; i <= model_.mesh.n_x; ++i) {  // i = n_x repeats i = 0 (see snapshot_mesh)
        const int node = model_.mesh.node(i, j);
        for (int c = 0; c < 2; ++c) {
          snap.displacement.push_back(u(2 * node + c));
          snap.velocity.push_back(v(2 * node + c));
        }
      }
    record_.snapshots.push_back(std::move(snap));
    if (source.substrate_sums) {  // the substrate's bulk fields in physical coordinates (u_y = -u_y')
      const LayerMesh& mesh = model_.substrate->mesh;
      Snapshot below{t, {}, {}};
      const Eigen::VectorXd &u_s = source.state.substrate.u, &v_s = source.state.substrate.v;
      for (int j = 0; j <= mesh.n_y; ++j)
        for (int i = 0; i <= mesh.n_x; ++i) {
          const int node = mesh.node(i, j);
          below.displacement.push_back(u_s(2 * node));
          below.displacement.push_back(-u_s(2 * node + 1));
          below.velocity.push_back(v_s(2 * node));
          below.velocity.push_back(-v_s(2 * node + 1));
        }
      record_.substrate_snapshots.push_back(std::move(below));
    }
    ++next;
  }
}

}  // namespace slidewave
