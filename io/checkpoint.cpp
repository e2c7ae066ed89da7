#include "io/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/output.hpp"

namespace polymech::io {

namespace {

constexpr char magic[8] = {'P', 'M', 'C', 'K', 'P', 'T', '0', '1'};

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
};

std::string file_name(std::int64_t step) {
  char b[48];
  std::snprintf(b, sizeof b, "checkpoint_%012lld.bin", static_cast<long long>(step));
  return b;
}

// The step of "checkpoint_<step>.bin", or -1 for any other name.
std::int64_t step_of(const std::filesystem::path& p) {
  const std::string n = p.filename().string();
  const std::string head = "checkpoint_", tail = ".bin";
  if (n.size() <= head.size() + tail.size() || n.compare(0, head.size(), head) != 0 ||
      n.compare(n.size() - tail.size(), tail.size(), tail) != 0)
    return -1;
  const std::string digits = n.substr(head.size(), n.size() - head.size() - tail.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stoll(digits);
}

void sync_path(const std::filesystem::path& p, bool directory) {
  const int fd = ::open(p.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

CheckpointStore::CheckpointStore(std::filesystem::path dir, int keep) : dir_(std::move(dir)), keep_(std::max(1, keep)) {}

std::filesystem::path CheckpointStore::write(std::int64_t step, const models::Archive& a) const {
  make_output_dir(dir_);
  const auto path = dir_ / file_name(step);
  auto part = path;
  part += ".part";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    if (!out) throw OutputError(part.string() + ": cannot open for writing");
    Fnv1a sum;
    auto put = [&](const void* p, std::size_t n) {
      out.write(static_cast<const char*>(p), static_cast<std::streamsize>(n));
      sum.add(p, n);
    };
    auto put_u64 = [&](std::uint64_t v) { put(&v, sizeof v); };
    put(magic, sizeof magic);
    put_u64(a.records().size());
    for (const auto& r : a.records()) {
      put_u64(r.name.size());
      put(r.name.data(), r.name.size());
      put_u64(r.bytes.size());
      put(r.bytes.data(), r.bytes.size());
    }
    out.write(reinterpret_cast<const char*>(&sum.h), sizeof sum.h);
    out.flush();
    if (!out) throw OutputError(part.string() + ": write failed (disk full?)");
  }
  sync_path(part, false);
  std::error_code ec;
  std::filesystem::rename(part, path, ec);
  if (ec) throw OutputError(path.string() + ": cannot rename the checkpoint into place (" + ec.message() + ")");
  sync_path(dir_, true);
  auto all = files();
  for (std::size_t k = 0; k + static_cast<std::size_t>(keep_) < all.size(); ++k) std::filesystem::remove(all[k], ec);
  return path;
}

std::vector<std::filesystem::path> CheckpointStore::files() const {
  std::vector<std::pair<std::int64_t, std::filesystem::path>> found;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec)) return {};
  for (const auto& e : std::filesystem::directory_iterator(dir_, ec)) {
    const std::int64_t s = step_of(e.path());
    if (s >= 0 && e.is_regular_file()) found.emplace_back(s, e.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::filesystem::path> out;
  for (auto& f : found) out.push_back(f.second);
  return out;
}

models::Archive CheckpointStore::read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::vector<char> data(static_cast<std::size_t>(in.tellg()));
  in.seekg(0);
  if (!in.read(data.data(), static_cast<std::streamsize>(data.size())))
    throw std::runtime_error(file.string() + ": cannot read");
  const std::size_t n = data.size();
  if (n < sizeof magic + 16 || std::memcmp(data.data(), magic, sizeof magic) != 0)
    throw std::runtime_error(file.string() + ": not a polymech checkpoint (or cut short)");
  Fnv1a sum;
  sum.add(data.data(), n - 8);
  std::uint64_t stored;
  std::memcpy(&stored, data.data() + n - 8, 8);
  if (stored != sum.h) throw std::runtime_error(file.string() + ": checksum mismatch (damaged or cut short)");
  std::size_t pos = sizeof magic;
  auto take_u64 = [&]() {
    if (pos + 8 > n - 8) throw std::runtime_error(file.string() + ": truncated record table");
    std::uint64_t v;
    std::memcpy(&v, data.data() + pos, 8);
    pos += 8;
    return v;
  };
  models::Archive a;
  const std::uint64_t count = take_u64();
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t ln = take_u64();
    if (ln > n - 8 - pos) throw std::runtime_error(file.string() + ": truncated record name");
    std::string name(data.data() + pos, ln);
    pos += ln;
    const std::uint64_t lb = take_u64();
    if (lb > n - 8 - pos) throw std::runtime_error(file.string() + ": truncated record '" + name + "'");
    a.put_bytes(name, data.data() + pos, lb);
    pos += lb;
  }
  return a;
}

std::optional<Checkpoint> CheckpointStore::latest() const {
  auto all = files();
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    try {
      Checkpoint c;
      c.archive = read(*it);
      c.file = *it;
      c.step = step_of(*it);
      return c;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "warning: skipping checkpoint %s\n", e.what());
    }
  }
  return std::nullopt;
}

void CheckpointStore::clear() const {
  std::error_code ec;
  for (const auto& f : files()) std::filesystem::remove(f, ec);
}

}  // namespace polymech::io
