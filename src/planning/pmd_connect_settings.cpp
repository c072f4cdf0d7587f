#include "pmdplan/planning/pmd_connect_settings.hpp"

#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {

void PmdConnectSettings::check() const {
  if (!(range > 0.0))
    throw InputError(
        "", "connect-range",
        "must be a positive factor of the start-goal distance (inf: no limit), got " + messageNumberText(range));
  if (round < 1 || round > 1'000'000)
    throw InputError("", "connect-round", "must be a whole number of samples from 1 to 1000000");
  if (probes > 64) throw InputError("", "connect-probes", "must be a whole number from 0 to 64");
  if (!(armGrowth >= 1.0) || !std::isfinite(armGrowth))
    throw InputError("", "connect-arm-growth", "must be a finite factor >= 1, got " + messageNumberText(armGrowth));
}

}  // namespace pmdplan
