// The structured assembly (fem/assembly): every block the layer model keeps is, bit for bit, the block
// of Eigen's setFromTriplets over the elements in order (the obvious assembly, written here as the
// oracle), for the stiffness of each integration and both mass matrices, on meshes with the periodic seam
// one and two elements wide of the smallest meshes; the stored rows' products (UniformRows::product) and the
// rows of a few node columns, the bits of the assembled blocks.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "fem/assembly.hpp"
#include "fem/quad4.hpp"
#include "mesh/layer_mesh.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// The obvious assembly: one triplet per nonzero element entry, duplicates summed in element order.
SparseMatrix triplet_assembly(const LayerMesh& mesh, const Matrix8& Ke) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const auto nodes = mesh.element_nodes(e);
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        if (Ke(a, b) != 0) triplets.emplace_back(2 * nodes[a / 2] + a % 2, 2 * nodes[b / 2] + b % 2, Ke(a, b));
  }
  SparseMatrix A(mesh.n_dofs(), mesh.n_dofs());
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

/// Same shape, same stored entries in the same order, the same bits.
template <typename Expected, typename Actual>
void expect_identical(const Expected& expected, const Actual& actual, const char* what) {
  ASSERT_EQ(expected.rows(), actual.rows()) << what;
  ASSERT_EQ(expected.cols(), actual.cols()) << what;
  ASSERT_EQ(expected.nonZeros(), actual.nonZeros()) << what;
  for (Eigen::Index k = 0; k <= expected.outerSize(); ++k)
    ASSERT_EQ(expected.outerIndexPtr()[k], actual.outerIndexPtr()[k]) << what << ": outer " << k;
  for (Eigen::Index k = 0; k < expected.nonZeros(); ++k) {
    ASSERT_EQ(expected.innerIndexPtr()[k], actual.innerIndexPtr()[k]) << what << ": entry " << k;
    ASSERT_EQ(expected.valuePtr()[k], actual.valuePtr()[k]) << what << ": entry " << k;
  }
}

void expect_blocks_of_triplet_assembly(const LayerMesh& mesh, const Matrix8& Ke) {
  const SparseMatrix full = triplet_assembly(mesh, Ke);
  const int n_free = mesh.n_free(), n_top = mesh.n_top(), n = mesh.n_dofs();
  const DofRange all{0, n}, free{0, n_free}, top{n_free, n};
  expect_identical(RowSparseMatrix(full), assemble_uniform_rows(mesh, Ke, all, all), "all, rows");
  expect_identical(full, assemble_uniform(mesh, Ke), "all, columns");
  expect_identical(SparseMatrix(full.topLeftCorner(n_free, n_free)), assemble_uniform_columns(mesh, Ke, free, free),
                   "free-free, columns");
  expect_identical(RowSparseMatrix(full.topLeftCorner(n_free, n_free)), assemble_uniform_rows(mesh, Ke, free, free),
                   "free-free, rows");
  expect_identical(RowSparseMatrix(full.topRightCorner(n_free, n_top)), assemble_uniform_rows(mesh, Ke, free, top),
                   "free-top, rows");
  expect_identical(RowSparseMatrix(full.bottomRows(n_top)), assemble_uniform_rows(mesh, Ke, top, all), "top, rows");
}

TEST(Assembly, BlocksAreTheTripletAssemblyBitForBit) {
  for (const LayerMesh& mesh : {LayerMesh(3, 1, 0.5), LayerMesh(4, 2, 0.5), LayerMesh(7, 5, 0.8)}) {
    for (Integration integration : testing::kAllIntegrations)
      for (double nu : {0.0, 0.3, 0.49})
        expect_blocks_of_triplet_assembly(mesh, quad4_stiffness(1000.0, nu, mesh.h, integration));
    for (MassKind kind : {MassKind::consistent, MassKind::lumped})
      expect_blocks_of_triplet_assembly(mesh, quad4_mass(2.5, mesh.h, kind));
  }
}

/// A mutation check of the oracle's premise: a nonsymmetric element matrix (each entry distinct) tells
/// rows from columns, so a transposed block cannot pass.
TEST(Assembly, ColumnsAreNotTheTransposedRows) {
  const LayerMesh mesh(5, 3, 1.0);
  Matrix8 Ke;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) Ke(a, b) = 1.0 + a + 0.125 * b;
  expect_blocks_of_triplet_assembly(mesh, Ke);
  const SparseMatrix columns = assemble_uniform(mesh, Ke);
  EXPECT_NE(SparseMatrix(columns.transpose()).coeff(0, 2), columns.coeff(0, 2));
}

// The default path multiplies M_ff by the leading block of M (all DOFs) instead of assembling M_ff: the bits of
// the assembled block's product, for the stiffness and both masses (rows next to the top have entries to skip),
// on vectors with values of every sign and size (and zeros, whose sign a sum from 0 keeps as Eigen's does).
TEST(Assembly, LeadingBlockProductIsTheBlocksProductBitForBit) {
  for (const LayerMesh& mesh : {LayerMesh(3, 1, 0.5), LayerMesh(7, 5, 0.8)}) {
    const DofRange all{0, mesh.n_dofs()}, free{0, mesh.n_free()};
    for (const Matrix8& Ke :
         {quad4_stiffness(1000.0, 0.3, mesh.h, Integration::full), quad4_mass(2.5, mesh.h, MassKind::consistent),
          quad4_mass(2.5, mesh.h, MassKind::lumped)}) {
      const RowSparseMatrix A = assemble_uniform_rows(mesh, Ke, all, all);
      const RowSparseMatrix block = assemble_uniform_rows(mesh, Ke, free, free);
      for (int seed : {1, 2}) {
        Eigen::VectorXd x = testing::random_vector(mesh.n_free(), seed);
        for (Eigen::Index k = 0; k < x.size(); k += 5) x(k) *= 1e-30;
        if (seed == 2) x.setZero();
        const Eigen::VectorXd expected = block * x, actual = leading_block_product(A, mesh.n_free(), x);
        ASSERT_EQ(actual.size(), expected.size());
        EXPECT_EQ(std::memcmp(actual.data(), expected.data(), sizeof(double) * actual.size()), 0);
      }
    }
  }
  const LayerMesh mesh(3, 1, 0.5);
  const RowSparseMatrix A = assemble_uniform_rows(mesh, quad4_mass(2.5, mesh.h, MassKind::consistent),
                                                  {0, mesh.n_dofs()}, {0, mesh.n_dofs()});
  EXPECT_THROW(leading_block_product(A, mesh.n_free(), Eigen::VectorXd::Zero(mesh.n_free() + 1)),
               std::invalid_argument);
}

TEST(Assembly, UniformRowsProductIsTheAssembledBlocksProductBitForBit) {
  for (const LayerMesh& mesh : {LayerMesh(3, 1, 0.5), LayerMesh(4, 2, 0.5), LayerMesh(7, 5, 0.8)}) {
    const int n = mesh.n_dofs(), n_free = mesh.n_free();
    const DofRange all{0, n}, free{0, n_free}, top{n_free, n};
    for (const Matrix8& Ke :
         {quad4_stiffness(1000.0, 0.3, mesh.h, Integration::full),
          quad4_stiffness(1000.0, 0.49, mesh.h, Integration::reduced), quad4_mass(2.5, mesh.h, MassKind::consistent),
          quad4_mass(2.5, mesh.h, MassKind::lumped)}) {
      const UniformRows rows(mesh, Ke);
      const RowSparseMatrix A = assemble_uniform_rows(mesh, Ke, all, all);
      for (const auto& [r, c] :
           {std::pair{all, all}, std::pair{free, free}, std::pair{top, top}, std::pair{free, top}}) {
        const RowSparseMatrix block = assemble_uniform_rows(mesh, Ke, r, c);
        for (int seed : {1, 2}) {
          Eigen::VectorXd x = testing::random_vector(c.size(), seed);
          for (Eigen::Index k = 0; k < x.size(); k += 5) x(k) *= 1e-30;
          if (seed == 2) x.setZero();
          const Eigen::VectorXd expected = block * x, actual = rows.product(r, c, x);
          ASSERT_EQ(actual.size(), expected.size());
          EXPECT_EQ(std::memcmp(actual.data(), expected.data(), sizeof(double) * actual.size()), 0)
              << "rows " << r.begin << ".." << r.end << ", columns " << c.begin << ".." << c.end << ", seed " << seed;
        }
      }
      // The same as the whole matrix's product, the block by Eigen's block product (the layer's uses).
      const Eigen::VectorXd x = testing::random_vector(n, 4);
      const Eigen::VectorXd whole = A * x, corner = A.bottomRightCorner(n - n_free, n - n_free) * x.tail(n - n_free);
      EXPECT_EQ(std::memcmp(rows.product(all, all, x).data(), whole.data(), sizeof(double) * n), 0);
      EXPECT_EQ(
          std::memcmp(rows.product(top, top, x.tail(n - n_free)).data(), corner.data(), sizeof(double) * corner.size()),
          0);
    }
  }
  const LayerMesh mesh(3, 1, 0.5);
  EXPECT_THROW(UniformRows(mesh, quad4_mass(2.5, mesh.h, MassKind::consistent))
                   .product({0, mesh.n_free()}, {0, mesh.n_free()}, Eigen::VectorXd::Zero(mesh.n_free() + 1)),
               std::invalid_argument);
}

TEST(Assembly, RowsOfSomeNodeColumnsAreTheAssembledRows) {
  const LayerMesh mesh(7, 3, 0.5);
  const Matrix8 Ke = quad4_stiffness(1000.0, 0.3, mesh.h, Integration::full);
  const DofRange all{0, mesh.n_dofs()};
  const RowSparseMatrix A = assemble_uniform_rows(mesh, Ke, all, all);
  const RowSparseMatrix some = UniformRows(mesh, Ke).rows(all, all, {0, 1, 6});
  ASSERT_EQ(some.rows(), A.rows());
  ASSERT_EQ(some.cols(), A.cols());
  int n_kept = 0;
  for (int row = 0; row < A.rows(); ++row) {
    const int i = (row / 2) % mesh.n_x;
    const bool kept = i == 0 || i == 1 || i == 6;
    const Eigen::SparseVector<double> expected =
        kept ? Eigen::SparseVector<double>(A.row(row).transpose()) : Eigen::SparseVector<double>(A.cols());
    const Eigen::SparseVector<double> actual = some.row(row).transpose();
    ASSERT_EQ(actual.nonZeros(), expected.nonZeros()) << "row " << row;
    for (Eigen::Index k = 0; k < actual.nonZeros(); ++k) {
      EXPECT_EQ(actual.innerIndexPtr()[k], expected.innerIndexPtr()[k]) << "row " << row;
      EXPECT_EQ(actual.valuePtr()[k], expected.valuePtr()[k]) << "row " << row;
    }
    n_kept += kept;
  }
  EXPECT_EQ(n_kept, 2 * 3 * (mesh.n_y + 1));
}

}  // namespace
}  // namespace slidewave
