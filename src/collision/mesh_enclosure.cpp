#include "mesh_enclosure.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Added to every extent, so that rounding never leaves a vertex outside (far below the band).
constexpr double kMargin = 1e-9;

enum class Form { Box, Cylinder, Capsule };

struct Candidate {
  Form form = Form::Box;
  double volume = std::numeric_limits<double>::infinity();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns; Cylinder, Capsule: axis is column 2
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();    ///< in the mesh frame
  Eigen::Vector3d half = Eigen::Vector3d::Zero();      ///< Box: half extents; Cylinder: radius, half length
  double from = 0.0, to = 0.0, radius = 0.0;           ///< Capsule: its core along the axis through centre
};

/// Candidates with axes `frame` (orthonormal columns): the box, and along each column a cylinder
/// and a capsule about the line through the box centre.
void tryFrame(const std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& frame, Candidate& best) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& p : points) {
    const Eigen::Vector3d local = frame.transpose() * p;
    low = low.cwiseMin(local), high = high.cwiseMax(local);
  }
  const Eigen::Vector3d middle = 0.5 * (low + high), half = (0.5 * (high - low)).array() + kMargin;
  Candidate box{Form::Box, 8.0 * half.prod(), frame, frame * middle, half};
  if (box.volume < best.volume) best = box;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Eigen::Matrix3d axes;
    axes.col(0) = frame.col(i), axes.col(1) = frame.col(j), axes.col(2) = frame.col(k);
    double radius2 = 0.0;
    for (const auto& p : points) {
      const Eigen::Vector3d local = frame.transpose() * p - middle;
      radius2 = std::max(radius2, local(i) * local(i) + local(j) * local(j));
    }
    // The core is fitted to the tight radius, so that the margin is left all round.
    const double tight = std::sqrt(radius2), radius = tight + kMargin;
    Candidate cylinder{
        Form::Cylinder, 2.0 * kPi * radius * radius * half(k), axes, frame * middle, {radius, half(k), 0.0}};
    if (cylinder.volume < best.volume) best = cylinder;
    // The capsule core [from, to] along the axis: every point within `radius` of it.
    double from = std::numeric_limits<double>::infinity(), to = -from;
    for (const auto& p : points) {
      const Eigen::Vector3d local = frame.transpose() * p - middle;
      const double reach = std::sqrt(std::max(0.0, tight * tight - local(i) * local(i) - local(j) * local(j)));
      from = std::min(from, local(k) + reach), to = std::max(to, local(k) - reach);
    }
    if (from > to) from = to = 0.5 * (from + to);
    Candidate capsule{Form::Capsule,
                      kPi * radius * radius * (to - from) + 4.0 / 3.0 * kPi * radius * radius * radius,
                      axes,
                      frame * middle,
                      Eigen::Vector3d::Zero(),
                      from,
                      to,
                      radius};
    if (capsule.volume < best.volume) best = capsule;
  }
}

void plainPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& origin, double* out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 3 + c] = rotation(r, c);
    out[9 + r] = origin(r);
  }
}

}  // namespace

ConvexPart meshEnclosure(const MeshShape& shape, const Eigen::Isometry3d& pose) {
  const TriangleMesh read = shape.triangles ? TriangleMesh{} : readMeshFile(shape.file, shape.scale);
  const auto& points = (shape.triangles ? *shape.triangles : read).vertices;
  Candidate best;
  tryFrame(points, Eigen::Matrix3d::Identity(), best);
  // The principal axes of the vertices, made right-handed.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) covariance += (p - mean) * (p - mean).transpose();
  Eigen::Matrix3d principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors();
  principal.col(2) = principal.col(0).cross(principal.col(1)).normalized();
  if (principal.allFinite()) tryFrame(points, principal, best);

  const Eigen::Matrix3d rotation = pose.linear() * best.axes;
  const Eigen::Vector3d centre = pose * best.centre;
  ConvexPart part;
  double placed[12];
  plainPose(rotation, centre, placed);
  if (best.form == Form::Box) {
    part = boxPart(placed, best.half.data());
  } else if (best.form == Form::Cylinder) {
    part = cylinderPart(placed, best.half(0), best.half(1));
  } else {
    const Eigen::Vector3d a = centre + best.from * rotation.col(2), b = centre + best.to * rotation.col(2);
    part = capsulePart(a.data(), b.data(), best.radius);
  }
  part.enclosure = true;
  return part;
}

}  // namespace pmdplan
