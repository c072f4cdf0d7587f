#pragma once
// Bad user input: says which file, which field (key, column, line) and what was expected.
#include <stdexcept>
#include <string>

namespace pmdplan {

class InputError : public std::runtime_error {
 public:
  /// `file` may be empty for input that has no file (command-line values); `field` names the key,
  /// column or "line N" where the problem is; `message` says what was wrong and what is expected.
  InputError(std::string file, std::string field, std::string message);

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  std::string field_;
  std::string message_;
};

}  // namespace pmdplan
