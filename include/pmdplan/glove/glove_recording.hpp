#pragma once
// A glove recording: raw sensor frames as the glove delivered them, before any calibration.
#include <string>
#include <vector>

#include "pmdplan/glove/cyberglove_sensors.hpp"

namespace pmdplan {

struct GloveRecording {
  /// One frame per sample, sensors in cyberGloveSensorNames() order.
  std::vector<GloveFrame> frames;
  /// Sample times in seconds, one per frame; empty when the source has no time column.
  std::vector<double> timeS;
  /// The source line of each frame (a CSV's line numbers, for messages); empty for other sources.
  std::vector<int> frameLines;
  /// Comment lines of the source ('#' lines of a CSV, without the '#'), e.g. the synthetic
  /// operator's notice that the data is not human.
  std::vector<std::string> notes;
  /// The file the frames came from (for messages), and where in it they are ("lines 3-13502").
  std::string source;
  std::string dataLocation;

  int frameCount() const { return static_cast<int>(frames.size()); }
};

}  // namespace pmdplan
