#pragma once
// The data a written viewer folder holds: viewer-data.js is `window.pmdplanViewerData = {...};`,
// the JSON between the first brace and the last semicolon.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_cli.hpp"

namespace pmdplan::test {

inline nlohmann::json viewerDocument(const std::filesystem::path& folder) {
  const std::string text = contents(folder / "viewer-data.js");
  const auto begin = text.find('{');
  return nlohmann::json::parse(text.substr(begin, text.rfind(';') - begin));
}

}  // namespace pmdplan::test
