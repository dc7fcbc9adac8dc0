// TetGen run in a child process. Debian's TetGen 1.5.0 is built with its assertions on: on a
// degenerate or self-intersecting input (a user's mesh, or a grown interface that has folded
// onto itself) it may abort or crash instead of throwing, and that must not take Phellem
// down with a signal. The child (fork) runs tetrahedralize() on the input already in memory
// and sends the mesh back through a pipe; a child that dies or reports an error is a
// TetgenFailure the caller turns into a UserError or a step without remeshing. The child never
// outlives Phellem: the kernel kills it when Phellem dies (PR_SET_PDEATHSIG, even by SIGKILL),
// a termination signal kills it first (util/temp_files.h LiveChild), and every way out of
// tetrahedralize_in_child kills and reaps it.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#define TETLIBRARY
#include <tetgen.h>

namespace phellem::bark {

struct TetgenMesh {
  std::vector<double> points;      // 3 per point, TetGen's order
  std::vector<int> tets;           // 4 per tetrahedron (TetGen's first-index is 0)
  std::vector<double> attributes;  // per tetrahedron, `attributes_per_tet` each
  int attributes_per_tet = 0;
};

class TetgenFailure : public std::runtime_error {
 public:
  explicit TetgenFailure(const std::string& what, bool timed_out = false) : std::runtime_error(what), timed_out_(timed_out) {}
  // Stopped at its time limit (rather than failing on its own).
  bool timed_out() const { return timed_out_; }

 private:
  bool timed_out_;
};

// tetrahedralize(switches, in, out) in a child process (its output to stdout and stderr
// discarded), killed if it has not finished after `time_limit_s` seconds. Throws TetgenFailure
// with what happened: TetGen's error code, the signal that stopped it, or the time limit.
TetgenMesh tetrahedralize_in_child(const std::string& switches, tetgenio& in, double time_limit_s);

}  // namespace phellem::bark
