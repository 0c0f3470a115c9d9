// Products with a block-circulant W read from its generating columns (contact/delassus.hpp:
// add_periodic_node_columns, periodic_residual) against the dense Eigen expressions: the node update bit
// for bit, the residual to round-off (its own summation order), on random block-circulant W of sizes that
// cover a partial column block and odd tails of the vector loops.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstring>
#include <random>

#include "contact/delassus.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// Random block-circulant W of n nodes (2n x 2n), the structure delassus_operator_periodic builds
/// (the kernels do not rely on its symmetry).
Eigen::MatrixXd random_block_circulant(int n, std::mt19937_64& generator) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd z0(2 * n), z1(2 * n);
  for (int i = 0; i < 2 * n; ++i) z0(i) = uniform(generator), z1(i) = uniform(generator);
  Eigen::MatrixXd W(2 * n, 2 * n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      for (int a = 0; a < 2; ++a) {
        const int s = 2 * (((i - k) % n + n) % n) + a;
        W(2 * i + a, 2 * k) = z0(s);
        W(2 * i + a, 2 * k + 1) = z1(s);
      }
  return W;
}

using testing::random_vector;

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

const int kNodeCounts[] = {1, 2, 3, 5, 31, 63, 64, 65, 97, 384, 1001, 2001};

TEST(PeriodicColumns, ResidualEqualsTheDenseProductToRoundOff) {
  std::mt19937_64 generator(20261124);
  for (int n : kNodeCounts) {
    const Eigen::MatrixXd W = random_block_circulant(n, generator);
    const Eigen::MatrixXd columns = delassus_periodic_columns(W);
    const Eigen::VectorXd q = random_vector(2 * n, generator), r = random_vector(2 * n, generator);
    const Eigen::VectorXd expected = q + W * r;
    // Each entry sums 2n products of numbers in [-1, 1]: its rounding error is below 2n eps of |W| |r|.
    const Eigen::VectorXd bound = 4 * n * 1.2e-16 * (q.cwiseAbs() + W.cwiseAbs() * r.cwiseAbs());
    Eigen::VectorXd y;
    periodic_residual(columns, n, q, r, y);
    EXPECT_TRUE(((y - expected).cwiseAbs().array() <= bound.array()).all())
        << "n = " << n << ", max difference " << (y - expected).cwiseAbs().maxCoeff();
  }
}

TEST(PeriodicColumns, NodeUpdateEqualsEigenBitForBit) {
  std::mt19937_64 generator(7);
  for (int n : kNodeCounts) {
    const Eigen::MatrixXd W = random_block_circulant(n, generator);
    const Eigen::MatrixXd columns = delassus_periodic_columns(W);
    Eigen::VectorXd expected = random_vector(2 * n, generator), y = expected;
    for (int k = 0; k < n; k += 1 + n / 7) {
      const Eigen::Vector2d delta = random_vector(2, generator);
      expected.noalias() += W.middleCols<2>(2 * k) * delta;
      add_periodic_node_columns(columns, n, k, delta.x(), delta.y(), y);
    }
    EXPECT_TRUE(same_bits(y, expected)) << "n = " << n << ", max difference " << (y - expected).cwiseAbs().maxCoeff();
  }
}

}  // namespace
}  // namespace slidewave
