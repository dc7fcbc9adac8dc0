// `turntable --degrees D`: NaN, infinities and angles beyond the documented range are refused
// on the command line (they used to reach Embree and abort in an assertion).
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

TEST(TurntableDegreesCli, NonFiniteAndHugeAnglesAreRefused) {
  const std::string dir = test::temp_dir("degrees_cli");
  test::write_text(dir + "/s.json", R"({"render": {"resolution": [8, 8], "spp": 1},
      "lights": [{"type": "environment"}], "objects": [{"type": "sphere", "radius": 1}]})");
  for (const std::string d : {"nan", "NaN", "inf", "-inf", "infinity", "1e30", "-1e7"}) {
    const auto r = test::run_phellem("turntable " + dir + "/s.json --frames 2 -o " + dir + "/f_%04d.exr --degrees " + d);
    EXPECT_EQ(r.exit_code, 2) << d << ": " << r.output;
    EXPECT_NE(r.output.find("phellem: error: <command line>: --degrees: "), std::string::npos) << d << ": " << r.output;
    EXPECT_NE(r.output.find("[-1000000, 1000000]"), std::string::npos) << d << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/f_0000.exr")) << d;
  }
  const auto ok = test::run_phellem("turntable " + dir + "/s.json --frames 2 -o " + dir + "/f_%04d.exr --degrees -90");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/f_0001.exr"));
}

}  // namespace
}  // namespace phellem
