// A check run's options resolved in-process (report/run_config.h): the
// command line's overrides over the scene, and each bad option a UserError
// carrying exit code 2 and naming the option.
#include <gtest/gtest.h>

#include <sstream>

#include "report/run_config.h"

using namespace pd;

namespace {

const std::string kDemo = std::string(PDCHECK_SOURCE_DIR) + "/testdata/demo/scene.json";

const char* no_env(const char*) {
  return nullptr;
}

CheckArgs demo_args() {
  CheckArgs a;
  a.scene = kDemo;
  a.jobs = 1;
  a.no_cache = true;
  return a;
}

// The message of the UserError resolving `a` throws, and its exit code.
std::pair<std::string, int> failure(const CheckArgs& a) {
  std::istringstream in;
  RunConfig config;
  try {
    resolve_run_config(a, in, no_env, config);
  } catch (const UserError& e) {
    return {e.what(), e.exit_code()};
  }
  return {"", 0};
}

}  // namespace

TEST(RunConfig, TheCommandLineOverridesTheScene) {
  CheckArgs a = demo_args();
  a.tolerance = "0.25";
  a.method = "grid";
  a.seed = std::uint64_t{1} << 60;
  a.pieces = "hull";
  a.pair_timeout = 7.5;
  std::istringstream in;
  RunConfig config;
  resolve_run_config(a, in, no_env, config);
  EXPECT_EQ(config.options.tolerance, 0.25);
  EXPECT_EQ(*config.scene.tolerance, 0.25);
  EXPECT_EQ(config.options.solver.method, Method::kGrid);
  EXPECT_EQ(config.options.solver.seed, std::uint64_t{1} << 60);
  EXPECT_EQ(config.options.pair_timeout, 7.5);
  EXPECT_EQ(config.options.cache_dir, "");  // --no-cache
  for (const PartSpec& p : config.scene.parts)
    if (p.mesh) {
      EXPECT_EQ(p.pieces, Pieces::kHull) << p.id;
    }
  EXPECT_FALSE(config.shard);
  EXPECT_FALSE(config.out_file);
}

TEST(RunConfig, EachBadOptionIsAUserErrorNamingIt) {
  CheckArgs units = demo_args();
  units.units = "parsec";
  CheckArgs tolerance = demo_args();
  tolerance.tolerance = "-1";
  CheckArgs method = demo_args();
  method.method = "guess";
  CheckArgs shard = demo_args();
  shard.shard = "1/2";
  shard.extra.junit = "junit.xml";
  CheckArgs total = demo_args();
  total.shard_total = 4;
  CheckArgs output = demo_args();
  output.output = "/nonexistent-directory/report.json";
  CheckArgs missing = demo_args();
  missing.scene = "no-such-scene.json";
  const std::pair<const CheckArgs*, const char*> cases[] = {
      {&units, "--units"},        {&tolerance, "--tolerance"}, {&method, "--method"},
      {&shard, "--junit"},        {&total, "--shard-total"},   {&output, "-o"},
      {&missing, "no-such-scene"}};
  for (const auto& [args, named] : cases) {
    const auto [message, code] = failure(*args);
    EXPECT_EQ(code, kExitBadInput) << named << ": " << message;
    EXPECT_NE(message.find(named), std::string::npos) << message;
  }
}
