// Narrowing the lane arrays (model/stick_phase/banded_lanes.hpp): the stick phase drops retired lanes from
// its arrays in place, and the lanes it keeps must see the same bits in every product and solve as in the
// wide arrays (a lane's arithmetic does not depend on its neighbours or on the row length).
#include <gtest/gtest.h>

#include <random>

#include "model/stick_phase/banded_lanes.hpp"

namespace slidewave {
namespace {

constexpr int kRows = 24, kHalfBandwidth = 3, kLanes = 21, kWidth = 8;

LaneVectors random_vectors(std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1, 1);
  LaneVectors x(kRows, kLanes);
  for (double& v : x.re) v = value(random);
  for (double& v : x.im) v = value(random);
  return x;
}

/// A diagonally dominant (so positive definite) symmetric band per lane.
BandedLanes random_band(std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1, 1);
  BandedLanes A(kRows, kHalfBandwidth, kLanes);
  for (int m = 0; m < kLanes; ++m)
    for (int r = 0; r < kRows; ++r)
      for (int k = 1; k <= kHalfBandwidth && r + k < kRows; ++k)
        A.a[A.at(r, k, m)] = A.a[A.at(r + k, -k, m)] = value(random);
  for (int m = 0; m < kLanes; ++m)
    for (int r = 0; r < kRows; ++r) A.a[A.at(r, 0, m)] = 2 * kHalfBandwidth + 1 + value(random);
  return A;
}

void expect_same_lanes(const LaneVectors& wide, const LaneVectors& narrow, const char* what) {
  ASSERT_EQ(narrow.lanes, kWidth) << what;
  for (int r = 0; r < kRows; ++r)
    for (int m = 0; m < kWidth; ++m) {
      // Bit for bit: == on doubles, and no NaN here.
      EXPECT_EQ(wide.get(r, m), narrow.get(r, m)) << what << " row " << r << " lane " << m;
    }
}

TEST(BandedLanes, NarrowingKeepsTheFirstLanesBitForBit) {
  std::mt19937 random(7);
  const LaneVectors x = random_vectors(random);
  LaneVectors narrow = x;
  narrow.narrow(kWidth);
  EXPECT_EQ(narrow.re.size(), static_cast<std::size_t>(kRows) * kWidth);
  expect_same_lanes(x, narrow, "LaneVectors::narrow");

  const BandedLanes A = random_band(random);
  BandedLanes in_place = A;
  in_place.narrow(kWidth);
  const BandedLanes copy = A.first_lanes(kWidth);
  for (int m = 0; m < kWidth; ++m)
    for (int r = 0; r < kRows; ++r)
      for (int k = -kHalfBandwidth; k <= kHalfBandwidth; ++k) {
        EXPECT_EQ(in_place.get(r, k, m), A.get(r, k, m));
        EXPECT_EQ(copy.get(r, k, m), A.get(r, k, m));
      }
  EXPECT_THROW(LaneVectors(x).narrow(kLanes + 1), std::invalid_argument);
}

TEST(BandedLanes, ProductsAndSolvesOfTheKeptLanesAreTheWideOnesBitForBit) {
  std::mt19937 random(11);
  const LaneVectors x = random_vectors(random);
  const BandedLanes A = random_band(random);
  // Over fewer active lanes than the arrays hold, as the stepper calls them.
  const int active = kWidth - 3;

  LaneVectors y_wide(kRows, kLanes), y_narrow(kRows, kWidth), x_narrow = x;
  x_narrow.narrow(kWidth);
  A.multiply(x, y_wide, 0, kRows, active);
  A.first_lanes(kWidth).multiply(x_narrow, y_narrow, 0, kRows, active);
  for (int r = 0; r < kRows; ++r)
    for (int m = 0; m < active; ++m) EXPECT_EQ(y_wide.get(r, m), y_narrow.get(r, m)) << "product, row " << r;

  const int first = 2;  // the stepper factorizes the interior rows
  const BandedLaneFactor wide(A, first);
  BandedLaneFactor narrowed(A, first);
  narrowed.narrow(kWidth);
  LaneVectors z_wide = x, z_narrow = x;
  z_narrow.narrow(kWidth);
  wide.solve(z_wide, active);
  narrowed.solve(z_narrow, active);
  for (int r = 0; r < kRows; ++r)
    for (int m = 0; m < active; ++m) EXPECT_EQ(z_wide.get(r, m), z_narrow.get(r, m)) << "solve, row " << r;
  // And the solve did solve: A z = x on the interior rows of an active lane (to round-off).
  LaneVectors Az(kRows, kLanes);
  A.multiply(z_wide, Az, first, kRows, active);
  for (int m = 0; m < active; ++m)
    for (int r = first; r < kRows; ++r) {
      std::complex<double> residual = x.get(r, m);
      for (int k = -kHalfBandwidth; k <= kHalfBandwidth; ++k)
        if (r + k < first && r + k >= 0) residual += A.get(r, k, m) * z_wide.get(r + k, m);  // columns outside
      EXPECT_LT(std::abs(Az.get(r, m) - residual), 1e-13) << "lane " << m << " row " << r;
    }
}

}  // namespace
}  // namespace slidewave
