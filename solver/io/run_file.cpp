#include "io/run_file.hpp"

#include "io/run_id.hpp"
#include "io/run_writer.hpp"

namespace slidewave {

void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& rec,
                    const Provenance& provenance) {
  RunWriter writer(temporary_path_for(path, provenance.run_id), config, provenance);
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
