#include "model/uniform_stick.hpp"

#include <algorithm>
#include <cmath>

#include "contact/delassus.hpp"

namespace slidewave {
namespace {

/// Shear transits H / c_s from the seed to the first slip of the unperturbed layer. The seed's kick shows
/// in T/N as noise of 4e-4 that HHT damps to the plateau of the layer's low modes (2e-5 at H/64, 6e-6 at
/// H/128, nu 0.2, f 1.5) within about four transits (docs/stick-phase.md): seeded this early, the layer
/// meets its first slip as it did when the seed was carried from t = 0.
constexpr double kLeadTransits = 4;

/// The layer's configuration for one mesh column: the same mesh row, one element wide (n_x = 1), solved by
/// CHOLMOD (the FFT solver needs n_x >= 3).
RunConfig column_config(const RunConfig& layer) {
  RunConfig c = layer;
  c.geometry.lambda_over_H = 1.0 / layer.mesh.elements_per_H;
  c.numerics.linear_solver = LinearSolverKind::cholmod;
  c.numerics.threads = 1;
  return c;
}

/// Entry 2 (j n_x + i) + d of the result is entry 2 j + d of the column: every mesh column the same.
Eigen::VectorXd broadcast(const Eigen::VectorXd& column, int n_x) {
  Eigen::VectorXd out(column.size() * n_x);
  for (Eigen::Index j = 0; j < column.size() / 2; ++j)
    for (int i = 0; i < n_x; ++i) out.segment<2>(2 * (j * n_x + i)) = column.segment<2>(2 * j);
  return out;
}

/// The inverse of broadcast(), from mesh column 0.
Eigen::VectorXd column_of(const Eigen::VectorXd& layer, int n_x) {
  Eigen::VectorXd out(layer.size() / n_x);
  for (Eigen::Index j = 0; j < out.size() / 2; ++j) out.segment<2>(2 * j) = layer.segment<2>(2 * j * n_x);
  return out;
}

bool all_stick(const std::vector<ContactState>& state) {
  return !state.empty() &&
         std::all_of(state.begin(), state.end(), [](ContactState s) { return s == ContactState::stick; });
}

Eigen::MatrixXd column_delassus(const HHTStepper& stepper) {
  return stepper.contact_weight() * delassus_operator_periodic(stepper.K_eff(), 1);
}

Eigen::VectorXd top_velocity(const LayerModel& column) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(column.n_top);
  v(0) = column.d.V0;
  return v;
}

}  // namespace

UniformStick::UniformStick(const LayerModel& layer, const PreloadState& preload)
    : layer_(layer),
      preload_(preload),
      column_(column_config(layer.config)),
      system_{column_.K, column_.K_ff, column_.M_ff, column_.M_ff_rows, column_.K_fd,
              column_.n_free, column_.n_top, column_.n_contact_dofs},
      stepper_(system_, HHTCoefficients(layer.config.time.hht_alpha, layer.d.dt),
               layer.config.time.contact_weighting == ContactWeighting::alpha,
               column_.factorize_split(effective_matrix(HHTCoefficients(layer.config.time.hht_alpha, layer.d.dt),
                                                        system_))),
      friction_(make_friction_law(layer.config.friction)),
      all_stick_(column_delassus(stepper_)),
      ledger_(column_, top_velocity(column_)),
      n_x_(layer.mesh.n_x),
      applies_(all_stick(preload.state)),
      q_(2), r_next_(2), du_(2) {}

Eigen::VectorXd UniformStick::top_after(std::int64_t step) const {
  const RunConfig& c = layer_.config;
  return column_.top_displacement(preload_.u_x_top + layer_.d.V0 * (step * layer_.d.dt),
                                  c.loading.Uy_over_H * layer_.d.H);
}

LoopState UniformStick::initial_column() const {
  LoopState loop;
  const Eigen::VectorXd u = column_of(preload_.u, n_x_);
  const Eigen::VectorXd v = column_of(Eigen::VectorXd::Zero(preload_.u.size()), n_x_);
  Eigen::VectorXd v_top = v;
  v_top.tail(column_.n_top) = top_velocity(column_);
  const Eigen::VectorXd r = preload_.r.head(2);
  loop.t_end = layer_.config.time.t_end;
  loop.dynamics = stepper_.initial_state(u, v_top, r, *column_.factorize(column_.M_ff));
  loop.contact.assign(1, preload_.state.front());
  loop.friction = friction_->initial_state(r);
  loop.energy = ledger_.start(loop.dynamics);
  return loop;
}

bool UniformStick::advance(LoopState& loop, EnergySums* sums_increment) {
  HHTState& s = loop.dynamics;
  stepper_.predict(s, top_after(loop.step + 1));
  const Eigen::VectorXd& u_free = stepper_.solve_free();
  q_ = u_free.head(2);
  q_(0) -= s.u(0);
  friction_->bounds(loop.friction, bounds_);
  r_next_ = s.r;
  if (!all_stick_.solve(q_, layer_.config.friction.f, bounds_, r_next_, loop.contact)) return false;
  stepper_.correct(r_next_, s);
  ++loop.step;
  du_ = s.u.head(2) - stepper_.u_previous().head(2);
  if (sums_increment) {
    EnergySums& e = loop.energy;
    e.energy_start = e.work_external = e.dissipation_friction = e.work_contact_normal = 0;
    e.hht.gamma = e.hht.beta = e.hht.shift = 0;
    ledger_.book_step(s, stepper_.u_previous(), stepper_.r_previous(), du_, e);
    *sums_increment = e;
  }
  friction_->update(du_, s.r, layer_.d.dt, loop.friction);
  return true;
}

std::int64_t UniformStick::handover_step(std::int64_t n_steps_max, const std::atomic<bool>* stop) {
  if (!applies_) return 0;
  LoopState probe = initial_column();
  while (probe.step < n_steps_max) {
    if (stop && stop->load()) return 0;
    if (!advance(probe, nullptr)) {
      const std::int64_t n_lead = std::lround(kLeadTransits * layer_.d.H / (layer_.d.c_s * layer_.d.dt));
      return std::max<std::int64_t>(0, probe.step - n_lead);  // probe.step = n_slip - 1
    }
  }
  return n_steps_max;
}

void UniformStick::start(LoopState& layer, Recorder& recorder, int preload_contact_iterations) {
  column_loop_ = initial_column();
  layer.step = 0;
  layer.t_end = column_loop_.t_end;
  layer.energy = column_loop_.energy;
  layer.energy.energy_start = n_x_ * (ledger_.kinetic(column_loop_.dynamics) + ledger_.elastic(column_loop_.dynamics));
  recorder.record_uniform_start(column_loop_, layer.energy, preload_contact_iterations,
                                n_x_ * ledger_.kinetic(column_loop_.dynamics),
                                n_x_ * ledger_.elastic(column_loop_.dynamics));
}

void UniformStick::resume_from(const LoopState& layer) {
  column_loop_ = initial_column();  // sizes, then every field from the layer's mesh column 0
  HHTState& s = column_loop_.dynamics;
  const HHTState& l = layer.dynamics;
  for (auto [to, from] : {std::pair{&s.u, &l.u}, {&s.v, &l.v}, {&s.acc, &l.acc}, {&s.Ku, &l.Ku}, {&s.Mu_f, &l.Mu_f},
                          {&s.Mv_f, &l.Mv_f}, {&s.Ma_f, &l.Ma_f}, {&s.r, &l.r}})
    *to = column_of(*from, n_x_);
  EnergySums& e = column_loop_.energy;
  e.F_top = column_of(layer.energy.F_top, n_x_);
  if (e.hht.on()) {
    const HhtDissipation& h = layer.energy.hht;
    e.hht.v_f = column_of(h.v_f, n_x_);
    e.hht.acc_f = column_of(h.acc_f, n_x_);
    e.hht.Ma_f = column_of(h.Ma_f, n_x_);
    e.hht.Ku_f = column_of(h.Ku_f, n_x_);
    e.hht.shift_f = column_of(h.shift_f, n_x_);
  }
  column_loop_.contact.assign(1, layer.contact.front());
  const std::size_t per_node = layer.friction.per_node.size() / layer.contact.size();
  column_loop_.friction.per_node.assign(layer.friction.per_node.begin(), layer.friction.per_node.begin() + per_node);
  column_loop_.recording = layer.recording;
  column_loop_.recording.u_contact_start = column_of(layer.recording.u_contact_start, n_x_);
  column_loop_.step = layer.step;
  column_loop_.t_end = layer.t_end;
}

bool UniformStick::step(LoopState& layer, Recorder& recorder) {
  EnergySums increment;
  if (!advance(column_loop_, &increment)) return false;
  EnergySums& e = layer.energy;
  e.work_external += n_x_ * increment.work_external;
  e.dissipation_friction += n_x_ * increment.dissipation_friction;
  e.work_contact_normal += n_x_ * increment.work_contact_normal;
  e.hht.gamma += n_x_ * increment.hht.gamma;
  e.hht.beta += n_x_ * increment.hht.beta;
  e.hht.shift += n_x_ * increment.hht.shift;
  layer.step = column_loop_.step;
  recorder.record_uniform_step(column_loop_, stepper_.u_previous(), e, n_x_ * ledger_.kinetic(column_loop_.dynamics),
                               n_x_ * ledger_.elastic(column_loop_.dynamics));
  return true;
}

void UniformStick::expand_into(LoopState& layer) const {
  const HHTState& s = column_loop_.dynamics;
  HHTState& l = layer.dynamics;
  for (auto [to, from] : {std::pair{&l.u, &s.u}, {&l.v, &s.v}, {&l.acc, &s.acc}, {&l.Ku, &s.Ku}, {&l.Mu_f, &s.Mu_f},
                          {&l.Mv_f, &s.Mv_f}, {&l.Ma_f, &s.Ma_f}, {&l.r, &s.r}})
    *to = broadcast(*from, n_x_);
  const EnergySums& e = column_loop_.energy;
  layer.energy.F_top = broadcast(e.F_top, n_x_);
  if (e.hht.on()) {
    HhtDissipation& h = layer.energy.hht;
    h.v_f = broadcast(e.hht.v_f, n_x_);
    h.acc_f = broadcast(e.hht.acc_f, n_x_);
    h.Ma_f = broadcast(e.hht.Ma_f, n_x_);
    h.Ku_f = broadcast(e.hht.Ku_f, n_x_);
    h.shift_f = broadcast(e.hht.shift_f, n_x_);
  }
  layer.contact.assign(n_x_, column_loop_.contact.front());
  layer.friction.per_node.clear();
  for (int i = 0; i < n_x_; ++i)
    layer.friction.per_node.insert(layer.friction.per_node.end(), column_loop_.friction.per_node.begin(),
                                   column_loop_.friction.per_node.end());
  layer.recording = column_loop_.recording;
  layer.recording.u_contact_start = broadcast(column_loop_.recording.u_contact_start, n_x_);
  layer.step = column_loop_.step;
}

}  // namespace slidewave
