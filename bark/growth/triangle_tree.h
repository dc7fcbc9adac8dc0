// CGAL's AABB tree over a vector of triangles, the spatial search of the growth's set-up
// (outside_lattice.h: distances to the surface) and of its contact test (growth_contact.h:
// faces near a vertex), with the conversion of Eigen points to CGAL's.
#pragma once

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

#include <Eigen/Core>

namespace phellem::bark::triangle_tree {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

inline K::Point_3 cgal(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace phellem::bark::triangle_tree
