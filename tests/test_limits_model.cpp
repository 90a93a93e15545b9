// The module's limits (core/io/limits_model.h): one description, each entry with its words; the
// paths make one tree; the default tolerance table, written as a document, reads back as the case
// reader reads a case's own table.
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "default_tolerances.h"
#include "limits_model.h"
#include "test_support.h"

namespace hobsharp {
namespace {

using Json = nlohmann::json;

TEST(LimitsModel, EntriesAreUniqueWithWordsAndMakeOneTree) {
  std::set<std::string> paths;
  for (const LimitDescription& d : limitFields()) {
    EXPECT_TRUE(paths.insert(d.path).second) << d.path << " is described twice";
    EXPECT_FALSE(d.words.empty()) << d.path;
    EXPECT_FALSE(d.kind.empty()) << d.path;
  }
  // No entry sits inside another's value: "a.b" and "a.b.c" cannot both be set.
  for (const std::string& p : paths)
    for (std::size_t dot = p.find('.'); dot != std::string::npos; dot = p.find('.', dot + 1))
      EXPECT_EQ(paths.count(p.substr(0, dot)), 0u) << p << " lies inside " << p.substr(0, dot);
  for (const char* p : {"format", "maxGridLines", "degree", "defaultGrid.radial", "axes.0.name", "axes.4.unit",
                        "correction.probeNoise", "correction.resolution.B", "inspection.defaultTolerances", "inspection.uncertainty"})
    EXPECT_EQ(paths.count(p), 1u) << p;
}

TEST(LimitsModel, TheDefaultTableReadsBackAsACasesOwnTable) {
  Json c = Json::parse(test::readFile("tab1.json"));
  c["inspection"]["tolerances"] = Json::parse(defaultToleranceJson());
  auto in = parseCase(c.dump());
  ASSERT_TRUE(in.ok()) << in.error().message;
  ASSERT_TRUE(in->inspection.tolerances.has_value());
  const ToleranceTable& read = *in->inspection.tolerances;
  const ToleranceTable& given = defaultToleranceTable();
  EXPECT_EQ(read.moduleEdges, given.moduleEdges);
  for (Check k : kChecks)
    for (ToleranceClass t : kClasses) {
      EXPECT_EQ(read.cells[static_cast<int>(k)][static_cast<int>(t)], given.cells[static_cast<int>(k)][static_cast<int>(t)])
          << checkName(k) << " " << className(t);
      EXPECT_EQ(read.confidence[static_cast<int>(k)][static_cast<int>(t)], given.confidence[static_cast<int>(k)][static_cast<int>(t)])
          << checkName(k) << " " << className(t);
    }
}

}  // namespace
}  // namespace hobsharp
