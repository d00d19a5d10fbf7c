// pdbench: what accuracy costs in time. Runs every depth method and setting over
// seeded generated pair sets, compares each depth with the exact reference, and
// prints per set: time per pair, relative error, α evaluations, Ipopt work.
// One process, one Ipopt application, pairs one after another (no parallelism):
// the times are single-core times.
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "batch/motion_sweep.h"
#include "corpus/contacts.h"
#include "corpus/exact_reference.h"
#include "corpus/generators.h"
#include "geometry/frame.h"
#include "peers.h"
#include "solve/methods.h"
#include "tolerances.h"

namespace {

using namespace pd;
using nlohmann::ordered_json;

struct Config {
  std::string name;
  SolverSettings settings;
  const pdbench::Peer* peer = nullptr;  ///< a library run instead of pdcheck (peers.h)
};

std::vector<Config> all_configs() {
  auto make = [](const std::string& name, Method m) {
    SolverSettings s;
    s.method = m;
    return Config{name, s};
  };
  std::vector<Config> c;
  c.push_back(make("exact", Method::kExact));
  for (double tau : {0.5, 0.9, 0.99}) {
    Config k =
        make("mlsl tau=" + std::to_string(tau).substr(0, tau == 0.99 ? 4 : 3), Method::kMlsl);
    k.settings.tau = tau;
    c.push_back(k);
  }
  // The default without its GJK + EPA bracket (issue 29): what the bracket bought.
  Config sampling = make("mlsl sampling only", Method::kMlsl);
  sampling.settings.epa = false;
  c.push_back(sampling);
  c.push_back(make("mlsl-paper", Method::kMlslPaper));
  c.push_back(make("gs-local 3x3", Method::kGsLocal));
  for (int k : {10, 40, 180}) {
    Config g = make("grid " + std::to_string(k), Method::kGrid);
    g.settings.grid = k;
    c.push_back(g);
  }
  static const std::vector<pdbench::Peer> peers = pdbench::available_peers();
  for (const pdbench::Peer& p : peers) c.push_back({p.name, SolverSettings{}, &p});
  return c;
}

struct Set {
  std::string name;
  std::function<testgen::PairCase(SphereSampler&, int)> make;  ///< (generator, pair index)
};

std::vector<Set> all_sets() {
  std::vector<Set> s;
  for (int n : {8, 30, 100, 1000})
    s.push_back({std::to_string(n) + "+" + std::to_string(n),
                 [n](SphereSampler& r, int) { return testgen::vertex_class(r, n); }});
  s.push_back({"paper-like", [](SphereSampler& r, int) { return testgen::paper_like(r); }});
  s.push_back(
      {"problem-14-like", [](SphereSampler& r, int) { return testgen::large_coordinates(r); }});
  for (int m : {10, 30, 100, 300, 1000})
    s.push_back({"zhou m=" + std::to_string(m),
                 [m](SphereSampler& r, int) { return testgen::zhou_spheres(r, m); }});
  // Contacts as CAD produces them (src/corpus/contacts.h); n is the vertex count
  // of the larger part. Fits, gaps and placements cycle with the pair index.
  using testgen::Contact;
  const std::pair<Contact, std::vector<int>> contacts[] = {{Contact::kPlates, {8, 30, 100, 1000}},
                                                           {Contact::kSeated, {8, 100, 1000}},
                                                           {Contact::kShaft, {32, 64, 128, 256}},
                                                           {Contact::kBall, {30, 100, 300, 1000}},
                                                           {Contact::kHairGap, {8, 100, 1000}}};
  for (const auto& [c, ns] : contacts)
    for (int n : ns)
      s.push_back(
          {"contact " + testgen::contact_name(c) + " n=" + std::to_string(n),
           [c = c, n](SphereSampler& r, int k) { return testgen::contact_case(r, c, n, k); }});
  s.push_back({"hard cases", [](SphereSampler& r, int k) { return testgen::hard_case(r, k); }});
  for (int n : {32, 128, 1000})
    s.push_back({"contained n=" + std::to_string(n),
                 [n](SphereSampler& r, int k) { return testgen::deep_containment(r, n, k); }});
  s.push_back({"apart 100+100",
               [](SphereSampler& r, int) { return testgen::apart_boxes_overlapping(r, 100); }});
  return s;
}

// CPU seconds of the calling thread: on a shared machine the wall time of a pair
// includes the time other processes held the core; this clock does not.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

// The q-quantile by nearest rank (q = 0.99: the p99).
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t k = static_cast<size_t>(std::ceil(q * double(v.size())));
  return v[std::min(v.size() - 1, k == 0 ? 0 : k - 1)];
}

// Relative error of a depth against the true one. Depths at or below the
// contact rounding (kGapRounding of the pair's frame scale, docs/numerics.md:
// pdcheck reports them as 0, touching) are contact for both: no error when both
// are there; otherwise the difference is relative to the larger of the true
// depth and that rounding.
double depth_error(double depth, double truth, double contact) {
  if (depth <= contact && truth <= contact) return 0.0;
  return std::abs(depth - truth) / std::max(truth, contact);
}

// The true depth the errors are measured against: the exact rational reference
// (corpus/exact_reference.h) wherever rounding could be 1e-9 of the depth —
// pairs of at most kExactReferencePoints differences, and every pair whose
// double-precision hull depth is below kExactFacetDepth of its scale; above
// that depth the double hull's rounding (kGapRounding of the scale) is below
// 1e-10 of it, and the exact hull of a million differences would take minutes.
double true_depth(const testgen::PairCase& c, double hull_depth, double scale, int& rational) {
  const bool small =
      static_cast<std::size_t>(c.a.cols() * c.b.cols()) <= testgen::kExactReferencePoints;
  if (!small && hull_depth >= tol::kExactFacetDepth * scale) return hull_depth;
  ++rational;
  return testgen::exact_reference_depth(c.a, c.b).depth;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string t; std::getline(in, t, ',');)
    if (!t.empty()) out.push_back(t);
  return out;
}

bool selected(const std::vector<std::string>& wanted, const std::string& name) {
  if (wanted.empty()) return true;
  // A name, or its leading words: "mlsl" selects every "mlsl tau=…", while
  // "mlsl tau=0.9" selects only itself (not 0.99), and "mlsl-paper" is its own.
  for (const auto& w : wanted)
    if (name.rfind(w, 0) == 0 && (name.size() == w.size() || name[w.size()] == ' ')) return true;
  return false;
}

// The paper's 14 problems had these vertex counts; ours are new random pairs
// with the same counts (the paper's polytopes are not published).
const std::pair<int, int> kPaperProblems[14] = {{8, 8},  {6, 9},  {14, 5}, {8, 10},  {9, 7},
                                                {10, 5}, {13, 6}, {9, 8},  {15, 9},  {15, 11},
                                                {8, 11}, {10, 6}, {10, 8}, {103, 93}};

testgen::PairCase paper_problem(SphereSampler& r, int k) {
  const int np = kPaperProblems[k].first, nq = kPaperProblems[k].second;  // captured below
  const double scale = k == 13 ? 1000.0 : 1.0;  // problem 14: coordinates in the thousands
  return testgen::overlapping(r, [&](SphereSampler& g) {
    const double ra = scale * (10 + 40 * g.uniform()), rb = scale * (10 + 40 * g.uniform());
    const Vec3 c = g.direction() * (ra + rb) * 0.5 * g.uniform();
    return testgen::PairCase{testgen::ellipsoid_polytope(g, np, Vec3::Zero(), ra),
                             testgen::ellipsoid_polytope(g, nq, c, rb)};
  });
}

// Tables I and II of the paper, on our problems: depth found and α evaluations
// per problem and method, then totals and CPU time.
int paper_tables(std::uint64_t seed, const std::string& json_path) {
  IpoptLocalSolver ipopt;
  std::vector<Config> cols;
  for (const Config& c : all_configs())
    if (c.name.rfind("grid", 0) == 0 || c.name == "mlsl-paper" || c.name == "gs-local 3x3" ||
        c.name == "mlsl tau=0.9" || c.name == "exact")
      cols.push_back(c);
  SphereSampler rng(seed);
  ordered_json rows = ordered_json::array();
  std::vector<double> total_evals(cols.size(), 0), total_s(cols.size(), 0);
  std::printf("| problem (n_p, n_q) |");
  for (const Config& c : cols) std::printf(" %s depth | evals |", c.name.c_str());
  std::printf("\n|---|");
  for (size_t k = 0; k < cols.size(); ++k) std::printf("---:|---:|");
  std::printf("\n");
  for (int k = 0; k < 14; ++k) {
    const testgen::PairCase pc = paper_problem(rng, k);
    std::printf("| %d: (%d, %d) |", k + 1, kPaperProblems[k].first, kPaperProblems[k].second);
    ordered_json row = {{"problem", k + 1}};
    for (size_t m = 0; m < cols.size(); ++m) {
      const auto t0 = std::chrono::steady_clock::now();
      const DepthSolution s = solve_convex_pair(pc.a, pc.b, cols[m].settings, ipopt);
      total_s[m] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      total_evals[m] += double(s.stats.alpha_evaluations);
      std::printf(" %.6g | %ld |", s.depth, s.stats.alpha_evaluations);
      row[cols[m].name] = {{"depth", s.depth}, {"evals", s.stats.alpha_evaluations}};
    }
    std::printf("\n");
    rows.push_back(row);
  }
  std::printf("| **α evaluations** |");
  for (size_t m = 0; m < cols.size(); ++m) std::printf(" | %.0f |", total_evals[m]);
  std::printf("\n| **CPU time (s)** |");
  for (size_t m = 0; m < cols.size(); ++m) std::printf(" | %.3g |", total_s[m]);
  std::printf("\n");
  ordered_json totals;
  for (size_t m = 0; m < cols.size(); ++m)
    totals[cols[m].name] = {{"evals", total_evals[m]}, {"seconds", total_s[m]}};
  if (!json_path.empty()) {
    std::ofstream f(json_path);
    f << ordered_json{{"problems", rows}, {"totals", totals}}.dump(1) << "\n";
    if (!f) return 2;
  }
  return 0;
}

// Zhou et al.'s experiment for each m: time per step warm-started from the
// previous step and solved from scratch, and the Ipopt work of each.
int zhou_timing(const std::string& ms, int steps) {
  IpoptLocalSolver ipopt;
  std::printf(
      "| m | steps | warm ms/step | cold ms/step | cold / warm | warm Ipopt calls/step | "
      "cold Ipopt calls/step |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& token : split(ms)) {
    const int m = std::stoi(token);
    SphereSampler r(1);
    Part a, b;
    a.pieces.push_back(convex_hull(testgen::sphere_polytope(r, m, Vec3::Zero(), 10)));
    b.pieces.push_back(convex_hull(testgen::sphere_polytope(r, m, Vec3(20, 10, 30), 10)));
    a.motion = RigidMotion{Vec3(0, 0, 0.05), Vec3::Zero(), Vec3::Zero()};
    b.motion = RigidMotion{Vec3::Zero(), Vec3::Zero(), -0.01 * Vec3(2, 1, 3)};
    MotionCheck check;
    check.grid = {0, double(steps - 1), 1};
    double ms_per[2];
    int calls[2];
    for (int w = 0; w < 2; ++w) {
      const auto t0 = std::chrono::steady_clock::now();
      const MotionSweep sw = sweep_pair(a, b, check, SolverSettings{}, ipopt, w == 0);
      ms_per[w] =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
          steps;
      calls[w] = sw.stats.ipopt_calls;
    }
    std::printf("| %d | %d | %.3g | %.3g | %.2f | %.2f | %.2f |\n", m, steps, ms_per[0], ms_per[1],
                ms_per[1] / ms_per[0], double(calls[0]) / steps, double(calls[1]) / steps);
    std::fflush(stdout);
  }
  return 0;
}

// One (set, method) cell of the table: every pair's time, error and counts.
struct CellRow {
  std::vector<double> ms, cpu_ms, err, evals, calls, iters;
  int fallbacks = 0;
  std::map<std::string, int> stops;
  ordered_json points = ordered_json::array();

  void add(const DepthSolution& s, double wall_ms, double cpu, double error) {
    ms.push_back(wall_ms);
    cpu_ms.push_back(cpu);
    err.push_back(error);
    evals.push_back(double(s.stats.alpha_evaluations));
    calls.push_back(s.stats.ipopt_calls);
    iters.push_back(s.stats.ipopt_iterations);
    fallbacks += !s.fallback.empty();
    ++stops[stop_reason_name(s.stats.stop_reason)];
    points.push_back({wall_ms, error, cpu});
  }

  std::string stop_text() const {
    std::string t;
    for (const auto& [name, count] : stops)
      t += (t.empty() ? "" : ", ") + name + " " + std::to_string(count);
    return t;
  }

  void print(const std::string& method) const {
    std::printf(
        "| %s | %zu | %.3g | %.3g | %.3g | %.3g | %.3g | %.1e | %.1e | %.0f | %.0f | %.0f | %d | "
        "%s |\n",
        method.c_str(), ms.size(), median(ms), quantile(ms, 0.99),
        *std::max_element(ms.begin(), ms.end()), median(cpu_ms), quantile(cpu_ms, 0.99),
        median(err), *std::max_element(err.begin(), err.end()), median(evals), median(calls),
        median(iters), fallbacks, stop_text().c_str());
    std::fflush(stdout);
  }

  ordered_json to_json(const std::string& set, const std::string& method) const {
    return {{"set", set},
            {"method", method},
            {"pairs", ms.size()},
            {"median_ms", median(ms)},
            {"p99_ms", quantile(ms, 0.99)},
            {"max_ms", *std::max_element(ms.begin(), ms.end())},
            {"median_cpu_ms", median(cpu_ms)},
            {"p99_cpu_ms", quantile(cpu_ms, 0.99)},
            {"median_rel_err", median(err)},
            {"max_rel_err", *std::max_element(err.begin(), err.end())},
            {"median_alpha_evals", median(evals)},
            {"median_ipopt_calls", median(calls)},
            {"median_ipopt_iterations", median(iters)},
            {"fallbacks", fallbacks},
            {"stop_reasons", stops},
            {"points", points}};
  }
};

// A set's pairs with the exact reference, solved once per pair (timed as the
// "exact" row).
struct SetCases {
  std::vector<testgen::PairCase> cases;
  std::vector<DepthSolution> exact;
  std::vector<double> truth;    ///< each pair's true depth (true_depth)
  std::vector<double> contact;  ///< each pair's contact rounding
  int rational = 0;             ///< pairs whose truth is the exact rational reference
};
SetCases make_cases(const Set& set, int pairs, std::uint64_t seed, IpoptLocalSolver& ipopt) {
  SetCases out;
  SphereSampler rng(seed);
  for (int k = 0; k < pairs; ++k) out.cases.push_back(set.make(rng, k));
  SolverSettings es;
  es.method = Method::kExact;
  for (const auto& c : out.cases) {
    out.exact.push_back(solve_convex_pair(c.a, c.b, es, ipopt));
    const double scale = pair_frame(c.a, c.b).scale;
    out.truth.push_back(true_depth(c, out.exact.back().depth, scale, out.rational));
    out.contact.push_back(tol::kGapRounding * scale);
  }
  return out;
}

// One method over a set's pairs, within `budget` seconds (at least one pair).
CellRow run_cell(const Set& set, const Config& cfg, const SetCases& sc, double budget, bool verbose,
                 IpoptLocalSolver& ipopt) {
  CellRow row;
  const auto cell0 = std::chrono::steady_clock::now();
  for (size_t k = 0; k < sc.cases.size(); ++k) {
    const double c0 = thread_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    DepthSolution s;
    double wall_ms = 0.0, cpu = 0.0;
    if (cfg.peer) {
      // The peer's own clock times its query alone; a failure is counted
      // with the fallbacks and scored with the depth it gave (0).
      const pdbench::PeerRun pr = pdbench::run_isolated(*cfg.peer, sc.cases[k].a, sc.cases[k].b);
      s.depth = pr.depth;
      s.fallback = pr.failure;
      wall_ms = cpu = pr.ms;
    } else {
      s = solve_convex_pair(sc.cases[k].a, sc.cases[k].b, cfg.settings, ipopt);
    }
    const auto t1 = std::chrono::steady_clock::now();
    if (!cfg.peer) {
      cpu = thread_cpu_ms() - c0;
      wall_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    }
    row.add(s, wall_ms, cpu, depth_error(s.depth, sc.truth[k], sc.contact[k]));
    if (verbose && row.err.back() > 1e-9)
      std::fprintf(stderr, "%s / %s pair %zu: rel. err %.2e, %.3g rad from the exact direction\n",
                   set.name.c_str(), cfg.name.c_str(), k, row.err.back(),
                   angle_between(s.direction, sc.exact[k].direction));
    if (std::chrono::duration<double>(t1 - cell0).count() > budget) break;
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pdbench: time and accuracy of every depth method against the exact reference"};
  int pairs = 20;
  double budget = 20.0;
  std::uint64_t seed = 1;
  std::string sets_arg, methods_arg, json_path;
  app.add_option("--pairs", pairs, "pairs per set")->check(CLI::PositiveNumber);
  app.add_option("--budget", budget,
                 "seconds per (set, method) cell; a slow method stops early (at least one pair)");
  app.add_option("--seed", seed, "corpus seed");
  app.add_option(
      "--sets", sets_arg,
      "comma-separated set names or their leading words, e.g. 30+30,zhou (default: all)");
  app.add_option(
      "--methods", methods_arg,
      "comma-separated method names or their leading words, e.g. mlsl,grid (default: all)");
  app.add_option("--json", json_path, "also write every row and every pair's point here");
  bool verbose = false;
  app.add_flag("--verbose", verbose, "name every pair off by more than 1e-9 relative (stderr)");
  std::string zhou;
  int zhou_steps = 2000;
  app.add_option("--zhou", zhou, "Zhou et al.'s motion experiment for these m (e.g. 10,100,1000)");
  app.add_option("--zhou-steps", zhou_steps, "time steps of --zhou")->check(CLI::PositiveNumber);
  bool paper = false;
  app.add_flag("--paper-tables", paper,
               "the paper's Tables I and II on 14 new pairs with its vertex counts");
  CLI11_PARSE(app, argc, argv);
  if (paper) return paper_tables(seed, json_path);
  if (!zhou.empty()) return zhou_timing(zhou, zhou_steps);

  const auto want_sets = split(sets_arg), want_methods = split(methods_arg);
  IpoptLocalSolver ipopt;
  ordered_json out = ordered_json::array();
  for (const Set& set : all_sets()) {
    if (!selected(want_sets, set.name)) continue;
    const SetCases sc = make_cases(set, pairs, seed, ipopt);
    std::printf("\n### %s (%d pairs, %d against the exact rational reference)\n\n",
                set.name.c_str(), pairs, sc.rational);
    std::printf(
        "| method | pairs | median ms | p99 ms | max ms | median CPU ms | p99 CPU ms | median rel. "
        "err | max rel. err | median α evals "
        "| median Ipopt calls | median Ipopt iters | fallbacks | stop reasons |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const Config& cfg : all_configs()) {
      if (!selected(want_methods, cfg.name)) continue;
      const CellRow row = run_cell(set, cfg, sc, budget, verbose, ipopt);
      row.print(cfg.name);
      out.push_back(row.to_json(set.name, cfg.name));
    }
  }
  if (!json_path.empty()) {
    std::ofstream f(json_path);
    f << out.dump(1) << "\n";
    if (!f) {
      std::cerr << "pdbench: cannot write " << json_path << "\n";
      return 2;
    }
  }
  return 0;
}
