// Mass redistribution at the contact (`mesh.mass = "redistributed"`, fem/mass_redistribution.hpp): the
// assembled mass keeps the layer's total mass and leaves the contact nodes kContactResidualMass of their
// inertia; and the physics it is for (docs/physics-notes.md, section 8): at a small Courant number c_s dt / h a
// long unregularized run with the consistent mass creates energy, with the redistributed one it does not.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <string>

#include "fem/mass_redistribution.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

LayerModel layer(const char* mass, int n, double t_end = 100.0) {
  return LayerModel(testing::make_config({{"mesh", {{"elements_per_H", n}, {"mass", mass}}},
                                          {"time", {{"t_end", t_end}}},
                                          {"output", {{"progress", "never"}}}}));
}

TEST(MassRedistribution, KeepsTheTotalMassAndTakesTheContactNodesInertia) {
  const LayerModel consistent = layer("consistent", 4), redistributed = layer("redistributed", 4);
  const Eigen::MatrixXd M = Eigen::MatrixXd(redistributed.M()), M0 = Eigen::MatrixXd(consistent.M());
  const double layer_mass = consistent.config.material.rho * consistent.d.H * consistent.d.lambda;
  Eigen::VectorXd x_dofs = Eigen::VectorXd::Zero(M.rows());  // a rigid translation along x
  for (Eigen::Index k = 0; k < M.rows(); k += 2) x_dofs(k) = 1;
  EXPECT_NEAR(x_dofs.dot(M * x_dofs), layer_mass, 1e-12 * layer_mass);
  EXPECT_NEAR(x_dofs.dot(M0 * x_dofs), layer_mass, 1e-12 * layer_mass);
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15 * M.cwiseAbs().maxCoeff());
  for (int k = 0; k < consistent.n_contact_dofs; ++k)  // the contact DOFs keep the residual share only
    EXPECT_NEAR(M(k, k), kContactResidualMass * M0(k, k), 1e-12 * M0(k, k)) << "contact DOF " << k;
  EXPECT_GT(M(consistent.n_contact_dofs, consistent.n_contact_dofs),
            M0(consistent.n_contact_dofs, consistent.n_contact_dofs));  // the row above carries it
  // The blocks the steps use are the same matrix's.
  const int n_f = redistributed.n_free;
  EXPECT_EQ((Eigen::MatrixXd(redistributed.M_ff()) - M.topLeftCorner(n_f, n_f)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((Eigen::MatrixXd(redistributed.M_ff_rows()) - M.topLeftCorner(n_f, n_f)).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n_f, -1.0, 2.0);  // M_ff x from M's rows, the same bits
  EXPECT_EQ(redistributed.free_mass_product(x), Eigen::VectorXd(redistributed.M_ff_rows() * x));
  EXPECT_EQ((Eigen::MatrixXd(redistributed.M_fd) - M.topRightCorner(n_f, M.cols() - n_f)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((Eigen::MatrixXd(redistributed.M_top_rows) - M.bottomRows(M.rows() - n_f)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(M.topLeftCorner(n_f, n_f)).info(), Eigen::Success);
}

/// max over t of E_kin + E_el - (E_kin + E_el)(0) - W_ext, over the energy that flowed (analysis/metrics/energy.py).
double energy_created(const RunRecord& record) {
  const GlobalSeries& g = record.global;
  const double start = g.energy_kinetic.front() + g.energy_elastic.front();
  double created = 0, flowed = 0;  // flowed: the largest |W_ext|, |E_el - E_el(0)|, E_kin, D_fric
  for (std::size_t k = 0; k < g.t.size(); ++k) {
    const double held = g.energy_kinetic[k] + g.energy_elastic[k];
    created = std::max(created, held - start - g.work_external[k]);
    flowed = std::max({flowed, std::abs(g.work_external[k]), std::abs(g.energy_elastic[k] - g.energy_elastic.front()),
                       g.energy_kinetic[k], g.dissipation_friction[k]});
  }
  return created / flowed;
}

TEST(MassRedistribution, KeepsALongRunAtASmallCourantNumberFromCreatingEnergy) {
  // H/8 at the default dt c_s = 0.5 m: c_s dt / h = 0.16, nu = 0.2, f = 1.5, 5000 s (slip from ~740 s).
  const double consistent = energy_created(simulate(layer("consistent", 8, 5000.0)));
  const double redistributed = energy_created(simulate(layer("redistributed", 8, 5000.0)));
  std::printf("energy created at c_s dt / h = 0.16: consistent mass %.3g, redistributed %.3g\n", consistent,
              redistributed);
  EXPECT_GT(consistent, 1.0) << "the consistent mass creates energy here (what the option is for)";
  EXPECT_LT(redistributed, 1e-5);
}

}  // namespace
}  // namespace slidewave
