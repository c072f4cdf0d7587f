#pragma once
// The sequences our samplers draw their numbers from: points of the unit cube [0, 1)^d. The
// paper's toolkit offers three (Sect. 6): uniform random, Halton (Halton 1960) and SDK (Rosell
// et al. 2007). Every sampler maps a point onto its own box, so the sequence is a setting of the
// run (`--sequence`), not of any one sampler.
#include <optional>
#include <string>

namespace pmdplan {

enum class SampleSequence {
  Random,  ///< "random": std::mt19937_64 numbers, coordinate after coordinate (the default)
  Halton,  ///< "halton": Halton points, each coordinate shifted by a seeded offset (halton_sequence.hpp)
  Sdk,     ///< "sdk": SDK cells with a seeded start and a random point in each cell (sdk_sequence.hpp)
};

/// "random", "halton", "sdk".
std::string sampleSequenceName(SampleSequence sequence);
std::optional<SampleSequence> parseSampleSequence(const std::string& name);
/// "random, halton, sdk" for messages.
std::string knownSampleSequenceNames();

/// One stream of points of [0, 1)^d.
class UnitSequence {
 public:
  virtual ~UnitSequence() = default;
  /// Writes the next point's `dimension` coordinates, each in [0, 1). `dimension` is at least 1 and
  /// at most the dimension the sequence was made for.
  virtual void next(int dimension, double* point) = 0;
};

}  // namespace pmdplan
