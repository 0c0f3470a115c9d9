#pragma once
// What the time loop offers to the outside while it runs: the record after every step (a streaming
// writer drains it, so the series do not pile up in memory), its evolving state (LoopState,
// model/loop_state.hpp) as named arrays when a checkpoint is due, and a state to start from instead
// of t = 0 (--resume). Continuing from a captured state gives the same steps, bit for bit, as the
// uninterrupted loop: LoopState is everything one step carries to the next, and the setup before the
// loop (matrices, preload, perturbation) is deterministic.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "model/run_record.hpp"

namespace slidewave {

/// Named arrays, bit-exact (model/loop_state_arrays.hpp maps LoopState to them).
struct StateArrays {
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<std::int64_t>> integers;
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  using Capture = std::function<StateArrays()>;
  /// Once the setup (preload, factorizations, Delassus operator) is done, before the first step and
  /// before start_state(): the moment to create output files, so that a run stopped or killed during
  /// its setup leaves none.
  virtual void setup_done() {}
  /// After each step's rows are recorded (and once after the rows of t = 0, at step 0).
  /// `capture` returns the state after that step; call it only when needed (it copies the state).
  virtual void after_step(RunRecord& record, const Capture& capture) = 0;
  /// When the loop has ended, for any reason, with the state after the last completed step.
  virtual void at_end(RunRecord& record, const Capture& capture) = 0;
  /// State to continue from (nullptr: start at t = 0). The record then starts empty: the rows up to
  /// that state are already in the output.
  virtual const StateArrays* start_state() const { return nullptr; }
};

}  // namespace slidewave
