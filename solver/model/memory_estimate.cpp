#include "model/memory_estimate.hpp"

#include <cstdio>

namespace slidewave {

std::string bytes_text(double bytes) {
  char text[32];
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(text, sizeof text, "%.0f MiB", bytes / (1024.0 * 1024));
  return text;
}

std::string MemoryEstimate::describe() const {
  return bytes_text(total()) + " (sparse matrices and vectors " + bytes_text(per_dof) +
         ", dense Delassus operator W and its factor " + bytes_text(dense) + ", output buffers " + bytes_text(output) +
         ", program " + bytes_text(base) + ")";
}

MemoryEstimate estimate_memory(const RunConfig& config) {
  const DerivedConstants d = config.derived();
  // In doubles: the products overflow no integer type, whatever the mesh.
  const double n_dofs = 2.0 * d.n_x * (d.n_y + 1.0), n_c = 2.0 * d.n_x;
  // A substrate (docs/substrate.md) is a second body of n_y,s rows, and a second W during the setup.
  const double n_dofs_substrate = config.substrate.present() ? 2.0 * d.n_x * (substrate_rows(config) + 1.0) : 0.0;
  MemoryEstimate e{};
  e.per_dof = 1240.0 * (n_dofs + n_dofs_substrate);
  e.dense = (config.substrate.present() ? 3 : 2) * 8.0 * n_c * n_c;
  e.output = 16.0 * n_dofs + 1024.0 * 1024;
  e.base = 24.0 * 1024 * 1024;
  return e;
}

}  // namespace slidewave
