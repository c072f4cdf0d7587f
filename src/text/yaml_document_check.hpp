#pragma once
// The checks parseYamlDocument makes on a YAML text as written, before yaml-cpp builds its nodes
// (yaml_field.hpp): one pass over the parser's events, linear in the text whatever its aliases do.
#include <cstddef>
#include <string>
#include <string_view>

namespace pmdplan {

/// The most values (scalars, lists and maps, keys included) a document may hold once its aliases
/// are expanded: an alias counts as often as the value it names has values.
constexpr std::size_t kMaxYamlValues = 10'000'000;
/// The deepest nesting of lists and maps a document may reach once its aliases are expanded
/// (yaml-cpp itself refuses more than 2000 levels as written).
constexpr std::size_t kMaxYamlDepth = 2000;

/// Throws InputError naming `file` for the first of: a syntax error (its line and column), an alias
/// inside the value it names (a cycle, which no reader could walk to its end), a map key that is
/// not a plain scalar, a key given twice in one map (its field path and both lines), more than
/// kMaxYamlValues values or more than kMaxYamlDepth levels counted through aliases.
void checkYamlDocument(std::string_view text, const std::string& file);

}  // namespace pmdplan
