// Checkpoints on disk: an Archive (models/common/archive.hpp) written as one file
// "<dir>/checkpoint_<step>.bin", atomically (written under ".part", flushed to the disk, renamed), the
// newest `keep` of them kept. Reading takes the newest file that is whole (length and checksum
// checked) and falls back to the one before when the newest is damaged.
//
// Layout: 8-byte magic "PMCKPT01", record count, then per record the name's length and bytes, the
// value's length and bytes (all lengths uint64, little-endian as the machine writes them), and last
// an FNV-1a 64-bit checksum of everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/archive.hpp"

namespace polymech::io {

struct Checkpoint {
  std::filesystem::path file;
  std::int64_t step = -1;
  models::Archive archive;
};

class CheckpointStore {
 public:
  explicit CheckpointStore(std::filesystem::path dir, int keep = 2);

  const std::filesystem::path& dir() const { return dir_; }
  // Writes the archive as the checkpoint of `step`, then removes all but the newest `keep`. Returns
  // the file written; a failure (disk full) is an OutputError and leaves the older checkpoints.
  std::filesystem::path write(std::int64_t step, const models::Archive& a) const;
  // The checkpoint files present, oldest first (whole or not).
  std::vector<std::filesystem::path> files() const;
  // The newest whole checkpoint; nothing when there is none. Damaged files are reported on stderr
  // and skipped.
  std::optional<Checkpoint> latest() const;
  // Removes every checkpoint file (a run that finished keeps none unless asked).
  void clear() const;

  static models::Archive read(const std::filesystem::path& file);  // throws std::runtime_error if damaged

 private:
  std::filesystem::path dir_;
  int keep_;
};

}  // namespace polymech::io
