#pragma once
// The vector instruction set the fast checker's kernels run on: detected once for the running
// CPU, and used by both the batched forward kinematics and the batch screen (which may also be
// told to run narrower, to compare the widths).

namespace pmdplan {

enum class SimdLevel { sse2, avx2, avx512 };

/// The widest level this CPU runs (SSE2 is the x86-64 baseline); detected on the first call.
SimdLevel widestSimdLevel();

/// Doubles per lane vector at the level: 2, 4 or 8.
constexpr int laneWidth(SimdLevel level) { return level == SimdLevel::avx512 ? 8 : level == SimdLevel::avx2 ? 4 : 2; }

/// "sse2", "avx2" or "avx512".
const char* simdLevelName(SimdLevel level);

}  // namespace pmdplan
