// The Gauss–Seidel node update with a block-circulant W read from its generating columns
// (contact/delassus.hpp: add_periodic_node_columns) against the dense Eigen expression, bit for bit, on
// random block-circulant W of sizes that cover odd tails of the vector loops; the update within a reach
// (the nodes near k updated as the whole update does, the others untouched, across both ends of the
// periodic numbering); and the reach of a W whose blocks decay at a known rate.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
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
      add_periodic_node_columns(columns, n, k, n, delta.x(), delta.y(), y);
    }
    EXPECT_TRUE(same_bits(y, expected)) << "n = " << n << ", max difference " << (y - expected).cwiseAbs().maxCoeff();
  }
}

TEST(PeriodicColumns, UpdateWithinAReachIsTheWholeUpdateThereAndNothingElsewhere) {
  std::mt19937_64 generator(11);
  for (int n : {5, 31, 64, 97, 384}) {
    const Eigen::MatrixXd W = random_block_circulant(n, generator);
    const Eigen::MatrixXd columns = delassus_periodic_columns(W);
    for (int reach : {0, 1, 2, n / 2 - 1}) {
      if (2 * reach + 1 >= n) continue;  // that is the whole update (above)
      for (int k : {0, 1, reach, n / 2, n - 1 - reach, n - 2, n - 1}) {
        if (k < 0 || k >= n) continue;
        const Eigen::Vector2d delta = random_vector(2, generator);
        const Eigen::VectorXd start = random_vector(2 * n, generator);
        Eigen::VectorXd whole = start, within = start;
        add_periodic_node_columns(columns, n, k, n, delta.x(), delta.y(), whole);
        add_periodic_node_columns(columns, n, k, reach, delta.x(), delta.y(), within);
        for (int i = 0; i < n; ++i) {
          const int distance = std::min((i - k + n) % n, (k - i + n) % n);
          const Eigen::VectorXd& expected = distance <= reach ? whole : start;
          EXPECT_TRUE(std::memcmp(within.data() + 2 * i, expected.data() + 2 * i, 2 * sizeof(double)) == 0)
              << "n = " << n << ", reach " << reach << ", k = " << k << ", node " << i << " at distance " << distance;
        }
      }
    }
  }
}

TEST(PeriodicColumns, ReachIsTheFarthestBlockAboveTheFloor) {
  // Block-circulant, the block at node distance d = 0.5^d B (largest entry 1): 0.5^19 > 1e-6 > 0.5^20.
  const int n = 101;
  const auto operator_with = [n](const auto& size_at_distance) {
    Eigen::Matrix2d B;
    B << 1.0, 0.3, 0.3, 0.8;
    Eigen::MatrixXd W(2 * n, 2 * n);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        W.block<2, 2>(2 * i, 2 * k) = size_at_distance(std::min((i - k + n) % n, (k - i + n) % n)) * B;
    return delassus_periodic_columns(W);
  };
  const auto decaying = [](int d) { return std::pow(0.5, d); };
  EXPECT_EQ(delassus_periodic_reach(operator_with(decaying), n, 1e-6), 19);
  EXPECT_EQ(delassus_periodic_reach(operator_with(decaying), n, 0.3), 1);
  EXPECT_EQ(delassus_periodic_reach(operator_with(decaying), n, 0.0), n / 2);
  // one block far out above the floor (noise, or a slowly decaying operator): the reach goes out to it
  const auto spiked = [&](int d) { return d == 40 ? 1e-5 : decaying(d); };
  EXPECT_EQ(delassus_periodic_reach(operator_with(spiked), n, 1e-6), 40);
}

}  // namespace
}  // namespace slidewave
