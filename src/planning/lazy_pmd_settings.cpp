#include "pmdplan/planning/lazy_pmd_settings.hpp"

#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {

void LazyPmdSettings::check() const {
  if (batch > 1'000'000) throw InputError("", "lazy-batch", "must be a whole number of arm boxes from 0 to 1000000");
  if (neighbours < 1) throw InputError("", "lazy-neighbours", "must be a whole number >= 1");
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError("", "lazy-radius",
                     "must be a positive, finite factor of the start-goal distance, got " + messageNumberText(radius));
  if (probes > 64) throw InputError("", "lazy-probes", "must be a whole number from 0 to 64");
  if (!(armGrowth >= 1.0) || !std::isfinite(armGrowth))
    throw InputError("", "lazy-arm-growth", "must be a finite factor >= 1, got " + messageNumberText(armGrowth));
}

}  // namespace pmdplan
