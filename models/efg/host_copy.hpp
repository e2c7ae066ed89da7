// The EFG model's copies between host vectors and device Views (set-up and the host-side solves); the
// copies every model shares are in models/common/host_copy.hpp.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace polymech::efg::detail {

// Points (x, y) from a flat host vector with `stride` values per point (the first two are x, y).
template <class T>
VecView<T, 2> to_points(const std::vector<double>& flat, int stride, const char* label) {
  const std::size_t n = flat.size() / static_cast<std::size_t>(stride);
  VecView<T, 2> v(std::string(label), n);
  auto h = Kokkos::create_mirror_view(v);
  for (std::size_t i = 0; i < n; ++i) {
    h(i, 0) = static_cast<T>(flat[i * static_cast<std::size_t>(stride)]);
    h(i, 1) = static_cast<T>(flat[i * static_cast<std::size_t>(stride) + 1]);
  }
  Kokkos::deep_copy(v, h);
  return v;
}

// A host vector of double into v (reallocated, with `label`, when its length differs).
template <class T>
void to_device(const Eigen::VectorXd& x, View1<T>& v, const char* label) {
  if (v.extent(0) != static_cast<std::size_t>(x.size())) v = View1<T>(std::string(label), static_cast<std::size_t>(x.size()));
  auto h = Kokkos::create_mirror_view(v);
  for (Eigen::Index i = 0; i < x.size(); ++i) h(static_cast<std::size_t>(i)) = static_cast<T>(x(i));
  Kokkos::deep_copy(v, h);
}

// A host vector of double as a View1<T> (converted element by element).
template <class T>
View1<T> to_device(const std::vector<double>& x, const char* label) {
  View1<T> v(std::string(label), x.size());
  auto h = Kokkos::create_mirror_view(v);
  for (std::size_t i = 0; i < x.size(); ++i) h(i) = static_cast<T>(x[i]);
  Kokkos::deep_copy(v, h);
  return v;
}

}  // namespace polymech::efg::detail
