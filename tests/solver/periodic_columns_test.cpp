// The Gauss–Seidel node update with a block-circulant W read from its generating columns
// (contact/delassus.hpp: add_periodic_node_columns) against the dense Eigen expression, bit for bit, on
// random block-circulant W of sizes that cover odd tails of the vector loops.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstring>
#include <random>

#include "contact/delassus.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

using testing::random_block_circulant;
using testing::random_vector;

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

const int kNodeCounts[] = {1, 2, 3, 5, 31, 63, 64, 65, 97, 384, 1001, 2001};

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
