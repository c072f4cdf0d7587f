#include "pmdplan/io/files/json_text.hpp"

#include <cmath>
#include <stdexcept>

#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

bool isPlain(const nlohmann::ordered_json& value) { return !value.is_object() && !value.is_array(); }

bool isPlainArray(const nlohmann::ordered_json& value) {
  if (!value.is_array()) return false;
  for (const auto& item : value)
    if (!isPlain(item)) return false;
  return true;
}

/// Objects of one key holding a plain value or a plain array stay on one line ({"positions": [...]}).
bool isOneLineObject(const nlohmann::ordered_json& value) {
  return value.is_object() && value.size() == 1 &&
         (isPlain(value.begin().value()) || isPlainArray(value.begin().value()));
}

void append(std::string& out, const nlohmann::ordered_json& value, int indent);

void appendPlain(std::string& out, const nlohmann::ordered_json& value) {
  switch (value.type()) {
    case nlohmann::ordered_json::value_t::number_float: {
      const double number = value.get<double>();
      if (!std::isfinite(number)) throw std::invalid_argument("formatJson: a number is not finite");
      // "-0" would read back as the integer 0; "-0.0" keeps the sign, so the round trip stays exact.
      out += (number == 0.0 && std::signbit(number)) ? "-0.0" : exactNumberText(number);
      break;
    }
    case nlohmann::ordered_json::value_t::number_unsigned:
      out += std::to_string(value.get<std::uint64_t>());
      break;
    case nlohmann::ordered_json::value_t::number_integer:
      out += std::to_string(value.get<std::int64_t>());
      break;
    default:  // strings (escaped by nlohmann), booleans, null
      out += value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  }
}

void appendInline(std::string& out, const nlohmann::ordered_json& value) {
  if (value.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i != 0) out += ", ";
      appendPlain(out, value[i]);
    }
    out += ']';
  } else if (value.is_object()) {
    out += '{';
    appendPlain(out, nlohmann::ordered_json(value.begin().key()));
    out += ": ";
    appendInline(out, value.begin().value());
    out += '}';
  } else {
    appendPlain(out, value);
  }
}

void append(std::string& out, const nlohmann::ordered_json& value, int indent) {
  if (isPlain(value) || isPlainArray(value) || isOneLineObject(value) || value.empty()) {
    if (value.is_object() && value.empty()) {
      out += "{}";
      return;
    }
    appendInline(out, value);
    return;
  }
  const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
  const bool object = value.is_object();
  out += object ? "{\n" : "[\n";
  bool first = true;
  for (auto item = value.begin(); item != value.end(); ++item) {
    if (!first) out += ",\n";
    first = false;
    out += inner;
    if (object) {
      appendPlain(out, nlohmann::ordered_json(item.key()));
      out += ": ";
    }
    append(out, item.value(), indent + 2);
  }
  out += '\n';
  out += std::string(static_cast<std::size_t>(indent), ' ');
  out += object ? '}' : ']';
}

}  // namespace

std::string formatJson(const nlohmann::ordered_json& document) {
  std::string out;
  append(out, document, 0);
  out += '\n';
  return out;
}

}  // namespace pmdplan
