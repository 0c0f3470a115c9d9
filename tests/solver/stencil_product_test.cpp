// The matrix-free K u of the periodic layer (fem/stencil_product.hpp) against Eigen's sparse product.
// Oracle: Eigen's row-major `K * u`, compared byte for byte (memcmp), on the layer's stiffness for small and
// realistic meshes, lambda = 2H, 4H, 6H, every integration and two Poisson ratios, with random u that also
// holds exact zeros of both signs. Sharpness: summing a row's terms in another order changes the bits
// (OrderOfTheTermsChangesTheBits), so the equality cannot hold by accident. A K that is not a periodic
// stencil (one entry changed, one entry added, the wrong period, a random matrix) is refused.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "fem/assembly.hpp"
#include "fem/stencil_product.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "model/layer_model.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

RowMatrix layer_stiffness(int n_x, int n_y, Integration integration, double nu) {
  const double h = 25.0 / n_y;
  return RowMatrix(assemble_uniform(LayerMesh(n_x, n_y, h), quad4_stiffness(1000.0, nu, h, integration)));
}

/// Values over many binades (as a displacement field with a preload and small waves has), with exact +0
/// and -0 entries.
Eigen::VectorXd random_field(int n, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 2), special(0, 19);
  Eigen::VectorXd u(n);
  for (int k = 0; k < n; ++k) {
    const int kind = special(generator);
    u(k) = kind == 0 ? 0.0 : kind == 1 ? -0.0 : std::ldexp(mantissa(generator), exponent(generator));
  }
  return u;
}

/// Every bit of x (hexadecimal floating point).
std::string exact(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

/// Index of the first entry whose bits differ, -1 if none.
int first_bitwise_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() != b.size()) return 0;
  for (int k = 0; k < a.size(); ++k)
    if (std::memcmp(&a(k), &b(k), sizeof(double)) != 0) return k;
  return -1;
}

void expect_bitwise_equal_to_eigen(const RowMatrix& K, int n_x, const std::string& where) {
  const StencilProduct stencil(K, n_x);
  for (std::uint64_t seed : {1, 2, 3}) {
    const Eigen::VectorXd u = random_field(static_cast<int>(K.cols()), seed);
    Eigen::VectorXd expected(K.rows()), Ku;
    expected.noalias() = K * u;
    stencil.apply(u, Ku);
    ASSERT_EQ(Ku.size(), expected.size()) << where;
    const int k = first_bitwise_difference(Ku, expected);
    EXPECT_EQ(std::memcmp(Ku.data(), expected.data(), sizeof(double) * Ku.size()), 0)
        << where << " seed " << seed << ": first difference in row " << k << ": " << exact(k >= 0 ? Ku(k) : 0)
        << " vs Eigen " << exact(k >= 0 ? expected(k) : 0);
  }
}

TEST(StencilProduct, EqualsEigenBitwiseOnTheLayerStiffness) {
  // n_x - 2 interior nodes: blocks of 8 and a remainder of 1 to 7, none (n_x = 18), or only a remainder.
  struct Mesh {
    int n_y, lambda_over_H;
  };
  for (const Mesh mesh : {Mesh{1, 3}, Mesh{2, 2}, Mesh{4, 2}, Mesh{3, 4}, Mesh{8, 6}, Mesh{9, 2}, Mesh{16, 2},
                          Mesh{32, 2}, Mesh{32, 4}, Mesh{16, 6}, Mesh{64, 2}})
    for (Integration integration : testing::kAllIntegrations)
      for (double nu : {0.2, 0.45}) {
        const int n_x = mesh.n_y * mesh.lambda_over_H;
        expect_bitwise_equal_to_eigen(layer_stiffness(n_x, mesh.n_y, integration, nu), n_x,
                                      "n_x = " + std::to_string(n_x) + " n_y = " + std::to_string(mesh.n_y) + " " +
                                          testing::integration_name(integration) + " nu = " + std::to_string(nu));
      }
}

TEST(StencilProduct, EqualsEigenBitwiseWhenEveryNodeIsASeamNode) {
  // n_x = 1, 2: no interior node, every row is kept as stored; n_x = 3: one interior node.
  for (int n_x : {1, 2, 3}) {
    RowMatrix K = layer_stiffness(3, 2, Integration::full, 0.3);
    const int n = 2 * n_x * 3;
    K = RowMatrix(K.topLeftCorner(n, n));
    expect_bitwise_equal_to_eigen(K, n_x, "n_x = " + std::to_string(n_x));
  }
}

TEST(StencilProduct, OrderOfTheTermsChangesTheBits) {
  // The oracle is sharp: the same terms summed last to first differ from Eigen's sum in some rows.
  const RowMatrix K = layer_stiffness(64, 32, Integration::reduced, 0.2);
  const Eigen::VectorXd u = random_field(static_cast<int>(K.cols()), 7);
  const Eigen::VectorXd expected = K * u;
  int n_rows_differing = 0;
  for (int row = 0; row < K.rows(); ++row) {
    double reversed = 0;
    for (int k = K.outerIndexPtr()[row + 1] - 1; k >= K.outerIndexPtr()[row]; --k)
      reversed += K.valuePtr()[k] * u(K.innerIndexPtr()[k]);
    n_rows_differing += std::memcmp(&reversed, &expected(row), sizeof(double)) != 0;
  }
  EXPECT_GT(n_rows_differing, K.rows() / 10);
}

/// The message of the std::invalid_argument that StencilProduct(K, n_x) throws, "" if it does not throw.
std::string refusal(const RowMatrix& K, int n_x) {
  try {
    StencilProduct stencil(K, n_x);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(StencilProduct, RefusesAStiffnessThatIsNotAPeriodicStencil) {
  const int n_x = 16, n_y = 4;
  const RowMatrix K = layer_stiffness(n_x, n_y, Integration::reduced, 0.2);
  ASSERT_EQ(refusal(K, n_x), "");

  // One interior coefficient off by one unit in the last place: node i = 5 of mesh row j = 2, d = 1.
  const int row = 2 * (2 * n_x + 5) + 1;
  RowMatrix changed = K;
  double& value = changed.coeffRef(row, row);
  value = std::nextafter(value, 2 * value);
  EXPECT_NE(refusal(changed, n_x).find("row " + std::to_string(row) + " (node i = 5, j = 2, d = 1)"), std::string::npos)
      << refusal(changed, n_x);

  // One entry more (an explicit zero, which Eigen's product also visits), in the template row of node 1.
  RowMatrix added = K;
  added.insert(2 * (n_x + 1), 2 * (n_x + 8)) = 0.0;
  EXPECT_NE(refusal(added, n_x).find("stores"), std::string::npos) << refusal(added, n_x);

  // Rows of a node with different columns.
  RowMatrix uneven = K;
  uneven.insert(2 * (n_x + 1) + 1, 2 * (n_x + 8)) = 1.0;
  EXPECT_NE(refusal(uneven, n_x).find("same columns"), std::string::npos) << refusal(uneven, n_x);

  // The wrong period: 2 n_x reads two mesh rows as one (the seam of the first is then an interior node).
  // A divisor of n_x is no wrong period: every half row is a stencil too, with seams in the middle of the
  // mesh row kept as stored, and the product stays exact.
  EXPECT_NE(refusal(K, 2 * n_x), "");
  expect_bitwise_equal_to_eigen(K, n_x / 2, "half the period");
  EXPECT_NE(refusal(K, 3), "");  // K.rows() not a multiple of 6
  EXPECT_NE(refusal(K, 0), "");

  // A random sparse symmetric matrix.
  std::mt19937_64 generator(11);
  std::uniform_int_distribution<int> index(0, static_cast<int>(K.rows()) - 1);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < 4 * K.rows(); ++k) {
    const int a = index(generator), b = index(generator);
    triplets.emplace_back(a, b, 1.0);
    triplets.emplace_back(b, a, 1.0);
  }
  RowMatrix random(K.rows(), K.cols());
  random.setFromTriplets(triplets.begin(), triplets.end());
  EXPECT_NE(refusal(random, n_x), "");
}

TEST(StencilProduct, TheStepperUsesItOnTheLayerAndKeepsEigensBits) {
  for (const char* solver : {"cholmod", "spectral"}) {
    const LayerModel m(
        testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"numerics", {{"linear_solver", solver}}}}));
    const HHTCoefficients hht(m.config.time.hht_alpha, m.d.dt);
    const PartitionedSystem system = m.partitioned();
    const HHTStepper stepper(system, hht, true, m.factorize_split(effective_matrix(hht, system)));
    EXPECT_TRUE(stepper.uses_stencil_product()) << solver;
    const Eigen::VectorXd u = random_field(m.n_free + m.n_top, 5);
    const HHTState s = stepper.initial_state(u, Eigen::VectorXd::Zero(u.size()),
                                             Eigen::VectorXd::Zero(m.n_contact_dofs), SparseCholesky(m.M_ff()));
    const Eigen::VectorXd expected = m.K() * u;
    EXPECT_EQ(first_bitwise_difference(s.Ku, expected), -1) << solver;
  }
}

}  // namespace
}  // namespace slidewave
