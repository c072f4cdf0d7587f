#include "pmdplan/glove/glove_csv.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/csv_reading.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

constexpr std::string_view kTimeColumn = "time_s";

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> splitCells(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? line.npos : comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

std::string lineField(int line) { return "line " + std::to_string(line); }

/// Which column holds what: -1 = time, otherwise a sensor index.
std::vector<int> readHeader(std::string_view line, int lineNumber, const std::string& source) {
  const auto cells = splitCells(line);
  std::vector<int> columns;
  std::vector<bool> seen(kCyberGloveSensorCount, false);
  bool hasTime = false;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string name(cells[c]);
    const std::string field = lineField(lineNumber) + ", column " + std::to_string(c + 1);
    if (name == kTimeColumn) {
      if (hasTime) throw InputError(source, field, "column time_s appears twice");
      hasTime = true;
      columns.push_back(-1);
      continue;
    }
    const int sensor = cyberGloveSensorIndex(name);
    if (sensor < 0)
      throw InputError(source, field,
                       "unknown column " + quotedText(name) + "; expected time_s (optional) and the sensor columns " +
                           std::string(cyberGloveSensorList()));
    if (seen[static_cast<std::size_t>(sensor)]) throw InputError(source, field, "column " + name + " appears twice");
    seen[static_cast<std::size_t>(sensor)] = true;
    columns.push_back(sensor);
  }
  std::string missing;
  for (int s = 0; s < kCyberGloveSensorCount; ++s)
    if (!seen[static_cast<std::size_t>(s)])
      missing += (missing.empty() ? "" : ", ") + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(s)]);
  if (!missing.empty())
    throw InputError(source, lineField(lineNumber),
                     "header lacks the sensor columns " + missing + " (all 22 CyberGlove sensors are needed)");
  return columns;
}

std::uint8_t readSensorCell(std::string_view cell, const std::string& source, const std::string& field) {
  if (const auto whole = parseWholeNumber(cell)) {
    if (*whole > 255)
      throw InputError(source, field, std::to_string(*whole) + " is outside the raw sensor range 0-255");
    return static_cast<std::uint8_t>(*whole);
  }
  if (const auto number = parseFiniteNumber(cell); number && std::floor(*number) == *number)
    throw InputError(source, field, messageNumberText(*number) + " is outside the raw sensor range 0-255");
  throw InputError(source, field, quotedText(cell) + " is not an integer 0-255");
}

}  // namespace

GloveRecording parseGloveCsv(std::string_view text, const std::string& sourceName) {
  text = withoutByteOrderMark(text);
  GloveRecording recording;
  recording.source = sourceName;
  std::vector<int> columns;
  bool hasTime = false;
  int lineNumber = 0;
  int firstDataLine = 0;
  int lastDataLine = 0;
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t end = text.find('\n', position);
    const std::string_view raw = text.substr(position, end == text.npos ? text.npos : end - position);
    position = end == text.npos ? text.size() : end + 1;
    ++lineNumber;
    const std::string_view line = trimmed(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      recording.notes.emplace_back(trimmed(line.substr(1)));
      continue;
    }
    if (columns.empty()) {
      columns = readHeader(line, lineNumber, sourceName);
      for (const int column : columns) hasTime = hasTime || column < 0;
      continue;
    }
    const auto cells = splitCells(line);
    if (cells.size() != columns.size())
      throw InputError(sourceName, lineField(lineNumber),
                       "expected " + std::to_string(columns.size()) + " columns as in the header, found " +
                           std::to_string(cells.size()));
    GloveFrame frame{};
    double time = 0.0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const int column = columns[c];
      const std::string columnName = column < 0
                                         ? std::string(kTimeColumn)
                                         : std::string(cyberGloveSensorNames()[static_cast<std::size_t>(column)]);
      const std::string field = lineField(lineNumber) + ", column " + columnName;
      if (column < 0) {
        const auto value = parseFiniteNumber(cells[c]);
        if (!value) throw InputError(sourceName, field, quotedText(cells[c]) + " is not a time in seconds");
        time = *value;
      } else {
        frame[static_cast<std::size_t>(column)] = readSensorCell(cells[c], sourceName, field);
      }
    }
    recording.frames.push_back(frame);
    if (hasTime) recording.timeS.push_back(time);
    recording.frameLines.push_back(lineNumber);
    if (firstDataLine == 0) firstDataLine = lineNumber;
    lastDataLine = lineNumber;
  }
  if (columns.empty())
    throw InputError(sourceName, "line " + std::to_string(std::max(lineNumber, 1)),
                     "empty recording; expected a header row naming time_s (optional) and the sensor columns " +
                         std::string(cyberGloveSensorList()));
  if (recording.frames.empty())
    throw InputError(sourceName, lineField(lineNumber), "the recording has a header but no frames");
  recording.dataLocation = "lines " + std::to_string(firstDataLine) + "-" + std::to_string(lastDataLine);
  return recording;
}

GloveRecording readGloveCsv(const std::filesystem::path& path) {
  return parseGloveCsv(readTextFile(path), path.string());
}

std::string formatGloveCsv(const GloveRecording& recording) {
  const bool hasTime = !recording.timeS.empty();
  std::string text;
  text.reserve(recording.frames.size() * 100 + 1024);
  for (const auto& note : recording.notes) text += "# " + note + "\n";
  if (hasTime) text += std::string(kTimeColumn) + ",";
  for (int s = 0; s < kCyberGloveSensorCount; ++s) {
    text += cyberGloveSensorNames()[static_cast<std::size_t>(s)];
    text += s + 1 < kCyberGloveSensorCount ? "," : "\n";
  }
  for (std::size_t f = 0; f < recording.frames.size(); ++f) {
    if (hasTime) text += exactNumberText(recording.timeS.at(f)) + ",";
    for (int s = 0; s < kCyberGloveSensorCount; ++s) {
      text += std::to_string(recording.frames[f][static_cast<std::size_t>(s)]);
      text += s + 1 < kCyberGloveSensorCount ? ',' : '\n';
    }
  }
  return text;
}

}  // namespace pmdplan
