// `"split": "nodes"` (docs/scene-format.md "Split by node"): a glTF with a
// node hierarchy and an OBJ with `o`/`g` groups, written here as exporters
// write them, split into one part per node: ids and groups from the names and
// the hierarchy, node transforms under the part's own, a known interference
// between two node parts, rules selecting node parts by group, caches and
// content hashes keyed by node, unreadable files and id clashes, and shards
// merged equal to the unsharded run.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "batch/content_hashes.h"
#include "cli_support.h"
#include "scene/node_names.h"
#include "scene/parts.h"
#include "scene/rule_index.h"
#include "scene/split_nodes.h"

using nlohmann::json;
using namespace pd::test;

namespace {

std::string dir() {
  const auto d =
      std::filesystem::temp_directory_path() / ("pdcheck_split_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d.string() + "/";
}

std::string base64(const std::string& bytes) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t k = 0;
  for (; k + 2 < bytes.size(); k += 3) {
    const unsigned v = (unsigned char)bytes[k] << 16 | (unsigned char)bytes[k + 1] << 8 |
                       (unsigned char)bytes[k + 2];
    for (int s = 18; s >= 0; s -= 6) out += t[(v >> s) & 63];
  }
  if (k < bytes.size()) {
    unsigned v = (unsigned char)bytes[k] << 16;
    if (k + 1 < bytes.size()) v |= (unsigned char)bytes[k + 1] << 8;
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += k + 1 < bytes.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

template <class T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A glTF 2.0 as exporters write it: one buffer (base64 data URI) holding a
// unit cube's float32 positions, the same cube moved +2 in x, and the
// triangles' uint16 indices; mesh 0 is the cube, mesh 1 has two primitives
// (the cube and its moved copy: assimp makes them two meshes on one node).
// `nodes` and `roots` are the file's nodes and its scene's root list.
std::string gltf(const json& nodes, const json& roots) {
  std::string buf;
  for (double dx : {0.0, 2.0})
    for (int k = 0; k < 8; ++k) {
      put(buf, float(dx + (k & 1)));
      put(buf, float((k >> 1) & 1));
      put(buf, float((k >> 2) & 1));
    }
  const int tri[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& t : tri)
    for (int c : t) put(buf, std::uint16_t(c));
  const json attr0 = {{"POSITION", 0}}, attr1 = {{"POSITION", 1}};
  json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "pdcheck test"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", roots}}}},
      {"nodes", nodes},
      {"meshes",
       {{{"name", "cube"}, {"primitives", {{{"attributes", attr0}, {"indices", 2}}}}},
        {{"name", "two"},
         {"primitives",
          {{{"attributes", attr0}, {"indices", 2}}, {{"attributes", attr1}, {"indices", 2}}}}}}},
      {"buffers",
       {{{"byteLength", buf.size()},
         {"uri", "data:application/octet-stream;base64," + base64(buf)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 96}},
        {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 96}},
        {{"buffer", 0}, {"byteOffset", 192}, {"byteLength", 72}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 8},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 1}}},
        {{"bufferView", 1},
         {"componentType", 5126},
         {"count", 8},
         {"type", "VEC3"},
         {"min", {2, 0, 0}},
         {"max", {3, 1, 1}}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 36}, {"type", "SCALAR"}}}}};
  return doc.dump();
}

json node(const std::string& name, std::optional<int> mesh, std::vector<double> t,
          std::vector<int> children = {}, std::optional<double> scale = std::nullopt) {
  json n = json::object();
  if (!name.empty()) n["name"] = name;
  if (mesh) n["mesh"] = *mesh;
  if (t != std::vector<double>{0, 0, 0}) n["translation"] = t;
  if (scale) n["scale"] = {*scale, *scale, *scale};
  if (!children.empty()) n["children"] = children;
  return n;
}

// The assembly: two scene roots (assimp puts them under a root of its own).
// frame (no mesh) holds a plate (the cube scaled 4: [0, 4]^3), a bolt reaching
// 0.5 into the plate's +x face (x in [3.5, 4.5]: the only overlap, depth 0.5),
// a second "bolt" apart, an unnamed node, and "sub/asm" (a name with '/')
// moved +10 in y holding "pin" (two meshes). "extra" stands alone at x = 50.
std::string assembly_gltf() {
  const json nodes = {node("frame", std::nullopt, {0, 0, 0}, {1, 2, 3, 4, 6}),
                      node("plate", 0, {0, 0, 0}, {}, 4.0),
                      node("bolt", 0, {3.5, 1, 1}),
                      node("bolt", 0, {10, 0, 0}),
                      node("", 0, {20, 0, 0}),
                      node("extra", 0, {50, 0, 0}),
                      node("sub/asm", std::nullopt, {0, 10, 0}, {7}),
                      node("pin", 1, {0, 0, 0})};
  const std::string path = dir() + "assembly.gltf";
  std::ofstream(path) << gltf(nodes, {0, 5});
  return path;
}

// An OBJ as CAD exporters write one: objects (`o`) and groups (`g`), sharing
// one vertex list. assimp makes each a child of the root, in file order (a
// repeated name is not tested here: assimp 5.2.5 then files later faces under
// another object).
std::string groups_obj() {
  const std::string path = dir() + "groups.obj";
  std::ofstream(path) << "# exported\nmtllib none.mtl\n"
                         "o housing\n"
                         "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\n"
                         "f 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
                         "g lid\n"
                         "v 0 0 5\nv 1 0 5\nv 0 1 5\nv 0 0 6\n"
                         "f 5 6 7\nf 5 6 8\nf 5 7 8\nf 6 7 8\n"
                         "o cover\n"
                         "v 9 0 0\nv 10 0 0\nv 9 1 0\nv 9 0 1\n"
                         "f 9 10 11\nf 9 10 12\nf 9 11 12\nf 10 11 12\n";
  return path;
}

std::string scene_file(const std::string& name, const json& scene) {
  const std::string path = dir() + name;
  std::ofstream(path) << scene.dump(1);
  return path;
}

json split_part(const std::string& id, const std::string& mesh) {
  return {{"id", id}, {"mesh", mesh}, {"units", "mm"}, {"split", "nodes"}};
}

std::map<std::string, pd::Part> by_id(const std::vector<pd::Part>& parts) {
  std::map<std::string, pd::Part> out;
  for (const pd::Part& p : parts) out[p.id] = p;
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(NodeMeshes, PathsFromTheHierarchy) {
  const pd::NodeMeshes m = pd::load_node_meshes(assembly_gltf());
  // frame's children in file order, then extra; pin's two meshes share its path.
  EXPECT_EQ(m.nodes,
            (std::vector<std::string>{"frame/plate", "frame/bolt", "frame/bolt#2", "frame/nodes[4]",
                                      "frame/sub%2Fasm/pin", "frame/sub%2Fasm/pin", "extra"}));
  ASSERT_EQ(m.meshes.size(), 7u);
  // Node transforms applied: the bolt sits at its translation.
  EXPECT_DOUBLE_EQ(m.meshes[1].vertices.row(0).minCoeff(), 3.5);
  EXPECT_DOUBLE_EQ(m.meshes[5].vertices.row(1).minCoeff(), 10.0);  // pin under sub/asm
  const pd::NodeMeshes obj = pd::load_node_meshes(groups_obj());
  EXPECT_EQ(obj.nodes, (std::vector<std::string>{"housing", "lid", "cover"}));
}

TEST(SplitNodes, IdsGroupsTagsAndPlacement) {
  json part = split_part("asm", assembly_gltf());
  part["group"] = "machine";
  part["tags"] = {"bought"};
  part["transform"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 100, 0, 0, 0, 1};
  const json obj = split_part("box", groups_obj());
  const json inline_part = {{"id", "loose"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}};
  pd::SceneSpec s = pd::load_scene_file(
      scene_file("placement.json",
                 {{"units", "mm"}, {"tolerance", 0.01}, {"parts", {inline_part, part, obj}}}));
  pd::split_node_parts(s);
  std::vector<std::string> ids, groups;
  for (const pd::PartSpec& p : s.parts) {
    ids.push_back(p.id);
    groups.push_back(p.group);
  }
  // Scene order kept; a split part's node parts in file order, where it stood.
  EXPECT_EQ(ids, (std::vector<std::string>{"loose", "asm/frame/plate", "asm/frame/bolt",
                                           "asm/frame/bolt#2", "asm/frame/nodes[4]",
                                           "asm/frame/sub%2Fasm/pin", "asm/extra", "box/housing",
                                           "box/lid", "box/cover"}));
  EXPECT_EQ(groups, (std::vector<std::string>{"", "machine/frame", "machine/frame", "machine/frame",
                                              "machine/frame", "machine/frame/sub%2Fasm", "machine",
                                              "", "", ""}));
  EXPECT_EQ(s.parts[2].tags, std::vector<std::string>{"bought"});

  const auto parts = by_id(pd::build_parts(s));
  // The node's transform, then the part's (+100 in z): the plate's scale, the
  // pin's translation under sub/asm, its two meshes one part.
  const pd::Part& plate = parts.at("asm/frame/plate");
  ASSERT_FALSE(plate.error) << *plate.error;
  EXPECT_TRUE(plate.box.lo.isApprox(pd::Vec3(0, 0, 100)));
  EXPECT_TRUE(plate.box.hi.isApprox(pd::Vec3(4, 4, 104)));
  const pd::Part& pin = parts.at("asm/frame/sub%2Fasm/pin");
  EXPECT_TRUE(pin.box.lo.isApprox(pd::Vec3(0, 10, 100)));
  EXPECT_TRUE(pin.box.hi.isApprox(pd::Vec3(3, 11, 101)));
  EXPECT_EQ(pin.pieces.size(), 1u);  // pieces auto: the hull of the node's meshes
  EXPECT_EQ(pin.vertex_count, 16);
  EXPECT_TRUE(parts.at("asm/extra").box.lo.isApprox(pd::Vec3(50, 0, 100)));
  EXPECT_TRUE(parts.at("box/cover").box.lo.isApprox(pd::Vec3(9, 0, 0)));
  EXPECT_TRUE(parts.at("box/lid").box.hi.isApprox(pd::Vec3(1, 1, 6)));

  // pieces "meshes": the node's meshes are its pieces.
  for (pd::PartSpec& p : s.parts)
    if (p.mesh) p.pieces = pd::Pieces::kMeshes;
  EXPECT_EQ(by_id(pd::build_parts(s)).at("asm/frame/sub%2Fasm/pin").pieces.size(), 2u);
}

TEST(SplitNodes, HashesAndCachesKeyTheNode) {
  pd::SceneSpec s = pd::load_scene_file(scene_file(
      "hashes.json",
      {{"units", "mm"}, {"tolerance", 0.01}, {"parts", {split_part("asm", assembly_gltf())}}}));
  pd::split_node_parts(s);
  // The two bolts are the same mesh at another place, plate and bolt#2 ... all
  // in one file: every node part has its own content hash.
  const std::vector<std::string> hashes = pd::part_content_hashes(s);
  EXPECT_EQ(std::set<std::string>(hashes.begin(), hashes.end()).size(), hashes.size());
  // A cache filled by one run gives the next the same parts without reading a
  // file (a read would crash the loader: every part an error). Keyed by the
  // file alone, every node part would get the first node's hull.
  for (pd::PartSpec& p : s.parts) p.pieces = pd::Pieces::kHull;
  const std::string cache = dir() + "cache";
  std::filesystem::remove_all(cache);
  const auto first = pd::build_parts(s, 1, {}, pd::kDefaultLoadTimeout, {cache, nullptr});
  const auto second = pd::build_parts(s, 1, {}, pd::kDefaultLoadTimeout, {cache, nullptr},
                                      pd::kAutoLoadMemory, [](const std::string&) { abort(); });
  ASSERT_EQ(first.size(), 6u);
  ASSERT_EQ(first.size(), second.size());
  for (size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(first[k].id, second[k].id);
    ASSERT_FALSE(second[k].error) << *second[k].error;
    EXPECT_TRUE(first[k].box.lo.isApprox(second[k].box.lo)) << first[k].id;
    EXPECT_TRUE(first[k].box.hi.isApprox(second[k].box.hi)) << first[k].id;
    EXPECT_EQ(first[k].vertex_count, second[k].vertex_count) << first[k].id;
  }
  EXPECT_FALSE(first[0].box.lo.isApprox(first[1].box.lo));
}

TEST(SplitNodes, NodeNamesCachedByFileContent) {
  const std::string cache = dir() + "names-cache";
  std::filesystem::remove_all(cache);
  const std::string path = scene_file(
      "names.json",
      {{"units", "mm"}, {"tolerance", 0.01}, {"parts", {split_part("box", groups_obj())}}});
  auto ids = [&](const pd::SplitLoad& load) {
    pd::SceneSpec s = pd::load_scene_file(path);
    pd::split_node_parts(s, load);
    std::vector<std::string> out;
    for (const pd::PartSpec& p : s.parts) out.push_back(p.id + (p.error ? " " + *p.error : ""));
    return out;
  };
  pd::SplitLoad load;
  load.cache_dir = cache;
  const std::vector<std::string> first = ids(load);
  EXPECT_EQ(first, (std::vector<std::string>{"box/housing", "box/lid", "box/cover"}));
  // A second split reads no file: a read would crash the loader (one part error).
  load.before_load = [](const std::string&) { abort(); };
  EXPECT_EQ(ids(load), first);
  // A changed file is another key: read again (and here, crashed).
  std::ofstream(groups_obj(), std::ios::app) << "o more\nf 1 2 3\n";
  const std::vector<std::string> changed = ids(load);
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0].rfind("box cannot load mesh file", 0), 0u) << changed[0];
}

// The split says how many files it reads and when each is done (progress: a
// STEP file is read and meshed there); a cached file is not counted.
TEST(SplitNodes, ReportsTheFilesItReads) {
  const std::string cache = dir() + "progress-cache";
  std::filesystem::remove_all(cache);
  const std::string path = scene_file(
      "progress.json",
      {{"units", "mm"}, {"tolerance", 0.01}, {"parts", {split_part("box", groups_obj())}}});
  size_t total = 0, read = 0;
  pd::SplitLoad load;
  load.cache_dir = cache;
  load.on_files = [&](size_t n) { total += n; };
  load.on_read = [&] { ++read; };
  pd::SceneSpec s = pd::load_scene_file(path);
  pd::split_node_parts(s, load);
  EXPECT_EQ(total, 1u);
  EXPECT_EQ(read, 1u);
  pd::SceneSpec again = pd::load_scene_file(path);
  pd::split_node_parts(again, load);  // from the cache: nothing read
  EXPECT_EQ(total, 1u);
  EXPECT_EQ(read, 1u);
}

TEST(SplitNodes, UnreadableFileIsOnePartErrorAndClashesNameBoth) {
  const std::string garbage = dir() + "garbage.glb";
  std::ofstream(garbage) << "glTF not really";
  const json scene = {
      {"units", "mm"},
      {"tolerance", 0.01},
      {"parts",
       {split_part("bad", garbage),
        {{"id", "ok"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}}},
      {"pairs", json::array({json::array({"bad/frame/bolt", "ok"})})}};
  pd::SceneSpec s = pd::load_scene_file(scene_file("bad.json", scene));
  pd::split_node_parts(s);
  ASSERT_EQ(s.parts.size(), 2u);
  EXPECT_EQ(s.parts[0].id, "bad");
  ASSERT_TRUE(s.parts[0].error);
  EXPECT_NE(s.parts[0].error->find(garbage), std::string::npos) << *s.parts[0].error;
  // The listed pair names the whole part now: an error pair, not a refused scene.
  EXPECT_EQ(*s.pairs, (std::vector<std::pair<std::string, std::string>>{{"bad", "ok"}}));
  const auto parts = pd::build_parts(s);
  EXPECT_TRUE(parts[0].error);
  EXPECT_FALSE(parts[1].error);

  // A node part whose id another part already has: both named.
  const json clash = {{"units", "mm"},
                      {"tolerance", 0.01},
                      {"parts",
                       {split_part("asm", assembly_gltf()),
                        {{"id", "asm/extra"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}}}};
  pd::SceneSpec c = pd::load_scene_file(scene_file("clash.json", clash));
  const std::string e = error_of([&] { pd::split_node_parts(c); });
  EXPECT_NE(e.find("parts[1] (\"asm/extra\")"), std::string::npos) << e;
  EXPECT_NE(e.find("parts[0] (\"asm\") node \"extra\""), std::string::npos) << e;
  // "split" is checked like every key.
  json wrong = clash;
  wrong["parts"][0]["split"] = "meshes";
  const std::string w = error_of([&] { pd::load_scene_file(scene_file("wrong.json", wrong)); });
  EXPECT_NE(w.find("parts[0].split"), std::string::npos) << w;
}

TEST(SplitNodes, RunFindsTheBoltInThePlateAndRulesSelectByGroup) {
  json part = split_part("asm", assembly_gltf());
  part["group"] = "machine";
  const json scene = {{"units", "mm"},
                      {"tolerance", 0.01},
                      {"parts", {part}},
                      {"rules",
                       {{"sets",
                         {{"frame", {{"groups", {"machine/frame"}}}},
                          {"pins", {{"groups", {"machine/frame/sub%2Fasm"}}}}}},
                        {"tests", json::array({{{"name", "frame"}, {"a", "frame"}}})}}}};
  const std::string path = scene_file("run.json", scene);
  const std::string out = dir() + "run-report.json";
  const auto r = pdcheck(path + " -o " + out + " --jobs 1 --quiet");
  ASSERT_EQ(r.code, 1) << r.err;
  const json report = json::parse(read_text(out));
  std::map<std::string, json> parts;
  for (const json& p : report["parts"]) parts[p["id"]] = p;
  EXPECT_EQ(parts.size(), 6u);
  EXPECT_EQ(parts["asm/frame/bolt"]["group"], "machine/frame");
  EXPECT_EQ(parts["asm/frame/sub%2Fasm/pin"]["sets"], json({"frame", "pins"}));
  EXPECT_EQ(parts["asm/extra"]["sets"], json::array());
  // The only overlap: the bolt 0.5 into the plate (the self test of "frame").
  int findings = 0;
  for (const json& p : report["pairs"]) {
    if (p["status"] != "interference") continue;
    ++findings;
    EXPECT_EQ(p["a"], "asm/frame/plate");
    EXPECT_EQ(p["b"], "asm/frame/bolt");
    EXPECT_NEAR(p["depth"].get<double>(), 0.5, 1e-6);
  }
  EXPECT_EQ(findings, 1);
}

TEST(SplitNodes, IgnoreSameFileTakesASplitFileAsOneFile) {
  // Navisworks's "items in the same file": node parts of one split file are
  // one file; a node part and another file's part are not.
  const json parts = {split_part("asm", assembly_gltf()), split_part("box", groups_obj())};
  pd::SceneSpec s = pd::load_scene_file(scene_file(
      "same-file.json", {{"units", "mm"},
                         {"tolerance", 0.01},
                         {"parts", parts},
                         {"rules", {{"ignore", {{{"same", "file"}, {"reason", "one model"}}}}}}}));
  pd::split_node_parts(s);
  const pd::RuleIndex index(*s.rules, s.parts);
  using Scope = pd::PairDecision::Scope;
  EXPECT_EQ(index.decide(0, 1).scope, Scope::kIgnored);  // asm/frame/plate, asm/frame/bolt
  EXPECT_EQ(index.decide(1, 7).scope, Scope::kChecked);  // asm/frame/bolt, box/housing
}

TEST(SplitNodes, MergedShardsEqualTheUnshardedRun) {
  // Two split files and a loose part: pairs across files and within each.
  json a = split_part("asm", assembly_gltf());
  json b = split_part("box", groups_obj());
  b["transform"] = {1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const json loose = {{"id", "loose"},
                      {"vertices", {{20, 0, 0}, {21, 0, 0}, {20, 1, 0}, {20.5, 0.5, 0.5}}}};
  const std::string path =
      scene_file("shards.json", {{"units", "mm"}, {"tolerance", 0.01}, {"parts", {a, b, loose}}});
  const std::string d = dir();
  const auto whole = pdcheck(path + " -o " + d + "whole.json --jobs 1 --quiet");
  ASSERT_LE(whole.code, 1) << whole.err;
  std::string shards;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = d + "shard-" + std::to_string(k) + ".json";
    const auto r =
        pdcheck(path + " --shard " + std::to_string(k) + "/3 -o " + out + " --jobs 1 --quiet");
    ASSERT_LE(r.code, 1) << r.err;
    shards += " " + out;
  }
  const auto m = pdcheck("merge" + shards + " -o " + d + "merged.json --quiet");
  ASSERT_EQ(m.code, whole.code) << m.err;
  const json w = json::parse(read_text(d + "whole.json"));
  const json g = json::parse(read_text(d + "merged.json"));
  auto pairs = [](const json& report) {
    std::map<std::string, std::string> out;
    for (const json& p : report["pairs"])
      out[p["a"].get<std::string>() + " " + p["b"].get<std::string>()] =
          p["status"].get<std::string>() + " " + p["depth"].dump();
    return out;
  };
  EXPECT_EQ(pairs(g), pairs(w));
  EXPECT_GE(pairs(w).size(), 3u);
  EXPECT_EQ(g["parts"].size(), w["parts"].size());
  EXPECT_EQ(g["hashes"], w["hashes"]);
}
