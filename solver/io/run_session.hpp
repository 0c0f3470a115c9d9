#pragma once
// The output side of one `slidewave run CONFIG -o RUN.h5 [--resume]` (docs/contracts.md section 2):
//   RUN.partial.h5     streamed while the run goes (io/run_writer.hpp), complete = 0 until the end
//   RUN.checkpoint.h5  every output.checkpoint_interval s of wall time and at SIGINT/SIGTERM (io/checkpoint.hpp)
//   RUN.h5 (+ RUN.xdmf) the partial file renamed into place when the run ends with a result (complete, or
//                      contact_not_converged); checkpoint and partial file are then gone.
// An interrupted run never creates or touches RUN.h5: RUN.partial.h5 and RUN.checkpoint.h5 stay.
// --resume continues from the checkpoint when it was written for the same configuration and build.
#include <chrono>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>

#include "config/run_config.hpp"
#include "io/checkpoint.hpp"
#include "io/run_writer.hpp"
#include "model/run_observer.hpp"

namespace slidewave {

/// The checkpoint belongs to another configuration or build: nothing was changed; the CLI exits 2.
class ResumeRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RunSession : public RunObserver {
 public:
  /// Prepares the output of a run into `final_path`. With `resume` and a checkpoint beside it: throws
  /// ResumeRefused (listing what differs) or carries the partial file's rows over; when the partial file
  /// no longer holds what the checkpoint counted (or the checkpoint is unreadable), starts over and says
  /// so on `notes`. Without: starts a new partial file (a stale checkpoint is removed).
  /// Throws IoError when a file cannot be written.
  RunSession(std::string final_path, const RunConfig& config, const Provenance& provenance, bool resume,
             std::ostream& notes);
  ~RunSession() override;

  void after_step(RunRecord& record, const Capture& capture) override;
  /// Interrupted: final checkpoint, RUN.partial.h5 closed (outcome interrupted). Otherwise: RUN.h5 in
  /// place, checkpoint removed. Throws IoError.
  void at_end(RunRecord& record, const Capture& capture) override;
  const StateArrays* start_state() const override { return resumed_ ? &start_.state : nullptr; }

  /// After an error: closes the partial file and removes it, unless a checkpoint written by this run
  /// makes it resumable. Returns what was kept, for the message ("" when nothing).
  std::string abandon() noexcept;

  const std::string& partial_path() const { return partial_path_; }
  const std::string& checkpoint_path() const { return checkpoint_path_; }

 private:
  void start_over(const Provenance& provenance);
  void write_checkpoint_now(RunRecord& record, const Capture& capture);

  std::string final_path_, partial_path_, checkpoint_path_;
  RunConfig config_;
  std::unique_ptr<RunWriter> writer_;
  Checkpoint start_;
  bool resumed_ = false;
  bool checkpoint_written_ = false;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_checkpoint_;
};

}  // namespace slidewave
