#pragma once
// The exclusive claim of one run on its output: flock(2) on RUN.h5.lock, taken before any file of the
// run is created, truncated or removed. A second run into the same output (from this checkout or from
// another one sharing the folder: Snakemake's lock is per work directory) is refused while the first
// holds it, with the description the holder wrote into the lock file.
//
// The kernel releases an flock when its descriptor closes, also when the process is killed (kill -9),
// so a lock never outlives its run. A run that ends (any exit code) removes the lock file while still
// holding it; after kill -9 the file stays, unlocked, blocking nothing, and tells the next run which
// run id the killed run's temporaries carry. flock is not reliable on every network filesystem (NFS
// before Linux 2.6.12): the final check of RunWriter::put_in_place (the file is the run's own) stays.
#include <stdexcept>
#include <string>

namespace slidewave {

/// Another run holds the output; what() names the lock file and that run. The CLI exits 2.
class OutputLocked : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// RUN.h5 -> RUN.h5.lock.
std::string lock_path_for(const std::string& h5_path);

class OutputLock {
 public:
  /// Locks `h5_path` (RUN.h5.lock, created if absent) without waiting, then records in the lock file
  /// who holds it: "run <run_id> pid <pid> on <host> since <UTC>: <description>".
  /// Throws OutputLocked when another process holds it, IoError (io/hdf5_support.hpp) when the lock
  /// file cannot be opened or locked.
  OutputLock(const std::string& h5_path, const std::string& run_id, const std::string& description);
  ~OutputLock();  ///< removes the lock file and releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// The run id the previous holder recorded ("" for a new lock file), read before this run replaced
  /// it: what that run may have left is named after it (io/output_path.hpp remove_temporaries_of).
  const std::string& previous_run_id() const { return previous_run_id_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::string previous_run_id_;
};

}  // namespace slidewave
