// One version string: CMake's project version, the generated header and CHANGELOG.md agree.
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "dispkin/version.hpp"

TEST(Version, ChangelogNewestEntryIsTheLibraryVersion) {
  std::ifstream file(std::string(DISPKIN_SOURCE_DIR) + "/CHANGELOG.md");
  ASSERT_TRUE(file.good());
  std::stringstream text;
  text << file.rdbuf();
  std::smatch match;
  const std::string content = text.str();
  ASSERT_TRUE(std::regex_search(content, match, std::regex(R"(## \[(\d+\.\d+\.\d+)\])")));
  EXPECT_EQ(match[1].str(), std::string(dispkin::version));
}
