#include "pmdplan/bench/planning_time_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pmdplan/io/figures/svg_elements.hpp"

namespace pmdplan {
namespace {

// Colour-blind safe palette (Okabe-Ito plus wine and grey), one colour per planner: the nine
// known planners get nine colours; more repeat.
const char* const kColours[] = {"#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9",
                                "#D55E00", "#F0E442", "#000000", "#882255", "#999999"};

using svg::line;
using svg::px;

std::string label(double x, double y, const std::string& content, const std::string& attributes = "") {
  return svg::text(x, y, content, std::string(svg::kFont) + " " + attributes);
}

double quantile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

std::string decadeLabel(int exponent) {
  if (exponent >= 0 && exponent <= 4) return std::to_string(static_cast<long>(std::lround(std::pow(10.0, exponent))));
  if (exponent < 0 && exponent >= -3) {
    char text[16];
    std::snprintf(text, sizeof text, "%.*f", -exponent, std::pow(10.0, exponent));
    return text;
  }
  return "1e" + std::to_string(exponent);
}

}  // namespace

std::string planningTimeBoxPlotSvg(const std::vector<RunRecord>& records, const std::vector<std::string>& tasks,
                                   const std::vector<std::string>& planners, double timeLimitSeconds) {
  // A floor keeps zero times (e.g. a run that failed at once) on the log axis.
  constexpr double kFloor = 1e-4;
  double low = timeLimitSeconds, high = timeLimitSeconds;
  for (const RunRecord& r : records) {
    low = std::min(low, std::max(r.planningTimeSeconds, kFloor));
    high = std::max(high, std::max(r.planningTimeSeconds, kFloor));
  }
  const int lowDecade = static_cast<int>(std::floor(std::log10(low)));
  const int highDecade = std::max(lowDecade + 1, static_cast<int>(std::ceil(std::log10(high))));

  const double boxWidth = 22.0, boxGap = 8.0, groupGap = 30.0;
  const double left = 70.0, top = 40.0, plotHeight = 320.0;
  const double groupWidth = static_cast<double>(planners.size()) * (boxWidth + boxGap) - boxGap;
  const double plotWidth = static_cast<double>(tasks.size()) * (groupWidth + groupGap) + groupGap;
  const double legendTop = top + plotHeight + 70.0;
  const double width = left + plotWidth + 20.0;
  const double height = legendTop + 20.0 * static_cast<double>(planners.size()) + 10.0;
  const auto y = [&](double seconds) {
    const double v = std::log10(std::max(seconds, kFloor));
    return top + plotHeight - (v - lowDecade) / (highDecade - lowDecade) * plotHeight;
  };

  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
                    "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += label(left, 22.0,
               "Planning time per run (log scale): whiskers min-max, failures at the time they stopped, successes/runs "
               "under each box",
               "font-size=\"13\"");
  for (int d = lowDecade; d <= highDecade; ++d) {
    const double yy = y(std::pow(10.0, d));
    svg += line(left, yy, left + plotWidth, yy, "#dddddd");
    svg += label(left - 8.0, yy + 4.0, decadeLabel(d), "font-size=\"11\" text-anchor=\"end\"");
  }
  svg +=
      label(18.0, top + plotHeight / 2.0, "seconds",
            "font-size=\"12\" transform=\"rotate(-90 18 " + px(top + plotHeight / 2.0) + ")\" text-anchor=\"middle\"");
  svg += line(left, top, left, top + plotHeight, "#333333");
  svg += line(left, top + plotHeight, left + plotWidth, top + plotHeight, "#333333");
  const double limitY = y(timeLimitSeconds);
  svg += line(left, limitY, left + plotWidth, limitY, "#c00000", "stroke-dasharray=\"6 4\"");
  svg += label(left + plotWidth - 4.0, limitY - 4.0, "time limit",
               "font-size=\"11\" text-anchor=\"end\" fill=\"#c00000\"");

  for (std::size_t t = 0; t < tasks.size(); ++t) {
    const double groupLeft = left + groupGap + static_cast<double>(t) * (groupWidth + groupGap);
    svg += label(groupLeft + groupWidth / 2.0, top + plotHeight + 36.0, tasks[t],
                 "font-size=\"12\" text-anchor=\"middle\"");
    for (std::size_t p = 0; p < planners.size(); ++p) {
      std::vector<double> times;
      std::size_t successes = 0;
      for (const RunRecord& r : records)
        if (r.task == tasks[t] && r.planner == planners[p]) {
          times.push_back(r.planningTimeSeconds);
          successes += r.succeeded();
        }
      const double x = groupLeft + static_cast<double>(p) * (boxWidth + boxGap);
      const std::string colour = kColours[p % (sizeof kColours / sizeof *kColours)];
      if (!times.empty()) {
        std::sort(times.begin(), times.end());
        const double q1 = y(quantile(times, 0.25)), q2 = y(quantile(times, 0.5)), q3 = y(quantile(times, 0.75));
        const double mid = x + boxWidth / 2.0;
        svg += line(mid, y(times.front()), mid, q1, colour);
        svg += line(mid, q3, mid, y(times.back()), colour);
        svg += line(x + 5.0, y(times.front()), x + boxWidth - 5.0, y(times.front()), colour);
        svg += line(x + 5.0, y(times.back()), x + boxWidth - 5.0, y(times.back()), colour);
        svg += "<rect x=\"" + px(x) + "\" y=\"" + px(q3) + "\" width=\"" + px(boxWidth) + "\" height=\"" +
               px(std::max(q1 - q3, 1.0)) + "\" fill=\"" + colour + "\" fill-opacity=\"0.35\" stroke=\"" + colour +
               "\"/>\n";
        svg += line(x, q2, x + boxWidth, q2, colour, "stroke-width=\"2\"");
      }
      svg += label(x + boxWidth / 2.0, top + plotHeight + 16.0,
                   std::to_string(successes) + "/" + std::to_string(times.size()),
                   "font-size=\"9\" text-anchor=\"middle\"");
    }
  }
  for (std::size_t p = 0; p < planners.size(); ++p) {
    const double yy = legendTop + 20.0 * static_cast<double>(p);
    const std::string colour = kColours[p % (sizeof kColours / sizeof *kColours)];
    svg += "<rect x=\"" + px(left) + "\" y=\"" + px(yy - 10.0) + "\" width=\"14\" height=\"12\" fill=\"" + colour +
           "\" fill-opacity=\"0.35\" stroke=\"" + colour + "\"/>\n";
    svg += label(left + 20.0, yy, planners[p], "font-size=\"12\"");
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace pmdplan
