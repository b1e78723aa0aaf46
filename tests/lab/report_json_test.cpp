// The lab's JSON reports: nlohmann's layout, keys in the order written, and every floating-point
// number with the six significant digits the reports have always had.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "../../src/lab/report_json.h"

namespace raylab {
namespace {

using detail::report_text;
using detail::ReportJson;

TEST(ReportJson, LayoutIsNlohmannsIndentedDumpWithKeysInTheOrderWritten) {
  ReportJson doc = {{"zebra", 1}, {"apple", "a \"quoted\" name"}, {"list", {1, 2}}, {"empty", ReportJson::array()}};
  doc["nested"] = {{"on", true}, {"off", nullptr}, {"none", ReportJson::object()}};
  EXPECT_EQ(report_text(doc), doc.dump(2) + "\n");  // no floats: exactly nlohmann's own layout
  EXPECT_LT(report_text(doc).find("zebra"), report_text(doc).find("apple"));
}

TEST(ReportJson, FloatsHaveSixSignificantDigits) {
  const ReportJson doc = {{"a", 0.00534988},  // nlohmann alone writes 0.0053498799999999996
                          {"b", 3.0},        {"c", 1234567.0}, {"d", 1.5e-5}, {"e", 2.0f / 3.0f}, {"n", 42}};
  EXPECT_EQ(report_text(doc),
            "{\n  \"a\": 0.00534988,\n  \"b\": 3,\n  \"c\": 1.23457e+06,\n  \"d\": 1.5e-05,\n  \"e\": 0.666667,\n"
            "  \"n\": 42\n}\n");
}

TEST(ReportJson, InfinitiesAndNanAreNull) {
  const ReportJson doc = {{"inf", std::numeric_limits<double>::infinity()}, {"nan", std::nan("")}};
  EXPECT_EQ(report_text(doc), "{\n  \"inf\": null,\n  \"nan\": null\n}\n");
}

TEST(ReportJson, InvalidUtf8IsReplacedNotThrown) {
  const ReportJson doc = {{"scene", std::string("caf\xe9.json")}};
  std::string text;
  EXPECT_NO_THROW(text = report_text(doc));
  EXPECT_NE(text.find("caf"), std::string::npos);
}

}  // namespace
}  // namespace raylab
