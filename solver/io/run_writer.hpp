#pragma once
// Streams run.h5 (docs/contracts.md section 2) while the run goes: the /interface and /global series
// are chunked datasets extended by rows, snapshots are written as they come, the outcome attributes
// are rewritten at every checkpoint and at the end. The RunRecord the loop appends to is only a
// buffer: drain() moves its rows to the file, so memory stays flat with run length.
//
// Every dataset carries a Fletcher32 checksum (HDF5 reports a corrupted chunk on read). The streamed
// series are not compressed, on purpose: an uncompressed chunk keeps its size and its place in the
// file when a partial chunk is completed later, so after a kill the rows a checkpoint counted are
// still where the file's last flushed index says (a compressed chunk would move to newly allocated
// space). The write-once snapshot arrays are compressed (shuffle + deflate).
//
// A writer writes one working file (for a run: RUN.partial.h5); put_in_place() renames it to its
// final name with the XDMF sidecars, only for a result (complete or contact failure).
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "config/run_config.hpp"
#include "io/output_path.hpp"  // partial_path_for
#include "io/run_attributes.hpp"
#include "io/run_layout.hpp"
#include "model/run_record.hpp"

namespace slidewave {

/// How far the stream is: rows written per series and a digest of each dataset's bytes (FNV-1a over
/// its elements), so that --resume can prove that a partial file still holds what a checkpoint counted.
struct StreamPosition {
  std::int64_t n_global_rows = 0;
  std::int64_t n_interface_rows = 0;
  std::int64_t n_snapshots = 0;
  std::map<std::string, std::uint64_t> digests;  ///< dataset path -> digest of its elements
  bool operator==(const StreamPosition& o) const {
    return n_global_rows == o.n_global_rows && n_interface_rows == o.n_interface_rows && n_snapshots == o.n_snapshots &&
           digests == o.digests;
  }
};

/// The partial file no longer holds the rows a checkpoint counted (killed mid-write, edited, replaced).
class StreamMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RunWriter {
 public:
  /// Creates (or replaces) `working_path` with the header attributes and the outcome "interrupted",
  /// complete = 0, until finish() says otherwise. Throws IoError naming the file and the reason.
  RunWriter(std::string working_path, const RunConfig& config, const Provenance& provenance);
  ~RunWriter();  ///< closes the file if still open (no rename, no removal)
  RunWriter(const RunWriter&) = delete;
  RunWriter& operator=(const RunWriter&) = delete;

  /// Appends the rows and snapshots the record holds and removes them from it (interface x, the
  /// snapshot mesh and the outcome fields stay). The record is then empty, ready for more rows.
  void drain(RunRecord& record);
  /// drain() when the record holds about a chunk of rows or a snapshot: cheap to call every step.
  void drain_if_full(RunRecord& record) {
    if (record.global.t.size() >= kGlobalBlockRows || record.interface.t.size() >= interface_block_rows_ ||
        !record.snapshots.empty())
      drain(record);
  }
  /// drain(), flush and fsync: what position() then counts is on disk. The outcome attributes then say
  /// what a kill would leave: complete = 0, end_reason interrupted, the record's n_steps_done.
  void flush_to_disk(RunRecord& record);
  /// drain(), the outcome attributes, close. Throws IoError (the file stays; see discard()).
  void finish(RunRecord& record);

  /// Renames the closed working file to `final_path` (atomic); the XDMF sidecars (io/xdmf.hpp) are
  /// staged before and renamed after it, so that they never point at a missing file. First checks that
  /// the working file is this writer's own (its run_id), readable and holding every row written: a
  /// file another run replaced or truncated under the same name never goes into place (IoError).
  void put_in_place(const std::string& final_path);
  /// Writes the XDMF sidecars of the closed working file beside it (an interrupted run's partial file).
  void write_sidecars();
  /// Renames the working file (open or not) to `new_path`, which it then writes.
  void move_to(const std::string& new_path);
  /// Closes (if open) and removes the working file: nothing of value is in it.
  void discard() noexcept;
  /// Closes the working file if open, without writing the outcome (after an error: the file stays).
  void close() noexcept;

  /// Copies the first rows counted by `position` from an earlier partial file (same layout) into this
  /// one and checks their digests: throws StreamMismatch when that file no longer holds them intact.
  void copy_prefix(const std::string& earlier_path, const StreamPosition& position);

  const StreamPosition& position() const { return position_; }
  const std::string& path() const { return path_; }

  static constexpr std::size_t kGlobalBlockRows = 1024;

 private:
  struct Series;
  void ensure_layout(const RunRecord& record);
  void check_own_file() const;
  /// substrate: the same snapshot of the substrate (null on a rigid flat), on substrate_mesh.
  void write_snapshot(const Snapshot& snapshot, const SnapshotMesh& mesh, const Snapshot* substrate,
                      const SnapshotMesh& substrate_mesh);

  std::string path_;
  std::string run_id_;  ///< Provenance::run_id: written as the root attribute run_id, names the staged sidecars
  struct Files;
  std::unique_ptr<Files> files_;
  std::map<std::string, std::unique_ptr<Series>> series_;  ///< by dataset path
  StreamPosition position_;
  std::size_t interface_block_rows_ = 256;
  RunRecord outline_;  ///< what the XDMF sidecars need: x, snapshot mesh and times, output times (at the end)
  int n_contact_ = 0;
  /// The /global series of this run: run_layout::kGlobalColumns, plus kHhtColumns when
  /// output.energy_decomposition asks for them.
  std::vector<const run_layout::GlobalColumn*> global_columns_;
};

}  // namespace slidewave
