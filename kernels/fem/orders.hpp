// Orders of the hexahedral elements the kernels are instantiated for (plain data: scenes check them).
#pragma once

namespace polymech::fem {

inline constexpr int min_order = 1;
inline constexpr int max_order = 4;

}  // namespace polymech::fem
