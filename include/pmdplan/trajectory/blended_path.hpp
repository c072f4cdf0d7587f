#pragma once
// A piecewise-linear joint-space path made differentiable by circular blends at its corners, as
// Kunz & Stilman's time-optimal trajectory generation does: at each interior waypoint a circular arc,
// tangent to both neighbouring segments, replaces the corner. The arc begins no farther than half a
// segment from the waypoint and passes within `blendTolerance` of it (Euclidean joint-space norm,
// radians), so every point of the blended path lies within that tolerance of the original polyline.
// The path is parameterised by arc length s.
#include <vector>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

class BlendedPath {
 public:
  struct Segment {
    double start = 0.0;  ///< arc length where the segment begins
    double length = 0.0;
    bool circular = false;
    Eigen::VectorXd origin;  ///< linear: the first point; circular: the centre
    Eigen::VectorXd x;       ///< linear: the unit direction; circular: unit vector centre -> first point
    Eigen::VectorXd y;       ///< circular: unit tangent at the first point
    double radius = 0.0;
  };
  /// Where the phase-plane limit curves may be non-smooth: segment boundaries (`discontinuity`:
  /// the curvature jumps) and the points of an arc where a joint's tangent component is zero.
  struct SwitchingPoint {
    double s = 0.0;
    bool discontinuity = false;
  };

  /// `waypoints` with no two consecutive equal and no reversal (a corner of 180°: it cannot be
  /// blended); blendTolerance > 0. Throws std::invalid_argument otherwise.
  BlendedPath(const std::vector<Configuration>& waypoints, double blendTolerance);

  double length() const { return length_; }
  /// Position, unit tangent dq/ds and curvature d²q/ds² at s in [0, length()]. At a segment
  /// boundary `before` picks the segment that ends there.
  Configuration position(double s, bool before = false) const;
  Eigen::VectorXd tangent(double s, bool before = false) const;
  Eigen::VectorXd curvature(double s, bool before = false) const;
  const std::vector<Segment>& segments() const { return segments_; }
  const std::vector<SwitchingPoint>& switchingPoints() const { return switchingPoints_; }
  /// Segment holding s (at a boundary the one that begins there unless `before`).
  const Segment& segmentAt(double s, bool before = false) const;

 private:
  void addLinear(const Eigen::VectorXd& from, const Eigen::VectorXd& to);
  void addArc(const Eigen::VectorXd& centre, const Eigen::VectorXd& x, const Eigen::VectorXd& y, double radius,
              double angle);

  std::vector<Segment> segments_;
  std::vector<SwitchingPoint> switchingPoints_;
  double length_ = 0.0;
};

/// Whether the corner at waypoint i (between i-1 -> i and i -> i+1) reverses direction (within
/// 1e-6 rad of 180°) and so needs the motion to stop there.
bool isReversal(const Configuration& before, const Configuration& at, const Configuration& after);

}  // namespace pmdplan
