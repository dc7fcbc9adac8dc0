// Seeds are unsigned 64-bit integers everywhere in a scene (render.seed, displacement,
// procedural meshes and every bark model), read exactly: no float on the way, no fractions,
// no negatives, nothing above 2^64 - 1; every refusal states the one range.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "util/errors.h"
#include "util/hash.h"

namespace phellem {
namespace {

using test::error_of;

const char* kRange = "[0, 18446744073709551615]";

std::string strips_tree(const std::string& seed) {
  return R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 2, 0]], "radius": [0.2],
             "bark": {"model": "strips", "seed": )" +
         seed + "}}]}";
}
std::string stress_mesh(const std::string& seed) {
  return R"({"objects": [{"type": "mesh", "procedural": {"shape": "sheet"}, "bark": {"model": "stress", "seed": )" + seed +
         "}}]}";
}
std::string render_seed(const std::string& seed) { return R"({"render": {"seed": )" + seed + "}}"; }
std::string displacement(const std::string& seed) {
  return R"({"objects": [{"type": "mesh", "procedural": {"shape": "trunk"}, "displacement": {"type": "noise", "seed": )" + seed +
         "}}]}";
}
std::string procedural(const std::string& seed) {
  return R"({"objects": [{"type": "mesh", "procedural": {"shape": "trunk", "seed": )" + seed + "}}]}";
}

SceneDesc parse(const std::string& json) { return parse_scene(json, "scene.json", "."); }

TEST(Seeds, BarkSeedsAreExactIntegers) {
  // 123456789 is not a float: through one it became 123456792.
  EXPECT_EQ(parse(strips_tree("123456789")).objects[0].tree.strip_bark->params.seed, 123456789u);
  EXPECT_EQ(parse(stress_mesh("123456789")).objects[0].stress_bark->params.seed, 123456789u);
  EXPECT_EQ(parse(strips_tree("4294967295")).objects[0].tree.strip_bark->params.seed, 4294967295u);
  EXPECT_EQ(parse(stress_mesh("4294967296")).objects[0].stress_bark->params.seed, 4294967296u);
  EXPECT_EQ(parse(strips_tree("18446744073709551615")).objects[0].tree.strip_bark->params.seed, 18446744073709551615u);
  EXPECT_EQ(parse(stress_mesh("18446744073709551615")).objects[0].stress_bark->params.seed, 18446744073709551615u);
}

TEST(Seeds, EverySeedTakesTheWholeRange) {
  const uint64_t top = 18446744073709551615u;
  EXPECT_EQ(uint64_t(parse(render_seed("18446744073709551615")).render.seed), top);
  EXPECT_EQ(uint64_t(parse(render_seed("4294967296")).render.seed), 4294967296u);
  EXPECT_EQ(uint64_t(parse(displacement("18446744073709551615")).objects[0].displacement.seed), top);
  EXPECT_EQ(uint64_t(parse(procedural("18446744073709551615")).objects[0].procedural->seed), top);
  // Bark without a seed of its own takes render.seed, all 64 bits of it.
  const std::string tree =
      R"({"render": {"seed": 12345678901234567890}, "objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 2, 0]],
                              "radius": [0.2], "bark": {"model": "strips"}}]})";
  EXPECT_EQ(parse(tree).objects[0].tree.strip_bark->params.seed, 12345678901234567890u);
}

TEST(Seeds, FractionsNegativesAndTooLargeAreRefusedWithTheRange) {
  struct Case {
    std::string json, path;
  };
  const std::vector<Case> cases = {
      {strips_tree("1.5"), "/objects/0/bark/seed"},
      {strips_tree("-1"), "/objects/0/bark/seed"},
      {strips_tree("18446744073709551616"), "/objects/0/bark/seed"},
      {stress_mesh("2.5"), "/objects/0/bark/seed"},
      {stress_mesh("18446744073709551616"), "/objects/0/bark/seed"},
      {render_seed("-1"), "/render/seed"},
      {render_seed("0.5"), "/render/seed"},
      {render_seed("18446744073709551616"), "/render/seed"},
      {render_seed("1e30"), "/render/seed"},
      {displacement("-3"), "/objects/0/displacement/seed"},
      {displacement("18446744073709551616"), "/objects/0/displacement/seed"},
      {procedural("-3"), "/objects/0/procedural/seed"},
      {procedural("18446744073709551616"), "/objects/0/procedural/seed"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(c.json);
    EXPECT_NE(msg.find("scene.json: " + c.path + ": "), std::string::npos) << c.json << "\n" << msg;
    EXPECT_NE(msg.find(kRange), std::string::npos) << c.json << "\n" << msg;
  }
}

TEST(Seeds, FoldSeedIsTheIdentityBelow2To32) {
  // What keeps every existing scene's output bit-identical: 32-bit consumers see the same seed.
  for (uint64_t s : {0ull, 1ull, 7ull, 123456789ull, 2147483647ull, 2147483648ull, 4294967295ull})
    EXPECT_EQ(fold_seed(s), uint32_t(s)) << s;
  // Above, the high half counts: 2^32 + 5 is not 5, and seeds differing only there differ.
  EXPECT_NE(fold_seed(4294967296ull + 5), 5u);
  EXPECT_NE(fold_seed(4294967296ull + 5), fold_seed(2 * 4294967296ull + 5));
  EXPECT_NE(fold_seed(18446744073709551615ull), 4294967295u);
}

}  // namespace
}  // namespace phellem
