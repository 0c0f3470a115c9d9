#include "io/run_file.hpp"

#include <unistd.h>


#include "io/run_writer.hpp"

namespace slidewave {

void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& rec,
                    const Provenance& provenance) {
  RunWriter writer(path + ".tmp." + std::to_string(::getpid()), config, provenance);
  try {
    RunRecord rows = rec;  // drained by the writer
    writer.finish(rows);
    writer.put_in_place(path);
  } catch (...) {
    writer.discard();
    throw;
  }
}

}  // namespace slidewave
