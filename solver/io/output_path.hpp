#pragma once
// The files a run writes, named from `-o RUN.h5`, and the check made before the run starts that it
// can write them without destroying anything: a whole run must never end in "cannot write" or
// overwrite its own input.
#include <stdexcept>
#include <string>
#include <vector>

namespace slidewave {

/// The output cannot or must not be written; the message names the path and the reason.
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where an interrupted run keeps what it computed, beside RUN.h5 which it never touches:
/// RUN.h5 -> RUN.partial.h5 (a name without the .h5 extension gets .partial.h5 appended).
std::string partial_path_for(const std::string& h5_path);

/// Every file a run into `h5_path` writes, replaces or removes (besides its temporaries, which carry
/// the run id: io/run_id.hpp): RUN.h5 and its XDMF sidecars, RUN.partial.h5 and its sidecars,
/// RUN.checkpoint.h5 and the lock file RUN.h5.lock.
std::vector<std::string> run_paths(const std::string& h5_path);

/// Removes the temporaries "<run path>.tmp.<run_id>" that the run `run_id` (read from the lock file
/// it held) may have left when it was killed; nothing when `run_id` is not a run id.
void remove_temporaries_of(const std::string& h5_path, const std::string& run_id);

/// Throws OutputPathError when
///  - `h5_path` names an XDMF file (ends in .xdmf: the sidecars of X.h5 are X.xdmf and X.interface.xdmf
///    and would replace it) or a folder;
///  - one of run_paths() is one of `inputs` (same file, by device and inode), or two of them are the
///    same file;
///  - its folder does not exist, is not a folder, or no file can be created in it (the operating
///    system's reason, tried with a probe file that is removed at once: as root, permission bits say
///    nothing, a read-only or special filesystem does).
void check_output_path(const std::string& h5_path, const std::vector<std::string>& inputs);

}  // namespace slidewave
