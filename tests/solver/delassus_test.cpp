// Delassus operator (contact/delassus): W = C K^-1 C^T against an explicit dense C K^-1 C^T (Eigen
// LLT), by n_c solves (delassus_operator) and by 2 solves and the periodic shift
// (delassus_operator_periodic), through both linear solvers (CHOLMOD and the FFT block-circulant one).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <memory>

#include "contact/delassus.hpp"
#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "model/layer_model.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

struct Tiny {
  RunConfig config;
  LayerModel model;
  Eigen::SparseMatrix<double> K_eff;
};

/// n_x = 5, n_y = 3: K_eff of the paper's HHT step (dynamic) or the static K_ff.
Tiny tiny_model(Integration integration, bool dynamic) {
  RunConfig config =
      testing::make_config({{"mesh", {{"elements_per_H", 3}, {"integration", testing::integration_name(integration)}}},
                            {"geometry", {{"lambda_over_H", 5.0 / 3.0}}}});
  LayerModel model(config);
  const HHTCoefficients hht(config.time.hht_alpha, model.d.dt);
  Eigen::SparseMatrix<double> K_eff = dynamic ? effective_matrix(hht, model.M_ff(), model.K_ff()) : model.K_ff();
  return {config, std::move(model), std::move(K_eff)};
}

/// Dense reference C K^-1 C^T; C selects the leading n_c free DOFs.
Eigen::MatrixXd dense_delassus(const Eigen::SparseMatrix<double>& K, int n_c) {
  const Eigen::MatrixXd K_dense(K);
  const Eigen::LLT<Eigen::MatrixXd> llt(K_dense);
  EXPECT_EQ(llt.info(), Eigen::Success);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n_c, K.rows());
  for (int k = 0; k < n_c; ++k) C(k, k) = 1;
  return C * llt.solve(C.transpose());
}

std::unique_ptr<LinearSolver> make_solver(const Tiny& t, bool circulant) {
  if (circulant) return std::make_unique<BlockCirculantSolver>(t.K_eff, t.model.mesh.n_x, t.model.mesh.n_y);
  return std::make_unique<SparseCholesky>(t.K_eff);
}

TEST(Delassus, EqualsDenseCKinvCt) {
  for (Integration integration : testing::kAllIntegrations)
    for (bool dynamic : {true, false})
      for (bool circulant : {false, true}) {
        const Tiny t = tiny_model(integration, dynamic);
        const int n_c = t.model.n_contact_dofs;
        ASSERT_EQ(n_c, 10);
        const Eigen::MatrixXd W_ref = dense_delassus(t.K_eff, n_c);
        const auto solver = make_solver(t, circulant);
        const Eigen::MatrixXd W = delassus_operator(*solver, n_c);
        const Eigen::MatrixXd W_periodic = delassus_operator_periodic(*solver, t.model.mesh.n_contact());
        const std::string where = testing::integration_name(integration) + (dynamic ? " K_eff" : " K_ff") +
                                  (circulant ? " circulant" : " cholmod");
        EXPECT_LE((W - W_ref).norm(), 1e-12 * W_ref.norm()) << where;
        EXPECT_LE((W_periodic - W_ref).norm(), 1e-12 * W_ref.norm()) << where << " (periodic shift)";
        EXPECT_EQ((W - W.transpose()).norm(), 0.0) << where;
        EXPECT_EQ((W_periodic - W_periodic.transpose()).norm(), 0.0) << where;
        // Its two generating columns, rotated, are W's columns bit for bit (what the sweeps read).
        const Eigen::MatrixXd columns = delassus_periodic_columns(W_periodic);
        const int n = t.model.mesh.n_contact();
        for (int k = 0; k < n; ++k)
          for (int b = 0; b < 2; ++b)
            EXPECT_EQ(Eigen::VectorXd(W_periodic.col(2 * k + b)),
                      Eigen::VectorXd(columns.col(b).segment(2 * ((n - k) % n), 2 * n)))
                << where << " column " << 2 * k + b;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(W_periodic);
        EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-6 * eig.eigenvalues().maxCoeff())
            << where << ": W must be positive definite";
      }
  // The contact DOFs of the mesh are the ones C selects: (u_x, u_y) of bottom node k at (2k, 2k+1).
  const Tiny t = tiny_model(Integration::reduced, true);
  for (int k = 0; k < t.model.mesh.n_contact(); ++k) {
    EXPECT_EQ(t.model.mesh.contact_dof_x(k), 2 * t.model.mesh.node(k, 0));
    EXPECT_EQ(t.model.mesh.contact_dof_y(k), 2 * t.model.mesh.node(k, 0) + 1);
  }
}

// The reflection x -> -x about a contact node maps the mesh onto itself and u_x to -u_x, so the
// coupling between u_x and u_y of the same node vanishes: each 2x2 diagonal block of W is diagonal.
// Blocks of different nodes do couple u_x and u_y; all nodes are equivalent (translation).
TEST(Delassus, PerNodeBlocksAreDiagonal) {
  for (Integration integration : testing::kAllIntegrations)
    for (bool dynamic : {true, false}) {
      const Tiny t = tiny_model(integration, dynamic);
      const Eigen::MatrixXd W = dense_delassus(t.K_eff, t.model.n_contact_dofs);
      double max_ratio = 0;
      for (int k = 0; k < t.model.mesh.n_contact(); ++k) {
        const Eigen::Matrix2d B = W.block<2, 2>(2 * k, 2 * k);
        max_ratio = std::max(max_ratio, std::fabs(B(0, 1)) / std::sqrt(B(0, 0) * B(1, 1)));
        EXPECT_NEAR(B(0, 0), W(0, 0), 1e-12 * W(0, 0)) << "translation invariance";
        EXPECT_NEAR(B(1, 1), W(1, 1), 1e-12 * W(1, 1)) << "translation invariance";
      }
      const std::string where = testing::integration_name(integration) + (dynamic ? " K_eff" : " K_ff");
      EXPECT_LE(max_ratio, 1e-12) << where;
      const double cross_node = std::fabs(W(0, 3)) / std::sqrt(W(0, 0) * W(3, 3));
      EXPECT_GT(cross_node, 1e-6) << where << ": neighbouring nodes couple u_x and u_y";
      ::testing::Test::RecordProperty(
          "max_offdiag_" + testing::integration_name(integration) + (dynamic ? "_dynamic" : "_static"),
          testing::sci(max_ratio));
    }
}

// Pure 1-point integration: the static K_ff of this layer (top fixed) is still positive definite.
TEST(Delassus, ReducedPureStaticStiffnessIsPositiveDefinite) {
  const Tiny t = tiny_model(Integration::reduced_pure, false);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(t.K_eff)};
  ::testing::Test::RecordProperty("min_over_max_eigenvalue",
                                  testing::sci(eig.eigenvalues().minCoeff() / eig.eigenvalues().maxCoeff()));
  EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-8 * eig.eigenvalues().maxCoeff());
}

}  // namespace
}  // namespace slidewave
