// NavierStokes2D's time-stepping state (the solution at t_n, t_n-1, t_n-2, time, last dt, step count) into a
// checkpoint and back (apps/common/restart.hpp): with it the next BDF2 step is the one a run never interrupted
// takes (the step's Newton iteration starts from it and refactorises at its first iteration: no other state).
#pragma once

#include <cstdint>
#include <string>

#include "common/archive.hpp"
#include "flow/navier_stokes.hpp"

namespace polymech::flow {

inline void save_time_state(models::Archive& a, const std::string& prefix, const NavierStokes2D::TimeState& s) {
  a.put_vector(prefix + "u", s.u);
  a.put_vector(prefix + "u_prev", s.u_prev);
  a.put_vector(prefix + "u_prev2", s.u_prev2);
  a.put(prefix + "time", s.time);
  a.put(prefix + "last_dt", s.last_dt);
  a.put(prefix + "steps", s.steps);
}

inline NavierStokes2D::TimeState load_time_state(const models::Archive& a, const std::string& prefix) {
  NavierStokes2D::TimeState s;
  s.u = a.get_vector<double>(prefix + "u");
  s.u_prev = a.get_vector<double>(prefix + "u_prev");
  s.u_prev2 = a.get_vector<double>(prefix + "u_prev2");
  s.time = a.get<double>(prefix + "time");
  s.last_dt = a.get<double>(prefix + "last_dt");
  s.steps = a.get<std::int64_t>(prefix + "steps");
  return s;
}

}  // namespace polymech::flow
