#include "io/run_session.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/hdf5_support.hpp"
#include "io/run_id.hpp"
#include "io/xdmf.hpp"

namespace slidewave {

namespace {

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

}  // namespace

RunSession::RunSession(std::string final_path, const RunConfig& config, const Provenance& provenance, bool resume,
                       std::ostream& notes)
    : final_path_(std::move(final_path)),
      partial_path_(partial_path_for(final_path_)),
      checkpoint_path_(checkpoint_path_for(final_path_)),
      config_(config),
      provenance_(provenance),
      notes_(notes),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(config.output.checkpoint_interval))) {
  if (!resume || !exists(checkpoint_path_)) return;
  Checkpoint checkpoint;
  try {
    checkpoint = read_checkpoint(checkpoint_path_);
  } catch (const IoError& e) {
    notes_ << "slidewave: cannot resume: " << e.what() << "; starting over\n";
    return;
  }
  const auto problems = checkpoint_mismatches(checkpoint, config);
  if (!problems.empty()) {
    std::string text = checkpoint_path_ + " was written for another run, so it cannot be resumed:\n";
    for (const auto& p : problems) text += "  " + p + "\n";
    text += "(run without --resume to start over, which removes it)";
    throw ResumeRefused(text);
  }
  const std::string inconsistency = inconsistent_counters(checkpoint, config);
  if (!inconsistency.empty()) {
    notes_ << "slidewave: cannot resume: " << checkpoint_path_ << " is damaged: " << inconsistency
           << "; starting over\n";
    return;
  }
  to_resume_ = std::move(checkpoint);
}

RunSession::~RunSession() = default;

void RunSession::setup_done() {
  last_checkpoint_ = std::chrono::steady_clock::now();
  if (to_resume_) resume_from(std::move(*to_resume_));
  to_resume_.reset();
  if (!writer_) start_over();
}

void RunSession::resume_from(Checkpoint checkpoint) {
  // The rows are copied into a new file that replaces the partial file only once they are verified:
  // a kill meanwhile leaves the partial file and the checkpoint as they were.
  writer_ = std::make_unique<RunWriter>(temporary_path_for(partial_path_, provenance_.run_id), config_, provenance_);
  try {
    writer_->copy_prefix(partial_path_, checkpoint.stream);
    writer_->move_to(partial_path_);
    start_ = std::move(checkpoint);
    resumed_ = true;
    checkpoint_written_ = true;  // the checkpoint on disk counts rows the new partial file holds
    notes_ << "slidewave: resuming from step " << start_.state.integers.at("counters").at(0) << " (" << checkpoint_path_
           << ")\n";
  } catch (const StreamMismatch& e) {
    writer_->discard();
    writer_.reset();
    notes_ << "slidewave: cannot resume: " << e.what() << "; starting over\n";
  } catch (...) {
    writer_->discard();  // the temporary copy; the partial file and the checkpoint stay as they were
    throw;
  }
}

void RunSession::start_over() {
  if (exists(checkpoint_path_) && std::remove(checkpoint_path_.c_str()) != 0)
    throw IoError("cannot remove the stale " + checkpoint_path_ + ": " + std::strerror(errno));
  writer_ = std::make_unique<RunWriter>(partial_path_, config_, provenance_);
}

void RunSession::write_checkpoint_now(RunRecord& record, const Capture& capture) {
  // The partial file first: the checkpoint must never count rows that are not on disk.
  writer_->flush_to_disk(record);
  Checkpoint checkpoint;
  checkpoint.config_json = config_.to_json().dump();
  checkpoint.build = current_build();
  checkpoint.stream = writer_->position();
  checkpoint.state = capture();
  checkpoint.run_id = provenance_.run_id;
  write_checkpoint(checkpoint_path_, checkpoint);
  checkpoint_written_ = true;
  last_checkpoint_ = std::chrono::steady_clock::now();
}

void RunSession::after_step(RunRecord& record, const Capture& capture) {
  if (config_.output.checkpoint_interval > 0 && std::chrono::steady_clock::now() - last_checkpoint_ >= interval_)
    write_checkpoint_now(record, capture);
  else
    writer_->drain_if_full(record);
}

void RunSession::at_end(RunRecord& record, const Capture& capture) {
  if (record.end_reason == "interrupted") {
    write_checkpoint_now(record, capture);
    writer_->finish(record);
    writer_->write_sidecars();  // so that ParaView shows what was computed
    return;
  }
  writer_->finish(record);
  writer_->put_in_place(final_path_);
  // RUN.h5 is in place: what served to resume goes (a leftover would only be refused or restarted),
  // with the sidecars an earlier interruption wrote for the partial file.
  std::remove(checkpoint_path_.c_str());
  std::remove(xdmf_path_for(partial_path_).c_str());
  std::remove(interface_xdmf_path_for(partial_path_).c_str());
}

std::string RunSession::abandon() noexcept {
  if (!writer_) return "";
  if (checkpoint_written_ && writer_->path() == partial_path_) {
    writer_->close();
    return partial_path_ + " and " + checkpoint_path_ + " are kept: rerun with --resume once the cause is fixed";
  }
  writer_->discard();  // the partial file, or the temporary copy of a resume
  return "";
}

}  // namespace slidewave
