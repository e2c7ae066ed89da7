// Device fields copied to the host as plain vectors of double (output, analysis), host vectors copied to
// the device (set-up), and the number format of the models' error messages.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace polymech::models {

// n x D, row-major.
template <class T, int D>
std::vector<double> to_host(const VecView<T, D>& v) {
  auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
  std::vector<double> out(static_cast<std::size_t>(D) * v.extent(0));
  for (std::size_t i = 0; i < v.extent(0); ++i)
    for (int k = 0; k < D; ++k) out[static_cast<std::size_t>(D) * i + k] = static_cast<double>(m(i, k));
  return out;
}

// An empty View (an effect that is off) gives an empty vector.
template <class T>
std::vector<double> to_host(const View1<T>& v) {
  if (v.extent(0) == 0) return {};
  auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
  return std::vector<double>(m.data(), m.data() + m.extent(0));
}

// A device View holding a host vector (set-up).
template <class V>
Kokkos::View<V*, MemSpace> to_device(const std::string& label, const std::vector<V>& host) {
  Kokkos::View<V*, MemSpace> d(label, host.size());
  auto h = Kokkos::create_mirror_view(d);
  for (std::size_t k = 0; k < host.size(); ++k) h(k) = host[k];
  Kokkos::deep_copy(d, h);
  return d;
}

// "%.4g" of a number, the form the models' messages print values in.
inline std::string format_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace polymech::models
