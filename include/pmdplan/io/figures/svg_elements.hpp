#pragma once
// The few SVG elements our figures are drawn with (no plotting library): numbers with a fixed
// number of decimals (never "-0.0", so output is stable), escaped text, text and line elements.
#include <string>

namespace pmdplan::svg {

/// The font every figure uses.
inline constexpr const char* kFont = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\"";

std::string fixed(double value, int decimals);
/// A coordinate: one decimal.
std::string px(double value);
/// `text` with &, <, > and " escaped for XML.
std::string escaped(const std::string& text);
/// <text> at (x, y) with extra attributes.
std::string text(double x, double y, const std::string& content, const std::string& attributes = "");
/// <line> from (x1, y1) to (x2, y2) with extra attributes.
std::string line(double x1, double y1, double x2, double y2, const std::string& stroke,
                 const std::string& attributes = "");

}  // namespace pmdplan::svg
