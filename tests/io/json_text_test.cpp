#include "pmdplan/io/files/json_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace pmdplan {
namespace {

TEST(FormatJson, PlainArraysInlineObjectsIndentedKeysInOrder) {
  nlohmann::ordered_json document;
  document["zeta"] = "first";
  document["alpha"] = nlohmann::ordered_json::array({1, 0.5, -2});
  nlohmann::ordered_json point;
  point["positions"] = nlohmann::ordered_json::array({0.1, 2.0});
  document["points"] = nlohmann::ordered_json::array({point, point});
  document["empty"] = nlohmann::ordered_json::object();
  document["nested"]["b"] = true;
  document["nested"]["a"] = nullptr;
  const std::string expected =
      "{\n"
      "  \"zeta\": \"first\",\n"
      "  \"alpha\": [1, 0.5, -2],\n"
      "  \"points\": [\n"
      "    {\"positions\": [0.1, 2]},\n"
      "    {\"positions\": [0.1, 2]}\n"
      "  ],\n"
      "  \"empty\": {},\n"
      "  \"nested\": {\n"
      "    \"b\": true,\n"
      "    \"a\": null\n"
      "  }\n"
      "}\n";
  EXPECT_EQ(formatJson(document), expected);
}

TEST(FormatJson, NumbersReadBackExactly) {
  const double values[] = {0.1, 1.0 / 3.0, -0.0, 1e-300, 6.02214076e23, M_PI, -1.5707963267948966, 5e-324};
  nlohmann::ordered_json document;
  for (const double v : values) document["v"].push_back(v);
  const nlohmann::json back = nlohmann::json::parse(formatJson(document));
  for (std::size_t i = 0; i < std::size(values); ++i) {
    EXPECT_EQ(back["v"][i].get<double>(), values[i]) << i;
    EXPECT_EQ(std::signbit(back["v"][i].get<double>()), std::signbit(values[i])) << i;
  }
}

TEST(FormatJson, StringsAreEscaped) {
  nlohmann::ordered_json document;
  document["quote\"key"] = "line\nbreak \\ \"q\"";
  EXPECT_EQ(nlohmann::json::parse(formatJson(document))["quote\"key"], "line\nbreak \\ \"q\"");
}

TEST(FormatJson, RejectsNonFiniteNumbers) {
  nlohmann::ordered_json document;
  document["x"] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(formatJson(document), std::invalid_argument);
  document["x"] = std::nan("");
  EXPECT_THROW(formatJson(document), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
