#include "pmdplan/io/figures/synergy_plots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/io/figures/svg_elements.hpp"
#include "pmdplan/synergy/figure7_joint_pairs.hpp"

namespace pmdplan {
namespace {

// The paper's Sect. 4.2: the first 1, 2 and 3 PMDs of its 13,500 recorded postures carry
// 42.19, 77.12 and 84.71 % of the variance (its Fig. 10).
constexpr std::array<double, 3> kPaperCumulativePercent{42.19, 77.12, 84.71};

using svg::fixed;
using svg::kFont;
using svg::px;
using svg::text;

std::string line(double x1, double y1, double x2, double y2, const std::string& stroke, double width = 1.0) {
  return svg::line(x1, y1, x2, y2, stroke, "stroke-width=\"" + fixed(width, 2) + "\"");
}

/// Value range [low, high] onto pixels [from, to] (to < from for a y axis pointing up).
struct Scale {
  double low, high, from, to;
  double operator()(double value) const { return from + (value - low) / (high - low) * (to - from); }
};

/// A round tick step giving about `ticks` intervals over `span`.
double tickStep(double span, int ticks) {
  const double raw = span / ticks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

/// Up to two lines of at most `width` characters, cut at spaces, "..." if more remains.
std::vector<std::string> wrapped(const std::string& content, std::size_t width) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < content.size() && lines.size() < 2) {
    std::size_t end = std::min(content.size(), start + width);
    if (end < content.size()) {
      const std::size_t space = content.rfind(' ', end);
      if (space != std::string::npos && space > start) end = space;
    }
    lines.push_back(content.substr(start, end - start));
    start = end + (end < content.size() && content[end] == ' ' ? 1 : 0);
  }
  if (start < content.size()) lines.back() += " ...";
  return lines;
}

/// NaN when a joint does not move (its spread no more than rounding of the mean).
double pearson(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd da = a.array() - a.mean();
  const Eigen::VectorXd db = b.array() - b.mean();
  const double rounding = 1e-12 * std::sqrt(static_cast<double>(a.size()));
  if (da.norm() <= rounding * (1.0 + std::abs(a.mean())) || db.norm() <= rounding * (1.0 + std::abs(b.mean())))
    return std::nan("");
  return da.dot(db) / (da.norm() * db.norm());
}

std::string signedText(double value) {
  if (std::isnan(value)) return "n/a";
  std::string result = value >= 0 ? "+" : "";
  result += fixed(value, 2);
  return result;
}

const char* paperWord(PaperCorrelation correlation) {
  switch (correlation) {
    case PaperCorrelation::Positive:
      return "positive";
    case PaperCorrelation::Negative:
      return "negative";
    case PaperCorrelation::Uncorrelated:
      return "none";
  }
  return "";
}

std::string svgOpen(double width, double height) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
         "\" viewBox=\"0 0 " + px(width) + " " + px(height) +
         "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

/// One scatter panel with its top-left corner at (left, top).
std::string scatterPanel(double left, double top, const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                         const JointLimit& xJoint, const JointLimit& yJoint, const Figure7JointPair& pair,
                         int maxPoints) {
  constexpr double kWidth = 400, kHeight = 330, kMarginLeft = 58, kMarginRight = 16, kMarginTop = 46,
                   kMarginBottom = 46;
  const double toDeg = 180.0 / std::numbers::pi;
  const Scale sx{xJoint.lower * toDeg, xJoint.upper * toDeg, left + kMarginLeft, left + kWidth - kMarginRight};
  const Scale sy{yJoint.lower * toDeg, yJoint.upper * toDeg, top + kHeight - kMarginBottom, top + kMarginTop};
  std::string svg;
  const double r = pearson(x, y);
  const double rPaper = r * paperSignOf(pair.first) * paperSignOf(pair.second);
  svg += text(left + kWidth / 2, top + 18, pair.first + "  vs  " + pair.second,
              std::string(kFont) + " font-size=\"13\" text-anchor=\"middle\" font-weight=\"bold\"");
  svg +=
      text(left + kWidth / 2, top + 35,
           "r = " + signedText(r) + "  (paper's signs: " + signedText(rPaper) + ")   paper: " + paperWord(pair.paper),
           std::string(kFont) + " font-size=\"11\" text-anchor=\"middle\" fill=\"#333\"");
  // Grid and ticks.
  for (int axis = 0; axis < 2; ++axis) {
    const Scale& s = axis == 0 ? sx : sy;
    const double step = tickStep(s.high - s.low, 5);
    for (double v = std::ceil(s.low / step - 1e-9) * step; v <= s.high + 1e-9; v += step) {
      if (axis == 0) {
        svg += line(s(v), sy.from, s(v), sy.to, "#e4e4e4");
        svg += text(s(v), sy.from + 14, fixed(v, step < 1 ? 1 : 0),
                    std::string(kFont) + " font-size=\"10\" text-anchor=\"middle\"");
      } else {
        svg += line(sx.from, s(v), sx.to, s(v), "#e4e4e4");
        svg += text(sx.from - 5, s(v) + 3.5, fixed(v, step < 1 ? 1 : 0),
                    std::string(kFont) + " font-size=\"10\" text-anchor=\"end\"");
      }
    }
  }
  svg += "<rect x=\"" + px(sx.from) + "\" y=\"" + px(sy.to) + "\" width=\"" + px(sx.to - sx.from) + "\" height=\"" +
         px(sy.from - sy.to) + "\" fill=\"none\" stroke=\"#555\"/>\n";
  svg += text((sx.from + sx.to) / 2, top + kHeight - 10, xJoint.name + " (deg)",
              std::string(kFont) + " font-size=\"11\" text-anchor=\"middle\"");
  const double yMid = (sy.from + sy.to) / 2;
  svg += text(left + 14, yMid, yJoint.name + " (deg)",
              std::string(kFont) + " font-size=\"11\" text-anchor=\"middle\" transform=\"rotate(-90 " + px(left + 14) +
                  " " + px(yMid) + ")\"");
  // Points: zero-length path segments with round caps draw as dots at a dozen bytes each.
  const Eigen::Index frames = x.size();
  const Eigen::Index drawn = std::min<Eigen::Index>(frames, std::max(1, maxPoints));
  svg +=
      "<path fill=\"none\" stroke=\"#1f5fa8\" stroke-opacity=\"0.35\" stroke-width=\"3\" stroke-linecap=\"round\" d=\"";
  for (Eigen::Index i = 0; i < drawn; ++i) {
    const Eigen::Index frame = i * frames / drawn;
    svg += 'M';
    svg += px(sx(x[frame] * toDeg));
    svg += ' ';
    svg += px(sy(y[frame] * toDeg));
    svg += "h0";
  }
  svg += "\"/>\n";
  return svg;
}

}  // namespace

std::string cumulativeVarianceSvg(const SynergyModel& model) {
  constexpr double kWidth = 680, kHeight = 440, kLeft = 64, kRight = 24, kTop = 76, kBottom = 64;
  const int n = model.directionCount();
  const Scale sy{0.0, 100.0, kHeight - kBottom, kTop};
  const double slot = (kWidth - kLeft - kRight) / std::max(1, n);
  const auto centre = [&](int k) { return kLeft + slot * (k + 0.5); };  // k: 0-based PMD index
  std::string svg = svgOpen(kWidth, kHeight);
  svg += text(kWidth / 2, 24, "Variance covered by the first PMDs (the paper's Fig. 10)",
              std::string(kFont) + " font-size=\"15\" text-anchor=\"middle\" font-weight=\"bold\"");
  double y = 42;
  for (const auto& part : wrapped(model.provenance, 100)) {
    svg += text(kWidth / 2, y, part, std::string(kFont) + " font-size=\"10\" text-anchor=\"middle\" fill=\"#555\"");
    y += 13;
  }
  for (int v = 0; v <= 100; v += 20) {
    svg += line(kLeft, sy(v), kWidth - kRight, sy(v), "#e4e4e4");
    svg += text(kLeft - 6, sy(v) + 4, std::to_string(v), std::string(kFont) + " font-size=\"11\" text-anchor=\"end\"");
  }
  svg += text(18, (sy.from + sy.to) / 2, "variance (%)",
              std::string(kFont) + " font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 18 " +
                  px((sy.from + sy.to) / 2) + ")\"");
  std::string cumulativeLine, markers;
  double cumulative = 0.0;
  for (int k = 0; k < n; ++k) {
    const double share = 100.0 * model.varianceFraction[k];
    cumulative += share;
    const double barWidth = slot * 0.56;
    svg += "<rect x=\"" + px(centre(k) - barWidth / 2) + "\" y=\"" + px(sy(share)) + "\" width=\"" + px(barWidth) +
           "\" height=\"" + px(sy(0) - sy(share)) + "\" fill=\"#8fb3dc\"/>\n";
    svg += text(centre(k), sy(0) + 16, std::to_string(k + 1),
                std::string(kFont) + " font-size=\"11\" text-anchor=\"middle\"");
    if (k > 0) cumulativeLine += ' ';
    cumulativeLine += px(centre(k));
    cumulativeLine += ',';
    cumulativeLine += px(sy(cumulative));
    markers += "<circle cx=\"" + px(centre(k)) + "\" cy=\"" + px(sy(cumulative)) + "\" r=\"3.5\" fill=\"#b03a2e\"/>\n";
    markers += text(centre(k), sy(cumulative) - 8, fixed(cumulative, 1),
                    std::string(kFont) + " font-size=\"10\" text-anchor=\"middle\" fill=\"#b03a2e\"");
  }
  svg +=
      "<polyline fill=\"none\" stroke=\"#b03a2e\" stroke-width=\"2\" points=\"" + cumulativeLine + "\"/>\n" + markers;
  for (int k = 0; k < std::min<int>(n, static_cast<int>(kPaperCumulativePercent.size())); ++k) {
    const double cx = centre(k), cy = sy(kPaperCumulativePercent[static_cast<std::size_t>(k)]);
    svg += "<path d=\"M" + px(cx) + " " + px(cy - 6) +
           "l6 6l-6 6l-6 -6z\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  }
  svg += text((kLeft + kWidth - kRight) / 2, kHeight - 22, "number of PMDs",
              std::string(kFont) + " font-size=\"12\" text-anchor=\"middle\"");
  // Legend.
  const double lx = kWidth - kRight - 190, ly = kHeight - kBottom - 70;
  svg +=
      "<rect x=\"" + px(lx) + "\" y=\"" + px(ly) + "\" width=\"180\" height=\"58\" fill=\"white\" stroke=\"#bbb\"/>\n";
  svg += "<rect x=\"" + px(lx + 8) + "\" y=\"" + px(ly + 8) + "\" width=\"14\" height=\"10\" fill=\"#8fb3dc\"/>\n";
  svg += text(lx + 28, ly + 17, "share of each PMD", std::string(kFont) + " font-size=\"11\"");
  svg += line(lx + 8, ly + 31, lx + 22, ly + 31, "#b03a2e", 2);
  svg += text(lx + 28, ly + 35, "cumulative", std::string(kFont) + " font-size=\"11\"");
  svg += "<path d=\"M" + px(lx + 15) + " " + px(ly + 42) +
         "l5 5l-5 5l-5 -5z\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  svg += text(lx + 28, ly + 51, "paper (1-3 PMDs)", std::string(kFont) + " font-size=\"11\"");
  return svg + "</svg>\n";
}

std::string jointPairsSvg(const Eigen::MatrixXd& postures, const JointLimits& joints,
                          const SynergyPlotSettings& options) {
  if (postures.cols() != static_cast<Eigen::Index>(joints.size()))
    throw std::invalid_argument("jointPairsSvg: one posture column per joint expected");
  const auto column = [&](const std::string& name) -> int {
    for (std::size_t j = 0; j < joints.size(); ++j)
      if (joints[j].name == name) return static_cast<int>(j);
    return -1;
  };
  std::vector<std::pair<const Figure7JointPair*, std::array<int, 2>>> panels;
  for (const Figure7JointPair& pair : figure7JointPairs()) {
    const int a = column(pair.first), b = column(pair.second);
    if (a >= 0 && b >= 0) panels.push_back({&pair, {a, b}});
  }
  constexpr double kPanelWidth = 400, kPanelHeight = 330, kHeader = 48;
  const int rows = (static_cast<int>(panels.size()) + 1) / 2;
  std::string svg = svgOpen(2 * kPanelWidth, kHeader + rows * kPanelHeight);
  const Eigen::Index drawn = std::min<Eigen::Index>(postures.rows(), options.maxScatterPoints);
  svg += text(kPanelWidth, 22, "Joint pairs of the paper's Fig. 7",
              std::string(kFont) + " font-size=\"15\" text-anchor=\"middle\" font-weight=\"bold\"");
  svg += text(kPanelWidth, 40,
              "r over all " + std::to_string(postures.rows()) + " postures; " + std::to_string(drawn) +
                  " drawn. Flexion positive here; the paper counts it negative.",
              std::string(kFont) + " font-size=\"11\" text-anchor=\"middle\" fill=\"#555\"");
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const auto& [pair, columns] = panels[p];
    svg +=
        scatterPanel(static_cast<double>(p % 2) * kPanelWidth, kHeader + static_cast<double>(p / 2) * kPanelHeight,
                     postures.col(columns[0]), postures.col(columns[1]), joints[static_cast<std::size_t>(columns[0])],
                     joints[static_cast<std::size_t>(columns[1])], *pair, options.maxScatterPoints);
  }
  return svg + "</svg>\n";
}

std::vector<std::filesystem::path> writeSynergyPlots(const std::filesystem::path& directory, const SynergyModel& model,
                                                     const Eigen::MatrixXd& postures, const JointLimits& joints,
                                                     const SynergyPlotSettings& options) {
  createOutputFolder(directory, "--plots");
  std::vector<std::filesystem::path> written{directory / "cumulative_variance.svg"};
  writeFileAtomically(written.back(), cumulativeVarianceSvg(model));
  if (postures.rows() > 0) {
    written.push_back(directory / "joint_pairs.svg");
    writeFileAtomically(written.back(), jointPairsSvg(postures, joints, options));
  }
  return written;
}

}  // namespace pmdplan
