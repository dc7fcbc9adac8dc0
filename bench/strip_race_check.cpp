// Every strip preset on a bent cone, for a ThreadSanitizer build: TBB runs on one thread (TSan
// does not see its synchronisation, libtbb not being instrumented), and the two halves of the
// split sweep run on two std::threads (strip_model.cpp under __SANITIZE_THREAD__), so that
// whatever TSan reports between them is real.
//
//   cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS=-fsanitize=thread
//         -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread    (one command)
//   cmake --build build-tsan --target phellem_bench_strip_race_check
//   setarch -R build-tsan/bench/phellem_bench_strip_race_check [STEPS]   (setarch: TSan needs
//   the address layout of a kernel without full randomization)
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bark/geometry/generalized_cylinder.h"
#include "bark/strips/presets.h"
#include "bark/strips/strip_domain.h"
#include "bark/strips/strip_model.h"

using namespace phellem::bark;

int main(int argc, char** argv) {
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  for (const std::string& name : strip_preset_names()) {
    StripParams p = *strip_preset(name);
    p.steps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 48;
    if (name == "plated") p.refracture_width = 0.01;
    const GeneralizedCylinder cone({{0, 0, 0}, {0, 1.2, 0.1}}, {0.2, 0.08});
    StripModel m(oriented_domain(cone, p), p);
    while (m.steps_done() < m.steps_total()) m.step();
    std::printf("%s: %zu strips, %d steps, %lld fractures, %lld propagations\n", name.c_str(), m.strips().size(), m.steps_done(),
                m.stats().created, m.stats().propagated);
  }
}
