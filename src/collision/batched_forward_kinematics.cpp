#include "pmdplan/collision/batched_forward_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "pmdplan/collision/simd_level.hpp"
#include "pmdplan/core/portable_math.hpp"

namespace pmdplan {
namespace {

using Plan = BatchedForwardKinematics::Plan;
constexpr int kValues = BatchedForwardKinematics::kPoseValues;
constexpr int kMaxPacked = 32;  ///< joints whose sines are computed together

void toPlain(const Eigen::Isometry3d& pose, double* out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 3 + c] = pose.linear()(r, c);
    out[9 + r] = pose.translation()(r);
  }
}

/// sin and cos of `count` values, in one loop of independent polynomials (it vectorises; built
/// for AVX-512, AVX2 and the SSE2 baseline, the loader picks one for the running CPU).
[[gnu::target_clones("avx512f", "avx2", "default")]] void sinCosArray(const double* x, double* s, double* c,
                                                                      int count) {
  for (int i = 0; i < count; ++i) portable::sinCos(x[i], s[i], c[i]);
}

/// A pose of N lanes: element i of lane l at v[i][l].
template <int N>
struct LanePose {
  double v[kValues][N];
};

// The whole walk for N lanes; `scratch` holds 3 x jointCount x N values (joint values, sines,
// cosines). The sines and cosines of all joints come first, in one loop of independent
// polynomials (they pipeline; inside the walk each would wait for the last).
template <int N>
[[gnu::always_inline]] inline void walk(const Plan& plan, const double* q, double* poseArray, double* scratch,
                                        const std::uint64_t* links = nullptr, int frame = -1) {
  const auto needed = [links](int link) { return !links || ((links[link >> 6] >> (link & 63)) & 1U); };
  auto* poses = reinterpret_cast<LanePose<N>*>(poseArray);
  const int joints = plan.jointCount;
  double* __restrict values = scratch;
  double* __restrict sines = scratch + joints * N;
  double* __restrict cosines = scratch + 2 * joints * N;
  for (int j = 0; j < joints; ++j) {
    const auto& v = plan.values[static_cast<std::size_t>(j)];
    for (int l = 0; l < N; ++l) values[j * N + l] = v.activeIndex >= 0 ? q[v.activeIndex * N + l] : 0.0;
  }
  for (int j = 0; j < joints; ++j) {
    const auto& v = plan.values[static_cast<std::size_t>(j)];
    if (v.mimicSource < 0) continue;
    for (int l = 0; l < N; ++l) values[j * N + l] = v.multiplier * values[v.mimicSource * N + l] + v.offset;
  }
  if (links) {
    // The needed joints' values side by side, so their polynomials vectorise too.
    double x[kMaxPacked * N], sx[kMaxPacked * N], cx[kMaxPacked * N];
    int packed = 0, at[kMaxPacked];
    const auto flush = [&] {
      sinCosArray(x, sx, cx, packed * N);
      for (int k = 0; k < packed; ++k)
        for (int l = 0; l < N; ++l) sines[at[k] * N + l] = sx[k * N + l], cosines[at[k] * N + l] = cx[k * N + l];
      packed = 0;
    };
    for (const auto& step : plan.steps) {
      if (step.motion != 1 || !needed(step.childLink)) continue;
      for (int l = 0; l < N; ++l) x[packed * N + l] = values[step.joint * N + l];
      at[packed++] = step.joint;
      if (packed == kMaxPacked) flush();
    }
    flush();
  } else {
    sinCosArray(values, sines, cosines, joints * N);
  }
  LanePose<N>& root = poses[frame >= 0 ? frame : plan.rootLink];
  constexpr double kIdentity[kValues] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  for (int i = 0; i < kValues; ++i)
    for (int l = 0; l < N; ++l) root.v[i][l] = frame >= 0 ? kIdentity[i] : plan.base[i];

  for (const auto& step : plan.steps) {
    if (!needed(step.childLink)) continue;
    const LanePose<N>& p = poses[step.parentLink];
    const double* o = step.origin;
    LanePose<N> c;  // in registers; stored once at the end
    // child = parent * origin
    if (step.permutes) {
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < N; ++l) c.v[r * 3 + k][l] = step.sign[k] * p.v[r * 3 + step.column[k]][l];
    } else {
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < N; ++l)
            c.v[r * 3 + k][l] = p.v[r * 3][l] * o[k] + p.v[r * 3 + 1][l] * o[3 + k] + p.v[r * 3 + 2][l] * o[6 + k];
    }
    if (step.translates) {
      for (int r = 0; r < 3; ++r)
        for (int l = 0; l < N; ++l)
          c.v[9 + r][l] = p.v[r * 3][l] * o[9] + p.v[r * 3 + 1][l] * o[10] + p.v[r * 3 + 2][l] * o[11] + p.v[9 + r][l];
    } else {
      for (int r = 0; r < 3; ++r)
        for (int l = 0; l < N; ++l) c.v[9 + r][l] = p.v[9 + r][l];
    }
    if (step.motion == 1) {
      // child.linear() *= rotation(axis, value), as Eigen's AngleAxis builds it.
      const double* s = sines + step.joint * N;
      const double* co = cosines + step.joint * N;
      if (step.axisZ != 0) {
        const double sign = step.axisZ;
        for (int r = 0; r < 3; ++r)
          for (int l = 0; l < N; ++l) {
            const double a = c.v[r * 3][l], b = c.v[r * 3 + 1][l];
            c.v[r * 3][l] = a * co[l] + b * (sign * s[l]);
            c.v[r * 3 + 1][l] = b * co[l] - a * (sign * s[l]);
          }
      } else {
        const double ax = step.axis[0], ay = step.axis[1], az = step.axis[2];
        double m[9][N];
        for (int l = 0; l < N; ++l) {
          const double t = 1.0 - co[l];
          m[0][l] = t * ax * ax + co[l], m[1][l] = t * ax * ay - s[l] * az, m[2][l] = t * ax * az + s[l] * ay;
          m[3][l] = t * ax * ay + s[l] * az, m[4][l] = t * ay * ay + co[l], m[5][l] = t * ay * az - s[l] * ax;
          m[6][l] = t * ax * az - s[l] * ay, m[7][l] = t * ay * az + s[l] * ax, m[8][l] = t * az * az + co[l];
        }
        for (int r = 0; r < 3; ++r) {
          double row[3][N];
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < N; ++l) row[k][l] = c.v[r * 3 + k][l];
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < N; ++l)
              c.v[r * 3 + k][l] = row[0][l] * m[k][l] + row[1][l] * m[3 + k][l] + row[2][l] * m[6 + k][l];
        }
      }
    } else if (step.motion == 2) {
      const double* value = values + step.joint * N;
      for (int r = 0; r < 3; ++r)
        for (int l = 0; l < N; ++l)
          c.v[9 + r][l] += value[l] * (c.v[r * 3][l] * step.axis[0] + c.v[r * 3 + 1][l] * step.axis[1] +
                                       c.v[r * 3 + 2][l] * step.axis[2]);
    }
    poses[step.childLink] = c;
  }
}

void batchBaseline(const Plan& plan, const double* q, double* poses, double* scratch) {
  walk<BatchedForwardKinematics::kLanes>(plan, q, poses, scratch);
}
[[gnu::target("avx2")]] void batchAvx2(const Plan& plan, const double* q, double* poses, double* scratch) {
  walk<BatchedForwardKinematics::kLanes>(plan, q, poses, scratch);
}
[[gnu::target("avx512f")]] void batchAvx512(const Plan& plan, const double* q, double* poses, double* scratch) {
  walk<BatchedForwardKinematics::kLanes>(plan, q, poses, scratch);
}

/// The kernel of the CPU's SIMD level.
using BatchKernel = void (*)(const Plan&, const double*, double*, double*);
BatchKernel batchKernel() {
  static const BatchKernel kernel = [] {
    switch (widestSimdLevel()) {
      case SimdLevel::avx512:
        return batchAvx512;
      case SimdLevel::avx2:
        return batchAvx2;
      case SimdLevel::sse2:
        break;
    }
    return batchBaseline;
  }();
  return kernel;
}

}  // namespace

BatchedForwardKinematics::BatchedForwardKinematics(const RobotModel& model, const Eigen::Isometry3d& base)
    : dof_(model.dof()), linkCount_(static_cast<int>(model.links().size())) {
  plan_.linkCount = linkCount_;
  plan_.jointCount = static_cast<int>(model.joints().size());
  plan_.rootLink = model.rootLink();
  toPlain(base, plan_.base);
  for (const auto& joint : model.joints())
    plan_.values.push_back({joint.activeIndex, joint.mimicSource, joint.mimicMultiplier, joint.mimicOffset});
  parentLink_.assign(static_cast<std::size_t>(linkCount_), -1);
  for (const auto& joint : model.joints()) parentLink_[static_cast<std::size_t>(joint.childLink)] = joint.parentLink;
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    Step step;
    step.parentLink = joint.parentLink;
    step.childLink = joint.childLink;
    step.joint = j;
    step.motion = joint.type == JointType::Fixed ? 0 : joint.type == JointType::Prismatic ? 2 : 1;
    toPlain(joint.origin, step.origin);
    for (int a = 0; a < 3; ++a) step.axis[a] = joint.axis[a];
    if (joint.axis.x() == 0.0 && joint.axis.y() == 0.0 && std::abs(joint.axis.z()) == 1.0)
      step.axisZ = joint.axis.z() > 0 ? 1 : -1;
    // A rotation whose entries are 0 or +-1 up to rounding (cos 90 deg is 6e-17 in doubles).
    step.permutes = true;
    for (int k = 0; k < 3; ++k) {
      int ones = 0;
      for (int r = 0; r < 3; ++r) {
        const double e = step.origin[r * 3 + k];
        if (std::abs(std::abs(e) - 1.0) <= 1e-15) {
          ++ones;
          step.column[k] = r;
          step.sign[k] = e > 0.0 ? 1.0 : -1.0;
        } else if (std::abs(e) > 1e-15) {
          step.permutes = false;
        }
      }
      step.permutes = step.permutes && ones == 1;
    }
    step.translates = step.origin[9] != 0.0 || step.origin[10] != 0.0 || step.origin[11] != 0.0;
    plan_.steps.push_back(step);
  }
}

void BatchedForwardKinematics::computeBatch(const double* jointsByLane, double* poses) const {
  thread_local std::vector<double> scratch;
  scratch.resize(3 * static_cast<std::size_t>(plan_.jointCount) * kLanes);
  batchKernel()(plan_, jointsByLane, poses, scratch.data());
}

void BatchedForwardKinematics::addWithAncestors(LinkSet& set, int link) const {
  for (int l = link; l >= 0; l = parentLink_[static_cast<std::size_t>(l)])
    set[static_cast<std::size_t>(l) >> 6] |= std::uint64_t{1} << (l & 63);
}

void BatchedForwardKinematics::computeSome(const double* q, double* poses, const LinkSet& links, int frame) const {
  thread_local std::vector<double> scratch;
  scratch.resize(3 * static_cast<std::size_t>(plan_.jointCount));
  walk<1>(plan_, q, poses, scratch.data(), links.data(), frame);
}

int BatchedForwardKinematics::commonAncestor(int a, int b) const {
  std::vector<int> chain;
  for (int l = a; l >= 0; l = parentLink_[static_cast<std::size_t>(l)]) chain.push_back(l);
  for (int l = b; l >= 0; l = parentLink_[static_cast<std::size_t>(l)])
    if (std::find(chain.begin(), chain.end(), l) != chain.end()) return l;
  return -1;
}

void BatchedForwardKinematics::computeOne(const double* q, double* poses) const {
  thread_local std::vector<double> scratch;
  scratch.resize(3 * static_cast<std::size_t>(plan_.jointCount));
  walk<1>(plan_, q, poses, scratch.data());
}

}  // namespace pmdplan
