// Post-processing of the crack edges (Spicker 2014 sec. 4.2): connected components
// (Figure 27) and the crack width at each crack vertex by the breadth-first search of
// Algorithm 1.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace phellem::bark {

// The crack edges as a graph over the mesh's vertices.
struct CrackGraph {
  std::vector<std::vector<uint32_t>> adjacency;  // per vertex: neighbours along crack edges
  static CrackGraph from_edges(std::size_t vertices, const std::vector<std::pair<uint32_t, uint32_t>>& edges);
};

// Component id per vertex (numbered in order of their smallest vertex), −1 for a vertex on
// no crack edge.
std::vector<int32_t> crack_components(const CrackGraph& g);

// Algorithm 1 for every vertex: the breadth-first distance (in crack edges) to the nearest
// vertex of degree 1 in its component; in a component without one (a closed crack), the
// search runs until it finds no new vertices and the width is the last distance at which it
// found one (the vertex's eccentricity). 0 off cracks. (As transcribed, the algorithm never
// increments its distance; counting levels is what its description says it computes.)
// The components with ends are done by one multi-source search from all their ends.
std::vector<int32_t> crack_widths(const CrackGraph& g);

}  // namespace phellem::bark
