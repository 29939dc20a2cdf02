// Reference sparse matrices with known properties, for the linear-solver tests and the
// factorization benchmark: the 7-point Laplacian of an N×N×N lattice has the structure of a 3-D
// lattice of translational connectors, one unknown per node.
#pragma once

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

// 7-point Laplacian on an N³ lattice with every neighbour outside the lattice held (Dirichlet):
// 6 on the diagonal, −1 per lattice neighbour, symmetric positive definite, upper storage.
// Unknown (x, y, z) is x + N (y + N z).
SparseMatrix laplacian_3d(int points_per_side);

// Stiffness of an N³ lattice of unit spacing with axial springs along the edges and the face
// diagonals (stiffness 1/length, matrix (1/L) d dᵀ for the unit direction d), three translations
// per node numbered node by node (node_block 3), and the nodes of the face x = 0 held by a unit
// spring to ground in each direction: an elasticity-like, symmetric positive definite system in
// upper storage. Node (x, y, z) is x + N (y + N z).
SparseMatrix truss_lattice_3d(int points_per_side);

}  // namespace clinch
