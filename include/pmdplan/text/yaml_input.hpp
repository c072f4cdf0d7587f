#pragma once
// Reading our YAML files with messages that name the file, the line and the key of every problem.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>

namespace pmdplan::yaml_input {

// The node-by-node reading of the glove, synergy and joint-limit files, on the one YAML loader of
// yaml_field.hpp (parseYamlDocument: empty files, syntax, repeated keys, alias bombs).

/// parseYamlDocument, then a map at the top level.
YAML::Node parseDocument(std::string_view text, const std::string& file);

/// "line N" (1-based) of a node, for InputError's field.
std::string lineOf(const YAML::Node& node);

/// The map entry `key` of `map`; throws InputError (line of `map`) if it is missing.
YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& file, const std::string& context);

/// Throws unless `node` is a map / a sequence.
void expectMap(const YAML::Node& node, const std::string& file, const std::string& context);
void expectSequence(const YAML::Node& node, const std::string& file, const std::string& context);

/// Throws InputError naming the line and the key of the first key not in `known`.
void rejectUnknownKeys(const YAML::Node& map, std::initializer_list<std::string_view> known, const std::string& file,
                       const std::string& context);

double number(const YAML::Node& node, const std::string& file, const std::string& context);
std::string text(const YAML::Node& node, const std::string& file, const std::string& context);
bool boolean(const YAML::Node& node, const std::string& file, const std::string& context);

/// `format:` and `version:` of our files: optional, but if present they must match.
void checkFormat(const YAML::Node& root, std::string_view expectedFormat, const std::string& file);

}  // namespace pmdplan::yaml_input
