// Strip-model bark on a whole tree (Lefebvre & Neyret 2002, sec. 5.3, Figure 20): one
// StripModel per generalized cylinder (trunk, branches), grown in lockstep. At a branching,
// sharp fracture tips of the parent near the line where the child emerges continue into the
// child's strips at the same 3D point, and the child's tips near its base continue into the
// parent: the curvilinear parameterization covers propagation along one cylinder, the 3D
// proximity test covers the junction. Horizontal fractures (strips along the axis) run around
// each limb and are not continued across junctions.
#pragma once

#include <functional>
#include <memory>
#include <set>
#include <vector>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/strips/strip_model.h"

namespace phellem::bark {

struct TreeCylinder {
  std::shared_ptr<const GeneralizedCylinder> cylinder;
  int parent = -1;    // index of the parent cylinder (-1: the trunk)
  double attach = 0;  // where it leaves the parent, as a fraction of the parent's length
};

// One fracture continued across a junction (for statistics and tests).
struct JunctionCrossing {
  int from = 0, to = 0;            // cylinder indices
  Eigen::Vector3d at_from, at_to;  // 3D points of the tip and of the new fracture
  int step = 0;
};

class TreeStripBark {
 public:
  // Throws StripParamError (from any cylinder's model) when a parameter is out of range.
  TreeStripBark(std::vector<TreeCylinder> cylinders, const StripParams& params);

  // One block of growth steps of every cylinder (StripModel::step(); every cylinder of a
  // tree has the same bark, so they advance alike), then the junction transfers.
  void step();
  // Applies every model's pending hardening and plasticity (StripModel::settle): call before
  // reading an intermediate state.
  void settle();
  // All remaining steps; `progress` is called after each block with (done, total).
  void run(const std::function<void(int, int)>& progress = {});

  const std::vector<TreeCylinder>& cylinders() const { return cylinders_; }
  const StripModel& model(size_t k) const { return *models_[k]; }
  size_t size() const { return models_.size(); }
  const std::vector<JunctionCrossing>& crossings() const { return crossings_; }

 private:
  struct Junction {
    int parent = 0, child = 0;
    size_t parent_first = 0, parent_last = 0;         // parent strips around the emergence line
    size_t child_last = 0;                            // child strips [0, child_last) near its base
    std::set<int32_t> sent_to_child, sent_to_parent;  // fracture roots already continued
  };
  void transfer(Junction& j, bool parent_to_child);

  std::vector<TreeCylinder> cylinders_;
  std::vector<std::unique_ptr<StripModel>> models_;
  std::vector<Junction> junctions_;
  std::vector<JunctionCrossing> crossings_;
};

}  // namespace phellem::bark
