#include "nosb_pd/setup.hpp"

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

double stable_time_step(const Config& c) {
  return c.dimension == 2 ? NosbPd<double, 2>::stable_time_step(c) : NosbPd<double, 3>::stable_time_step(c);
}

}  // namespace polymech::nosb_pd
