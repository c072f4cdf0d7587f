#include "urdf_capsules.hpp"

#include <algorithm>
#include <cmath>

namespace pmdplan {
namespace {

/// Same within rounding: URDF writers print the same number for a capsule's cylinder and caps.
bool sameLength(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::max(a, b)); }

/// The unused sphere of `shapes` centred on `centre` with radius `radius`, or -1.
int endSphere(const std::vector<PlacedShape>& shapes, const std::vector<char>& used, const Eigen::Vector3d& centre,
              double radius) {
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const auto* sphere = std::get_if<SphereShape>(&shapes[i].shape);
    if (sphere && !used[i] && sameLength(sphere->radius, radius) &&
        (shapes[i].pose.translation() - centre).norm() <= 1e-9)
      return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

std::vector<UrdfCapsule> urdfCapsules(const std::vector<PlacedShape>& shapes) {
  std::vector<char> used(shapes.size(), 0);
  std::vector<UrdfCapsule> result;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const auto* cylinder = std::get_if<CylinderShape>(&shapes[i].shape);
    if (!cylinder) continue;
    used[i] = 1;
    UrdfCapsule capsule;
    capsule.cylinder = static_cast<int>(i);
    capsule.radius = cylinder->radius;
    const Eigen::Vector3d a = shapes[i].pose * Eigen::Vector3d(0, 0, -0.5 * cylinder->length);
    const Eigen::Vector3d b = shapes[i].pose * Eigen::Vector3d(0, 0, 0.5 * cylinder->length);
    const int capA = endSphere(shapes, used, a, cylinder->radius);
    const int capB = capA >= 0 && a != b ? endSphere(shapes, used, b, cylinder->radius) : -1;
    if (capA >= 0 && capB >= 0) {
      used[static_cast<std::size_t>(capA)] = used[static_cast<std::size_t>(capB)] = 1;
      capsule.capA = capA, capsule.capB = capB;
      capsule.radius =
          std::max({cylinder->radius, std::get<SphereShape>(shapes[static_cast<std::size_t>(capA)].shape).radius,
                    std::get<SphereShape>(shapes[static_cast<std::size_t>(capB)].shape).radius});
    }
    result.push_back(capsule);
  }
  return result;
}

}  // namespace pmdplan
