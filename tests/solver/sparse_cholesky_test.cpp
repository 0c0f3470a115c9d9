// SparseCholesky (linalg/sparse_cholesky) calls CHOLMOD, loaded on first use, as Eigen's CholmodSupport does in
// supernodal L L^T mode: the same solutions bit for bit (this test links CHOLMOD for Eigen's side), on the layer's
// matrices (large enough for supernodes), for one and several right-hand sides; a matrix that is not positive
// definite is refused.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <cstring>
#include <stdexcept>

#include "linalg/sparse_cholesky.hpp"
#include "model/layer_model.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

TEST(SparseCholesky, SolvesAsEigensCholmodSupernodalLltBitForBit) {
  for (int n : {4, 16}) {
    const RunConfig config =
        testing::make_config({{"mesh", {{"elements_per_H", n}}}, {"geometry", {{"lambda_over_H", 2.0}}}});
    const LayerModel model(config);
    const HHTCoefficients hht(0.1, model.d.dt);
    const Eigen::SparseMatrix<double> K_eff = effective_matrix(hht, model.M_ff(), model.K_ff());
    for (const Eigen::SparseMatrix<double>* A : {&K_eff, &model.K_ff(), &model.M_ff()}) {
      Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> eigen;
      eigen.setMode(Eigen::CholmodSupernodalLLt);
      eigen.compute(*A);
      ASSERT_EQ(eigen.info(), Eigen::Success);
      const SparseCholesky ours(*A);
      ASSERT_EQ(ours.size(), A->rows());
      const Eigen::VectorXd b = testing::random_vector(ours.size(), 5);
      const Eigen::VectorXd x_eigen = eigen.solve(b);
      EXPECT_TRUE(same_bits(ours.solve(b), x_eigen)) << "H/" << n;
      Eigen::VectorXd x(ours.size());
      ours.solve_into(b, x);
      EXPECT_TRUE(same_bits(x, x_eigen)) << "H/" << n << " solve_into";
      const Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(A->rows(), 3, [](Eigen::Index i, Eigen::Index j) {
        return std::sin(0.37 * static_cast<double>(i) + static_cast<double>(j));
      });
      const Eigen::MatrixXd X_eigen = eigen.solve(B);
      EXPECT_TRUE(same_bits(ours.solve(B), X_eigen)) << "H/" << n << " three right-hand sides";
      // The test is not blind: a solution one ulp off in one entry is told apart.
      Eigen::VectorXd off = x_eigen;
      off(0) = std::nextafter(off(0), 2 * off(0) + 1);
      EXPECT_FALSE(same_bits(off, x_eigen));
    }
  }
}

TEST(SparseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  const RunConfig config =
      testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"geometry", {{"lambda_over_H", 2.0}}}});
  const LayerModel model(config);
  const Eigen::SparseMatrix<double> negative = -model.M_ff();
  EXPECT_THROW(SparseCholesky{negative}, std::runtime_error);
}

}  // namespace
}  // namespace slidewave
