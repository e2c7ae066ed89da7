// Result files: every file is written under "<name>.part" and renamed when complete, so a killed run
// never leaves a half-written file under a name that looks whole; a writer destroyed before it
// finished (an exception) removes its part file.
//
//  - AtomicFile / write_text_file: any text file (CSV, JSON, XDMF);
//  - write_csv: named columns of numbers;
//  - write_json: summary.json and friends;
//  - SnapshotWriter: HDF5 snapshots of point or mesh fields with an XDMF index that ParaView opens.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/archive.hpp"

namespace polymech::io {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Create a folder (and parents) for results, with a clear error when that is impossible.
void make_output_dir(const std::filesystem::path& dir);

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& part_path() const { return part_; }
  // Flush, close and rename to the final name; errors (disk full) are OutputErrors.
  void commit();

 private:
  std::filesystem::path path_, part_;
  std::ofstream out_;
  bool committed_ = false;
};

void write_text_file(const std::filesystem::path& path, const std::string& text);
void write_json(const std::filesystem::path& path, const nlohmann::json& j);

// Columns of equal length under a header row; numbers with 17 significant digits.
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& columns);

// A field on the points of a snapshot: `components` values per point (1: scalar, 2 or 3: vector).
struct SnapshotField {
  std::string name;
  int components = 1;
  std::vector<double> values;  // points x components, row-major
};

// Named argument types: nvcc 11.8 mis-parses nested braced lists passed straight to these functions
// from function templates (docs/DEVELOPING.md, CUDA pitfalls); callers build a Columns / Fields first.
using Columns = std::vector<std::vector<double>>;
using Fields = std::vector<SnapshotField>;

// The geometry every snapshot shares: points and, for meshes, cells of one type.
struct SnapshotMesh {
  int dim = 2;                    // 2 or 3 coordinates per point
  std::vector<double> points;     // n x dim
  std::string cell_type = "Polyvertex";  // XDMF topology: Polyvertex (particles), Quadrilateral, Hexahedron
  int nodes_per_cell = 1;
  std::vector<std::int64_t> cells;  // n_cells x nodes_per_cell (empty for Polyvertex)
  std::int64_t point_count() const { return static_cast<std::int64_t>(points.size()) / dim; }
};

// HDF5 file "<stem>.h5" with /mesh/points, /mesh/cells and /step_<n>/<field> per snapshot, plus
// "<stem>.xdmf", a temporal collection over the snapshots. Fields are stored as float32 unless
// double_precision is set (results are read by eye and by plots; float keeps 2e6-particle snapshots
// small).
//
// Checkpoints: save() closes the open HDF5 file as a sealed segment "<stem>.seg<k>.h5.part" (never
// written again, so a kill after it cannot damage what the checkpoint points to) and records the
// snapshots so far; resume() on a new writer continues from such a record, dropping any segment
// sealed after it. finish() merges the segments into "<stem>.h5".
class SnapshotWriter {
 public:
  SnapshotWriter(const std::filesystem::path& dir, const std::string& stem, SnapshotMesh mesh,
                 bool double_precision = false);
  ~SnapshotWriter();
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  void add(std::int64_t step, double time, const std::vector<SnapshotField>& fields);
  // Close, rename the HDF5 file, write the XDMF index. Returns the XDMF path.
  std::filesystem::path finish();
  std::size_t snapshots() const { return steps_.size(); }

  // For a checkpoint: seal the open segment and put what was written under "<prefix>...".
  void save(models::Archive& a, const std::string& prefix = "snapshots/");
  // Continue from a checkpoint's record (on a writer just constructed for the same mesh).
  void resume(const models::Archive& a, const std::string& prefix = "snapshots/");

 private:
  struct Written {
    std::int64_t step;
    double time;
    std::vector<std::pair<std::string, int>> fields;  // name, components
    int segment = 0;                                  // the HDF5 file it is in
  };
  std::filesystem::path segment_path(int k) const;
  void open_segment(bool with_mesh);
  std::filesystem::path dir_, h5_, h5_part_, xdmf_;
  std::string stem_;
  int sealed_ = 0;  // segments sealed so far; the open file is segment `sealed_`
  SnapshotMesh mesh_;
  bool double_;
  std::int64_t file_ = -1;  // hid_t
  std::vector<Written> steps_;
  bool finished_ = false;
};

}  // namespace polymech::io
