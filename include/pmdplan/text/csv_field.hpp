#pragma once
// One field of a CSV file (RFC 4180): as it is, or double-quoted with its quotes doubled when it
// holds a comma, a quote or a line break.
#include <string>

namespace pmdplan {

std::string csvField(const std::string& text);

}  // namespace pmdplan
