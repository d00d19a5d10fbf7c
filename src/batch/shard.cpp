#include "batch/shard.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <map>
#include <numeric>
#include <tuple>

#include "batch/broad_phase.h"
#include "scene/mesh_loader.h"
#include "tolerances.h"

namespace pd {

namespace {

// A whole decimal integer, or nullopt.
std::optional<long> integer(const std::string& s) {
  if (s.empty() || s.size() > 12) return std::nullopt;
  for (size_t k = 0; k < s.size(); ++k)
    if (!(std::isdigit(static_cast<unsigned char>(s[k])) || (k == 0 && s[k] == '-')))
      return std::nullopt;
  if (s == "-") return std::nullopt;
  return std::strtol(s.c_str(), nullptr, 10);
}

ShardSpec checked(long k, long n, const std::string& what) {
  if (n < 1 || n > 1000000) throw ShardError(what + ": the shard count must be 1 to 1000000");
  if (k < 1 || k > n)
    throw ShardError(what + ": shard " + std::to_string(k) + " is not in 1.." + std::to_string(n));
  return {static_cast<int>(k), static_cast<int>(n)};
}

// The placed points' box, widened by a rounding slack: it must contain the
// box of any hull of these points, however the hull's vertices were computed.
std::optional<Aabb> plan_box(const std::optional<Aabb>& placed_box) {
  if (!placed_box) return std::nullopt;  // the hull fails too
  const Aabb& box = *placed_box;
  const double size = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  return box.inflated(tol::kPlanBoxSlack * size);
}

std::optional<Aabb> plan_box(const Points& placed, const PartSpec& spec,
                             const std::optional<MotionCheck>& motion) {
  if (placed.cols() == 0 || !placed.allFinite()) return std::nullopt;  // the hull fails too
  Aabb box = Aabb::of(placed);
  if (motion && spec.motion)
    for (long k = 0; k < motion->grid.steps(); ++k)
      box = box.merged(Aabb::of(spec.motion->at(placed, motion->grid.time(k))));
  return plan_box(box);
}

// Boxes and vertex counts of every part. Mesh files are read in batches so a
// large scene never holds all its meshes at once.
void plan_boxes(const SceneSpec& scene, int threads, double load_timeout, ScenePlan& plan,
                const MeshLoadHook& before_load) {
  const size_t n = scene.parts.size();
  plan.boxes.assign(n, std::nullopt);
  plan.vertices.assign(n, 0);
  // file -> parts, by (path, pieces meshes, split by node)
  std::map<std::tuple<std::string, bool, bool>, std::vector<size_t>> users;
  for (size_t k = 0; k < n; ++k) {
    const PartSpec& s = scene.parts[k];
    if (s.error) continue;  // known unusable (a split part whose file cannot be read)
    if (s.mesh) {
      users[{*s.mesh, s.pieces == Pieces::kMeshes, s.node.has_value()}].push_back(k);
    } else if (s.vertex_summary) {  // the same box as below, computed when the list was read
      plan.vertices[k] = s.vertex_summary->count;
      plan.boxes[k] = plan_box(s.vertex_summary->placed_box);
    } else {
      plan.vertices[k] = s.vertices->cols();
      plan.boxes[k] = plan_box(place_points(*s.vertices, s), s, scene.checks.motion);
    }
  }
  std::vector<std::pair<MeshRequest, const std::vector<size_t>*>> files;
  for (const auto& [key, parts] : users) {
    const auto& [path, split, by_node] = key;
    files.push_back({{path, split || by_node, by_node, false}, &parts});
  }
  const size_t batch = 64;
  for (size_t f0 = 0; f0 < files.size(); f0 += batch) {
    const size_t f1 = std::min(files.size(), f0 + batch);
    std::vector<MeshRequest> requests;
    for (size_t f = f0; f < f1; ++f) requests.push_back(files[f].first);
    const std::vector<LoadedMeshes> read =
        load_meshes_isolated(requests, threads, load_timeout, kAutoLoadMemory, before_load);
    for (size_t f = f0; f < f1; ++f) {
      const LoadedMeshes& m = read[f - f0];
      if (m.error) continue;  // the part's own load reports why
      // Per node path ("" when not split by node), its meshes' vertices.
      std::map<std::string, std::vector<const Mesh*>> of_node;
      for (size_t i = 0; i < m.meshes.size(); ++i)
        of_node[files[f].first.by_node ? m.nodes[i] : ""].push_back(&m.meshes[i]);
      for (size_t k : *files[f].second) {
        const auto it = of_node.find(scene.parts[k].node.value_or(""));
        if (it == of_node.end()) continue;  // the file changed: the part's load reports why
        long count = 0;
        for (const Mesh* mesh : it->second) count += mesh->vertices.cols();
        Points all(3, count);
        long at = 0;
        for (const Mesh* mesh : it->second) {
          all.middleCols(at, mesh->vertices.cols()) = mesh->vertices;
          at += mesh->vertices.cols();
        }
        plan.vertices[k] = count;
        plan.boxes[k] =
            plan_box(place_points(all, scene.parts[k]), scene.parts[k], scene.checks.motion);
      }
    }
  }
}

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto k = slash == std::string::npos ? std::nullopt : integer(text.substr(0, slash));
  const auto n = slash == std::string::npos ? std::nullopt : integer(text.substr(slash + 1));
  if (!k || !n) throw ShardError("--shard: \"" + text + "\" is not K/N (e.g. 2/4) or auto");
  return checked(*k, *n, "--shard " + text);
}

ShardSpec shard_from_environment(const std::function<const char*(const char*)>& env,
                                 std::optional<int> total, std::optional<int> base) {
  auto var = [&](const char* name) -> std::optional<std::string> {
    const char* v = env(name);
    if (!v) return std::nullopt;
    return std::string(v);
  };
  auto number = [&](const char* name, const std::string& v) {
    const auto x = integer(v);
    if (!x)
      throw ShardError("--shard auto: " + std::string(name) + "=\"" + v + "\" is not an integer");
    return *x;
  };
  const auto ci_index = var("CI_NODE_INDEX"), ci_total = var("CI_NODE_TOTAL");
  const auto slurm_id = var("SLURM_ARRAY_TASK_ID");
  if ((ci_index || ci_total) && slurm_id)
    throw ShardError(
        "--shard auto: both CI_NODE_INDEX/CI_NODE_TOTAL and SLURM_ARRAY_TASK_ID are set; give "
        "--shard K/N");
  if (ci_index || ci_total) {
    if (!ci_index || !ci_total)
      throw ShardError(std::string("--shard auto: ") +
                       (ci_index ? "CI_NODE_TOTAL" : "CI_NODE_INDEX") + " is not set (CI_NODE_" +
                       (ci_index ? "INDEX" : "TOTAL") + " is)");
    const long k = number("CI_NODE_INDEX", *ci_index), n = number("CI_NODE_TOTAL", *ci_total);
    if (total && *total != n)
      throw ShardError("--shard auto: --shard-total " + std::to_string(*total) +
                       " disagrees with CI_NODE_TOTAL=" + std::to_string(n));
    return checked(
        k, n, "--shard auto (CI_NODE_INDEX=" + *ci_index + ", CI_NODE_TOTAL=" + *ci_total + ")");
  }
  if (slurm_id) {
    if (!total)
      throw ShardError(
          "--shard auto: SLURM_ARRAY_TASK_ID is set but not --shard-total N (the array's size)");
    const long id = number("SLURM_ARRAY_TASK_ID", *slurm_id);
    long first = base.value_or(0);
    if (const auto min = var("SLURM_ARRAY_TASK_MIN")) {
      first = number("SLURM_ARRAY_TASK_MIN", *min);
      if (base && *base != first)
        throw ShardError("--shard auto: --shard-base " + std::to_string(*base) +
                         " disagrees with SLURM_ARRAY_TASK_MIN=" + *min);
    }
    if (const auto count = var("SLURM_ARRAY_TASK_COUNT"))
      if (number("SLURM_ARRAY_TASK_COUNT", *count) != *total)
        throw ShardError("--shard auto: --shard-total " + std::to_string(*total) +
                         " disagrees with SLURM_ARRAY_TASK_COUNT=" + *count);
    return checked(id - first + 1, *total,
                   "--shard auto (SLURM_ARRAY_TASK_ID=" + *slurm_id + ", array base " +
                       std::to_string(first) + ")");
  }
  throw ShardError(
      "--shard auto: neither CI_NODE_INDEX/CI_NODE_TOTAL nor SLURM_ARRAY_TASK_ID is set; every "
      "shard would check the same pairs. Give --shard K/N");
}

ScenePlan plan_scene(const SceneSpec& scene, int shards, int threads, double load_timeout,
                     const MeshLoadHook& before_load) {
  ScenePlan plan;
  plan.shards = shards;
  plan.listed = scene.pairs.has_value();
  plan_boxes(scene, threads, load_timeout, plan, before_load);
  const int n = static_cast<int>(scene.parts.size());
  for (long v : plan.vertices) plan.vertices_total += v;

  if (plan.listed) {
    std::map<std::string, int> index;
    for (int k = 0; k < n; ++k) index[scene.parts[k].id] = k;
    for (const auto& [a, b] : *scene.pairs) {
      const int ia = index.at(a), ib = index.at(b);
      plan.pairs.emplace_back(std::min(ia, ib), std::max(ia, ib));
    }
    std::sort(plan.pairs.begin(), plan.pairs.end());
    plan.pairs.erase(std::unique(plan.pairs.begin(), plan.pairs.end()), plan.pairs.end());
  } else {
    std::vector<Aabb> boxes;
    std::vector<int> usable;
    for (int k = 0; k < n; ++k)
      if (plan.boxes[k]) {
        usable.push_back(k);
        boxes.push_back(*plan.boxes[k]);
      }
    for (const auto& [i, j] : overlapping_boxes(boxes, broad_phase_reach(scene.checks)))
      plan.pairs.emplace_back(usable[i], usable[j]);
  }

  // Pairs along the axis where the parts spread most, cut into runs of equal
  // expected cost: neighbouring pairs share parts, so a shard's parts are few.
  std::vector<Aabb> present;
  for (const auto& b : plan.boxes)
    if (b) present.push_back(*b);
  const int axis = widest_spread_axis(present);
  auto centre = [&](int k) {
    return plan.boxes[k] ? plan.boxes[k]->lo[axis] + plan.boxes[k]->hi[axis] : 0.0;
  };
  std::vector<size_t> order(plan.pairs.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> key(plan.pairs.size());
  for (size_t p = 0; p < plan.pairs.size(); ++p)
    key[p] = centre(plan.pairs[p].first) + centre(plan.pairs[p].second);
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) {
    return key[x] < key[y] || (key[x] == key[y] && plan.pairs[x] < plan.pairs[y]);
  });
  auto cost = [&](size_t p) {
    return tol::kShardPairCost + double(plan.vertices[plan.pairs[p].first]) +
           double(plan.vertices[plan.pairs[p].second]);
  };
  double total = 0.0;
  for (size_t p = 0; p < plan.pairs.size(); ++p) total += cost(p);
  plan.pair_shard.assign(plan.pairs.size(), 0);
  double before = 0.0;
  for (size_t p : order) {
    const double c = cost(p);
    const int s = total > 0 ? static_cast<int>((before + 0.5 * c) / total * shards) : 0;
    plan.pair_shard[p] = std::clamp(s, 0, shards - 1);
    before += c;
  }

  // Owners: a part with pairs belongs to the first shard that loads it; the
  // rest go, in scene order, to the shard with the fewest vertices so far.
  plan.owner.assign(n, -1);
  std::vector<std::pair<int, int>> needs;  // (part, shard)
  for (size_t p = 0; p < plan.pairs.size(); ++p) {
    needs.emplace_back(plan.pairs[p].first, plan.pair_shard[p]);
    needs.emplace_back(plan.pairs[p].second, plan.pair_shard[p]);
  }
  std::sort(needs.begin(), needs.end());
  needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
  std::vector<double> load(shards, 0.0);
  for (const auto& [part, s] : needs) {
    load[s] += double(plan.vertices[part]);
    if (plan.owner[part] < 0) plan.owner[part] = s;
  }
  for (int k = 0; k < n; ++k)
    if (plan.owner[k] < 0) {
      const int s = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      plan.owner[k] = s;
      load[s] += double(plan.vertices[k]);
    }
  return plan;
}

std::vector<int> shard_parts(const ScenePlan& plan, int shard) {
  std::vector<char> take(plan.owner.size(), 0);
  for (size_t k = 0; k < plan.owner.size(); ++k) take[k] = plan.owner[k] == shard;
  for (size_t p = 0; p < plan.pairs.size(); ++p)
    if (plan.pair_shard[p] == shard) take[plan.pairs[p].first] = take[plan.pairs[p].second] = 1;
  std::vector<int> out;
  for (size_t k = 0; k < take.size(); ++k)
    if (take[k]) out.push_back(static_cast<int>(k));
  return out;
}

}  // namespace pd
