// pdbench: what accuracy costs in time. Runs every depth method and setting over
// seeded generated pair sets, compares each depth with the exact reference, and
// prints per set: time per pair, relative error, α evaluations, Ipopt work.
// One process, one Ipopt application, pairs one after another (no parallelism):
// the times are single-core times.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "corpus/generators.h"
#include "solve/methods.h"

namespace {

using namespace pd;
using nlohmann::ordered_json;

struct Config {
  std::string name;
  SolverSettings settings;
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
  c.push_back(make("mlsl-paper", Method::kMlslPaper));
  c.push_back(make("gs-local 3x3", Method::kGsLocal));
  for (int k : {10, 40, 180}) {
    Config g = make("grid " + std::to_string(k), Method::kGrid);
    g.settings.grid = k;
    c.push_back(g);
  }
  return c;
}

struct Set {
  std::string name;
  std::function<testgen::PairCase(SphereSampler&)> make;
};

std::vector<Set> all_sets() {
  std::vector<Set> s;
  for (int n : {8, 30, 100, 1000})
    s.push_back({std::to_string(n) + "+" + std::to_string(n),
                 [n](SphereSampler& r) { return testgen::vertex_class(r, n); }});
  s.push_back({"paper-like", [](SphereSampler& r) { return testgen::paper_like(r); }});
  s.push_back({"problem-14-like", [](SphereSampler& r) { return testgen::large_coordinates(r); }});
  for (int m : {10, 30, 100, 300, 1000})
    s.push_back({"zhou m=" + std::to_string(m),
                 [m](SphereSampler& r) { return testgen::zhou_spheres(r, m); }});
  return s;
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
  for (const auto& w : wanted)
    if (name.rfind(w, 0) == 0) return true;  // a prefix selects ("mlsl" = every τ)
  return false;
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
  app.add_option("--sets", sets_arg, "comma-separated set name prefixes (default: all)");
  app.add_option("--methods", methods_arg, "comma-separated method name prefixes (default: all)");
  app.add_option("--json", json_path, "also write every row and every pair's point here");
  bool verbose = false;
  app.add_flag("--verbose", verbose, "name every pair off by more than 1e-9 relative (stderr)");
  CLI11_PARSE(app, argc, argv);

  const auto want_sets = split(sets_arg), want_methods = split(methods_arg);
  IpoptLocalSolver ipopt;
  ordered_json out = ordered_json::array();
  for (const Set& set : all_sets()) {
    if (!selected(want_sets, set.name)) continue;
    SphereSampler rng(seed);
    std::vector<testgen::PairCase> cases;
    for (int k = 0; k < pairs; ++k) cases.push_back(set.make(rng));
    // The reference, once per pair (timed as the "exact" row below).
    std::vector<DepthSolution> exact_sol;
    std::vector<double> exact;
    SolverSettings es;
    es.method = Method::kExact;
    for (const auto& c : cases) {
      exact_sol.push_back(solve_convex_pair(c.a, c.b, es, ipopt));
      exact.push_back(exact_sol.back().depth);
    }

    std::printf("\n### %s (%d pairs)\n\n", set.name.c_str(), pairs);
    std::printf(
        "| method | pairs | median ms | max ms | median rel. err | max rel. err | median α evals "
        "| median Ipopt calls | median Ipopt iters | fallbacks |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Config& cfg : all_configs()) {
      if (!selected(want_methods, cfg.name)) continue;
      std::vector<double> ms, err, evals, calls, iters;
      int fallbacks = 0;
      ordered_json points = ordered_json::array();
      const auto cell0 = std::chrono::steady_clock::now();
      for (size_t k = 0; k < cases.size(); ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        const DepthSolution s = solve_convex_pair(cases[k].a, cases[k].b, cfg.settings, ipopt);
        const auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        err.push_back(std::abs(s.depth - exact[k]) / exact[k]);
        evals.push_back(double(s.stats.alpha_evaluations));
        calls.push_back(s.stats.ipopt_calls);
        iters.push_back(s.stats.ipopt_iterations);
        fallbacks += !s.fallback.empty();
        if (verbose && err.back() > 1e-9)
          std::fprintf(stderr,
                       "%s / %s pair %zu: rel. err %.2e, %.3g rad from the exact direction\n",
                       set.name.c_str(), cfg.name.c_str(), k, err.back(),
                       angle_between(s.direction, exact_sol[k].direction));
        points.push_back({ms.back(), err.back()});
        if (std::chrono::duration<double>(t1 - cell0).count() > budget) break;
      }
      const double max_err = *std::max_element(err.begin(), err.end());
      std::printf("| %s | %zu | %.3g | %.3g | %.1e | %.1e | %.0f | %.0f | %.0f | %d |\n",
                  cfg.name.c_str(), ms.size(), median(ms), *std::max_element(ms.begin(), ms.end()),
                  median(err), max_err, median(evals), median(calls), median(iters), fallbacks);
      std::fflush(stdout);
      out.push_back({{"set", set.name},
                     {"method", cfg.name},
                     {"pairs", ms.size()},
                     {"median_ms", median(ms)},
                     {"max_ms", *std::max_element(ms.begin(), ms.end())},
                     {"median_rel_err", median(err)},
                     {"max_rel_err", max_err},
                     {"median_alpha_evals", median(evals)},
                     {"median_ipopt_calls", median(calls)},
                     {"median_ipopt_iterations", median(iters)},
                     {"fallbacks", fallbacks},
                     {"points", points}});
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
