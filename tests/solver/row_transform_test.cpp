// The DFT along x of the layer's rows (model/stick_phase/row_transform.hpp): the inverse undoes the forward
// transform, and the inverse of a narrowed lane array (the stick phase drops retired lanes from its arrays)
// reads the dropped lanes from the full array it is given, or as zero, bit for bit as the full array would.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "model/stick_phase/row_transform.hpp"

namespace slidewave {
namespace {

constexpr int kNx = 16, kMeshRows = 3;

std::vector<double> random_rows(std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<double> x(2 * kMeshRows * kNx);
  for (double& v : x) v = value(random);
  return x;
}

TEST(RowTransform, InverseUndoesForward) {
  std::mt19937 random(3);
  const RowTransform transform(kNx);
  const std::vector<double> x = random_rows(random);
  LaneVectors X(2 * kMeshRows, transform.lanes());
  transform.forward(x.data(), X);
  std::vector<double> back(x.size());
  transform.inverse(X, kMeshRows, back.data());
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(back[k], x[k], 1e-15) << k;
}

TEST(RowTransform, ANarrowedArrayReadsTheDroppedLanesFromTheFullOneOrAsZero) {
  std::mt19937 random(5);
  const RowTransform transform(kNx);
  LaneVectors X(2 * kMeshRows, transform.lanes());
  const std::vector<double> x = random_rows(random);
  transform.forward(x.data(), X);
  const int width = 4;
  LaneVectors narrow = X;
  narrow.narrow(width);

  std::vector<double> full(x.size()), from_beyond(x.size()), zeros(x.size()), full_zeroed(x.size());
  transform.inverse(X, kMeshRows, full.data());
  transform.inverse(narrow, kMeshRows, from_beyond.data(), &X);
  EXPECT_EQ(from_beyond, full);  // bit for bit

  LaneVectors X_zeroed = X;
  for (int r = 0; r < X.rows; ++r)
    for (int m = width; m < X.lanes; ++m) X_zeroed.set(r, m, 0.0);
  transform.inverse(X_zeroed, kMeshRows, full_zeroed.data());
  transform.inverse(narrow, kMeshRows, zeros.data());
  EXPECT_EQ(zeros, full_zeroed);
  EXPECT_NE(zeros, full);  // the dropped lanes did carry something

  LaneVectors wrong(2 * kMeshRows, width);
  EXPECT_THROW(transform.inverse(narrow, kMeshRows, zeros.data(), &wrong), std::invalid_argument);
}

}  // namespace
}  // namespace slidewave
