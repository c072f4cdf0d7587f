#pragma once
// What the fast checker's narrow phase (narrow_phase.hpp) says about one pair at one configuration,
// and a pair it could not prove apart, as the screens list them for the exact checker.

namespace pmdplan::fast {

/// EnclosuresOverlap: like Uncertain (the exact checker decides), with a mesh's enclosure
/// overlapping the other side by more than the band, so the exact checker is asked about it first.
enum class Outcome { Apart, Overlapping, Uncertain, EnclosuresOverlap };

/// A pair not proven apart: self (two links a and b) or a link a and obstacle b.
struct Flag {
  bool self;
  int a;
  int b;
  Outcome outcome;
};

}  // namespace pmdplan::fast
