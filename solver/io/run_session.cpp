#include "io/run_session.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/hdf5_support.hpp"
#include "io/xdmf.hpp"

namespace slidewave {

namespace {

namespace fs = std::filesystem;

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

/// Removes what killed runs into the same output may have left: "<name>.tmp.<pid>" of the run file,
/// the partial file and the checkpoint, and the staged sidecars "<RUN>.xdmf.tmp", "<RUN>.interface.xdmf.tmp".
void remove_stale_temporaries(const std::vector<std::string>& names) {
  for (const auto& name : names) {
    const fs::path path(name);
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const std::string prefix = path.filename().string() + ".tmp";
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      const std::string file = entry.path().filename().string();
      if (file == prefix || file.rfind(prefix + ".", 0) == 0) fs::remove(entry.path(), error);
    }
  }
}

}  // namespace

RunSession::RunSession(std::string final_path, const RunConfig& config, const Provenance& provenance, bool resume,
                       std::ostream& notes)
    : final_path_(std::move(final_path)),
      partial_path_(partial_path_for(final_path_)),
      checkpoint_path_(checkpoint_path_for(final_path_)),
      config_(config),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(config.output.checkpoint_interval))),
      last_checkpoint_(std::chrono::steady_clock::now()) {
  if (resume && exists(checkpoint_path_)) {
    Checkpoint checkpoint;
    bool readable = true;
    try {
      checkpoint = read_checkpoint(checkpoint_path_);
    } catch (const IoError& e) {
      notes << "slidewave: cannot resume: " << e.what() << "; starting over\n";
      readable = false;
    }
    if (readable) {
      const auto problems = checkpoint_mismatches(checkpoint, config);
      if (!problems.empty()) {
        std::string text = checkpoint_path_ + " was written for another run, so it cannot be resumed:\n";
        for (const auto& p : problems) text += "  " + p + "\n";
        text += "(run without --resume to start over, which removes it)";
        throw ResumeRefused(text);
      }
      remove_stale_temporaries({final_path_, partial_path_, checkpoint_path_, xdmf_path_for(final_path_),
                            interface_xdmf_path_for(final_path_)});
      // The rows are copied into a new file that replaces the partial file only once they are verified:
      // a kill meanwhile leaves the partial file and the checkpoint as they were.
      writer_ = std::make_unique<RunWriter>(partial_path_ + ".tmp." + std::to_string(::getpid()), config, provenance);
      try {
        writer_->copy_prefix(partial_path_, checkpoint.stream);
        writer_->move_to(partial_path_);
        start_ = std::move(checkpoint);
        resumed_ = true;
        checkpoint_written_ = true;  // the checkpoint on disk counts rows the new partial file holds
        const auto& counters = start_.state.integers.at("counters");
        notes << "slidewave: resuming from step " << counters.at(0) << " (" << checkpoint_path_ << ")\n";
      } catch (const StreamMismatch& e) {
        writer_->discard();
        writer_.reset();
        notes << "slidewave: cannot resume: " << e.what() << "; starting over\n";
      } catch (...) {
        writer_->discard();  // the temporary copy; the partial file and the checkpoint stay as they were
        throw;
      }
    }
  }
  if (!writer_) start_over(provenance);
}

RunSession::~RunSession() = default;

void RunSession::start_over(const Provenance& provenance) {
  remove_stale_temporaries({final_path_, partial_path_, checkpoint_path_, xdmf_path_for(final_path_),
                            interface_xdmf_path_for(final_path_)});
  if (exists(checkpoint_path_) && std::remove(checkpoint_path_.c_str()) != 0)
    throw IoError("cannot remove the stale " + checkpoint_path_ + ": " + std::strerror(errno));
  writer_ = std::make_unique<RunWriter>(partial_path_, config_, provenance);
}

void RunSession::write_checkpoint_now(RunRecord& record, const Capture& capture) {
  // The partial file first: the checkpoint must never count rows that are not on disk.
  writer_->flush_to_disk(record);
  Checkpoint checkpoint;
  checkpoint.config_json = config_.to_json().dump();
  checkpoint.build = current_build();
  checkpoint.stream = writer_->position();
  checkpoint.state = capture();
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
  writer_->discard();
  std::remove((partial_path_ + ".tmp." + std::to_string(::getpid())).c_str());
  return "";
}

}  // namespace slidewave
