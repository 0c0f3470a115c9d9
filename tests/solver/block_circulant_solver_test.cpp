// FFT block-circulant solver (linalg/block_circulant_solver) against CHOLMOD (linalg/sparse_cholesky)
// and a dense LLT on the layer's own matrices: K_eff, K_ff, M_ff for every integration and mass, odd
// and even n_x (the Nyquist mode), n_y from 1; the same bits for any thread count; and its refusals
// (not circulant, not symmetric, not SPD).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstring>
#include <random>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "same_run_support.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

using testing::random_vector;

struct Layer {
  RunConfig config;
  LayerModel model;
};

Layer layer(int n_x, int n_y, Integration integration, const char* mass) {
  // lambda_over_H = n_x / n_y gives n_x columns of elements.
  RunConfig config = testing::make_config({{"mesh",
                                            {{"elements_per_H", std::max(n_y, 2)},
                                             {"integration", testing::integration_name(integration)},
                                             {"mass", mass}}},
                                           {"geometry", {{"lambda_over_H", double(n_x) / std::max(n_y, 2)}}}});
  return {config, LayerModel(config)};
}

TEST(BlockCirculantSolver, MatchesCholmodAndDenseOnTheLayerMatrices) {
  for (int n_x : {3, 4, 5, 8})
    for (int n_y : {2, 3, 5})
      for (Integration integration : testing::kAllIntegrations)
        for (const char* mass : {"consistent", "lumped"}) {
          const Layer l = layer(n_x, n_y, integration, mass);
          ASSERT_EQ(l.model.mesh.n_x, n_x);
          const HHTCoefficients hht(0.1, l.model.d.dt);
          const Eigen::SparseMatrix<double> K_eff = effective_matrix(hht, l.model.M_ff(), l.model.K_ff());
          const std::string where = "n_x = " + std::to_string(n_x) + " n_y = " + std::to_string(n_y) + " " +
                                    testing::integration_name(integration) + " " + mass;
          const std::vector<std::pair<const char*, Eigen::SparseMatrix<double>>> matrices = {
              {"K_eff", K_eff}, {"M_ff", l.model.M_ff()}, {"K_ff", l.model.K_ff()}};
          for (const auto& [name, A] : matrices) {
            std::string reason;
            ASSERT_TRUE(BlockCirculantSolver::is_block_circulant(A, n_x, n_y, &reason))
                << where << " " << name << ": " << reason;
            const BlockCirculantSolver fft(A, n_x, n_y);
            EXPECT_EQ(fft.size(), A.rows());
            const Eigen::VectorXd b = random_vector(fft.size(), 17);
            const Eigen::VectorXd x = fft.solve(b);
            const Eigen::VectorXd x_dense = Eigen::MatrixXd(A).llt().solve(b);
            const Eigen::VectorXd x_cholmod = SparseCholesky(A).solve(b);
            EXPECT_LE((x - x_dense).norm(), 1e-11 * x_dense.norm()) << where << " " << name;
            EXPECT_LE((x - x_cholmod).norm(), 1e-11 * x_cholmod.norm()) << where << " " << name;
            EXPECT_LE((A * x - b).norm(), 1e-11 * b.norm() * Eigen::MatrixXd(A).norm() * x.norm() / b.norm())
                << where << " " << name;
          }
        }
}

TEST(BlockCirculantSolver, SolveVariantsAgreeBitwise) {
  const Layer l = layer(6, 4, Integration::reduced, "consistent");
  const Eigen::SparseMatrix<double> A = 10.0 * l.model.M_ff() + l.model.K_ff();
  const BlockCirculantSolver fft(A, 6, 4);
  const Eigen::VectorXd b = random_vector(fft.size(), 3);
  const Eigen::VectorXd x = fft.solve(b);
  EXPECT_EQ(fft.solve(b), x) << "repeatable";
  Eigen::VectorXd in_place = b;
  fft.solve_into(in_place, in_place);
  EXPECT_EQ(in_place, x) << "b and x may be the same vector";
  Eigen::MatrixXd B(fft.size(), 3);
  B << b, random_vector(fft.size(), 4), random_vector(fft.size(), 5);
  const Eigen::MatrixXd X = fft.solve(B);
  EXPECT_EQ(Eigen::VectorXd(X.col(0)), x);
  EXPECT_EQ(Eigen::VectorXd(X.col(2)), fft.solve(Eigen::VectorXd(B.col(2))));
  EXPECT_THROW(fft.solve(Eigen::VectorXd(Eigen::VectorXd::Zero(fft.size() + 1))), std::invalid_argument);
}

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// The default path factorizes K_ff and M_ff from the blocks read off the rows of K and M (on all DOFs), without
// assembling K_ff or M_ff: the same factors as the checked constructor makes from those, so the same solution to
// the bit, for every mass (the redistributed one is not exactly circulant: slice 0's entries are the ones both
// read), integration, odd and even n_x. Through LayerModel::factorize, which also serves `cholmod` from K_ff, M_ff.
TEST(BlockCirculantSolver, BlocksReadOffTheRowsOnAllDofsFactorizeToTheSameBits) {
  for (int n_x : {3, 4, 7})
    for (int n_y : {2, 3})
      for (Integration integration : testing::kAllIntegrations)
        for (const char* mass : {"consistent", "lumped", "redistributed"}) {
          const Layer l = layer(n_x, n_y, integration, mass);
          const LayerModel& m = l.model;
          const std::string where = "n_x = " + std::to_string(n_x) + " n_y = " + std::to_string(n_y) + " " +
                                    testing::integration_name(integration) + " " + mass;
          const Eigen::VectorXd b = random_vector(m.n_free, 21);
          for (const auto& [which, A] : {std::pair{LayerModel::FreeBlock::stiffness, &m.K_ff()},
                                         std::pair{LayerModel::FreeBlock::mass, &m.M_ff()}}) {
            const BlockCirculantSolver checked(*A, n_x, n_y);
            const BlockCirculantSolver of_rows(
                circulant_blocks_of_rows(which == LayerModel::FreeBlock::stiffness ? m.K() : m.M(), n_x, n_y), n_x, n_y);
            EXPECT_EQ(of_rows.bandwidth(), checked.bandwidth()) << where;
            const Eigen::VectorXd x = checked.solve(b);
            EXPECT_TRUE(same_bits(of_rows.solve(b), x)) << where;
            EXPECT_TRUE(same_bits(m.factorize(which)->solve(b), x)) << where;
          }
        }
  const Layer l = layer(5, 3, Integration::reduced, "consistent");
  EXPECT_THROW(circulant_blocks_of_rows(l.model.K(), 5, 5), std::invalid_argument);  // more rows than K has
  EXPECT_THROW(BlockCirculantSolver(circulant_blocks_of_rows(l.model.K(), 5, 3), 5, 2), std::invalid_argument);
}

// numerics.threads: the FFT rows and the wavenumbers are shared out to the threads, and every row and
// wavenumber is computed the same way for any count, so x is the same to the bit. n_x = 40 gives 22
// lanes, split at a multiple of 8 (both threads sweep), and n_y = 5 an uneven split of the rows; the odd
// n_x = 41 has no Nyquist mode.
TEST(BlockCirculantSolver, ThreadCountDoesNotChangeABit) {
  for (int n_x : {40, 41}) {
    const int n_y = 5;
    const Layer l = layer(n_x, n_y, Integration::reduced, "consistent");
    ASSERT_EQ(l.model.mesh.n_x, n_x);
    const Eigen::SparseMatrix<double> A = 10.0 * l.model.M_ff() + l.model.K_ff();
    BlockCirculantSolver one(A, n_x, n_y, 1);
    const Eigen::VectorXd b = random_vector(one.size(), 11);
    const Eigen::VectorXd g = random_vector(one.n_contact(), 12);
    const Eigen::VectorXd x_one = one.solve(b);
    Eigen::VectorXd u_contact_one(one.n_contact()), u_one(one.size());
    one.solve_free(b, u_contact_one);
    one.solve_loaded(g, u_one);
    for (int threads : {2, 3}) {
      BlockCirculantSolver team(A, n_x, n_y, threads);
      EXPECT_EQ(team.threads(), threads);
      const std::string where = "n_x = " + std::to_string(n_x) + ", " + std::to_string(threads) + " threads";
      EXPECT_TRUE(same_bits(team.solve(b), x_one)) << where << ": solve";
      Eigen::VectorXd u_contact(team.n_contact()), u(team.size());
      team.solve_free(b, u_contact);
      EXPECT_TRUE(same_bits(u_contact, u_contact_one)) << where << ": solve_free";
      team.solve_loaded(g, u);
      EXPECT_TRUE(same_bits(u, u_one)) << where << ": solve_loaded";
    }
  }
  const Layer l = layer(5, 3, Integration::reduced, "consistent");
  EXPECT_THROW(BlockCirculantSolver(l.model.K_ff(), 5, 3, 0), std::invalid_argument);
}

TEST(BlockCirculantSolver, RefusesWhatItCannotSolve) {
  const Layer l = layer(5, 3, Integration::reduced, "consistent");
  const Eigen::SparseMatrix<double> A = 10.0 * l.model.M_ff() + l.model.K_ff();
  std::string reason;
  // Not circulant: one entry of slice 2 differs from slice 0 (symmetrically, so only circulance fails).
  Eigen::SparseMatrix<double> broken = A;
  const int dof = 2 * l.model.mesh.node(2, 1);
  broken.coeffRef(dof, dof) *= 1.01;
  EXPECT_FALSE(BlockCirculantSolver::is_block_circulant(broken, 5, 3, &reason));
  EXPECT_FALSE(reason.empty());
  EXPECT_THROW(BlockCirculantSolver(broken, 5, 3), std::invalid_argument);
  // Not circulant: slice 3 lacks an entry that slice 0 has (removed from the structure), named in the reason.
  Eigen::SparseMatrix<double> lacking = A;
  const int gone = 2 * l.model.mesh.node(3, 1);
  lacking.prune([gone](Eigen::Index r, Eigen::Index c, double) { return !(r == gone && c == gone); });
  ASSERT_EQ(lacking.nonZeros(), A.nonZeros() - 1);
  EXPECT_FALSE(BlockCirculantSolver::is_block_circulant(lacking, 5, 3, &reason));
  EXPECT_NE(reason.find("column slice 3 lacks the entry (2, 2) of block B_0"), std::string::npos) << reason;
  // Not symmetric: the same change in every slice, on one side of the diagonal.
  Eigen::SparseMatrix<double> skew = A;
  for (int i = 0; i < 5; ++i) skew.coeffRef(2 * l.model.mesh.node(i, 0), 2 * l.model.mesh.node(i, 1)) += 1.0;
  EXPECT_FALSE(BlockCirculantSolver::is_block_circulant(skew, 5, 3, &reason));
  EXPECT_THROW(BlockCirculantSolver(skew, 5, 3), std::invalid_argument);
  // Wrong sizes.
  EXPECT_FALSE(BlockCirculantSolver::is_block_circulant(A, 4, 3, &reason));
  EXPECT_THROW(BlockCirculantSolver(A, 5, 2), std::invalid_argument);
  // Not positive definite.
  const Eigen::SparseMatrix<double> negative = -A;
  EXPECT_TRUE(BlockCirculantSolver::is_block_circulant(negative, 5, 3));
  EXPECT_THROW(BlockCirculantSolver(negative, 5, 3), std::runtime_error);
}

// numerics.linear_solver: both solvers give the same discrete run to round-off. Compared before the
// slip onset (the stick phase is not chaotic; after onset round-off differences grow).
TEST(BlockCirculantSolver, SameRunAsCholmodBeforeSlipOnset) {
  testing::expect_same_run_before_slip_onset("spectral", "cholmod");
}

}  // namespace
}  // namespace slidewave
