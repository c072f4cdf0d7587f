#pragma once
// Strict reading of one YAML node together with where it came from, so that every complaint can
// name the file, the field path (`obstacles[2].cylinder.radius`) and the line.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pmdplan {

class YamlField {
 public:
  /// The document root of `file` (the name errors report).
  YamlField(std::string file, YAML::Node root);

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }
  /// 1-based line of the node in the file, or 0 where yaml-cpp gives none.
  int line() const { return line_; }

  /// "<path> (line N)", the InputError field of this node's complaints ("document" for the root).
  std::string location() const;
  /// Throws the InputError for this field: location() and the message.
  [[noreturn]] void fail(const std::string& message) const;

  /// Requires a map whose keys are plain scalars, each allowed and none repeated; `expected`
  /// describes the allowed form for the messages, `unknownKeyLabel` names what a stray key is.
  void requireMapWithKeys(std::initializer_list<std::string_view> allowed, const std::string& expected,
                          const std::string& unknownKeyLabel = "unknown key") const;
  /// Requires a map and returns its entries in file order, rejecting repeated keys (yaml-cpp keeps
  /// both entries of a repeated key and answers lookups with the first, so we check ourselves).
  std::vector<std::pair<std::string, YamlField>> mapEntries(const std::string& expected) const;
  bool has(std::string_view key) const;
  /// The value under `key`; fails naming the missing field if absent.
  YamlField child(std::string_view key, const std::string& expected) const;
  std::optional<YamlField> optionalChild(std::string_view key) const;
  /// The elements of a sequence (fails if this is not a sequence).
  std::vector<YamlField> elements(const std::string& expected) const;

  /// A plain scalar string (not a map, list or null); `expected` describes it for messages.
  std::string text(const std::string& expected) const;
  /// A finite number written as a plain YAML scalar (quoted strings, booleans, NaN and infinities
  /// are rejected).
  double number(const std::string& expected) const;
  double positiveNumber(const std::string& expected) const;
  /// `true` or `false`, written as such (YAML 1.1's yes/no/on/off are refused).
  bool boolean(const std::string& expected) const;
  /// A list of exactly three finite numbers.
  Eigen::Vector3d vector3(const std::string& expected) const;
  Eigen::Vector3d positiveVector3(const std::string& expected) const;

 private:
  YamlField(std::string file, std::string path, YAML::Node node);
  YamlField at(std::string path, YAML::Node node) const { return {file_, std::move(path), node}; }

  std::string file_;
  std::string path_;
  YAML::Node node_;
  int line_ = 0;
};

/// Joins a parent field path and a key: "" + "base" = "base", "base" + "xyz" = "base.xyz"; a key
/// from a file is shown as message_text.hpp's fieldKeyText shows it (escaped, or measured if long).
std::string joinFieldPath(const std::string& parent, std::string_view key);

/// The one way our YAML files are loaded: an InputError naming `file` for an empty text ("line 1"),
/// a syntax error ("line N, column M"), a key given twice in any map (its field path and line), an
/// alias inside the value it names (a cycle) or a document that aliases make larger or deeper than
/// pmdplan reads (src/text/yaml_document_check.hpp).
YAML::Node parseYamlDocument(std::string_view text, const std::string& file);

/// The root of one of pmdplan's own files (calibration, mapping, synergy model, ...): the document
/// parsed as parseYamlDocument does, a map with only `keys`, and `format:` and `version:` optional
/// but, where given, `format` and 1. `expected` describes the file for the messages.
YamlField parseYamlFile(std::string_view text, const std::string& file, std::string_view format,
                        std::initializer_list<std::string_view> keys, const std::string& expected);

}  // namespace pmdplan
