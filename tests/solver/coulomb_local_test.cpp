// Exact local Signorini–Coulomb solve of one node (contact/coulomb_local) on hand-built cases whose
// answers are written out below, then on random cases against the direct conditions and brute force; the node's
// 2 x 2 solve against Eigen's LDLT bit for bit.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <random>

#include "contact/coulomb_local.hpp"
#include "contact_oracle.hpp"

namespace slidewave {
namespace {

Eigen::Matrix2d diagonal_D() { return Eigen::Vector2d(2.0, 3.0).asDiagonal(); }
Eigen::Matrix2d coupled_D() {
  Eigen::Matrix2d D;
  D << 2.0, 0.5, 0.5, 3.0;
  return D;
}

void expect_solution(const LocalContactSolution& got, ContactState state, const Eigen::Vector2d& r_expected) {
  EXPECT_TRUE(got.consistent);
  EXPECT_EQ(got.state, state);
  EXPECT_NEAR(got.r.x(), r_expected.x(), 1e-14 * (1 + r_expected.norm()));
  EXPECT_NEAR(got.r.y(), r_expected.y(), 1e-14 * (1 + r_expected.norm()));
}

TEST(CoulombLocal, OpenWhenTheFreeGapIsNonNegative) {
  for (const Eigen::Matrix2d& D : {diagonal_D(), coupled_D()}) {
    expect_solution(solve_local_coulomb(LocalOperator(D), {0.3, 0.1}, 0.5), ContactState::open, {0, 0});
    expect_solution(solve_local_coulomb(LocalOperator(D), {-0.3, 0.0}, 0.5), ContactState::open, {0, 0});  // grazing
  }
}

// Diagonal D = diag(2, 3), f = 0.5: stick r = -D^-1 b when |r_x| <= f r_y; otherwise u_y = 0 gives
// r_y = -b_y / 3, r_x = -s f r_y, and the slip direction s = sign(du_x) with du_x = b_x + 2 r_x.
TEST(CoulombLocal, HandBuiltDiagonalCases) {
  const Eigen::Matrix2d D = diagonal_D();
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.1, -0.6}, 0.5), ContactState::stick, {-0.05, 0.2});
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.5, -0.6}, 0.5), ContactState::slip,
                  {-0.1, 0.2});  // du_x = +0.3
  expect_solution(solve_local_coulomb(LocalOperator(D), {-0.5, -0.6}, 0.5), ContactState::slip,
                  {0.1, 0.2});  // du_x = -0.3
  // On the cone edge |r_x| = f r_y exactly: stick (du_x = 0) is the answer.
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.2, -0.6}, 0.5), ContactState::stick, {-0.1, 0.2});
  // Frictionless: r_x = 0, pure normal reaction, free tangential motion.
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.4, -0.6}, 0.0), ContactState::slip, {0.0, 0.2});
  // The slip increments come out as predicted.
  const auto slip = solve_local_coulomb(LocalOperator(D), {0.5, -0.6}, 0.5);
  const Eigen::Vector2d y = Eigen::Vector2d(0.5, -0.6) + D * slip.r;
  EXPECT_NEAR(y.x(), 0.3, 1e-15);
  EXPECT_NEAR(y.y(), 0.0, 1e-15);
}

// Coupled D = [[2, 0.5], [0.5, 3]], f = 0.5. Slip in direction s: u_y = b_y + 0.5 r_x + 3 r_y = 0 and
// r_x = -s f r_y give r_y = -b_y / (3 - 0.5 s f).
TEST(CoulombLocal, HandBuiltCoupledCases) {
  const Eigen::Matrix2d D = coupled_D();
  const double f = 0.5;
  // stick: r = -D^-1 b = -(1/5.75) (3 b_x - 0.5 b_y, -0.5 b_x + 2 b_y)
  const Eigen::Vector2d b_stick(0.1, -0.6);
  expect_solution(solve_local_coulomb(LocalOperator(D), b_stick, f), ContactState::stick,
                  Eigen::Vector2d(-(3 * 0.1 + 0.5 * 0.6) / 5.75, -(-0.5 * 0.1 - 2 * 0.6) / 5.75));
  const double ry_forward = 0.6 / (3 - 0.5 * f), ry_backward = 0.6 / (3 + 0.5 * f);
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.5, -0.6}, f), ContactState::slip,
                  {-f * ry_forward, ry_forward});
  expect_solution(solve_local_coulomb(LocalOperator(D), {-0.5, -0.6}, f), ContactState::slip,
                  {f * ry_backward, ry_backward});
  // directions: du_x = b_x + 2 r_x + 0.5 r_y
  EXPECT_GT(0.5 + 2 * (-f * ry_forward) + 0.5 * ry_forward, 0);
  EXPECT_LT(-0.5 + 2 * (f * ry_backward) + 0.5 * ry_backward, 0);
}

// Prakash–Clifton: the bound is a given value while closed, whatever r_y.
TEST(CoulombLocal, FixedBound) {
  const Eigen::Matrix2d D = coupled_D();
  const double bound = 0.05;
  // stick inside the bound: r = -D^-1 b = -(3 b_x - 0.5 b_y, -0.5 b_x + 2 b_y) / 5.75 for b = (-0.08, -0.6)
  const auto stick = solve_local_coulomb(LocalOperator(D), {-0.08, -0.6}, 1.0, bound);
  expect_solution(stick, ContactState::stick,
                  Eigen::Vector2d(-(3 * -0.08 + 0.5 * 0.6), -(-0.5 * -0.08 - 2 * 0.6)) / 5.75);
  EXPECT_LE(std::fabs(stick.r.x()), bound);
  // slip forward: r_x = -bound, u_y = 0 gives r_y = (0.6 + 0.5 bound) / 3
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.5, -0.6}, 1.0, bound), ContactState::slip,
                  {-bound, (0.6 + 0.5 * bound) / 3});
  expect_solution(solve_local_coulomb(LocalOperator(D), {-0.5, -0.6}, 1.0, bound), ContactState::slip,
                  {bound, (0.6 - 0.5 * bound) / 3});
  // open is still decided by the free gap
  expect_solution(solve_local_coulomb(LocalOperator(D), {0.5, 0.2}, 1.0, bound), ContactState::open, {0, 0});
}

// Random SPD D (diagonal and coupled), random b, f in {0, 0.3, 1, 2}: the answer satisfies the
// conditions directly and is one of the brute-force solutions (the unique one when D is diagonal).
TEST(CoulombLocal, RandomCasesAgainstConditionsAndEnumeration) {
  std::mt19937_64 generator(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int n_cases = 0, n_multiple = 0;
  for (double f : {0.0, 0.3, 1.0, 2.0})
    for (bool coupled : {false, true})
      for (int trial = 0; trial < 500; ++trial) {
        Eigen::Matrix2d A;
        A << uniform(generator), uniform(generator), uniform(generator), uniform(generator);
        Eigen::Matrix2d D = A * A.transpose() + 0.2 * Eigen::Matrix2d::Identity();
        if (!coupled) D(0, 1) = D(1, 0) = 0;
        const Eigen::Vector2d b(uniform(generator), uniform(generator));
        const auto got = solve_local_coulomb(LocalOperator(D), b, f);
        const std::string where = "f = " + std::to_string(f) + " trial " + std::to_string(trial);
        ASSERT_TRUE(got.consistent) << where;
        const Eigen::MatrixXd W = D;
        const Eigen::VectorXd q = b, r = got.r;
        EXPECT_EQ(testing::signorini_coulomb_violations(W, q, f, r, 1e-12), "") << where;
        const auto all = testing::enumerate_solutions(W, q, f, 1e-12);
        ASSERT_FALSE(all.empty()) << where;
        double nearest = 1e300;
        for (const auto& s : all) nearest = std::min(nearest, (s - r).cwiseAbs().maxCoeff());
        EXPECT_LE(nearest, 1e-10) << where;
        if (!coupled) {
          EXPECT_EQ(all.size(), 1u) << where << ": diagonal D has a unique solution";
        }
        ++n_cases;
        n_multiple += all.size() > 1;
      }
  ::testing::Test::RecordProperty("cases_with_several_solutions", n_multiple);
  EXPECT_EQ(n_cases, 4000);
}

bool same_bits(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 2) == 0;
}

TEST(CoulombLocal, TheNodesSolveIsEigensLdltBitForBit) {
  // Random SPD blocks over twelve decades, with either diagonal entry the larger (both pivot orders), nearly
  // singular ones, the diagonal and the exactly singular block (its zero pivot gives 0, as Eigen's pseudo-inverse).
  std::mt19937_64 generator(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Eigen::Matrix2d> blocks = {diagonal_D(), coupled_D(), (Eigen::Matrix2d() << 1, 1, 1, 1).finished(),
                                         (Eigen::Matrix2d() << 0.5, 0, 0, 3).finished()};
  for (int k = 0; k < 20000; ++k) {
    const double scale = std::pow(10.0, 12 * unit(generator));
    const double a = std::exp(3 * unit(generator)), c = std::exp(3 * unit(generator));
    const double coupling = (k % 10 == 0 ? 1 - 1e-12 : std::fabs(unit(generator))) * std::sqrt(a * c);
    blocks.push_back(scale *
                     (Eigen::Matrix2d() << a, coupling * (k % 2 ? 1 : -1), coupling * (k % 2 ? 1 : -1), c).finished());
  }
  int n_swapped = 0, n_checked = 0;
  for (const Eigen::Matrix2d& D : blocks) {
    const LocalOperator node(D);
    const Eigen::LDLT<Eigen::Matrix2d> ldlt(D);
    n_swapped += ldlt.transpositionsP().indices()(0) == 1;
    for (int j = 0; j < 5; ++j) {
      const Eigen::Vector2d b(unit(generator) * std::pow(10.0, 6 * unit(generator)), unit(generator));
      const Eigen::Vector2d expected = ldlt.solve(b);
      ASSERT_TRUE(same_bits(node.solve(b), expected))
          << "D = [" << D.row(0) << "; " << D.row(1) << "], b = " << b.transpose() << ": " << node.solve(b).transpose()
          << " vs " << expected.transpose();
      ++n_checked;
    }
  }
  EXPECT_GT(n_swapped, 5000) << "both pivot orders are checked";
  EXPECT_EQ(n_checked, 5 * static_cast<int>(blocks.size()));
}

}  // namespace
}  // namespace slidewave
