// Number and string formatting of the least-squares estimator's messages and reports (issue 34): printf-style
// numbers, and JSON numbers (non-finite as null) and strings. Host-only.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace polymech::estimation {

namespace detail {

inline std::string fmt(double v, const char* f = "%.6g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

inline std::string json_number(double v) { return std::isfinite(v) ? fmt(v, "%.17g") : "null"; }

inline std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      o += b;
    }
    else o += c;
  }
  return o + "\"";
}

}  // namespace detail

}  // namespace polymech::estimation
