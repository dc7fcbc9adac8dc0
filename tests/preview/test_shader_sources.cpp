// The preview's GLSL validated offline by Khronos' reference compiler (glslangValidator, from
// Debian's glslang-tools), stage by stage as the program assembles them — so a shader that
// only llvmpipe would accept, or one that no driver would, fails here too.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "preview/shaders.h"
#include "tests/support/test_util.h"

using namespace phellem;
using namespace phellem::preview;

namespace {

int validate(const std::string& path) {
  const std::string cmd = "glslangValidator " + path + " > " + path + ".log 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST(ShaderSources, EveryStageValidatesWithGlslangValidator) {
  ASSERT_EQ(std::system("command -v glslangValidator > /dev/null"), 0) << "glslang-tools is not installed";
  const std::string dir = test::temp_dir("shader_sources");
  // Every variant: no bark, cracks with and without tints, a fracture field; each with and
  // without an image displacement.
  for (const auto& [kind, tints] : {std::pair{0, false}, std::pair{1, false}, std::pair{1, true}, std::pair{2, false}})
    for (bool image : {false, true})
      for (Stage s : {Stage::Vertex, Stage::TessControl, Stage::TessEvaluation, Stage::Fragment}) {
        const std::string path =
            dir + "/bark_" + std::to_string(kind) + (tints ? "t" : "") + (image ? "i." : ".") + stage_extension(s);
        std::ofstream(path) << stage_source(s, bark_defines(kind, tints, image));
        EXPECT_EQ(validate(path), 0) << test::read_text(path + ".log");
      }
  for (const char* frag : {"background.frag", "overlay.frag"})
    for (Stage s : {Stage::Vertex, Stage::Fragment}) {
      const std::string path = dir + "/" + std::string(frag).substr(0, std::string(frag).find('.')) + "_screen." + stage_extension(s);
      std::ofstream(path) << screen_source(s, frag);
      EXPECT_EQ(validate(path), 0) << test::read_text(path + ".log");
    }
  // The check can fail: a stage with an undeclared variable is refused.
  const std::string bad = dir + "/broken.frag";
  std::ofstream(bad) << "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(undeclared); }\n";
  EXPECT_NE(validate(bad), 0);
}

TEST(ShaderSources, StagesStartWithTheVersionAndIncludeTheirFilesInOrder) {
  const std::string tese = stage_source(Stage::TessEvaluation);
  EXPECT_EQ(tese.rfind("#version 450 core\n", 0), 0u);
  const size_t noise = tese.find("float gradient_noise("), crack = tese.find("CrackSample crack_at("),
               main_at = tese.find("void main()");
  ASSERT_NE(noise, std::string::npos);
  ASSERT_NE(crack, std::string::npos);
  EXPECT_LT(noise, crack);
  EXPECT_LT(crack, main_at);
  // The image displacement's lookup comes before the evaluation stage that calls it.
  const size_t image = tese.find("float image_displacement_at(");
  ASSERT_NE(image, std::string::npos);
  EXPECT_LT(image, main_at);
  EXPECT_THROW(shader_file("missing.glsl"), std::logic_error);
}
