#include "model/stick_phase/row_transform.hpp"

#include <fftw3.h>

#include <algorithm>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace slidewave {
namespace {

/// The FFTW planner is not thread-safe (FFTW manual, sec. 5.2).
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

struct RowTransform::Plans {
  fftw_plan forward = nullptr, inverse = nullptr;
  std::vector<double> re, im, data;  ///< scratch spectrum of one mesh row (2 rows x lanes), real row
  ~Plans() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (inverse) fftw_destroy_plan(inverse);
  }
};

RowTransform::RowTransform(int n_x) : n_x_(n_x), plans_(std::make_unique<Plans>()) {
  if (n_x < 3) throw std::invalid_argument("RowTransform: n_x must be >= 3");
  const int lanes = this->lanes();
  plans_->re.assign(2 * static_cast<std::size_t>(lanes), 0.0);
  plans_->im.assign(plans_->re.size(), 0.0);
  plans_->data.assign(2 * static_cast<std::size_t>(n_x), 0.0);
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_NO_SIMD;
  std::lock_guard<std::mutex> lock(planner_mutex());
  const fftw_iodim forward_dim{n_x, 2, 1}, forward_loop{2, 1, lanes};  // along i (stride 2); d = 0, 1
  const fftw_iodim inverse_dim{n_x, 1, 2}, inverse_loop{2, lanes, 1};
  plans_->forward = fftw_plan_guru_split_dft_r2c(1, &forward_dim, 1, &forward_loop, plans_->data.data(),
                                                 plans_->re.data(), plans_->im.data(), flags);
  plans_->inverse = fftw_plan_guru_split_dft_c2r(1, &inverse_dim, 1, &inverse_loop, plans_->re.data(),
                                                 plans_->im.data(), plans_->data.data(), flags);
  if (!plans_->forward || !plans_->inverse) throw std::runtime_error("RowTransform: FFTW planning failed");
}

RowTransform::~RowTransform() = default;

void RowTransform::forward(const double* x, LaneVectors& X) const {
  const int lanes = this->lanes();
  for (int j = 0; j < X.rows / 2; ++j) {
    // r2c does not write its input (FFTW's default for out-of-place real-to-complex transforms).
    fftw_execute_split_dft_r2c(plans_->forward, const_cast<double*>(x) + 2 * static_cast<std::size_t>(j) * n_x_,
                               plans_->re.data(), plans_->im.data());
    std::copy_n(plans_->re.data(), lanes, X.re.data() + X.at(2 * j, 0));
    std::copy_n(plans_->im.data(), lanes, X.im.data() + X.at(2 * j, 0));
    for (int m = 0; m < lanes; ++m) {  // u_y: -i (a + i b) = b - i a
      X.re[X.at(2 * j + 1, m)] = plans_->im[lanes + m];
      X.im[X.at(2 * j + 1, m)] = -plans_->re[lanes + m];
    }
  }
}

void RowTransform::inverse(const LaneVectors& X, int n_mesh_rows, double* x, const LaneVectors* beyond) const {
  const int lanes = this->lanes();
  if (X.lanes > lanes || (X.lanes < lanes && beyond && beyond->lanes != lanes))
    throw std::invalid_argument("RowTransform::inverse: lanes do not match the transform");
  const double scale = 1.0 / n_x_;
  const auto value = [&](int r, int m) {
    return m < X.lanes ? X.get(r, m) : beyond ? beyond->get(r, m) : std::complex<double>(0.0, 0.0);
  };
  for (int j = 0; j < n_mesh_rows; ++j) {
    // c2r destroys its input: the scratch copy, u_y turned back (i (a + i b) = -b + i a).
    for (int m = 0; m < lanes; ++m) {
      const std::complex<double> u_x = value(2 * j, m), u_y = value(2 * j + 1, m);
      plans_->re[m] = u_x.real();
      plans_->im[m] = u_x.imag();
      plans_->re[lanes + m] = -u_y.imag();
      plans_->im[lanes + m] = u_y.real();
    }
    double* row = x + 2 * static_cast<std::size_t>(j) * n_x_;
    fftw_execute_split_dft_c2r(plans_->inverse, plans_->re.data(), plans_->im.data(), row);
    for (int k = 0; k < 2 * n_x_; ++k) row[k] *= scale;
  }
}

}  // namespace slidewave
