#include "pmdplan/core/sequences/sample_sequence.hpp"

namespace pmdplan {

std::string sampleSequenceName(SampleSequence sequence) {
  switch (sequence) {
    case SampleSequence::Random:
      return "random";
    case SampleSequence::Halton:
      return "halton";
    case SampleSequence::Sdk:
      return "sdk";
  }
  return "random";
}

std::optional<SampleSequence> parseSampleSequence(const std::string& name) {
  for (const SampleSequence s : {SampleSequence::Random, SampleSequence::Halton, SampleSequence::Sdk})
    if (name == sampleSequenceName(s)) return s;
  return std::nullopt;
}

std::string knownSampleSequenceNames() { return "random, halton, sdk"; }

}  // namespace pmdplan
