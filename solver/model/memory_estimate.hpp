#pragma once
// The memory a run needs, from the sizes of what it allocates, so that a mesh that cannot fit is refused
// before its setup (`slidewave run`, exit 2) instead of growing for minutes into std::bad_alloc or the
// OOM killer. With n = 2 n_x (n_y + 1) DOFs and n_c = 2 n_x contact DOFs:
//   per DOF  1240 B: the sparse matrices (18 nonzeros a row: a node couples with 9 nodes x 2 DOFs; 12 B
//            a nonzero, value and index: 216 B a row per matrix; K and M over all DOFs, K_ff, M_ff, its
//            row-major copy and K_eff over the free ones) and some 20 vectors of doubles. Counting them
//            all gives 6 x 216 + 20 x 8 = 1456 B, an upper bound; 1240 B is the measured peak (not all
//            live at once).
//   dense    the Delassus operator W, n_c x n_c doubles, twice: W and its symmetrized copy while it is
//            built (contact/delassus.hpp), W and its LDLT in the preload, W and its LLT with
//            contact.all_stick = exact. This is the term that grows with the square of the period.
//   output   a snapshot held until written (displacement and velocity, 16 B a DOF) and 1 MiB of row buffers.
//   base     24 MiB: the binary, its libraries and HDF5 (the peak of an H/16 run).
// Calibrated against the peak RSS (/usr/bin/time -v, circulant solver, 5 s runs): H/16, 32, 64, 128 at
// lambda 2H and H/64, 128, 256 at lambda 6H measured 0.90 to 0.97 of the estimate (H/256, lambda 6H:
// 987 MiB measured, 1102 MiB estimated). Not included: CHOLMOD's factor (numerics.linear_solver =
// cholmod, the oracle path, meant for small meshes).
#include <string>

#include "config/run_config.hpp"

namespace slidewave {

struct MemoryEstimate {
  double per_dof, dense, output, base;  ///< bytes
  double total() const { return per_dof + dense + output + base; }
  /// "2.4 GiB (sparse matrices and vectors 1.1 GiB, dense Delassus operator W 1.2 GiB, ...)".
  std::string describe() const;
};

/// The estimate for a valid configuration (sizes from RunConfig::derived()).
MemoryEstimate estimate_memory(const RunConfig& config);

/// "1.5 GiB", "312 MiB".
std::string bytes_text(double bytes);

}  // namespace slidewave
