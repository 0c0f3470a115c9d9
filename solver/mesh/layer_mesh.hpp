#pragma once
// Structured periodic mesh of square Q4 elements on the layer [0, lambda) x [0, H].
// Node (i, j), i in [0, n_x) (x = i h, periodic: i = n_x is i = 0), j in [0, n_y] (y = j h).
// Node id = j * n_x + i; degree of freedom 2 * id + d (d = 0: u_x, d = 1: u_y).
// Row j = 0 touches the rigid flat (contact nodes); row j = n_y is displacement-controlled.
#include <array>
#include <vector>

namespace slidewave {

struct LayerMesh {
  LayerMesh(int n_x, int n_y, double h);

  int n_x, n_y;
  double h;
  int n_nodes() const { return n_x * (n_y + 1); }
  int n_dofs() const { return 2 * n_nodes(); }
  int n_elements() const { return n_x * n_y; }
  int node(int i, int j) const { return j * n_x + ((i % n_x) + n_x) % n_x; }
  /// Element e = j * n_x + i; nodes counter-clockwise from the lower-left corner.
  std::array<int, 4> element_nodes(int e) const;
  double x(int node_id) const { return (node_id % n_x) * h; }
  double y(int node_id) const { return (node_id / n_x) * h; }

  /// Free DOFs (rows j < n_y) are numbered first, 0..n_free-1, then the top (Dirichlet) DOFs.
  int n_free() const { return 2 * n_x * n_y; }
  int n_top() const { return 2 * n_x; }
  /// Contact DOFs in free numbering: contact node k (x = k h) has u_x at 2k and u_y at 2k+1.
  int contact_dof_x(int k) const { return 2 * k; }
  int contact_dof_y(int k) const { return 2 * k + 1; }
  int n_contact() const { return n_x; }
};

}  // namespace slidewave
