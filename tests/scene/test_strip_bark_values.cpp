// Strip bark's irregular-fissure keys (issue 22) outside their ranges are refused at their
// JSON paths with the range; values inside, the edges included, parse.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parser.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string error_of(const std::string& extra) {
  try {
    parse_scene(R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1, 0]], "radius": [0.1, 0.1],
                                 "bark": {"model": "strips", "preset": "fissured", )" +
                    extra + "}}]}",
                "scene.json", ".");
  } catch (const UserError& e) {
    return e.what();
  }
  return "<no error>";
}

void expect_refused(const std::string& key, const std::string& value, const std::string& range) {
  const auto msg = error_of("\"" + key + "\": " + value);
  EXPECT_NE(msg.find("scene.json: /objects/0/bark/" + key + ": " + key + ": " + range), std::string::npos) << msg;
}

TEST(StripBarkValues, ProbabilitiesOutsideTheirRangesAreRefused) {
  expect_refused("toughness_fraction", "1", "must be in [0, 1)");
  expect_refused("toughness_fraction", "-0.1", "must be in [0, 1)");
  expect_refused("anastomosis", "1.5", "must be in [0, 1]");
  expect_refused("anastomosis", "-0.01", "must be in [0, 1]");
  expect_refused("fork_probability", "2", "must be in [0, 1]");
  expect_refused("fork_probability", "-1", "must be in [0, 1]");
  expect_refused("weakness_noise", "1", "must be in [0, 1)");
  expect_refused("weakness_noise", "-0.5", "must be in [0, 1)");
  for (const char* ok : {R"("toughness_fraction": 0)", R"("toughness_fraction": 0.99)", R"("anastomosis": 1)",
                         R"("fork_probability": 1)", R"("fork_probability": 0)", R"("weakness_noise": 0.9)"})
    EXPECT_EQ(error_of(ok), "<no error>") << ok;
}

TEST(StripBarkValues, SizesMustBePositive) {
  for (const char* key : {"toughness_size", "anastomosis_reach", "fork_offset", "weakness_noise_size"}) {
    expect_refused(key, "0", "must be a positive number");
    expect_refused(key, "-0.01", "must be a positive number");
    EXPECT_EQ(error_of(std::string("\"") + key + "\": 0.03"), "<no error>") << key;
  }
}

TEST(StripBarkValues, SpiralAndPowerProfileRanges) {
  expect_refused("spiral_deg", "46", "must be in [-45, 45]");
  expect_refused("spiral_deg", "-90", "must be in [-45, 45]");
  EXPECT_EQ(error_of(R"("spiral_deg": -45)"), "<no error>");
  auto depth = [](const std::string& inner) { return error_of(R"("depth": {)" + inner + "}"); };
  EXPECT_EQ(depth(R"("profile": "power", "exponent": 0.25)"), "<no error>");
  EXPECT_EQ(depth(R"("profile": "power", "exponent": 8)"), "<no error>");
  for (const char* bad : {"0.2", "9", "-1"}) {
    const std::string msg = depth(std::string(R"("profile": "power", "exponent": )") + bad);
    EXPECT_NE(msg.find("scene.json: /objects/0/bark/depth/exponent: must be in [0.25, 8]"), std::string::npos) << msg;
  }
  const std::string msg = depth(R"("profile": "u", "exponent": 2)");
  EXPECT_NE(msg.find("/objects/0/bark/depth/exponent: exponent applies to the \"power\" profile only"), std::string::npos) << msg;
}

TEST(StripBarkValues, WeaknessNoiseWidensTheThresholdBound) {
  // sec. 3.2.3's lower bound on S holds for the weakest jittered threshold, which the noise
  // lowers: a noise that takes it below the bound is an error naming the threshold.
  const auto msg = error_of(R"("weakness_noise": 0.99, "threshold_noise": 0.9)");
  EXPECT_NE(msg.find("/objects/0/bark: threshold: S = "), std::string::npos) << msg;
}

}  // namespace
}  // namespace phellem
