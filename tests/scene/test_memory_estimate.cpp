// scene/memory_estimate: sizes, the budget, and estimates that follow the knobs they name.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "scene/memory_budget.h"
#include "scene/scene_parser.h"
#include "util/errors.h"
#include "util/memory.h"

namespace phellem {
namespace {

TEST(MemoryEstimate, ParsesSizes) {
  EXPECT_EQ(parse_memory_size("4096"), 4096.0);
  EXPECT_EQ(parse_memory_size("6G"), 6.0 * 1073741824.0);
  EXPECT_EQ(parse_memory_size("6GiB"), 6.0 * 1073741824.0);
  EXPECT_EQ(parse_memory_size("512m"), 512.0 * 1048576.0);
  EXPECT_EQ(parse_memory_size("1.5T"), 1.5 * 1099511627776.0);
  EXPECT_NEAR(parse_memory_size("50%"), 0.5 * physical_memory(), 1.0);
  for (const char* bad : {"", "G", "-1G", "0", "6 parsecs", "150%", "nan", "inf"})
    EXPECT_THROW(parse_memory_size(bad), std::invalid_argument) << bad;
}

TEST(MemoryEstimate, TheBudgetIsTheOptionThenTheVariableThenAShareOfPhysicalMemory) {
  EXPECT_GT(physical_memory(), 256.0 * 1048576.0);
  unsetenv("PHELLEM_MEMORY_LIMIT");
  EXPECT_NEAR(memory_budget("").bytes, kDefaultMemoryShare * physical_memory(), 1.0);
  setenv("PHELLEM_MEMORY_LIMIT", "3G", 1);
  EXPECT_EQ(memory_budget("").bytes, 3.0 * 1073741824.0);
  EXPECT_EQ(memory_budget("2G").bytes, 2.0 * 1073741824.0);
  EXPECT_EQ(memory_budget("2G").source, "--memory-limit 2G");
  setenv("PHELLEM_MEMORY_LIMIT", "three", 1);
  EXPECT_THROW(memory_budget(""), UserError);
  unsetenv("PHELLEM_MEMORY_LIMIT");
}

double peak(const std::string& json, MemoryRequest req = {}) {
  return estimate_memory(parse_scene(json, "scene.json", "."), req).peak().bytes();
}

std::string strip_tree(const std::string& length, const std::string& bark) {
  return R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, )" + length +
         R"(, 0]], "radius": 0.15, "bark": {"model": "strips")" + bark + "}}]}";
}

TEST(MemoryEstimate, GrowsWithTheKnobsItNames) {
  MemoryRequest sim;
  sim.command = MemoryCommand::Simulate;
  sim.meshes = false;
  sim.field_width = sim.field_height = 16;
  const double base = peak(R"({"objects": []})", sim);  // the program itself
  EXPECT_GT(base, 100e6);
  // Twice the strips: twice the simulation.
  const double one = peak(strip_tree("10", ""), sim) - base, two = peak(strip_tree("20", ""), sim) - base;
  EXPECT_NEAR(two / one, 2.0, 0.05);
  // Strips half as wide: twice as many, with as many elements each.
  EXPECT_NEAR((peak(strip_tree("10", R"(, "strip_width": 0.0025)"), sim) - base) / one, 2.0, 0.05);
  // Elements four times as long: a quarter of them, the strips' own cost stays.
  const double longer = peak(strip_tree("10", R"(, "element_length": 0.04)"), sim) - base;
  EXPECT_GT(longer, 0.25 * one);
  EXPECT_LT(longer, 0.5 * one);
  // The fields: field_resolution for render, --res for simulate.
  MemoryRequest render;
  render.height = 100;
  EXPECT_GT(peak(strip_tree("1", R"(, "field_resolution": [4096, 4096])"), render),
            peak(strip_tree("1", R"(, "field_resolution": [1024, 1024])"), render) + 0.9e9);
  sim.field_width = sim.field_height = 4096;
  EXPECT_GT(peak(strip_tree("1", ""), sim), 4096.0 * 4096 * 80);
}

TEST(MemoryEstimate, NamesTheLargestPartAtThePeak) {
  MemoryRequest render;
  render.height = 100;
  render.film = {"the film", 5e9, "", "--res", "lower --res"};
  const SceneDesc d = parse_scene(strip_tree("1", ""), "scene.json", ".");
  try {
    check_memory(estimate_memory(d, render), {4e9, "test"});
    FAIL() << "not refused";
  } catch (const UserError& e) {
    EXPECT_EQ(e.where(), "--res");
    EXPECT_NE(e.detail().find("more than the 3.7 GiB allowed (test); lower --res"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_memory(estimate_memory(d, render), {6e9, "test"}));
}

std::string grown_log(const std::string& thickness, const std::string& cracks) {
  return R"({"objects": [{"type": "mesh", "procedural": {"shape": "log", "triangles": 4000, "radius": 0.08, "height": 0.6},
      "growth": {"steps": 10, "thickness": )" + thickness + R"(, "cracks": )" + cracks + R"(},
      "bark": {"model": "stress", "pattern": "horizontal"}}]})";
}

const MemoryItem* item_named(const MemoryMoment& m, const std::string& start) {
  for (const auto& i : m.items)
    if (i.what.rfind(start, 0) == 0) return &i;
  return nullptr;
}

TEST(MemoryEstimate, AGrowthCountsItsTetrahedraAndTheCrackingOfItsGrownSurface) {
  for (MemoryCommand command : {MemoryCommand::Simulate, MemoryCommand::Render}) {
    MemoryRequest req;
    req.command = command;
    req.height = 100;
    const auto moment = [&](const std::string& json) {
      const MemoryEstimate e = estimate_memory(parse_scene(json, "scene.json", "."), req);
      for (const auto& m : e.moments)
        if (m.stage.rfind("growing", 0) == 0) return m;
      ADD_FAILURE() << "no growing moment";
      return MemoryMoment{};
    };
    const MemoryMoment on = moment(grown_log("0.06", "true")), off = moment(grown_log("0.06", "false"));
    const MemoryItem* coupling = item_named(on, "the crack coupling of");
    ASSERT_NE(coupling, nullptr);
    EXPECT_EQ(coupling->where, "/objects/0/growth/edge_length");
    EXPECT_EQ(item_named(off, "the crack coupling of"), nullptr);
    EXPECT_NEAR(on.bytes() - off.bytes(), coupling->bytes, 1.0);
    // The coupling cracks the grown surface: thicker growth, more surface, more of both.
    const MemoryMoment thick = moment(grown_log("0.24", "true"));
    EXPECT_GT(item_named(thick, "the crack coupling of")->bytes, 1.5 * coupling->bytes);
    EXPECT_GT(item_named(thick, "the cambial growth of")->bytes, 1.5 * item_named(on, "the cambial growth of")->bytes);
    // TetGen's child at the grown size (about 500 bytes per tetrahedron measured, against 350
    // for the complex), and the parent's copies while it takes a re-tetrahedralized volume in
    // (up to 176 measured): items of their own, in step with the complex.
    struct Expected {
      const char* what;
      const char* where;
      double low, high;  // × the complex's bytes
    };
    for (const Expected& x : {Expected{"TetGen's process tetrahedralizing the grown", "/objects/0/growth/edge_length", 1.2, 1.5},
                              Expected{"the new volume of", "/objects/0/growth/tetrahedra/remesh_blocked", 0.4, 0.6}})
      for (const MemoryMoment* mm : {&on, &thick}) {
        const MemoryItem* item = item_named(*mm, x.what);
        ASSERT_NE(item, nullptr) << x.what;
        EXPECT_EQ(item->where, x.where);
        const double complex = item_named(*mm, "the cambial growth of")->bytes;
        EXPECT_GT(item->bytes, x.low * complex) << x.what;
        EXPECT_LT(item->bytes, x.high * complex) << x.what;
      }
    // A growth that never re-tetrahedralizes takes no new volume in (TetGen still runs once).
    std::string never = grown_log("0.06", "true");
    const size_t at = never.find("\"growth\": {");
    ASSERT_NE(at, std::string::npos);
    never.insert(at + 11, "\"tetrahedra\": {\"remesh_blocked\": 0}, ");
    EXPECT_EQ(item_named(moment(never), "the new volume of"), nullptr);
    EXPECT_NE(item_named(moment(never), "TetGen's process tetrahedralizing the grown"), nullptr);
    // No separate cracking of the ungrown input: the coupling is the object's cracking.
    const MemoryEstimate e = estimate_memory(parse_scene(grown_log("0.06", "true"), "scene.json", "."), req);
    for (const auto& m : e.moments) EXPECT_EQ(m.stage.rfind("cracking", 0), std::string::npos) << m.stage;
  }
}

}  // namespace
}  // namespace phellem
