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

/// Throws OutputPathError when
///  - `h5_path` names an XDMF file (ends in .xdmf: the sidecars of X.h5 are X.xdmf and X.interface.xdmf
///    and would replace it) or a folder;
///  - it, its sidecars or their .partial variants are one of `inputs` (same file, by device and inode);
///  - its folder does not exist, is not a folder, or no file can be created in it (the operating
///    system's reason, tried with a probe file that is removed at once: as root, permission bits say
///    nothing, a read-only or special filesystem does).
void check_output_path(const std::string& h5_path, const std::vector<std::string>& inputs);

}  // namespace slidewave
