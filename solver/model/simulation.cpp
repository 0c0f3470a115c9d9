#include "model/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "contact/contact_solver.hpp"
#include "contact/delassus.hpp"
#include "contact/friction_law.hpp"
#include "model/contact_step.hpp"
#include "model/energy_ledger.hpp"
#include "model/loop_state.hpp"
#include "model/loop_state_arrays.hpp"
#include "model/mode_seed.hpp"
#include "model/recorder.hpp"
#include "model/stick_phase/phase_support.hpp"
#include "model/stick_phase/slip_phase_run.hpp"
#include "model/stick_phase/stick_phase_run.hpp"
#include "model/stick_phase/wavenumber_slip_step.hpp"
#include "model/substrate.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

/// Adds the time since the last call to one field of the profile, and counts steps and sweeps (no-op
/// without a profile).
class Stopwatch {
 public:
  explicit Stopwatch(StepProfile* p) : profile_(p), last_(std::chrono::steady_clock::now()) {}
  void lap(double StepProfile::*field) {
    if (!profile_) return;
    const auto now = std::chrono::steady_clock::now();
    profile_->*field += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }
  void count_stick_phase(std::int64_t steps) {
    if (profile_) profile_->stick_phase_steps = steps;
  }
  void count(std::int64_t step, int contact_sweeps) {
    if (!profile_) return;
    profile_->steps = step;
    profile_->contact_sweeps += contact_sweeps;
  }

 private:
  StepProfile* profile_;
  std::chrono::steady_clock::time_point last_;
};

/// Calls the progress callback about once a second of wall time.
class ProgressPacer {
 public:
  explicit ProgressPacer(const ProgressCallback& callback)
      : callback_(callback), last_(std::chrono::steady_clock::now()) {}
  void step_done(double t, const LoopState& loop, const Recorder& recorder) {
    ++steps_since_report_;
    if (!callback_) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - last_).count();
    if (elapsed < 1.0) return;
    int n_slip = 0;
    for (auto s : loop.contact) n_slip += s == ContactState::slip;
    callback_(t, loop.t_end, steps_since_report_ / elapsed, recorder.last_T_over_N(), n_slip);
    last_ = now;
    steps_since_report_ = 0;
  }

 private:
  const ProgressCallback& callback_;
  std::chrono::steady_clock::time_point last_;
  std::int64_t steps_since_report_ = 0;
};

/// Velocity of every DOF at the start of the dynamic stage: the top's u_x at V0, the rest at rest (or, with
/// `mode_seed.start` = sliding, every u_x at V0).
Eigen::VectorXd start_velocity(const LayerModel& m) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(m.n_free + m.n_top);
  const int first = m.config.mode_seed.sliding_start ? 0 : m.n_free;
  for (int dof = first; dof < m.n_free + m.n_top; dof += 2) v(dof) = m.d.V0;
  return v;
}

/// The substrate's dynamics (model/substrate.hpp, in its mirrored frame): its own HHT stepper on its own FFT
/// split solver, its mass factorization, its energy ledger; its bottom is held at 0.
struct SubstrateBody {
  SubstrateBody(const LayerModel& body, const HHTCoefficients& hht, bool alpha_weighted)
      : model(body),
        system(body.partitioned()),
        stepper(system, hht, alpha_weighted, body.factorize_split(effective_matrix(hht, system))),
        M_ff(body.factorize(LayerModel::FreeBlock::mass)),
        ledger(body, Eigen::VectorXd::Zero(body.n_top)),
        u_bottom(Eigen::VectorXd::Zero(body.n_top)) {}
  /// W_S = w C K_eff,S^-1 C^T in the substrate's frame.
  Eigen::MatrixXd delassus() const {
    return stepper.contact_weight() * delassus_operator_periodic(stepper.K_eff(), model.mesh.n_contact());
  }
  /// Its contact forces S r from the layer's r.
  const Eigen::VectorXd& load(const Eigen::VectorXd& r) {
    S_r = r;
    mirror_x_components(S_r);
    return S_r;
  }
  const LayerModel& model;
  PartitionedSystem system;
  HHTStepper stepper;
  std::unique_ptr<LinearSolver> M_ff;
  EnergyLedger ledger;
  Eigen::VectorXd u_bottom, S_r;
};

/// Steps to the first time at or after t_end: the configuration's count (DerivedConstants::n_steps, the one
/// formula), which parsing bounds by time.max_steps; the check guards a configuration made without parsing.
std::int64_t step_count(const DerivedConstants& d) {
  if (!(d.n_steps < 9.2e18))
    throw std::overflow_error("time: t_end / dt = " + std::to_string(d.n_steps) + " steps overflows 64 bits");
  return static_cast<std::int64_t>(d.n_steps);
}

/// State at t = 0 of the dynamic stage, before the seed: the preload, the top moving at V0, the acceleration
/// consistent with the preload reactions (`dynamics`), the running sums at zero.
LoopState start_state(const LayerModel& m, const PreloadState& pre, HHTState dynamics, const FrictionLaw& friction,
                      const EnergyLedger& ledger) {
  LoopState loop;
  loop.t_end = m.config.time.t_end;
  loop.dynamics = std::move(dynamics);
  loop.contact = pre.state;
  loop.friction = friction.initial_state(pre.r);
  loop.energy = ledger.start(loop.dynamics);
  return loop;
}

/// The substrate's state at t = 0: the preload at rest, loaded by the preload reactions.
void start_substrate(const PreloadState& pre, SubstrateBody& sub, LoopState& loop) {
  const int n = sub.model.n_free + sub.model.n_top;
  loop.substrate = sub.stepper.initial_state(pre.u_substrate, Eigen::VectorXd::Zero(n), sub.load(pre.r), *sub.M_ff);
  loop.substrate_energy = sub.ledger.start(loop.substrate);
}

/// Adds the seeded perturbation that breaks translation invariance: a uniform random displacement of every
/// free DOF but the contact nodes' normal ones (no gap, no penetration), amplitude relative to the preshear
/// top displacement, from std::mt19937_64(seed), on top of the single-mode seed if there is one
/// (model/mode_seed.hpp). The acceleration changes by M_ff da = -(K du)_f, which keeps M a + K u - C^T r,
/// and with it the HHT step's carried state, as it was (with the redistributed mass the contact rows' share goes
/// into r instead); the seed's elastic energy is part of the energy at the start.
void add_seed(const LayerModel& m, const PreloadState& pre, const EnergyLedger& ledger, const LinearSolver& M_ff,
              LoopState& loop) {
  const auto& c = m.config;
  const int n_f = m.n_free, n_c = m.n_contact_dofs;
  Eigen::VectorXd du = mode_seed_displacement(m);
  std::mt19937_64 generator(static_cast<std::uint64_t>(c.perturbation.seed));
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double amplitude = c.perturbation.amplitude * std::fabs(pre.u_x_top);
  for (int dof = 0; dof < n_f; ++dof) {
    const double xi = uniform(generator);
    if (dof < n_c && dof % 2 == 1) continue;
    du(dof) += amplitude * xi;
  }
  HHTState& s = loop.dynamics;
  const double elastic_before = ledger.elastic(s);
  const Eigen::VectorXd K_du = m.stiffness_product(du);
  s.u += du;
  s.Ku += K_du;
  s.Mu_f += m.free_mass_product(du.head(n_f));
  s.Ma_f -= K_du.head(n_f);
  Eigen::VectorXd da = M_ff.solve(Eigen::VectorXd(-K_du.head(n_f)));
  if (c.mesh.mass == MassKind::redistributed) {
    // The contact nodes carry (almost) no inertia (fem/mass_redistribution.hpp): their rows are quasi-static,
    // so the reaction, not an acceleration, takes the seed's load there: dr with (M_ff^-1 (C^T dr - K du))_c = 0.
    // (An acceleration would be the load over 1e-6 of a node's mass: a start with kinetic energy from nowhere.)
    const Eigen::VectorXd dr = delassus_operator_periodic(M_ff, n_c / 2).ldlt().solve(Eigen::VectorXd(-da.head(n_c)));
    Eigen::VectorXd load = Eigen::VectorXd::Zero(n_f);
    load.head(n_c) = dr;
    da += M_ff.solve(load);
    s.r += dr;
    s.Ma_f.head(n_c) += dr;
  }
  s.acc.head(n_f) += da;
  EnergySums& e = loop.energy;
  e.energy_start += ledger.elastic(s) - elastic_before;
  e.F_top = s.Ku.tail(m.n_top) + m.M_top_rows * s.acc;
  if (e.hht.on()) {  // the shift term s = M a + K u - C^T r (free rows) is unchanged
    e.hht.acc_f = s.acc.head(n_f);
    e.hht.Ma_f = s.Ma_f;
    e.hht.Ku_f = s.Ku.head(n_f);
  }
}

}  // namespace

RunRecord simulate(const LayerModel& m, const ProgressCallback& progress, const std::atomic<bool>* stop_requested,
                   StepProfile* profile, RunObserver* observer) {
  Stopwatch watch(profile);
  const RunConfig& c = m.config;
  const int n_c = m.n_contact_dofs;

  // 1. Preload: quasi-static compression, then shear until T/N = preshear_ratio f (stages 1 and 2).
  const PreloadState pre = solve_preload(m);

  // 2. For a run that steps plainly (model/stick_phase/slip_phase_run.hpp says which do not): the effective
  //    matrix K_eff, factorized once, and the Delassus operator W = w C K_eff^-1 C^T.
  const HHTCoefficients hht(c.time.hht_alpha, m.d.dt);
  const bool slip_phase = slip_phase_applies(m);
  std::optional<PartitionedSystem> system;  // the free-free blocks too: built for the plain path only
  std::unique_ptr<HHTStepper> stepper;
  std::unique_ptr<SubstrateBody> sub;
  Eigen::MatrixXd W;
  if (!slip_phase) {
    system.emplace(m.partitioned());
    const bool alpha_weighted = c.time.contact_weighting == ContactWeighting::alpha;
    stepper =
        std::make_unique<HHTStepper>(*system, hht, alpha_weighted, m.factorize_split(effective_matrix(hht, *system)));
    W = stepper->contact_weight() * delassus_operator_periodic(stepper->K_eff(), n_c / 2);
    // With a substrate: its own stepper, and the pair's operator W_L + S W_S S (model/substrate.hpp).
    if (m.substrate) {
      sub = std::make_unique<SubstrateBody>(*m.substrate, hht, alpha_weighted);
      W = pair_delassus(W, sub->delassus());
    }
  }
  const auto friction = make_friction_law(c.friction);
  const GaussSeidelSettings settings{c.contact.tolerance, c.contact.max_iterations, m.d.p0 * m.d.h};

  // 3. The state at t = 0 with the seed, and the output rows at t = 0; or, continuing a run, the state of
  //    its checkpoint (whose rows are already in the output).
  const auto M_ff = m.factorize(LayerModel::FreeBlock::mass);
  const EnergyLedger ledger(m, start_velocity(m).tail(m.n_top));
  LoopState loop =
      start_state(m, pre,
                  stepper ? stepper->initial_state(pre.u, start_velocity(m), pre.r, *M_ff)
                          : hht_initial_state([&m](const auto& x_f) { return m.free_mass_product(x_f); }, m.n_free, n_c,
                                              pre.u, start_velocity(m), pre.r, m.stiffness_product(pre.u), *M_ff),
                  *friction, ledger);
  add_seed(m, pre, ledger, *M_ff, loop);
  Recorder recorder(m, ledger, pre);
  if (sub) {
    start_substrate(pre, *sub, loop);
    recorder.attach_substrate(sub->ledger);
  }
  const std::int64_t n_steps_max = step_count(m.d);
  if (observer) observer->setup_done();
  // The slip phase's lanes, once they hold the state (model/stick_phase/slip_phase_run.hpp): checkpoints keep them.
  std::unique_ptr<WavenumberSlipStep> slip;
  const RunObserver::Capture capture = [&loop, &slip] {
    StateArrays arrays = to_arrays(loop);
    if (slip && slip->owns_state()) slip->save(arrays);
    return arrays;
  };
  const bool stick_phase = stick_phase_applies(m, loop);
  LoopState seeded;  // the state at t = 0, which the stick phase of a resumed run replays from
  const StateArrays* resumed = observer ? observer->start_state() : nullptr;
  if (resumed) {
    if (stick_phase) seeded = loop;
    loop.recording.u_contact_start.resize(n_c);
    restore_from_arrays(*resumed, loop);
  } else {
    recorder.record_start(loop, pre.contact_iterations);
    if (observer) observer->after_step(recorder.rows(), capture);
  }
  const bool resumed_in_slip_phase = slip_phase && resumed && WavenumberSlipStep::saved_in(*resumed);
  watch.lap(&StepProfile::setup);
  ProgressPacer pacer(progress);
  std::string failure;  // why the run stopped early, if it did
  const PhaseHooks hooks{[&] { return stop_requested && stop_requested->load(); },
                         [&](double StepProfile::*part) { watch.lap(part); },
                         [&](const LoopState& view, int contact_sweeps, const RunObserver::Capture& full) {
                           watch.count(view.step, contact_sweeps);
                           pacer.step_done(view.step * hht.dt, view, recorder);
                           if (observer) observer->after_step(recorder.rows(), full);
                         }};

  // The layer's blocks per wavenumber, which both phases step on (made once, where one of them runs).
  std::optional<WavenumberBlocks> blocks;
  const auto wavenumber_blocks = [&]() -> const WavenumberBlocks& {
    if (!blocks) blocks.emplace(m);
    return *blocks;
  };

  // 4. The stick phase in wavenumbers, while every node sticks (model/stick_phase/stick_phase_run.hpp).
  if (stick_phase && !resumed_in_slip_phase && all_stuck(loop.contact)) {
    run_stick_phase(m, wavenumber_blocks(), pre.u_x_top, *friction, loop.step > 0 ? seeded : loop, n_steps_max,
                    recorder, hooks, loop);
    watch.lap(&StepProfile::stick_phase);
    watch.count_stick_phase(loop.step);
  }

  // 5. The slip phase in wavenumbers, to the end of the run (model/stick_phase/slip_phase_run.hpp); made after
  //    the stick phase has freed its lanes, so that the two never hold memory at once (and not at all when the
  //    run ends in the stick phase).
  if (slip_phase && before_end(loop.step, n_steps_max, loop, hht.dt)) {
    slip = std::make_unique<WavenumberSlipStep>(m, wavenumber_blocks(), pre.u_x_top, settings, *friction);
    if (resumed_in_slip_phase)
      slip->restore(loop, *resumed);
    else
      slip->start(loop);
    watch.lap(&StepProfile::setup);
    failure = run_slip_phase(*slip, m, n_steps_max, recorder, hooks, loop);
  }

  // 6. Plain time loop (the substrate pair, the HHT terms of the ledger; and every run of a model stepped
  //    plainly), up to the first step at or after t_end (which stop_after_opening may shorten).
  if (stepper) {
    HHTStepper& plain = *stepper;
    HHTState& s = loop.dynamics;
    ContactStep contact(n_c, W, settings);
    Eigen::VectorXd du(n_c);  // contact displacement increment of the step
    // The top's prescribed displacement after `step` steps: u_x(preload) + V0 t, the preload's u_y.
    const auto top_after = [&](std::int64_t step) {
      return m.top_displacement(pre.u_x_top + m.d.V0 * (step * hht.dt), c.loading.Uy_over_H * m.d.H);
    };
    Eigen::VectorXd u_d_next = top_after(loop.step + 1), u_d_following;
    while (failure.empty() && before_end(loop.step, n_steps_max, loop, hht.dt)) {
      if (stop_requested && stop_requested->load()) {
        failure = "interrupted";
        break;
      }
      const double t = (loop.step + 1) * hht.dt;
      // 6a. Predictor and free solve (r(n+1) = 0), the top displaced to u_d(n+1).
      plain.predict(s, u_d_next);
      watch.lap(&StepProfile::predictor);
      const Eigen::VectorXd& u_free = plain.solve_free();
      std::optional<SubstrateContact> substrate;
      if (sub) {
        sub->stepper.predict(loop.substrate, sub->u_bottom);
        substrate.emplace(SubstrateContact{sub->stepper.solve_free(), loop.substrate.u});
      }
      watch.lap(&StepProfile::free_solve);
      // 6b. Contact forces r(n+1): Signorini–Coulomb at every node (pair), bounds from the friction law.
      const GaussSeidelReport report =
          contact.solve(u_free, s.u, s.r, *friction, loop.friction, loop.contact, substrate ? &*substrate : nullptr);
      if (!report.converged) {
        failure = "contact_not_converged";
        break;
      }
      watch.lap(&StepProfile::contact);
      // 6c. Correction with r(n+1) and Newmark update, and with them the predictor of the next step.
      u_d_following = top_after(loop.step + 2);
      plain.correct(contact.r_next, s, &u_d_following);
      if (sub) sub->stepper.correct(sub->load(contact.r_next), loop.substrate, &sub->u_bottom);
      u_d_next.swap(u_d_following);
      watch.lap(&StepProfile::correction);
      // 6d. Energy ledger, friction memory, output rows, first opening.
      ++loop.step;
      du = s.u.head(n_c) - plain.u_previous().head(n_c);
      ledger.book_step(s, plain.u_previous(), plain.r_previous(), du, loop.energy);
      if (sub) {  // each body books its own contact work; the friction law sees the relative increment
        Eigen::VectorXd du_substrate = loop.substrate.u.head(n_c) - sub->stepper.u_previous().head(n_c);
        sub->ledger.book_step(loop.substrate, sub->stepper.u_previous(), sub->stepper.r_previous(), du_substrate,
                              loop.substrate_energy);
        mirror_x_components(du_substrate);
        du += du_substrate;
      }
      friction->update(du, s.r, hht.dt, loop.friction);
      recorder.record_step(loop, plain.u_previous(), report, sub ? &sub->stepper.u_previous() : nullptr);
      if (recorder.detect_first_opening(loop)) shorten_after_opening(c.time, t, loop);
      watch.lap(&StepProfile::diagnostics);
      watch.count(loop.step, report.iterations);
      pacer.step_done(t, loop, recorder);
      if (observer) observer->after_step(recorder.rows(), capture);
    }
  }
  RunRecord record = recorder.finish(loop, failure.empty(), failure.empty() ? loop.end_reason : failure);
  if (observer) observer->at_end(record, capture);
  return record;
}

}  // namespace slidewave
