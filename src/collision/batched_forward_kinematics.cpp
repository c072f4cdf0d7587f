#include "pmdplan/collision/batched_forward_kinematics.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace pmdplan {
namespace {

using Plan = BatchedForwardKinematics::Plan;
constexpr int kValues = BatchedForwardKinematics::kPoseValues;

void toPlain(const Eigen::Isometry3d& pose, double* out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 3 + c] = pose.linear()(r, c);
    out[9 + r] = pose.translation()(r);
  }
}

// sin and cos without library calls, so a loop over lanes vectorises: x = k pi/2 + r with |r| <=
// pi/4 (Cody-Waite, three parts of pi/2: exact for |x| < 1e5), Taylor series to r^17 / r^18 (the
// next terms are below 1e-19), quadrant from the low bits of k.
[[gnu::always_inline]] inline void sinCos(double x, double& s, double& c) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  constexpr double kShifter = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  constexpr double kPio2a = 1.57079632673412561417e+00, kPio2b = 6.07710050630396597660e-11,
                   kPio2c = 2.02226624879595063154e-21;
  const double shifted = x * kTwoOverPi + kShifter;
  const double k = shifted - kShifter;
  // The low mantissa bits of `shifted` hold k (mod 2^51, two's complement): its quadrant.
  const std::uint64_t quadrant = std::bit_cast<std::uint64_t>(shifted);
  const double r = ((x - k * kPio2a) - k * kPio2b) - k * kPio2c;
  const double r2 = r * r;
  const double sr =
      r + r * r2 *
              (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800 +
              r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0 + r2 * (1.0 / 355687428096000.0))))))));
  const double cr =
      1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
              r2 * (1.0 / 479001600.0 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0 +
              r2 * (-1.0 / 6402373705728000.0)))))))));
  const std::uint64_t swap = 0 - (quadrant & 1);  // all ones in odd quadrants: sin <-> cos
  const std::uint64_t sb = std::bit_cast<std::uint64_t>(sr), cb = std::bit_cast<std::uint64_t>(cr);
  const std::uint64_t sinBits = (sb & ~swap) | (cb & swap);
  const std::uint64_t cosBits = (cb & ~swap) | (sb & swap);
  s = std::bit_cast<double>(sinBits ^ ((quadrant & 2) << 62));        // negative in quadrants 2, 3
  c = std::bit_cast<double>(cosBits ^ (((quadrant + 1) & 2) << 62));  // negative in quadrants 1, 2
}

/// sin and cos of N lanes (a separate loop, so it vectorises on its own).
template <int N>
[[gnu::always_inline]] inline void sinCosLanes(const double* x, double* s, double* c) {
  for (int l = 0; l < N; ++l) sinCos(x[l], s[l], c[l]);
}

/// A pose of N lanes: element i of lane l at v[i][l]. Local copies of these (not pointers into
/// the pose array) let the compiler keep lanes in registers without aliasing doubts.
template <int N>
struct LanePose {
  double v[kValues][N];
};

// The whole walk for N lanes; `values` is scratch for jointCount x N joint values.
template <int N>
[[gnu::always_inline]] inline void walk(const Plan& plan, const double* q, double* poseArray, double* values) {
  auto* poses = reinterpret_cast<LanePose<N>*>(poseArray);
  for (int j = 0; j < plan.jointCount; ++j) {
    const auto& v = plan.values[static_cast<std::size_t>(j)];
    for (int l = 0; l < N; ++l) values[j * N + l] = v.activeIndex >= 0 ? q[v.activeIndex * N + l] : 0.0;
  }
  for (int j = 0; j < plan.jointCount; ++j) {
    const auto& v = plan.values[static_cast<std::size_t>(j)];
    if (v.mimicSource < 0) continue;
    for (int l = 0; l < N; ++l) values[j * N + l] = v.multiplier * values[v.mimicSource * N + l] + v.offset;
  }
  LanePose<N>& root = poses[plan.rootLink];
  for (int i = 0; i < kValues; ++i)
    for (int l = 0; l < N; ++l) root.v[i][l] = plan.base[i];

  for (const auto& step : plan.steps) {
    const LanePose<N> p = poses[step.parentLink];
    const double* o = step.origin;
    LanePose<N> c;
    // child = parent * origin
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < N; ++l) c.v[r * 3 + k][l] = p.v[r * 3][l] * o[k] + p.v[r * 3 + 1][l] * o[3 + k] + p.v[r * 3 + 2][l] * o[6 + k];
      for (int l = 0; l < N; ++l) c.v[9 + r][l] = p.v[r * 3][l] * o[9] + p.v[r * 3 + 1][l] * o[10] + p.v[r * 3 + 2][l] * o[11] + p.v[9 + r][l];
    }
    double value[N];
    for (int l = 0; l < N; ++l) value[l] = values[step.joint * N + l];
    if (step.motion == 1) {
      // child.linear() *= rotation(axis, value), as Eigen's AngleAxis builds it.
      double s[N], co[N];
      sinCosLanes<N>(value, s, co);
      if (step.axisZ != 0) {
        for (int l = 0; l < N; ++l) s[l] *= step.axisZ;
        for (int r = 0; r < 3; ++r)
          for (int l = 0; l < N; ++l) {
            const double a = c.v[r * 3][l], b = c.v[r * 3 + 1][l];
            c.v[r * 3][l] = a * co[l] + b * s[l];
            c.v[r * 3 + 1][l] = b * co[l] - a * s[l];
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
            for (int l = 0; l < N; ++l) c.v[r * 3 + k][l] = row[0][l] * m[k][l] + row[1][l] * m[3 + k][l] + row[2][l] * m[6 + k][l];
        }
      }
    } else if (step.motion == 2) {
      for (int r = 0; r < 3; ++r)
        for (int l = 0; l < N; ++l)
          c.v[9 + r][l] += value[l] * (c.v[r * 3][l] * step.axis[0] + c.v[r * 3 + 1][l] * step.axis[1] + c.v[r * 3 + 2][l] * step.axis[2]);
    }
    poses[step.childLink] = c;
  }
}

void batchBaseline(const Plan& plan, const double* q, double* poses, double* values) {
  walk<BatchedForwardKinematics::kLanes>(plan, q, poses, values);
}
[[gnu::target("avx2")]] void batchAvx2(const Plan& plan, const double* q, double* poses, double* values) {
  walk<BatchedForwardKinematics::kLanes>(plan, q, poses, values);
}

bool detectAvx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}

}  // namespace

bool BatchedForwardKinematics::usesAvx2() {
  static const bool avx2 = detectAvx2();
  return avx2;
}

BatchedForwardKinematics::BatchedForwardKinematics(const RobotModel& model, const Eigen::Isometry3d& base)
    : dof_(model.dof()), linkCount_(static_cast<int>(model.links().size())) {
  plan_.linkCount = linkCount_;
  plan_.jointCount = static_cast<int>(model.joints().size());
  plan_.rootLink = model.rootLink();
  toPlain(base, plan_.base);
  for (const auto& joint : model.joints())
    plan_.values.push_back({joint.activeIndex, joint.mimicSource, joint.mimicMultiplier, joint.mimicOffset});
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    Step step;
    step.parentLink = joint.parentLink;
    step.childLink = joint.childLink;
    step.joint = j;
    step.motion = joint.type == JointType::Fixed ? 0 : joint.type == JointType::Prismatic ? 2 : 1;
    toPlain(joint.origin, step.origin);
    for (int a = 0; a < 3; ++a) step.axis[a] = joint.axis[a];
    if (joint.axis.x() == 0.0 && joint.axis.y() == 0.0 && std::abs(joint.axis.z()) == 1.0) step.axisZ = joint.axis.z() > 0 ? 1 : -1;
    plan_.steps.push_back(step);
  }
}

void BatchedForwardKinematics::computeBatch(const double* jointsByLane, double* poses) const {
  thread_local std::vector<double> values;
  values.resize(static_cast<std::size_t>(plan_.jointCount) * kLanes);
  if (usesAvx2())
    batchAvx2(plan_, jointsByLane, poses, values.data());
  else
    batchBaseline(plan_, jointsByLane, poses, values.data());
}

void BatchedForwardKinematics::computeOne(const double* q, double* poses) const {
  thread_local std::vector<double> values;
  values.resize(static_cast<std::size_t>(plan_.jointCount));
  walk<1>(plan_, q, poses, values.data());
}

}  // namespace pmdplan
