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
#include <optional>
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
  /// Prepares the output of a run into `final_path`, creating no file yet (setup_done() does: a kill
  /// during the model's setup, minutes for a large mesh, leaves nothing behind). With `resume` and a
  /// checkpoint beside it: reads it (its digest and its step counters against its row counts are
  /// checked) and throws ResumeRefused, listing what differs, when it was written for another
  /// configuration or build; an unreadable, damaged or inconsistent checkpoint is reported on `notes`
  /// and the run starts over. Temporaries are named after `provenance.run_id` (io/run_id.hpp).
  RunSession(std::string final_path, const RunConfig& config, const Provenance& provenance, bool resume,
             std::ostream& notes);
  ~RunSession() override;

  /// Creates RUN.partial.h5: the checkpoint's rows carried over from the earlier partial file (when they
  /// are intact; else a note on `notes` and a start from the beginning), or a new one (a stale
  /// checkpoint is removed). Throws IoError when a file cannot be written.
  void setup_done() override;
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
  void resume_from(Checkpoint checkpoint);
  void start_over();
  void write_checkpoint_now(RunRecord& record, const Capture& capture);

  std::string final_path_, partial_path_, checkpoint_path_;
  RunConfig config_;
  Provenance provenance_;
  std::ostream& notes_;
  std::unique_ptr<RunWriter> writer_;
  std::optional<Checkpoint> to_resume_;  ///< read and verified by the constructor, used by setup_done()
  Checkpoint start_;
  bool resumed_ = false;
  bool checkpoint_written_ = false;
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_checkpoint_;
};

}  // namespace slidewave
