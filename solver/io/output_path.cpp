#include "io/output_path.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "io/checkpoint.hpp"
#include "io/output_lock.hpp"
#include "io/run_id.hpp"
#include "io/xdmf.hpp"

namespace slidewave {
namespace {

bool ends_with_ignoring_case(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(),
                    [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {};
  struct stat sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

std::string partial_path_for(const std::string& h5_path) {
  const bool has_h5 = ends_with_ignoring_case(h5_path, ".h5");
  return (has_h5 ? h5_path.substr(0, h5_path.size() - 3) : h5_path) + ".partial.h5";
}

std::vector<std::string> run_paths(const std::string& h5_path) {
  const std::string partial = partial_path_for(h5_path);
  return {h5_path,
          xdmf_path_for(h5_path),
          interface_xdmf_path_for(h5_path),
          partial,
          xdmf_path_for(partial),
          interface_xdmf_path_for(partial),
          checkpoint_path_for(h5_path),
          lock_path_for(h5_path)};
}

void remove_temporaries_of(const std::string& h5_path, const std::string& run_id) {
  if (!is_run_id(run_id)) return;
  for (const auto& path : run_paths(h5_path)) ::unlink(temporary_path_for(path, run_id).c_str());
}

void check_output_path(const std::string& h5_path, const std::vector<std::string>& inputs) {
  const std::string head = "output " + h5_path + ": ";
  if (h5_path.empty() || h5_path.back() == '/') throw OutputPathError(head + "not a file name");
  if (ends_with_ignoring_case(h5_path, ".xdmf"))
    throw OutputPathError(
        head +
        "names an XDMF file: the XDMF sidecars of the run (written next to the HDF5 "
        "file, X.h5 -> X.xdmf, X.interface.xdmf) would replace it; give the HDF5 name, e.g. -o run.h5");

  const auto written = run_paths(h5_path);
  for (std::size_t i = 0; i < written.size(); ++i) {
    for (const auto& input : inputs)
      if (same_file(written[i], input))
        throw OutputPathError(head + "the run would write or remove " + written[i] + ", which is the input file " +
                              input);
    for (std::size_t k = 0; k < i; ++k)
      if (written[k] == written[i] || same_file(written[k], written[i]))
        throw OutputPathError(head + "the run would write both " + written[k] + " and " + written[i] +
                              ", which are the same file");
  }

  struct stat info {};
  if (::stat(h5_path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) throw OutputPathError(head + "is a folder");

  const std::string folder = folder_of(h5_path);
  if (::stat(folder.c_str(), &info) != 0)
    throw OutputPathError(head + "folder " + folder + ": " + std::strerror(errno));
  if (!S_ISDIR(info.st_mode)) throw OutputPathError(head + folder + ": " + std::strerror(ENOTDIR));
  const std::string probe = h5_path + ".probe." + std::to_string(::getpid());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) throw OutputPathError(head + "cannot create a file in folder " + folder + ": " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace slidewave
