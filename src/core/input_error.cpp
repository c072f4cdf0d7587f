#include "pmdplan/core/input_error.hpp"

#include "pmdplan/core/message_text.hpp"

namespace pmdplan {
namespace {
std::string compose(const std::string& file, const std::string& field, const std::string& message) {
  std::string text;
  if (!file.empty()) text += file + ": ";
  if (!field.empty()) text += field + ": ";
  return text + message;
}
}  // namespace

// Every part escaped (message_text.hpp): a file name, key or value with a terminal escape or a line
// break in it is shown, not acted on, and the message stays one line.
InputError::InputError(std::string file, std::string field, std::string message)
    : std::runtime_error(compose(escapedText(file), escapedText(field), escapedText(message))),
      file_(escapedText(file)),
      field_(escapedText(field)),
      message_(escapedText(message)) {}

}  // namespace pmdplan
