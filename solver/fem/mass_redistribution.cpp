#include "fem/mass_redistribution.hpp"

#include <array>

namespace slidewave {

Matrix8 quad4_contact_row_mass(double rho, double h) {
  Matrix8 top_edge = Matrix8::Zero();  // local nodes 3, 4 (indices 2, 3): the edge at y = h
  const double m = rho * h * h;
  for (int a : {2, 3})
    for (int b : {2, 3})
      for (int d = 0; d < 2; ++d) top_edge(2 * a + d, 2 * b + d) = m * (a == b ? 2.0 : 1.0) / 6.0;
  return kContactResidualMass * quad4_mass(rho, h, MassKind::consistent) + (1 - kContactResidualMass) * top_edge;
}

namespace {

template <typename Matrix>
void add_contact_row_difference(const LayerMesh& mesh, double rho, Matrix& M, DofRange rows, DofRange cols) {
  const Matrix8 delta = quad4_contact_row_mass(rho, mesh.h) - quad4_mass(rho, mesh.h, MassKind::consistent);
  for (int e = 0; e < mesh.n_x; ++e) {  // elements 0..n_x-1: the bottom row (layer_mesh.hpp)
    const std::array<int, 4> nodes = mesh.element_nodes(e);
    for (int p = 0; p < 8; ++p)
      for (int q = 0; q < 8; ++q) {
        const int r = 2 * nodes[p / 2] + p % 2, c = 2 * nodes[q / 2] + q % 2;
        if (delta(p, q) == 0 || r < rows.begin || r >= rows.end || c < cols.begin || c >= cols.end) continue;
        M.coeffRef(r - rows.begin, c - cols.begin) += delta(p, q);
      }
  }
}

}  // namespace

void redistribute_contact_mass(const LayerMesh& mesh, double rho, RowSparseMatrix& M, DofRange rows, DofRange cols) {
  add_contact_row_difference(mesh, rho, M, rows, cols);
}

void redistribute_contact_mass(const LayerMesh& mesh, double rho, SparseMatrix& M, DofRange rows, DofRange cols) {
  add_contact_row_difference(mesh, rho, M, rows, cols);
}

}  // namespace slidewave
