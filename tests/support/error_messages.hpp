// Helpers for tests of bad input (scenes, meshes): temporary files, one-line edits of a valid text, a
// loader's error for a text, and the check that an error message names "<file>:<line>:" and says what
// is allowed.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace polymech::testing {

// A folder of this test's own under the temp directory, removed at the end.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("polymech_") + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

// s with the first `from` replaced by `to` (a test bug if `from` is not there).
inline std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' is not in the text";
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// 1-based line of the first occurrence of `fragment` (-1 if absent).
inline int line_of(const std::string& text, const std::string& fragment) {
  const auto at = text.find(fragment);
  return at == std::string::npos ? -1 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// The message is not empty, names "<file_name>:<line>:" (line > 0) and contains every fragment.
inline void expect_message(const std::string& msg, const std::string& file_name, int line,
                           const std::vector<std::string>& fragments) {
  ASSERT_FALSE(msg.empty()) << "the input was accepted, expected an error";
  if (line > 0) {
    const std::string escaped = std::regex_replace(file_name, std::regex(R"([.])"), R"(\.)");
    EXPECT_TRUE(std::regex_search(msg, std::regex(escaped + ":" + std::to_string(line) + ":"))) << msg;
  }
  for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "missing '" << f << "' in: " << msg;
}

// The message of the error load(path) throws for `text` written as <name> in a folder of the test's
// own ("" if it loaded).
template <class Load>
std::string error_message(const std::string& text, Load&& load, const std::string& name = "scene.toml") {
  TempDir dir;
  const auto path = dir.write(name, text);
  try {
    load(path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// load() refuses `text` with a message naming "<name>:<line>:" and containing every fragment.
template <class Load>
void expect_load_error(const std::string& text, Load&& load, int line, const std::vector<std::string>& fragments,
                       const std::string& name = "scene.toml") {
  expect_message(error_message(text, load, name), name, line, fragments);
}

}  // namespace polymech::testing
