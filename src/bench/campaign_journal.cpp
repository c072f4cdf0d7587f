#include "pmdplan/bench/campaign_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "pmdplan/collision/checker_kind.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"

namespace pmdplan {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ",") + item;
  return text;
}

}  // namespace

std::string CampaignJournal::header(const BenchOptions& o) {
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
                                                               const BenchOptions& options) {
  if (!std::filesystem::is_directory(folder))
    throw InputError(folder.string(), "--journal",
                     "no such journal folder; expected the folder of a campaign started with --journal");
  const std::string expected = header(options);
  std::map<std::size_t, RunRecord> records;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const auto name = entry.path().filename().string();
    if (name.rfind("rank", 0) != 0) continue;
    if (entry.path().extension() == ".tsv")
      throw InputError(entry.path().string(), "line 1",
                       "a journal of an older pmdplan (tab-separated lines); this one writes and reads JSON lines "
                       "(rank<R>.jsonl): finish that campaign with the pmdplan that started it, or use another folder");
    if (entry.path().extension() != ".jsonl") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    if (!in) throw InputError(entry.path().string(), "--journal", "cannot be read");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Whole lines only: a last line without its newline was cut short, and its run is run again.
    std::size_t start = 0, lineNumber = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = text.substr(start, end - start);
      const std::string where = "line " + std::to_string(++lineNumber);
      if (start == 0) {
        if (line != expected)
          throw InputError(entry.path().string(), "--journal",
                           "belongs to another campaign (" + line + "); expected '" + expected +
                               "': use another folder or remove it");
        continue;
      }
      const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
      const bool hasJob = json.is_object() && json.contains("job") && json.at("job").is_number_unsigned();
      const auto record = hasJob ? runRecordFromJson(json, 1) : std::nullopt;
      if (!record)
        throw InputError(entry.path().string(), where,
                         "expected one finished run: a JSON object of \"job\" and the keys of a run record");
      records[json.at("job").get<std::size_t>()] = *record;
    }
  }
  return records;
}

CampaignJournal::CampaignJournal(const std::filesystem::path& folder, const BenchOptions& options, int rank)
    : file_(folder / ("rank" + std::to_string(rank) + ".jsonl")), header_(header(options)) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "--journal", "cannot create the journal folder: " + error.message());
  records_ = finishedJobs(folder, options);
  if (!std::filesystem::exists(file_) || std::filesystem::file_size(file_) == 0) {
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
  if (fd < 0) throw std::runtime_error("cannot append to the journal " + file_.string() + ": " + std::strerror(errno));
  const ssize_t written = ::write(fd, line.data(), line.size());
  const int saved = errno;
  ::fsync(fd);
  ::close(fd);
  if (written != static_cast<ssize_t>(line.size()))
    throw std::runtime_error("cannot append to the journal " + file_.string() + ": " + std::strerror(saved));
  records_[job] = record;
}

}  // namespace pmdplan
