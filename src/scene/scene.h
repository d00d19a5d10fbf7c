// The scene: what to check, as read from a scene file or a part list.
// Format: docs/scene-format.md (schema: docs/scene.schema.json).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/motion.h"
#include "geometry/types.h"
#include "scene/rules.h"
#include "solve/settings.h"
#include "user_error.h"

namespace pd {

struct LoadedMeshes;  // scene/mesh_loader.h

/// An unusable scene or bad usage (exit code 2). The message names the file and
/// the JSON path of the offending field.
class SceneError : public UserError {
 public:
  using UserError::UserError;
};

/// How a part is cut into convex pieces (docs/scene-format.md, docs/solver.md):
/// auto = its hull, refined where the hull stage flags a nonconvex part;
/// hull = its hull only; meshes = each mesh instance's hull; decompose = its
/// hull, refined where the hull stage flags it, whatever its measured convexity.
enum class Pieces { kAuto, kHull, kMeshes, kDecompose };
std::optional<Pieces> parse_pieces(const std::string& name);
const char* pieces_name(Pieces p);
inline constexpr const char* kPiecesNames = "auto, hull, meshes, decompose";

/// An inline vertex list read but not kept (load_scene_file with keep_vertices
/// false, for --shard): what the shard plan and the content hash need, and
/// where to read the list again for the parts a shard loads (read_inline_vertices).
struct VertexSummary {
  long count = 0;
  std::optional<Aabb> placed_box;      ///< of place_points(list); nullopt: not all finite
  std::array<char, 32> digest{};       ///< vertex_digest of the list, held in place (no allocation)
  std::size_t offset = 0, length = 0;  ///< the list's bytes in the scene file
};

struct PartSpec {
  std::string id;
  std::string where;                ///< "scene.json: parts[3]", for messages
  std::optional<std::string> mesh;  ///< a path usable from the working directory
  std::optional<Points> vertices;   ///< inline vertices, in the part's units
  /// Instead of `vertices` when they were not kept (see VertexSummary).
  std::optional<VertexSummary> vertex_summary;
  double to_scene_units = 1.0;  ///< part unit / scene unit
  Mat4 transform = Mat4::Identity();
  Pieces pieces = Pieces::kAuto;      ///< the hull, refined where it flags a nonconvex part
  std::optional<RigidMotion> motion;  ///< only with checks.motion
  /// The concave sag its exporter was set to (scene units): replaces the
  /// measured one under `tolerance: auto`.
  std::optional<double> sag;
  /// B-rep files (STEP, .brep): the linear deflection to mesh them at (scene
  /// units), when the part or the scene gives one (brep_deflection).
  std::optional<double> deflection;
  /// The part's `units` key as written, when it has one (a STEP file's own
  /// unit wins over it: the parts stage says so when they differ).
  std::optional<std::string> units_key;
  /// Rules (scene/rules.h) select parts by these: free labels, and a
  /// `/`-separated product path ("wing/rib-7/bracket"; "" = none).
  std::vector<std::string> tags;
  std::string group;
  /// `"split": "nodes"`: the scene part stands for one part per node of its
  /// mesh file, made by split_node_parts before anything plans with parts.
  bool split_nodes = false;
  /// A B-rep file without `"split"`: split when it holds more than one leaf
  /// instance (an assembly), else kept whole (a part file).
  bool split_auto = false;
  /// A node part (split_node_parts): the node path of its meshes in `mesh`.
  std::optional<std::string> node;
  /// Why the part cannot be built, known before its geometry is read (a split
  /// part whose file cannot be read: it stays one part, with this error).
  std::optional<std::string> error;
};

/// `"tolerance": "auto"` (docs/numerics.md, "Tessellation sag"): each pair's
/// band from its parts' measured sags and coordinate steps where they meet,
/// clamped to [min, max] when given (scene units).
struct AutoTolerance {
  std::optional<double> min, max;
  /// The band of two parts of concave sags sa, sb and coordinate steps ra, rb
  /// where they meet: (sa + sb + ra + rb)·(1 + kAutoToleranceMargin), clamped.
  double band(double sa, double sb, double ra, double rb) const;
};

/// Effects beyond the static check, computed only when the scene asks.
struct ClearanceCheck {
  double min = 0.0;  ///< scene units, > 0
  struct PerPair {
    std::string a, b;
    double min;
  };
  std::vector<PerPair> pairs;  ///< overrides of `min` for named pairs
  double rules_reach = 0.0;    ///< the largest clearance a rule asks (attach_rules)
};
struct MotionCheck {
  TimeGrid grid;
  bool series = false;  ///< the whole signed-distance series in the report
};
struct Checks {
  std::optional<ClearanceCheck> clearance;
  std::optional<MotionCheck> motion;
};

/// Solver fields given by the scene; each overrides the default, and the
/// command line overrides the scene.
struct SolverOverrides {
  std::optional<Method> method;
  std::optional<std::uint64_t> seed;
  std::optional<double> tau;
  std::optional<int> samples;
  std::optional<int> grid;
  std::optional<int> gs_local;
  void apply(SolverSettings& s) const;
};

struct SceneSpec {
  std::string path;  ///< the scene file, or "-" for standard input
  std::optional<std::string> units;
  /// A fixed tolerance; under `auto` the nominal one (its `min`, else 0) where
  /// one number stands for the scene (the baseline's `updated` rule).
  std::optional<double> tolerance;
  std::optional<AutoTolerance> auto_tolerance;  ///< "tolerance": "auto" or {"auto": true, …}
  /// The scene's `deflection` (scene units): B-rep parts without their own.
  std::optional<double> deflection;
  std::vector<PartSpec> parts;
  std::optional<std::vector<std::pair<std::string, std::string>>> pairs;
  SolverOverrides solver;
  Checks checks;
  std::optional<Rules> rules;  ///< the scene's `rules`, or --rules FILE
  bool part_list = false;      ///< read from a plain part list (parse_part_list), not a scene JSON
  /// The B-rep files split_node_parts read, meshed by node at their parts'
  /// deflection (key brep_read_key): the parts stage's loaders, forked from
  /// this process, take them as read instead of reading the files again, and
  /// the run lets them go once the parts are built (mutable: a cache of the
  /// files, not the scene's content; a later build reads the files).
  mutable std::shared_ptr<const std::map<std::string, LoadedMeshes>> brep_reads;
};

/// The linear deflection a B-rep part is meshed at (scene units): its own
/// `deflection`, else the scene's, else tol::kDeflectionFraction of the scene's
/// tolerance, else (tolerance auto) tol::kAutoDeflectionMm in the scene's unit.
double brep_deflection(const SceneSpec& s, const PartSpec& p);

/// The same in the part's file units (0 for a mesh file): brep_deflection over
/// its placement's largest stretch.
double file_deflection(const SceneSpec& s, const PartSpec& p);

/// Why the scene gives nothing to check, when it has no part: a scene whose
/// `parts` is empty, or a part list without a path (a failed export upstream).
/// The CLI refuses such input (exit 2) unless --allow-empty. nullopt: it has parts.
std::optional<std::string> empty_scene_problem(const SceneSpec& s);

/// Parses a scene document. `path` names it in messages; mesh paths are taken
/// relative to `base_dir`. Throws SceneError.
/// `units` (the command line's --units), when given, is the unit of a scene that
/// declares none; a scene that declares another one is refused (SceneError naming both).
/// `threads` > 1 parses and converts the parts in parallel; the result and any
/// error message are the same as with one thread. Inline vertex lists are read
/// by scan_vertex_array when plain (scene/vertex_scan.h).
SceneSpec parse_scene_json(std::string_view text, const std::string& path,
                           const std::string& base_dir,
                           const std::optional<std::string>& units = std::nullopt, int threads = 1);

/// The reference reading parse_scene_json must agree with: the whole text
/// through the general JSON parser, every vertex by it, one thread. Slower;
/// for differential tests and fuzzing (tests/fuzz/fuzz_scene.cpp).
SceneSpec parse_scene_json_whole(std::string_view text, const std::string& path,
                                 const std::string& base_dir,
                                 const std::optional<std::string>& units = std::nullopt);

/// Reads a scene file from disk (throws SceneError when unreadable).
/// `keep_vertices` false (a shard: it loads few parts but plans with all) keeps
/// a VertexSummary instead of the vertices of each inline part read by the
/// scanner, except moving parts (the plan sweeps their vertices).
SceneSpec load_scene_file(const std::string& path,
                          const std::optional<std::string>& units = std::nullopt, int threads = 1,
                          bool keep_vertices = true);

/// Reads again, from the scene file, the vertices of every part of `s` that has
/// a VertexSummary instead, and drops the summary. Throws SceneError, naming the
/// part, when the file changed since it was read (the digest differs).
void read_inline_vertices(SceneSpec& s);

/// A part's points in scene units and place: its units, then its transform.
Points place_points(const Points& p, const PartSpec& spec);

/// The content hash of an inline vertex list: its doubles' bits.
std::string vertex_digest(const Points& p);

/// A plain part list: one mesh path per line, or "id<TAB>path"; blank lines and
/// lines starting with '#' are skipped. Paths are relative to the working directory.
/// A line's id is part_list_id(path), so `find x` and `find ./x` give the same ids.
SceneSpec parse_part_list(const std::string& text, const std::string& path);

/// The id of a part-list path: lexically normal ("./" and "//" gone, "a/../"
/// resolved without looking at the file system), and relative to the working
/// directory when it is an absolute path inside it.
std::string part_list_id(const std::string& path);

/// Whether `path` names a mesh format by its extension (.stl, .obj, .ply, .gltf,
/// .glb, .3mf, .off, .fbx, .dae, .3ds; any case): given where a scene is
/// expected, the message suggests the part-list form `pdcheck -`.
bool looks_like_mesh_file(const std::string& path);

/// Standard input: a scene JSON when it starts with '{', a part list otherwise.
SceneSpec parse_stdin_scene(const std::string& text,
                            const std::optional<std::string>& units = std::nullopt,
                            int threads = 1);

/// The command line's --pieces: every mesh part takes `p` (inline parts are the
/// hull of their vertices whatever the mode).
void override_pieces(SceneSpec& s, Pieces p);

/// Gives the scene its rules: a rule's clearance needs checks.clearance (the
/// check it refines), and widens the broad phase's reach. Throws SceneError.
void attach_rules(SceneSpec& s, Rules rules);

/// Checks that ids are unique and pairs name known parts (throws SceneError).
/// Before split_node_parts (scene/split_nodes.h), an id under a split part
/// ("<id>/...") counts as known; split_node_parts checks again.
void validate_scene(const SceneSpec& s);

}  // namespace pd
