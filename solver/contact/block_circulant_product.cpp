#include "contact/block_circulant_product.hpp"

#include <fftw3.h>

#include <stdexcept>
#include <string>

#include "linalg/fftw_planner.hpp"

namespace slidewave {

// The work arrays and the plans made on them: in (2n, the two components interleaved as the contact
// vectors are), the split spectrum re/im (component a at a * (n/2 + 1)), out (2n, interleaved).
struct BlockCirculantProduct::Plans {
  explicit Plans(int n)
      : in(2 * static_cast<std::size_t>(n)),
        out(in.size()),
        re(2 * static_cast<std::size_t>(n / 2 + 1)),
        im(re.size()) {
    const int h = n / 2 + 1;
    const fftw_iodim forward_dim{n, 2, 1}, forward_loop{2, 1, h};
    const fftw_iodim inverse_dim{n, 1, 2}, inverse_loop{2, h, 1};
    // ESTIMATE and NO_SIMD: the plan is a function of n alone (linalg/block_circulant_solver.cpp).
    const unsigned flags = FFTW_ESTIMATE | FFTW_NO_SIMD;
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward = fftw_plan_guru_split_dft_r2c(1, &forward_dim, 1, &forward_loop, in.data(), re.data(), im.data(), flags);
    inverse = fftw_plan_guru_split_dft_c2r(1, &inverse_dim, 1, &inverse_loop, re.data(), im.data(), out.data(), flags);
    if (!forward || !inverse) throw std::runtime_error("BlockCirculantProduct: FFTW planning failed");
  }
  ~Plans() {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(inverse);
  }
  std::vector<double> in, out, re, im;
  fftw_plan forward = nullptr, inverse = nullptr;
};

BlockCirculantProduct::BlockCirculantProduct(const Eigen::MatrixXd& first_columns)
    : n_(static_cast<int>(first_columns.rows() / 2)), plans_(std::make_unique<Plans>(n_)) {
  if (first_columns.cols() != 2 || first_columns.rows() != 2 * n_ || n_ < 1)
    throw std::invalid_argument("BlockCirculantProduct: the first columns must be 2n x 2 with n >= 1");
  const int h = n_ / 2 + 1;
  spectrum_.assign(h, Eigen::Matrix2cd::Zero());
  for (int b = 0; b < 2; ++b) {  // G(:, b)(m) = DFT of column b, component a
    std::copy(first_columns.col(b).data(), first_columns.col(b).data() + 2 * n_, plans_->in.begin());
    fftw_execute(plans_->forward);
    for (int m = 0; m < h; ++m)
      for (int a = 0; a < 2; ++a) spectrum_[m](a, b) = {plans_->re[a * h + m], plans_->im[a * h + m]};
  }
}

BlockCirculantProduct::BlockCirculantProduct(int n_nodes, std::vector<Eigen::Matrix2cd> spectrum)
    : n_(n_nodes), spectrum_(std::move(spectrum)), plans_(std::make_unique<Plans>(n_nodes)) {}

BlockCirculantProduct::~BlockCirculantProduct() = default;
BlockCirculantProduct::BlockCirculantProduct(BlockCirculantProduct&&) noexcept = default;
BlockCirculantProduct& BlockCirculantProduct::operator=(BlockCirculantProduct&&) noexcept = default;

BlockCirculantProduct BlockCirculantProduct::inverse() const {
  std::vector<Eigen::Matrix2cd> inverted(spectrum_.size());
  for (std::size_t m = 0; m < spectrum_.size(); ++m) {
    const Eigen::Matrix2cd& G = spectrum_[m];
    // Hermitian positive definite 2 x 2: positive diagonal and determinant.
    const double det = (G(0, 0) * G(1, 1) - G(0, 1) * G(1, 0)).real();
    if (!(G(0, 0).real() > 0 && det > 0))
      throw std::invalid_argument("BlockCirculantProduct: the operator is not positive definite at wavenumber " +
                                  std::to_string(m));
    inverted[m] << G(1, 1) / det, -G(0, 1) / det, -G(1, 0) / det, G(0, 0) / det;
  }
  return BlockCirculantProduct(n_, std::move(inverted));
}

const double* BlockCirculantProduct::transform(const double* r) const {
  const int h = n_ / 2 + 1;
  std::copy(r, r + 2 * n_, plans_->in.begin());
  fftw_execute(plans_->forward);
  double *re = plans_->re.data(), *im = plans_->im.data();
  const double scale = 1.0 / n_;  // FFTW's c2r is unnormalized
  for (int m = 0; m < h; ++m) {
    const Eigen::Vector2cd R(std::complex<double>(re[m], im[m]), std::complex<double>(re[h + m], im[h + m]));
    const Eigen::Vector2cd Y = spectrum_[m] * R * scale;
    re[m] = Y(0).real(), im[m] = Y(0).imag();
    re[h + m] = Y(1).real(), im[h + m] = Y(1).imag();
  }
  fftw_execute(plans_->inverse);
  return plans_->out.data();
}

void BlockCirculantProduct::apply(const Eigen::VectorXd& r, Eigen::VectorXd& y) const {
  y = Eigen::Map<const Eigen::VectorXd>(transform(r.data()), 2 * n_);
}

void BlockCirculantProduct::residual(const Eigen::VectorXd& q, const Eigen::VectorXd& r, Eigen::VectorXd& y) const {
  y = q + Eigen::Map<const Eigen::VectorXd>(transform(r.data()), 2 * n_);
}

}  // namespace slidewave
