#include "mesh/layer_mesh.hpp"

#include <stdexcept>

namespace slidewave {

LayerMesh::LayerMesh(int nx, int ny, double hh) : n_x(nx), n_y(ny), h(hh) {
  if (n_x < 3 || n_y < 1 || !(h > 0)) throw std::invalid_argument("LayerMesh: need n_x >= 3, n_y >= 1, h > 0");
}

std::array<int, 4> LayerMesh::element_nodes(int e) const {
  const int i = e % n_x, j = e / n_x;
  return {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
}

}  // namespace slidewave
