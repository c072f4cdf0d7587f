#pragma once
// The tests' reference for contact: the signed distance between two convex solids (boxes,
// cylinders, spheres, capsules, convex meshes) — their distance when apart, minus their
// penetration depth (the shortest translation that separates them) when they overlap — computed
// without FCL and without the checkers' own kernels.
//
// Closed forms where they exist: a sphere against anything is the point signed distance of its
// centre minus its radius (box, cylinder, sphere, capsule), two capsules their segments' distance
// minus both radii. Every other pair (box-box, box-cylinder, capsule-box, capsule-cylinder,
// cylinder-cylinder, meshes) uses the support-function identity
//     sd(A, B) = max over unit u of  g(u) = min_{b in B} u.b - max_{a in A} u.a,
// the widest gap between the two shapes' shadows on a line. Every u gives g(u) <= sd, so the value
// returned never overstates a clearance nor understates a depth. When the shapes are apart g has
// one local maximum on the sphere (g is concave and positive there), which the search climbs to;
// when they overlap the maximum lies at a facet normal of the Minkowski difference, and the search
// starts from those candidates (face normals, cross products of edge directions, great circles
// perpendicular to each edge direction) as well as from a dense lattice, then refines the best
// starts by a pattern search down to 1e-13 rad. tests/collision/contact_reference_test.cpp measures
// it against the closed forms: agreement within 1e-9 m (1e-6 mm), far below the 0.01 mm the
// checkers are held to. Meshes are taken as the hull of their vertices: the reference is for the
// convex meshes the tests build (tessellated primitives).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "pmdplan/model/collision_shape.hpp"
#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan::reference {

struct Solid {
  enum class Kind { Sphere, Capsule, Box, Cylinder, Mesh };
  Kind kind = Kind::Sphere;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();        ///< world
  Eigen::Vector3d half = Eigen::Vector3d::Zero();                ///< box half extents
  double radius = 0.0;                                           ///< sphere, capsule, cylinder
  double halfLength = 0.0;                                       ///< capsule core, cylinder (local z)
  std::shared_ptr<const std::vector<Eigen::Vector3d>> vertices;  ///< mesh, local
};

/// A shape placed at `pose` in the world.
inline Solid solid(const Shape& shape, const Eigen::Isometry3d& pose) {
  Solid s;
  s.pose = pose;
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    s.kind = Solid::Kind::Box;
    s.half = 0.5 * box->size;
  } else if (const auto* cylinder = std::get_if<CylinderShape>(&shape)) {
    s.kind = Solid::Kind::Cylinder;
    s.radius = cylinder->radius;
    s.halfLength = 0.5 * cylinder->length;
  } else if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    s.radius = sphere->radius;
  } else {
    const auto& mesh = std::get<MeshShape>(shape);
    const TriangleMesh read = mesh.triangles ? TriangleMesh{} : readMeshFile(mesh.file, mesh.scale);
    s.kind = Solid::Kind::Mesh;
    s.vertices =
        std::make_shared<const std::vector<Eigen::Vector3d>>(mesh.triangles ? mesh.triangles->vertices : read.vertices);
  }
  return s;
}

inline Solid capsule(const Eigen::Isometry3d& pose, double radius, double halfLength) {
  Solid s;
  s.kind = Solid::Kind::Capsule, s.pose = pose, s.radius = radius, s.halfLength = halfLength;
  return s;
}

/// max over the solid of u.x (u need not be unit length).
inline double support(const Solid& s, const Eigen::Vector3d& u) {
  const Eigen::Vector3d v = s.pose.linear().transpose() * u;
  double local = 0.0;
  switch (s.kind) {
    case Solid::Kind::Sphere:
      local = s.radius * u.norm();
      break;
    case Solid::Kind::Capsule:
      local = s.halfLength * std::abs(v.z()) + s.radius * u.norm();
      break;
    case Solid::Kind::Box:
      local = v.cwiseAbs().dot(s.half);
      break;
    case Solid::Kind::Cylinder:
      local = s.radius * std::hypot(v.x(), v.y()) + s.halfLength * std::abs(v.z());
      break;
    case Solid::Kind::Mesh:
      local = -1e300;
      for (const auto& p : *s.vertices) local = std::max(local, p.dot(v));
      break;
  }
  return u.dot(s.pose.translation()) + local;
}

/// The gap between the shadows of a and b on the line along unit u (a below, b above).
inline double shadowGap(const Solid& a, const Solid& b, const Eigen::Vector3d& u) {
  return -support(b, -u) - support(a, u);
}

/// Signed distance from a point (world) to a box, cylinder, sphere or capsule: closed form.
inline double pointSignedDistance(const Solid& s, const Eigen::Vector3d& world) {
  const Eigen::Vector3d p = s.pose.inverse() * world;
  switch (s.kind) {
    case Solid::Kind::Sphere:
      return p.norm() - s.radius;
    case Solid::Kind::Capsule:
      return Eigen::Vector3d(p.x(), p.y(), p.z() - std::clamp(p.z(), -s.halfLength, s.halfLength)).norm() - s.radius;
    case Solid::Kind::Box: {
      const Eigen::Vector3d q = p.cwiseAbs() - s.half;
      return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    }
    case Solid::Kind::Cylinder: {
      const double radial = std::hypot(p.x(), p.y()) - s.radius, axial = std::abs(p.z()) - s.halfLength;
      return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) + std::min(std::max(radial, axial), 0.0);
    }
    case Solid::Kind::Mesh:
      break;
  }
  return std::nan("");
}

/// Distance between the segments p0-p1 and q0-q1 (closed form, clamped parameters).
inline double segmentSegmentDistance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                     const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 1e-300 && e <= 1e-300) return r.norm();
  if (a <= 1e-300) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-300) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denominator = a * e - b * b;
      s = denominator > 1e-300 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
      if (t > 1.0) t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return ((p0 + s * d1) - (q0 + t * d2)).norm();
}

/// The directions a solid contributes to the candidate set: its edge directions (which form
/// cross products and great circles) and its face normals.
inline void solidDirections(const Solid& s, std::vector<Eigen::Vector3d>& edges, std::vector<Eigen::Vector3d>& faces) {
  const Eigen::Matrix3d& r = s.pose.linear();
  switch (s.kind) {
    case Solid::Kind::Sphere:
      break;
    case Solid::Kind::Capsule:
      edges.push_back(r.col(2));
      break;
    case Solid::Kind::Cylinder:
      edges.push_back(r.col(2));
      faces.push_back(r.col(2));
      break;
    case Solid::Kind::Box:
      for (int i = 0; i < 3; ++i) edges.push_back(r.col(i)), faces.push_back(r.col(i));
      break;
    case Solid::Kind::Mesh:
      // The tests' meshes are tessellated primitives: their vertices' principal axes stand in for
      // the edge directions; every lattice direction and refinement covers the rest.
      for (int i = 0; i < 3; ++i) edges.push_back(r.col(i)), faces.push_back(r.col(i));
      break;
  }
}

/// The pattern search's moves: twelve directions 30 degrees apart, turned by the golden angle
/// from one round to the next (kTurns rounds, then again), as (cos, sin) pairs.
constexpr int kTurns = 64;
inline const std::vector<std::pair<double, double>>& patternMoves() {
  static const std::vector<std::pair<double, double>> moves = [] {
    std::vector<std::pair<double, double>> out;
    for (int turn = 0; turn < kTurns; ++turn)
      for (int k = 0; k < 12; ++k) {
        const double angle = turn * 2.399963229728653 + k * 0.5235987755982988;
        out.emplace_back(std::cos(angle), std::sin(angle));
      }
    return out;
  }();
  return moves;
}

/// Refines a start direction by a pattern search on the sphere (twelve directions, turned by the
/// golden angle at every try so that no ridge of g stays between them). g has ridges where the
/// shadow of an edge direction shrinks to a point (u perpendicular to it): on such a great circle
/// every trial is also tried projected onto it, so the search follows the ridge.
inline double climb(const Solid& a, const Solid& b, const std::vector<Eigen::Vector3d>& edges, Eigen::Vector3d& u,
                    double stopAbove = 1e300) {
  double best = shadowGap(a, b, u);
  int rounds = 0;
  const auto tryDirection = [&](const Eigen::Vector3d& trial) {
    const double gap = shadowGap(a, b, trial);
    if (gap <= best + 1e-16) return false;
    best = gap, u = trial;
    return true;
  };
  const auto& moves = patternMoves();
  for (double step = 0.05; step > 1e-13 && ++rounds < 5000 && best <= stopAbove;) {
    const Eigen::Vector3d t1 = u.unitOrthogonal(), t2 = u.cross(t1), from = u;
    bool improved = false;
    for (int k = 0; k < 12; ++k) {
      const auto [c, s] = moves[static_cast<std::size_t>((rounds % kTurns) * 12 + k)];
      const Eigen::Vector3d moved = from + step * (c * t1 + s * t2);
      improved |= tryDirection(moved.normalized());
      for (const auto& e : edges)
        if (std::abs(from.dot(e)) < 1e-12) improved |= tryDirection((moved - moved.dot(e) * e).normalized());
    }
    if (!improved) step *= 0.7;
  }
  return best;
}

/// The Fibonacci lattice of 1,200 directions, and half the unit circle in degrees, made once.
inline const std::vector<Eigen::Vector3d>& fibonacciLattice() {
  static const std::vector<Eigen::Vector3d> lattice = [] {
    constexpr int count = 1200;
    std::vector<Eigen::Vector3d> out;
    for (int k = 0; k < count; ++k) {
      const double z = 1.0 - (2.0 * k + 1.0) / count, r = std::sqrt(1.0 - z * z), phi = k * 2.399963229728653;
      out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    return out;
  }();
  return lattice;
}
inline const std::vector<std::pair<double, double>>& halfCircle() {
  static const std::vector<std::pair<double, double>> circle = [] {
    std::vector<std::pair<double, double>> out;
    for (int k = 0; k < 180; ++k) out.emplace_back(std::cos(k * M_PI / 180), std::sin(k * M_PI / 180));
    return out;
  }();
  return circle;
}

struct SignedDistance {
  double metres = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< the u found (support method)
};

/// The support-function maximisation for any two solids (see the file comment). With `stopAbove`
/// it stops as soon as it has proven sd > stopAbove (the value returned is then only a bound).
inline SignedDistance supportSignedDistance(const Solid& a, const Solid& b, double stopAbove = 1e300) {
  std::vector<Eigen::Vector3d> edges, faces;
  solidDirections(a, edges, faces);
  solidDirections(b, edges, faces);
  // The eight best starts so far (gap, direction), and an early answer once one exceeds stopAbove.
  constexpr std::size_t kKeep = 8;
  std::vector<std::pair<double, Eigen::Vector3d>> best;
  SignedDistance early{-1e300};
  const auto visit = [&](const Eigen::Vector3d& direction) {
    for (const Eigen::Vector3d& u : {direction, Eigen::Vector3d(-direction)}) {
      const double gap = shadowGap(a, b, u);
      if (gap > stopAbove) {
        early = {gap, u};
        return true;
      }
      if (best.size() < kKeep || gap > best.back().first) {
        if (best.size() == kKeep) best.pop_back();
        best.insert(std::upper_bound(best.begin(), best.end(), gap,
                                     [](double g, const auto& entry) { return g > entry.first; }),
                    {gap, u});
      }
    }
    return false;
  };
  const Eigen::Vector3d centres = b.pose.translation() - a.pose.translation();
  if (centres.norm() > 0.0 && visit(centres.normalized())) return early;
  for (const auto& f : faces)
    if (visit(f)) return early;
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (edges[i].cross(edges[j]).norm() > 1e-9 && visit(edges[i].cross(edges[j]).normalized())) return early;
  for (const auto& e : edges) {  // great circles perpendicular to each edge direction
    const Eigen::Vector3d t1 = e.unitOrthogonal(), t2 = e.cross(t1);
    for (const auto& [c, s] : halfCircle())
      if (visit(c * t1 + s * t2)) return early;
  }
  for (const auto& u : fibonacciLattice())
    if (visit(u)) return early;
  SignedDistance result{-1e300};
  for (auto [gap, u] : best) {
    gap = climb(a, b, edges, u, stopAbove);
    if (gap > result.metres) result = {gap, u};
    if (result.metres > stopAbove) break;
  }
  return result;
}

/// The reference signed distance of two solids (metres; negative: penetration depth). With
/// `stopAbove`, a value above it may be only a lower bound (the search stops once it is proven).
inline double signedDistance(const Solid& a, const Solid& b, double stopAbove = 1e300) {
  using Kind = Solid::Kind;
  if (a.kind == Kind::Sphere && b.kind != Kind::Mesh) return pointSignedDistance(b, a.pose.translation()) - a.radius;
  if (b.kind == Kind::Sphere && a.kind != Kind::Mesh) return pointSignedDistance(a, b.pose.translation()) - b.radius;
  if (a.kind == Kind::Capsule && b.kind == Kind::Capsule) {
    const auto end = [](const Solid& s, double sign) {
      return Eigen::Vector3d(s.pose * Eigen::Vector3d(0, 0, sign * s.halfLength));
    };
    return segmentSegmentDistance(end(a, -1), end(a, 1), end(b, -1), end(b, 1)) - a.radius - b.radius;
  }
  return supportSignedDistance(a, b, stopAbove).metres;
}

/// A certain proof of separation, cheap: the gap along the line between the centres (or a
/// bounding-sphere test) is positive. Used to skip pairs that cannot be in contact.
inline bool certainlyApart(const Solid& a, const Solid& b, double margin) {
  const Eigen::Vector3d centres = b.pose.translation() - a.pose.translation();
  if (centres.norm() == 0.0) return false;
  return shadowGap(a, b, centres.normalized()) > margin;
}

}  // namespace pmdplan::reference
