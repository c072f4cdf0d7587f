#include "pmdplan/bench/campaign_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "pmdplan/collision/checker_kind.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/io/files/json_repeated_keys.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"

namespace pmdplan {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ",") + item;
  return text;
}

/// Every entry named rank<R>.jsonl is one of the journal's files: a folder, a FIFO or a device of
/// that name is the user's mistake, not something to open (a FIFO would block for ever).
void requireRegularFile(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(file.string(), "--journal",
                     "is not a regular file; a journal folder holds the files rank<R>.jsonl that pmdplan writes: "
                     "remove or rename it, or use another folder");
}

/// The campaign settings of a journal's first line ("tasks=... planners=... runs=3 ..."), split at
/// the spaces outside brackets.
std::vector<std::string> campaignSettings(const std::string& campaign) {
  std::vector<std::string> settings(1);
  int depth = 0;
  for (const char c : campaign) {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    if (c == ' ' && depth == 0)
      settings.emplace_back();
    else
      settings.back() += c;
  }
  return settings;
}

/// How a journal's first line differs from this campaign's, without showing the file's contents
/// (message_text.hpp): the first of this campaign's settings it does not have, and its own value of it.
std::string campaignDifference(const std::string& line, const std::string& expected) {
  const nlohmann::json given = nlohmann::json::parse(line, nullptr, false);
  if (!given.is_object() || !given.contains("campaign") || !given.at("campaign").is_string())
    return "its first line is " + quotedText(line);
  const auto theirs = campaignSettings(given.at("campaign").get<std::string>());
  const auto ours = campaignSettings(nlohmann::json::parse(expected).at("campaign").get<std::string>());
  for (const std::string& setting : ours) {
    if (std::find(theirs.begin(), theirs.end(), setting) != theirs.end()) continue;
    const std::string key = setting.substr(0, setting.find('=') + 1);  // "runs="
    const std::string name = key.substr(0, key.size() - 1);
    for (const std::string& other : theirs)
      if (other.rfind(key, 0) == 0) return "its " + name + " is " + quotedText(other.substr(key.size()));
    return "it has no " + name;
  }
  return "its first line is " + quotedText(line);
}

}  // namespace

std::string CampaignJournal::header(const BenchSettings& o) {
  std::ostringstream text;
  text.precision(17);
  text << "tasks=" << joined(o.tasks) << " planners=" << joined(o.planners) << " runs=" << o.runs << " seed=" << o.seed
       << " time-limit=" << o.timeLimit << " grace=" << o.graceSeconds << " checker=" << checkerKindName(o.checker)
       << " tolerance=" << o.toleranceMetres << " synergies=" << o.synergies.string() << " pmd-settings=["
       << describePlannerSettings(o.pmdParameters) << "] full-settings=[" << describePlannerSettings(o.fullParameters)
       << "]";
  return nlohmann::ordered_json{{"pmdplan_bench_journal", 1}, {"campaign", text.str()}}.dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::map<std::size_t, RunRecord> CampaignJournal::finishedJobs(const std::filesystem::path& folder,
                                                               const BenchSettings& options) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw InputError(folder.string(), "--journal",
                     "no such journal folder; expected the folder of a campaign started with --journal");
  const std::string expected = header(options);
  std::map<std::size_t, RunRecord> records;
  std::filesystem::directory_iterator entries(folder, error);
  if (error) throw InputError(folder.string(), "--journal", "cannot list the journal folder: " + error.message());
  for (; entries != std::filesystem::directory_iterator(); entries.increment(error)) {
    const auto& entry = *entries;
    const auto name = entry.path().filename().string();
    if (name.rfind("rank", 0) != 0) continue;
    if (entry.path().extension() == ".tsv")
      throw InputError(entry.path().string(), "line 1",
                       "a journal of an older pmdplan (tab-separated lines); this one writes and reads JSON lines "
                       "(rank<R>.jsonl): finish that campaign with the pmdplan that started it, or use another folder");
    if (entry.path().extension() != ".jsonl") continue;
    requireRegularFile(entry.path());
    std::ifstream in(entry.path(), std::ios::binary);
    if (!in) throw InputError(entry.path().string(), "--journal", "cannot be read");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(entry.path().string(), "--journal", "cannot be read");
    // Whole lines only: a last line without its newline was cut short, and its run is run again.
    std::size_t start = 0, lineNumber = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = text.substr(start, end - start);
      const std::string where = "line " + std::to_string(++lineNumber);
      if (start == 0) {
        if (line != expected)
          throw InputError(entry.path().string(), "--journal",
                           "belongs to another campaign (" + campaignDifference(line, expected) + "); expected '" +
                               expected + "': use another folder or remove it");
        continue;
      }
      // A key given twice would leave one of its values unread: refused, naming the key.
      const nlohmann::json json =
          nlohmann::json::parse(line, refuseRepeatedJsonKeys(entry.path().string(), where), false);
      const bool hasJob = json.is_object() && json.contains("job") && json.at("job").is_number_unsigned();
      const auto record = hasJob ? runRecordFromJson(json, 1) : std::nullopt;
      if (!record)
        throw InputError(entry.path().string(), where,
                         "expected one finished run: a JSON object of \"job\" and the keys of a run record");
      records[json.at("job").get<std::size_t>()] = *record;
    }
  }
  if (error) throw InputError(folder.string(), "--journal", "cannot list the journal folder: " + error.message());
  return records;
}

CampaignJournal::CampaignJournal(const std::filesystem::path& folder, const BenchSettings& options, int rank)
    : file_(folder / ("rank" + std::to_string(rank) + ".jsonl")), header_(header(options)) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "--journal", "cannot create the journal folder: " + error.message());
  records_ = finishedJobs(folder, options);  // this rank's file, if there, is a regular file
  const auto size = std::filesystem::file_size(file_, error);
  if (error || size == 0) {
    std::ofstream out(file_, std::ios::app);
    out << header_ << '\n';
    if (!out.flush()) throw InputError(file_.string(), "--journal", "cannot be written");
  }
}

const RunRecord* CampaignJournal::find(std::size_t job) const {
  const auto found = records_.find(job);
  return found == records_.end() ? nullptr : &found->second;
}

void CampaignJournal::append(std::size_t job, const RunRecord& record) {
  // One write() of the whole line on an O_APPEND descriptor: a crash leaves whole lines, or a last
  // line without its newline that the next reading skips.
  nlohmann::ordered_json json = {{"job", job}};
  json.update(runRecordToJson(record));
  const std::string line = json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  const int fd = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
  // The journal is the user's folder: a file made unwritable, replaced or a full disk is bad input.
  if (fd < 0) throw InputError(file_.string(), "--journal", std::string("cannot append: ") + std::strerror(errno));
  const ssize_t written = ::write(fd, line.data(), line.size());
  const int saved = errno;
  ::fsync(fd);
  ::close(fd);
  if (written != static_cast<ssize_t>(line.size()))
    throw InputError(file_.string(), "--journal",
                     std::string("cannot append: ") + (written < 0 ? std::strerror(saved) : "a short write"));
  records_[job] = record;
}

}  // namespace pmdplan
