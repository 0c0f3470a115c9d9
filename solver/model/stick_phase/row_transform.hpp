#pragma once
// The DFT along x of the layer's free-DOF vectors (DOF 2 (j n_x + i) + d, mesh rows j of two rows
// r = 2 j + d): X_m(r) = sum_i x_i(r) e^{-i theta_m i}, theta_m = 2 pi m / n_x, m = 0..n_x/2 (the lanes of
// model/stick_phase/banded_lanes.hpp; X_{n_x-m} = conj X_m), and its inverse
// x_i(r) = (1/n_x) sum_{m=0}^{n_x-1} X_m(r) e^{i theta_m i}. The convention of
// linalg/block_circulant_solver.hpp, with FFTW plans made the same way (ESTIMATE, NO_SIMD: a function of
// the sizes alone), one plan per direction for one mesh row, executed row by row through a scratch
// spectrum (FFTW's split new-array execution wants the plan's own real/imaginary offset).
// The spectra are given in the basis of model/stick_phase/wavenumber_blocks.hpp: the u_y rows (odd r)
// multiplied by -i after the forward transform, by i before the inverse.
#include <memory>

#include "model/stick_phase/banded_lanes.hpp"

namespace slidewave {

class RowTransform {
 public:
  /// @param n_x elements along x (>= 3); lanes = n_x / 2 + 1
  explicit RowTransform(int n_x);
  ~RowTransform();
  RowTransform(const RowTransform&) = delete;
  RowTransform& operator=(const RowTransform&) = delete;

  int lanes() const { return n_x_ / 2 + 1; }
  /// X = DFT of x, mesh rows [0, n_rows / 2) (x holds n_rows n_x values).
  void forward(const double* x, LaneVectors& X) const;
  /// x = inverse DFT of rows [0, 2 n_mesh_rows) of X (x gets 2 n_mesh_rows n_x values). X may hold fewer
  /// lanes than lanes() (a narrowed array of the stick phase): the others are then read from `beyond`
  /// (every lane), or are zero if it is null.
  void inverse(const LaneVectors& X, int n_mesh_rows, double* x, const LaneVectors* beyond = nullptr) const;

 private:
  int n_x_;
  struct Plans;
  std::unique_ptr<Plans> plans_;
};

}  // namespace slidewave
