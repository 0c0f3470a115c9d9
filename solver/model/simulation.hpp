#pragma once
// A run: the preload (stages 1 and 2, model/layer_model.hpp), then stage 3, the dynamic shear of the
// preloaded layer, top u_x growing at V0 from zero initial velocity, integrated with HHT
// (time/hht_stepper.hpp); exact Signorini–Coulomb contact each step on the Delassus operator of K_eff
// (factorized once), with the friction bounds of the configured law (contact/friction_law.hpp).
//
// Per step:  predictor  u~ = u + dt v + dt^2 (1/2 - beta) a
//            free solve K_eff u_free = M u~ / (beta dt^2) - (1-a) K_fd u_d(n+1) - a K u(n) + a' C^T r(n)
//            contact    y = C u_free - (u_x(n), 0) + w W r(n+1) under the local law (contact/*)
//            correction u(n+1) = u_free + w Z r(n+1)
//            record     energy ledger, friction memory, output rows, first opening (model/recorder.hpp)
// where w = 1-a, a' = a ("alpha" weighting, contact forces like F_ext) or w = 1, a' = 0 ("end").
// Everything carried from step to step is in LoopState (model/loop_state.hpp).
// With a deformable substrate (docs/substrate.md, model/substrate.hpp) the substrate takes the same step with
// its own stepper (its bottom held), the contact problem is the pair's (q = q_L + S q_S, W = W_L + S W_S S),
// and its correction takes S r(n+1).
#include <atomic>
#include <functional>

#include "model/layer_model.hpp"
#include "model/recorder.hpp"
#include "model/run_observer.hpp"
#include "model/run_record.hpp"
#include "model/step_profile.hpp"

namespace slidewave {

/// Called about once a second of wall time, with (t, t_end, steps per second, T/N, n slipping nodes).
using ProgressCallback = std::function<void(double, double, double, double, int)>;

/// Runs all three stages. Never throws for a contact step that misses tolerance: the record is then
/// returned with complete = false and end_reason = "contact_not_converged".
/// @param stop_requested  polled every step (signal handlers set it); ends the run as "interrupted"
/// @param profile         if given, receives the wall-time split (bench/ only)
/// @param observer        if given, sees the rows after every step (streaming, checkpoints) and may give a
///                        state to continue from (model/run_observer.hpp); the returned record then holds
///                        only the rows the observer left in it
RunRecord simulate(const LayerModel& model, const ProgressCallback& progress = {},
                   const std::atomic<bool>* stop_requested = nullptr, StepProfile* profile = nullptr,
                   RunObserver* observer = nullptr);

}  // namespace slidewave
