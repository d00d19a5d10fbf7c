// Open CASCADE on demand (brep/brep_backend.h): the pdcheck binary does not
// link it, a STEP file loads the module beside the binary, and where the
// module is missing each B-rep file is a part error that says so while the
// mesh parts are checked.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "brep_cases.h"
#include "shell_run.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using Kind = pd_test::BrepSolid::Kind;

namespace {

// A scene of one STEP assembly (a box and a cylinder 1 mm deep into it) and
// the demo's two meshes, written in `dir`.
void write_mixed_scene(const std::string& dir) {
  pd_test::write_step_assembly(dir + "/pair.step",
                               {{"box", {Kind::kBox, {10, 10, 10}}, pd::Vec3(1000, 0, 0)},
                                {"rod", {Kind::kCylinder, {2, 20}}, pd::Vec3(1005, 5, 9)}});
  const std::string demo = std::string(PDCHECK_SOURCE_DIR) + "/testdata/demo/";
  json scene = {{"units", "mm"},
                {"tolerance", 0.1},
                {"parts",
                 {{{"id", "pair"}, {"mesh", "pair.step"}},
                  {{"id", "base"}, {"mesh", demo + "base.stl"}},
                  {{"id", "cover"}, {"mesh", demo + "cover.obj"}}}}};
  std::ofstream(dir + "/scene.json") << scene.dump(1);
}

}  // namespace

TEST(BrepModule, ThePdcheckBinaryLinksNoOpenCascadeLibrary) {
  const std::string dir = pd_test::scratch_dir("brep_module_needed");
  const auto r = pd_test::shell(dir, "readelf -d \"$PDCHECK\" | grep NEEDED");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("libc.so"), std::string::npos) << r.out;  // the listing is real
  EXPECT_EQ(r.out.find("libTK"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("libtbb"), std::string::npos) << r.out;
}

TEST(BrepModule, AStepFileIsReadThroughTheModuleBesideTheBinary) {
  const std::string dir = pd_test::scratch_dir("brep_module_beside");
  write_mixed_scene(dir);
  const auto r = pd_test::shell(dir, "\"$PDCHECK\" scene.json --no-cache -q -o report.json");
  EXPECT_EQ(r.code, 1) << r.err;  // the rod in the box
  const json report = json::parse(pd_test::read_text(dir + "/report.json"));
  EXPECT_EQ(report["summary"]["part_errors"], 0) << r.err;
  int rods = 0;
  for (const json& p : report["pairs"])
    if (p["a"] == "pair/box" && p["b"] == "pair/rod") {
      ++rods;
      EXPECT_EQ(p["status"], "interference") << p.dump();
    }
  EXPECT_EQ(rods, 1) << report["pairs"].dump();
}

TEST(BrepModule, WithoutTheModuleEachBrepFileIsAPartErrorAndTheMeshesAreChecked) {
  const std::string dir = pd_test::scratch_dir("brep_module_missing");
  write_mixed_scene(dir);
  // The binary alone in a directory of its own: no module beside it.
  fs::create_directories(dir + "/bin");
  fs::copy_file(pd_test::kPdcheck, dir + "/bin/pdcheck");
  const auto r = pd_test::shell(dir, "bin/pdcheck scene.json --no-cache -o report.json");
  EXPECT_EQ(r.code, 3) << r.err;  // a part could not be read: its pairs are unchecked
  EXPECT_NE(r.err.find("pair.step"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pdcheck_occt.so"), std::string::npos) << r.err;
  const json report = json::parse(pd_test::read_text(dir + "/report.json"));
  EXPECT_EQ(report["summary"]["part_errors"], 1) << r.err;
  int meshes = 0;  // the demo's base and cover, checked
  for (const json& p : report["pairs"])
    if (p["a"] == "base" && p["b"] == "cover") {
      ++meshes;
      EXPECT_NE(p["status"], "error") << p.dump();
    }
  EXPECT_EQ(meshes, 1) << r.out;
}

TEST(BrepModule, ARerunFromTheCacheNeedsNoModule) {
  const std::string dir = pd_test::scratch_dir("brep_module_rerun");
  write_mixed_scene(dir);
  fs::create_directories(dir + "/bin");
  fs::copy_file(pd_test::kPdcheck, dir + "/bin/pdcheck");
  // The first run meshes the file and stores its read; a rerun takes it from
  // the cache and never calls Open CASCADE (the rod's interference is
  // certified by the sag bound), so even a binary without the module runs it.
  // The dynamic linker names each object it loads (LD_DEBUG=files): the
  // first run loads the module, a rerun of the same binary does not.
  const std::string cache = " --cache cache -q -o report.json 2>&1 | grep -c pdcheck_occt.so";
  const auto first = pd_test::shell(dir, "LD_DEBUG=files \"$PDCHECK\" scene.json" + cache);
  EXPECT_NE(first.out, "0\n") << first.err;
  const auto rerun = pd_test::shell(dir, "LD_DEBUG=files \"$PDCHECK\" scene.json" + cache);
  EXPECT_EQ(rerun.out, "0\n") << rerun.err;
  const auto again = pd_test::shell(dir, "bin/pdcheck scene.json --cache cache -q -o report.json");
  EXPECT_EQ(again.code, 1) << again.err;
  const json report = json::parse(pd_test::read_text(dir + "/report.json"));
  EXPECT_EQ(report["summary"]["part_errors"], 0) << again.err;
  for (const json& p : report["pairs"])
    if (p["a"] == "pair/box") {
      EXPECT_EQ(p["status"], "interference") << p.dump();
      EXPECT_EQ(p["exact"]["verdict"], "interference") << p.dump();
    }
}
