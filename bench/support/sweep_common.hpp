// What the accuracy-cost sweeps share: comma-separated number lists from the command line and the CPU
// time of the process (the cost measure on a shared machine, where wall time is not).
#pragma once

#include <sys/resource.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymech::sweeps {

// "4,2,1" -> {4, 2, 1}; anything else is an error naming the option and what is allowed.
inline std::vector<double> parse_numbers(const std::string& option, const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size())
      throw std::invalid_argument(option + " '" + text + "': '" + item +
                                  "' is not a number; allowed: numbers separated by commas, e.g. 4,2,1");
    out.push_back(x);
  }
  if (out.empty()) throw std::invalid_argument(option + " is empty; allowed: numbers separated by commas, e.g. 4,2,1");
  return out;
}

// User + system CPU seconds of this process so far.
inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace polymech::sweeps
