#pragma once
// The order-2 space as the finest level of the multilevel method (docs/method.md §10): the
// lowest-order space on the same mesh is the level below it, and the levels below that are
// the usual hierarchy.

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"
#include "fem/fosls_space.hpp"
#include "fem/p2_rt1_space.hpp"

namespace fosls {

/// P1 × RT0 ⊂ P2 × RT1 on one mesh as a full, Cartesian matrix: u at a midpoint the mean of its
/// edge's ends, RT0's flux S as the end DOFs (S/2, S/2), a triangle's σ means those of its RT0
/// field (exact: the spaces are nested).
Eigen::SparseMatrix<double> order2_embedding(const FoslsSpace<2>& lowest, const P2Rt1Space& order2);

/// The lowest-order interpolant of an order-2 field, both as full rotated DOF vectors: u at the
/// vertices, each edge's flux (the sum of its two end DOFs: RT0's canonical interpolation,
/// which keeps the divergence's mean on every triangle and the force on every edge). What the
/// output of an order-2 solve is written from (contact output, VTU, docs/method.md §10).
Vector lowest_order_interpolant(const FoslsSpace<2>& lowest, const P2Rt1Space& order2,
                                const Vector& x_full);

/// The level of `order2` above `lowest`: the embedding between free DOFs in both spaces' rotated
/// coordinates, the vertex patches (the vertex's node, the midpoints and σ DOFs of its edges and
/// the σ means of its triangles: every DOF whose function lives in the vertex's star), the
/// contact links (each contact edge's P1 DOFs with its order-2 DOFs: the ends and the midpoint of
/// U_n, the two S_n ends) and the contact strip.
Level order2_level(const FoslsSpace<2>& lowest, const P2Rt1Space& order2);

}  // namespace fosls
