// Every exit-2 message has three parts, `phellem: error: <file>: <where>: <what>`: the file
// (or <command line>), where in it (an option, a JSON path, an element, a line, or the
// operation on the file as a whole) and what is wrong. A representative run of each kind of
// failure, including those that used to leave <where> out.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

// The first line of the error, without "phellem: error: ".
std::string error_line(const std::string& output) {
  const std::string head = "phellem: error: ";
  const auto p = output.find(head);
  if (p == std::string::npos) return "";
  const auto e = output.find('\n', p);
  return output.substr(p + head.size(), e == std::string::npos ? std::string::npos : e - p - head.size());
}

// phellem without the --quiet that run_phellem appends (for a run with no arguments at all).
test::CommandResult run_bare(const std::string& args) {
  return test::run_command(std::string(PHELLEM_BINARY) + " " + args + " 2>&1");
}

struct Case {
  std::string what;  // the failure
  test::CommandResult result;
  std::string prefix;  // "<file>: <where>: " expected at the start of the message
};

void expect_three_parts(const Case& c) {
  EXPECT_EQ(c.result.exit_code, 2) << c.what << ": " << c.result.output;
  const std::string line = error_line(c.result.output);
  EXPECT_EQ(line.rfind(c.prefix, 0), 0u) << c.what << ": expected \"" << c.prefix << "...\", got: " << c.result.output;
  // file, where and what: each non-empty.
  const auto a = line.find(": ");
  const auto b = a == std::string::npos ? a : line.find(": ", a + 2);
  ASSERT_NE(b, std::string::npos) << c.what << ": fewer than three parts: " << line;
  EXPECT_GT(a, 0u) << line;
  EXPECT_GT(b, a + 2) << line;
  EXPECT_LT(b + 2, line.size()) << line;
}

TEST(ErrorWhereCli, EveryMessageHasFileWhereAndWhat) {
  const std::string d = test::temp_dir("error_where");
  const std::string tiny = R"({"render": {"resolution": [8, 8], "spp": 1}, "lights": [{"type": "environment"}],
                               "objects": [{"type": "sphere", "radius": 1}]})";
  test::write_text(d + "/tiny.json", tiny);
  test::write_text(d + "/overflow.json", R"({"camera": {"fov_deg": 1e999}})");
  test::write_text(d + "/dup.json", R"({"render": {"spp": 1, "spp": 2}})");
  test::write_text(d + "/nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  test::write_text(d + "/obj.json", R"({"objects": [{"type": "mesh", "file": "nofaces.obj"}]})");
  test::write_text(d + "/nomesh.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "scene": 0})");
  test::write_text(d + "/nomesh.json", R"({"objects": [{"type": "mesh", "file": "nomesh.gltf"}]})");
  test::write_text(d + "/broken.gltf", "{\"asset\": ");
  test::write_text(d + "/broken.json", R"({"objects": [{"type": "mesh", "file": "broken.gltf"}]})");
  test::write_text(d + "/stress.json", R"({"objects": [{"type": "mesh", "name": "t",
      "procedural": {"shape": "trunk", "triangles": 500}, "bark": {"model": "stress", "iterations": 2}}]})");
  test::write_text(d + "/nobark.json", tiny);
  std::filesystem::create_directories(d + "/taken.exr");  // a folder where the output should go

  const std::vector<Case> cases = {
      {"no command", run_bare(""), "<command line>: command: "},
      {"unknown option", test::run_phellem("render --frobnicate"), "<command line>: --frobnicate: "},
      {"bad --seed", test::run_phellem("render --seed -1"), "<command line>: --seed: "},
      {"missing scene", test::run_phellem("render " + d + "/none.json -o " + d + "/o.exr"), d + "/none.json: open: "},
      {"JSON syntax", test::run_phellem("render " + d + "/broken.gltf -o " + d + "/o.exr"), d + "/broken.gltf: line 1, column "},
      {"overflowing number", test::run_phellem("render " + d + "/overflow.json -o " + d + "/o.exr"),
       d + "/overflow.json: /camera/fov_deg: "},
      {"duplicate key", test::run_phellem("render " + d + "/dup.json -o " + d + "/o.exr"), d + "/dup.json: /render/spp: "},
      {"OBJ without faces", test::run_phellem("render " + d + "/obj.json -o " + d + "/o.exr"), d + "/nofaces.obj: faces: "},
      {"glTF without meshes", test::run_phellem("render " + d + "/nomesh.json -o " + d + "/o.exr"), d + "/nomesh.gltf: meshes: "},
      {"broken glTF", test::run_phellem("render " + d + "/broken.json -o " + d + "/o.exr"), d + "/broken.gltf: read: "},
      {"EXR not writable", test::run_phellem("render " + d + "/tiny.json -o /proc/phellem_never.exr"),
       "/proc/phellem_never.exr: write: "},  // every write is checked in one place (issue 43)
      {"PNG not writable", test::run_phellem("render " + d + "/tiny.json --png /proc/phellem_never.png"),
       "/proc/phellem_never.png: write: "},
      {"output is a folder", test::run_phellem("render " + d + "/tiny.json -o " + d + "/taken.exr"),
       d + "/taken.exr: -o: "},  // refused before any work
      {"output folder impossible", test::run_phellem("render " + d + "/tiny.json -o /proc/no/x.exr"),
       "/proc/no/x.exr: -o: "},  // refused before any work
      {"stats not writable", test::run_phellem("render " + d + "/tiny.json -o " + d + "/o.exr --stats /proc/phellem_stats.json"),
       "/proc/phellem_stats.json: write: "},
      {"simulate folder impossible", test::run_phellem("simulate " + d + "/stress.json -o /proc/no/out"), "/proc/no/out: -o: "},
      {"simulate mesh not writable", test::run_phellem("simulate " + d + "/stress.json -o /proc"), "/proc/t.glb: write: "},
      {"simulate without bark", test::run_phellem("simulate " + d + "/nobark.json -o " + d + "/sim"),
       d + "/nobark.json: /objects: "},
      {"unknown view", test::run_phellem("render --view NoSuchView --png x.png"), "<command line>: --view: "},
  };
  for (const auto& c : cases) expect_three_parts(c);
}

}  // namespace
}  // namespace phellem
