// Products with a 2 x 2 block-circulant operator by FFT (contact/block_circulant_product.hpp) against the
// dense Eigen products: A r and q + A r on random block-circulant A, A^{-1} r on symmetric positive definite
// ones (the structure of the Delassus operator of a periodic layer), all to round-off, for node counts
// that are odd, even, prime and large; an indefinite operator is refused.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <stdexcept>

#include "contact/block_circulant_product.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

using testing::random_block_circulant;
using testing::random_vector;

const int kNodeCounts[] = {1, 2, 3, 5, 31, 64, 97, 128, 384, 1001};

// An FFT product's rounding error grows like log2(n) eps of the product's scale (FFTW's algorithms are
// stable), spread over all entries: 64 eps of |A| |r| plus 1e-3 of its largest entry bounds it for the n
// here, and a wrong index or a missing 1/n breaks it by orders of magnitude.
Eigen::VectorXd error_bound(const Eigen::MatrixXd& A, const Eigen::VectorXd& r) {
  const Eigen::VectorXd magnitude = A.cwiseAbs() * r.cwiseAbs();
  return 64 * 2.2e-16 * (magnitude.array() + 1e-3 * magnitude.maxCoeff()).matrix();
}

TEST(BlockCirculantProduct, EqualsTheDenseProductToRoundOff) {
  std::mt19937_64 generator(20261127);
  for (int n : kNodeCounts) {
    const Eigen::MatrixXd A = random_block_circulant(n, generator);
    const BlockCirculantProduct product(A.leftCols<2>());
    const Eigen::VectorXd q = random_vector(2 * n, generator), r = random_vector(2 * n, generator);
    Eigen::VectorXd y, z;
    product.apply(r, y);
    product.residual(q, r, z);
    const Eigen::VectorXd bound = error_bound(A, r);
    EXPECT_TRUE(((y - A * r).cwiseAbs().array() <= bound.array()).all())
        << "n = " << n << ", max difference " << (y - A * r).cwiseAbs().maxCoeff();
    EXPECT_TRUE(((z - q - A * r).cwiseAbs().array() <= bound.array() + 2.2e-16).all()) << "n = " << n;
  }
}

TEST(BlockCirculantProduct, InverseSolvesTheDenseSystemToRoundOff) {
  std::mt19937_64 generator(11);
  for (int n : kNodeCounts) {
    // B B^T of a block-circulant B is block-circulant and SPD; the shift keeps its condition moderate.
    const Eigen::MatrixXd B = random_block_circulant(n, generator);
    const Eigen::MatrixXd A = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(2 * n, 2 * n);
    const BlockCirculantProduct inverse = BlockCirculantProduct(A.leftCols<2>()).inverse();
    const Eigen::VectorXd r = random_vector(2 * n, generator);
    Eigen::VectorXd x;
    inverse.apply(r, x);
    // Backward stable: x solves A x = r up to a residual of a few eps |A| |x| (the dense LLT's own standard).
    const Eigen::VectorXd residual = A * x - r;
    const Eigen::VectorXd bound = 64 * 2.2e-16 * (A.cwiseAbs() * x.cwiseAbs() + r.cwiseAbs());
    EXPECT_TRUE((residual.cwiseAbs().array() <= bound.array()).all())
        << "n = " << n << ", max residual " << residual.cwiseAbs().maxCoeff();
  }
}

TEST(BlockCirculantProduct, InverseRefusesAnIndefiniteOperator) {
  const int n = 8;
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  for (int i = 0; i < n; ++i) A(2 * i + 1, 2 * i + 1) = -1;  // negative at every wavenumber
  EXPECT_THROW(BlockCirculantProduct(A.leftCols<2>()).inverse(), std::invalid_argument);
}

}  // namespace
}  // namespace slidewave
