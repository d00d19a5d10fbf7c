#include "batch/refine_cache.h"

#include <nlohmann/json.hpp>

#include "cache_file.h"
#include "hash.h"
#include "tolerances.h"

namespace pd {

namespace {

// 2: the "solved" flag moved into the checked body (cache_file.h).
// 3: nonconvex pairs decided by the overlap thickness (at, reason, undecided).
constexpr CacheKind kKind{"pdcheck-refinement-4", ".pdr"};

void add_points(Hasher& h, const Points& p) {
  h.add(std::string_view(reinterpret_cast<const char*>(p.data()), sizeof(double) * p.size()));
}

void add_part(Hasher& h, const Part& p) {
  h.add("part").add(static_cast<double>(static_cast<int>(p.mode)));
  h.add(p.convex ? (*p.convex ? "convex" : "nonconvex") : "unmeasured");
  h.add(static_cast<double>(p.pieces.size()));
  for (const Hull& piece : p.pieces) add_points(h, piece.vertices);
  if (p.surface) {
    h.add(p.surface->file_hash);
    for (int k = 0; k < 16; ++k) h.add(p.surface->placement(k / 4, k % 4));
    h.add(p.surface->stretch);
  }
}

// The refinement's own fields, which the worker encoding does not carry
// (nlohmann writes doubles in round-trip precision).
std::string encode_refinement_fields(const PairResult& r) {
  nlohmann::json j;
  j["depth_source"] = r.depth_source;
  if (r.hull_depth) j["hull_depth"] = *r.hull_depth;
  if (r.depth_bounds) j["depth_bounds"] = {(*r.depth_bounds)[0], (*r.depth_bounds)[1]};
  if (r.confirmed) j["confirmed"] = *r.confirmed;
  if (r.pieces) j["pieces"] = {(*r.pieces)[0], (*r.pieces)[1]};
  if (r.at) j["at"] = {r.at->x(), r.at->y(), r.at->z()};
  if (!r.reason.empty()) j["reason"] = r.reason;
  return j.dump();
}

void decode_refinement_fields(const std::string& line, PairResult& r) {
  const nlohmann::json j = nlohmann::json::parse(line);
  r.depth_source = j.at("depth_source").get<std::string>();
  r.hull_depth.reset();
  r.depth_bounds.reset();
  r.confirmed.reset();
  r.pieces.reset();
  r.at.reset();
  r.reason.clear();
  if (j.contains("at"))
    r.at = Vec3(j.at("at").at(0).get<double>(), j.at("at").at(1).get<double>(),
                j.at("at").at(2).get<double>());
  if (j.contains("reason")) r.reason = j.at("reason").get<std::string>();
  if (j.contains("hull_depth")) r.hull_depth = j.at("hull_depth").get<double>();
  if (j.contains("depth_bounds"))
    r.depth_bounds = {
        {j.at("depth_bounds").at(0).get<double>(), j.at("depth_bounds").at(1).get<double>()}};
  if (j.contains("confirmed")) r.confirmed = j.at("confirmed").get<bool>();
  if (j.contains("pieces"))
    r.pieces = {{j.at("pieces").at(0).get<int>(), j.at("pieces").at(1).get<int>()}};
}

}  // namespace

std::string refinement_key(const Part& a, const Part& b, const PairResult& hull,
                           const RunOptions& options, const PairChecks& checks) {
  Hasher h;
  h.add(kKind.format);
  add_part(h, a);
  add_part(h, b);
  h.add(status_name(hull.status)).add(hull.depth);
  for (int k = 0; k < 3; ++k) h.add(hull.direction[k]);
  h.add(options.tolerance).add(options.pair_timeout);
  const SolverSettings& s = options.solver;
  h.add(method_name(s.method)).add(static_cast<double>(s.seed));
  for (double x :
       {double(s.samples), s.reduced, s.sigma, s.tau, double(s.min_iterations), s.link_scale,
        double(s.max_iterations), double(s.max_local_solves), s.max_seconds, double(s.paper_n),
        double(s.paper_m), double(s.grid), double(s.gs_local)})
    h.add(x);
  h.add(checks.clearance ? *checks.clearance : -1.0);
  for (double x :
       {tol::kConcavityFraction, tol::kDecomposeSeconds,
        static_cast<double>(tol::kThicknessMaxEvaluations), tol::kThicknessSeconds,
        tol::kThicknessBracket, static_cast<double>(tol::kLocalPlanesMaxFaces),
        static_cast<double>(tol::kLocalPlanesMaxPlanes),
        static_cast<double>(tol::kLocalPlanesMaxChoices), tol::kLocalPlanesMaxKappa,
        tol::kLocalPlanesFirstKappa, static_cast<double>(tol::kLocalPlanesMaxWedges),
        static_cast<double>(tol::kLocalPlanesWedgeTries),
        static_cast<double>(tol::kDecomposeMaxWork), static_cast<double>(tol::kDecomposeSamples)})
    h.add(x);
  return h.hex();
}

// Body: the "solved" flag (0 or 1) line, the refinement's fields as one JSON
// line, then the result as the worker encoding (lossless for doubles).
std::optional<StoredRefinement> read_cached_refinement(const std::string& dir,
                                                       const std::string& key) {
  const std::optional<std::string> body = read_cache_entry(dir, kKind, key);
  if (!body || body->size() < 2 || ((*body)[0] != '0' && (*body)[0] != '1') || (*body)[1] != '\n')
    return std::nullopt;
  try {
    const size_t eol = body->find('\n', 2);
    if (eol == std::string::npos) return std::nullopt;
    StoredRefinement r;
    r.result = decode_pair_result(body->substr(eol + 1));
    decode_refinement_fields(body->substr(2, eol - 2), r.result);
    r.solved = (*body)[0] == '1';
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string write_cached_refinement(const std::string& dir, const std::string& key,
                                    const StoredRefinement& r) {
  return write_cache_entry(dir, kKind, key,
                           std::string(r.solved ? "1" : "0") + "\n" +
                               encode_refinement_fields(r.result) + "\n" +
                               encode_pair_result(r.result));
}

}  // namespace pd
