// Which BCF topics an export holds and their GUIDs (bcf_topics.cpp).
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "report/bcf_topics.h"
#include "results/fingerprint.h"

TEST(BcfTopics, GuidsAreStableVersion8Uuids) {
  const std::regex uuid("[a-f0-9]{8}-[a-f0-9]{4}-8[a-f0-9]{3}-[89ab][a-f0-9]{3}-[a-f0-9]{12}");
  std::set<std::string> seen;
  for (const std::string& key :
       std::vector<std::string>{"", "a", "b", pd::pair_fingerprint("frame", "lid")})
    for (const std::string kind : {"topic", "viewpoint"}) {
      const std::string g = pd::bcf_guid(kind, key);
      EXPECT_TRUE(std::regex_match(g, uuid)) << g;
      EXPECT_EQ(g, pd::bcf_guid(kind, key));
      EXPECT_TRUE(seen.insert(g).second) << kind << " " << key;
    }
}
