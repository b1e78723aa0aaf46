// "Did you mean ...?": the edit distance against hand-counted cases, and the suggestion rule
// that offers a near name and stays silent for a far one.

#include "raylab/core/suggest.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace raylab {
namespace {

TEST(EditDistance, CountsEachKindOfEditOnce) {
  EXPECT_EQ(edit_distance("render", "render"), 0u);
  EXPECT_EQ(edit_distance("rendr", "render"), 1u);     // an insertion
  EXPECT_EQ(edit_distance("sppp", "spp"), 1u);         // a deletion
  EXPECT_EQ(edit_distance("sampler", "sampled"), 1u);  // a replacement
  EXPECT_EQ(edit_distance("redner", "render"), 1u);    // two neighbours swapped
  EXPECT_EQ(edit_distance("", "diff"), 4u);
  EXPECT_EQ(edit_distance("info", ""), 4u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(EditDistance, IsSymmetricAndIgnoresCase) {
  const std::vector<std::string> words = {"render", "rednr", "Quality", "qaulity", "bench", "", "convert"};
  for (const std::string& a : words) {
    for (const std::string& b : words) EXPECT_EQ(edit_distance(a, b), edit_distance(b, a)) << a << " " << b;
  }
  EXPECT_EQ(edit_distance("RENDER", "render"), 0u);
}

TEST(EditDistance, NeverExceedsTheLongerWordNorFallsBelowTheLengthGap) {
  const std::vector<std::string> words = {"spp", "seed", "sampler", "checkpoint", "x", "max-depth"};
  for (const std::string& a : words) {
    for (const std::string& b : words) {
      const std::size_t d = edit_distance(a, b);
      EXPECT_LE(d, std::max(a.size(), b.size()));
      EXPECT_GE(d, a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
    }
  }
}

TEST(ClosestName, SuggestsTheNearNameAndNothingFar) {
  const std::vector<std::string> commands = {"render", "diff", "info", "convert", "compare", "quality", "bench"};
  EXPECT_EQ(closest_name("rendr", commands), "render");
  EXPECT_EQ(closest_name("comapre", commands), "compare");
  EXPECT_EQ(closest_name("dif", commands), "diff");
  EXPECT_EQ(closest_name("benchmark", commands), std::nullopt);  // 4 edits from bench
  EXPECT_EQ(closest_name("xyz", commands), std::nullopt);
  EXPECT_EQ(closest_name("render", commands), std::nullopt);  // not misspelled
}

TEST(ClosestName, ShortWordsGetOneEditAtMost) {
  const std::vector<std::string> options = {"spp", "seed", "json"};
  EXPECT_EQ(closest_name("sppp", options), "spp");
  EXPECT_EQ(closest_name("sed", options), "seed");
  EXPECT_EQ(closest_name("sp", options), "spp");
  EXPECT_EQ(closest_name("ab", options), std::nullopt);
  EXPECT_EQ(suggestion_tolerance(4), 1u);
  EXPECT_EQ(suggestion_tolerance(5), 2u);
  EXPECT_EQ(suggestion_tolerance(9), 3u);
}

TEST(ClosestName, TakesTheNearestThenTheFirst) {
  const std::vector<std::string> names = {"max-depth", "max-memory", "aa-depth"};
  EXPECT_EQ(closest_name("max-dept", names), "max-depth");
  const std::vector<std::string> tied = {"bat", "cat"};
  EXPECT_EQ(closest_name("at", tied), "bat");
}

}  // namespace
}  // namespace raylab
