#include "fem/assembly.hpp"

#include <vector>

namespace slidewave {

SparseMatrix assemble_uniform(const LayerMesh& mesh, const Matrix8& Ke) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(mesh.n_elements()) * 64);
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

}  // namespace slidewave
