#include "pmdplan/io/files/path_csv.hpp"

#include <cmath>
#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/text/csv_field.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
std::string formatPathCsv(const std::vector<std::string>& jointNames, const std::vector<Configuration>& points) {
  std::string out;
  for (std::size_t i = 0; i < jointNames.size(); ++i) {
    if (i != 0) out += ',';
    out += csvField(jointNames[i]);
  }
  out += '\n';
  for (std::size_t row = 0; row < points.size(); ++row) {
    const Configuration& q = points[row];
    if (q.size() != static_cast<Eigen::Index>(jointNames.size()))
      throw std::invalid_argument("formatPathCsv: point " + std::to_string(row) + " has " + std::to_string(q.size()) +
                                  " values for " + std::to_string(jointNames.size()) + " joints");
    for (Eigen::Index k = 0; k < q.size(); ++k) {
      if (!std::isfinite(q[k]))
        throw std::invalid_argument("formatPathCsv: point " + std::to_string(row) + " is not finite");
      if (k != 0) out += ',';
      out += exactNumberText(q[k]);
    }
    out += '\n';
  }
  return out;
}

void writePathCsv(const std::filesystem::path& file, const std::vector<std::string>& jointNames,
                  const std::vector<Configuration>& points) {
  writeFileAtomically(file, formatPathCsv(jointNames, points));
}

}  // namespace pmdplan
