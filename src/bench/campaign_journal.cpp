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
  text << "# pmdplan bench journal: tasks=" << joined(o.tasks) << " planners=" << joined(o.planners)
       << " runs=" << o.runs << " seed=" << o.seed << " time-limit=" << o.timeLimit << " grace=" << o.graceSeconds
       << " checker=" << checkerKindName(o.checker) << " tolerance=" << o.toleranceMetres
       << " synergies=" << o.synergies.string() << " pmd-settings=[" << describePlannerSettings(o.pmdParameters)
       << "] full-settings=[" << describePlannerSettings(o.fullParameters) << "]";
  return text.str();
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
    if (name.rfind("rank", 0) != 0 || entry.path().extension() != ".tsv") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    if (!in) throw InputError(entry.path().string(), "--journal", "cannot be read");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Whole lines only: a last line without its newline was cut short, and its run is run again.
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = text.substr(start, end - start);
      if (start == 0) {
        if (line != expected)
          throw InputError(entry.path().string(), "--journal",
                           "belongs to another campaign (" + line + "); expected '" + expected +
                               "': use another folder or remove it");
        continue;
      }
      const std::size_t tab = line.find('\t');
      const auto record = tab == std::string::npos ? std::nullopt : decodeRunRecord(line.substr(tab + 1));
      if (!record || line.find_first_not_of("0123456789") != tab)
        throw InputError(entry.path().string(), "--journal", "a line is not a job index and a run record");
      records[std::stoul(line.substr(0, tab))] = *record;
    }
  }
  return records;
}

CampaignJournal::CampaignJournal(const std::filesystem::path& folder, const BenchOptions& options, int rank)
    : file_(folder / ("rank" + std::to_string(rank) + ".tsv")), header_(header(options)) {
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
  const std::string line = std::to_string(job) + "\t" + encodeRunRecord(record) + "\n";
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
