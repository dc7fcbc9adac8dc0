// `--seed S` takes any unsigned 64-bit integer, like the scene's seeds; anything else is
// refused on the command line with the range. The high 32 bits reach the bark models.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

const char* kRange = "[0, 18446744073709551615]";

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(SeedCli, AcceptsTheWholeUnsigned64BitRange) {
  const std::string dir = test::temp_dir("seed_cli_ok");
  test::write_text(dir + "/s.json", R"({"render": {"resolution": [8, 8], "spp": 1},
      "lights": [{"type": "environment"}], "objects": [{"type": "sphere", "radius": 1}]})");
  for (const std::string seed : {"0", "4294967295", "4294967296", "18446744073709551615"}) {
    const auto r = test::run_phellem("render " + dir + "/s.json -o " + dir + "/o.exr --seed " + seed);
    EXPECT_EQ(r.exit_code, 0) << seed << ": " << r.output;
  }
}

TEST(SeedCli, RefusesNegativesFractionsAndTooLargeWithTheRange) {
  for (const std::string seed : {"-1", "1.5", "18446744073709551616", "99999999999999999999999", "seven", "0x10"}) {
    const auto r = test::run_phellem("render --seed " + seed);
    EXPECT_EQ(r.exit_code, 2) << seed << ": " << r.output;
    EXPECT_NE(r.output.find("phellem: error: <command line>: --seed: "), std::string::npos) << seed << ": " << r.output;
    EXPECT_NE(r.output.find(kRange), std::string::npos) << seed << ": " << r.output;
  }
}

TEST(SeedCli, HighBitsOfTheSeedReachTheStressModel) {
  // 2^32 + 5 is not 5: a seed is not cut to 32 bits on its way to the simulation.
  const std::string dir = test::temp_dir("seed_cli_stress");
  test::write_text(dir + "/s.json", R"({"objects": [{"type": "mesh", "name": "t",
      "procedural": {"shape": "trunk", "triangles": 2000, "radius": 0.1, "height": 0.6},
      "bark": {"model": "stress", "preset": "pine", "iterations": 10}}]})");
  auto crack_summary = [&](const std::string& seed) {
    const auto r = test::run_phellem("simulate " + dir + "/s.json -o " + dir + "/out" + seed + " --seed " + seed);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_all(dir + "/out" + seed + "/t.glb");
  };
  const std::string low = crack_summary("5"), high = crack_summary("4294967301"), again = crack_summary("5");
  ASSERT_FALSE(low.empty());
  EXPECT_EQ(low, again);
  EXPECT_NE(low, high);
}

}  // namespace
}  // namespace phellem
