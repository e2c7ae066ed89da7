#include "mps_elastic/setup.hpp"

#include "mps_elastic/mps_elastic.hpp"

namespace polymech::mps_elastic {

double stable_time_step(const Config& c) { return MpsElastic<double>::stable_time_step(c); }

}  // namespace polymech::mps_elastic
