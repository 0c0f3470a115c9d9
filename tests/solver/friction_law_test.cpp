// Friction laws (contact/friction_law.hpp): the registry maps friction.regularization to the law; the
// Coulomb law leaves the bound to the contact solver (f r_y, no bounds, no state); Prakash–Clifton starts
// its regularized normal force at the preload reaction, bounds friction by f sigma, and relaxes sigma
// towards R_n with the implicit step theta = (|du_x| + v* dt) / L, checked on hand-computed values.
#include <gtest/gtest.h>

#include "contact/coulomb_friction.hpp"
#include "contact/prakash_clifton.hpp"

namespace slidewave {
namespace {

TEST(FrictionLaw, RegistryMakesTheConfiguredLaw) {
  FrictionConfig config;
  config.regularization = Regularization::none;
  EXPECT_NE(dynamic_cast<CoulombFriction*>(make_friction_law(config).get()), nullptr);
  config.regularization = Regularization::prakash_clifton;
  EXPECT_NE(dynamic_cast<PrakashClifton*>(make_friction_law(config).get()), nullptr);
}

TEST(FrictionLaw, CoulombHasNoBoundsAndNoState) {
  const CoulombFriction law;
  const Eigen::VectorXd r = (Eigen::VectorXd(4) << -0.5, 2.0, 0.1, 3.0).finished();
  FrictionState state = law.initial_state(r);
  EXPECT_TRUE(state.per_node.empty());
  std::vector<double> bounds{1.0, 2.0};  // left over from elsewhere: must be cleared
  law.bounds(state, bounds);
  EXPECT_TRUE(bounds.empty()) << "empty bounds: the contact solver applies f r_y";
  law.update(Eigen::VectorXd::Ones(4), r, 0.1, state);
  EXPECT_TRUE(state.per_node.empty());
}

TEST(FrictionLaw, PrakashCliftonStartsAtThePreloadAndRelaxesTowardsThePressure) {
  const double f = 1.5, L = 0.5, v_star = 0.3, dt = 0.2;
  const PrakashClifton law(f, L, v_star);
  const Eigen::VectorXd r0 = (Eigen::VectorXd(4) << -0.5, 2.0, 0.1, 3.0).finished();
  FrictionState state = law.initial_state(r0);
  EXPECT_EQ(state.per_node, (std::vector<double>{2.0, 3.0}));
  std::vector<double> bounds;
  law.bounds(state, bounds);
  EXPECT_EQ(bounds, (std::vector<double>{f * 2.0, f * 3.0}));

  // Node 0 slips by 0.2 (theta = (0.2 + 0.06) / 0.5 = 0.52), node 1 sticks (theta = 0.06 / 0.5 = 0.12).
  const Eigen::VectorXd du = (Eigen::VectorXd(4) << -0.2, 0.0, 0.0, 0.01).finished();
  const Eigen::VectorXd r1 = (Eigen::VectorXd(4) << 0.0, 4.0, 0.0, 0.0).finished();
  law.update(du, r1, dt, state);
  EXPECT_NEAR(state.per_node[0], (2.0 + 0.52 * 4.0) / 1.52, 1e-15);
  EXPECT_NEAR(state.per_node[1], 3.0 / 1.12, 1e-15);
  // Without slip and with v* = 0 the memory does not move.
  const PrakashClifton frozen(f, L, 0.0);
  FrictionState kept = frozen.initial_state(r0);
  frozen.update(Eigen::VectorXd::Zero(4), r1, dt, kept);
  EXPECT_EQ(kept.per_node, (std::vector<double>{2.0, 3.0}));
}

}  // namespace
}  // namespace slidewave
