#include "io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "config/strict_json.hpp"
#include "io/hdf5_support.hpp"

namespace slidewave {
namespace {

/// The whole content of the open file (the holder line), cut to a readable length.
std::string read_all(int fd) {
  std::string text;
  char buffer[4096];
  ssize_t n;
  off_t offset = 0;
  while ((n = ::pread(fd, buffer, sizeof buffer, offset)) > 0 && text.size() < 65536) {
    text.append(buffer, static_cast<std::size_t>(n));
    offset += n;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\0')) text.pop_back();
  return text;
}

}  // namespace

std::string lock_path_for(const std::string& h5_path) { return h5_path + ".lock"; }

OutputLock::OutputLock(const std::string& h5_path, const std::string& run_id, const std::string& description)
    : path_(lock_path_for(h5_path)) {
  // The holder removes the file when it ends: a lock taken on a file just removed (opened before the
  // removal) is no lock, so the path must still name the locked file; else try again.
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw IoError("cannot open the lock file " + path_ + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string other = read_all(fd_);
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        throw OutputLocked("output " + h5_path + " is being written by another run (it holds the lock " + path_ +
                           "): " + (other.empty() ? "a run starting now" : excerpt(other, 300)) +
                           "; wait for it to end, or write elsewhere");
      throw IoError("cannot lock " + path_ + ": " + std::strerror(error));
    }
    struct stat locked {};
    struct stat named {};
    if (::fstat(fd_, &locked) == 0 && ::stat(path_.c_str(), &named) == 0 && locked.st_dev == named.st_dev &&
        locked.st_ino == named.st_ino)
      break;
    ::close(fd_);
  }
  const std::string previous = read_all(fd_);
  if (previous.rfind("run ", 0) == 0) previous_run_id_ = previous.substr(4, previous.find(' ', 4) - 4);
  char host[256] = "unknown host";
  ::gethostname(host, sizeof host - 1);
  char since[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(since, sizeof since, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  const std::string line = "run " + run_id + " pid " + std::to_string(::getpid()) + " on " + host + " since " + since +
                           ": " + description + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, line.data(), line.size(), 0) != static_cast<ssize_t>(line.size())) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    throw IoError("cannot write the lock file " + path_ + ": " + reason);
  }
}

OutputLock::~OutputLock() {
  ::unlink(path_.c_str());  // while still holding it (see the constructor)
  ::close(fd_);
}

}  // namespace slidewave
