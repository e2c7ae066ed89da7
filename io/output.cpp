#include "io/output.hpp"

#include <hdf5.h>

#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>

namespace polymech::io {

void make_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw OutputError(dir.string() + ": cannot create the output folder (" + ec.message() + ")");
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  part_ = path_;
  part_ += ".part";
  out_.open(part_, std::ios::out | std::ios::trunc);
  if (!out_) throw OutputError(part_.string() + ": cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(part_, ec);
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw OutputError(part_.string() + ": write failed (disk full?)");
  std::error_code ec;
  std::filesystem::rename(part_, path_, ec);
  if (ec) throw OutputError(path_.string() + ": cannot rename the finished file into place (" + ec.message() + ")");
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

void write_json(const std::filesystem::path& path, const nlohmann::json& j) { write_text_file(path, j.dump(2) + "\n"); }

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& columns) {
  if (header.size() != columns.size()) throw OutputError(path.string() + ": CSV header and columns disagree");
  std::size_t rows = columns.empty() ? 0 : columns[0].size();
  for (const auto& c : columns)
    if (c.size() != rows) throw OutputError(path.string() + ": CSV columns of different lengths");
  AtomicFile f(path);
  auto& o = f.stream();
  for (std::size_t k = 0; k < header.size(); ++k) o << (k ? "," : "") << header[k];
  o << '\n' << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t k = 0; k < columns.size(); ++k) o << (k ? "," : "") << columns[k][r];
    o << '\n';
  }
  f.commit();
}

// --- HDF5 + XDMF ------------------------------------------------------------------------------------

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw OutputError("HDF5: " + what + " failed");
}

// Write an n x cols dataset (cols == 1: 1D) of doubles as `file_type`.
void write_dataset(hid_t loc, const std::string& name, const double* data, hsize_t n, hsize_t cols, hid_t file_type) {
  const hsize_t dims[2] = {n, cols};
  const int rank = cols == 1 ? 1 : 2;
  hid_t space = H5Screate_simple(rank, dims, nullptr);
  hid_t set = H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) {
    H5Sclose(space);
    throw OutputError("HDF5: cannot create dataset " + name);
  }
  const herr_t st = H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(set);
  H5Sclose(space);
  check(st, "writing " + name);
}

void write_dataset_i64(hid_t loc, const std::string& name, const std::int64_t* data, hsize_t n, hsize_t cols) {
  const hsize_t dims[2] = {n, cols};
  hid_t space = H5Screate_simple(2, dims, nullptr);
  hid_t set = H5Dcreate2(loc, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) {
    H5Sclose(space);
    throw OutputError("HDF5: cannot create dataset " + name);
  }
  const herr_t st = H5Dwrite(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(set);
  H5Sclose(space);
  check(st, "writing " + name);
}

std::string step_group(std::int64_t step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "step_%08lld", static_cast<long long>(step));
  return buf;
}

}  // namespace

SnapshotWriter::SnapshotWriter(const std::filesystem::path& dir, const std::string& stem, SnapshotMesh mesh,
                               bool double_precision)
    : dir_(dir), mesh_(std::move(mesh)), double_(double_precision) {
  if (mesh_.dim != 2 && mesh_.dim != 3) throw OutputError("SnapshotWriter: dim must be 2 or 3");
  make_output_dir(dir_);
  stem_ = stem;
  h5_ = dir_ / (stem + ".h5");
  h5_part_ = dir_ / (stem + ".h5.part");
  xdmf_ = dir_ / (stem + ".xdmf");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become OutputErrors, not stderr dumps
  open_segment(true);
}

std::filesystem::path SnapshotWriter::segment_path(int k) const {
  char b[32];
  std::snprintf(b, sizeof b, ".seg%04d.h5.part", k);
  return dir_ / (stem_ + b);
}

void SnapshotWriter::open_segment(bool with_mesh) {
  file_ = H5Fcreate(h5_part_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw OutputError(h5_part_.string() + ": cannot create HDF5 file");
  if (!with_mesh) return;
  hid_t g = H5Gcreate2(file_, "mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  write_dataset(g, "points", mesh_.points.data(), static_cast<hsize_t>(mesh_.point_count()),
                static_cast<hsize_t>(mesh_.dim), H5T_IEEE_F64LE);
  if (!mesh_.cells.empty())
    write_dataset_i64(g, "cells", mesh_.cells.data(), mesh_.cells.size() / static_cast<std::size_t>(mesh_.nodes_per_cell),
                      static_cast<hsize_t>(mesh_.nodes_per_cell));
  H5Gclose(g);
}

void SnapshotWriter::save(models::Archive& a, const std::string& prefix) {
  check(H5Fclose(file_), "closing " + h5_part_.string());
  file_ = -1;
  std::error_code ec;
  std::filesystem::rename(h5_part_, segment_path(sealed_), ec);
  if (ec) throw OutputError(segment_path(sealed_).string() + ": cannot seal the snapshot segment (" + ec.message() + ")");
  ++sealed_;
  open_segment(false);
  a.put(prefix + "segments", static_cast<std::int64_t>(sealed_));
  a.put(prefix + "count", static_cast<std::uint64_t>(steps_.size()));
  std::vector<std::int64_t> steps, segments, comps;
  std::vector<double> times;
  std::string names;
  for (const auto& w : steps_) {
    steps.push_back(w.step);
    times.push_back(w.time);
    segments.push_back(w.segment);
    comps.push_back(static_cast<std::int64_t>(w.fields.size()));
    for (const auto& [n, c] : w.fields) {
      names += n + '\n';
      comps.push_back(c);
    }
  }
  a.put_vector(prefix + "steps", steps);
  a.put_vector(prefix + "times", times);
  a.put_vector(prefix + "segment_of", segments);
  a.put_vector(prefix + "components", comps);
  a.put_string(prefix + "field_names", names);
}

void SnapshotWriter::resume(const models::Archive& a, const std::string& prefix) {
  const auto sealed = a.get<std::int64_t>(prefix + "segments");
  const auto steps = a.get_vector<std::int64_t>(prefix + "steps");
  const auto times = a.get_vector<double>(prefix + "times");
  const auto segments = a.get_vector<std::int64_t>(prefix + "segment_of");
  const auto comps = a.get_vector<std::int64_t>(prefix + "components");
  const std::string names = a.get_string(prefix + "field_names");
  for (std::int64_t k = 0; k < sealed; ++k)
    if (!std::filesystem::exists(segment_path(static_cast<int>(k))))
      throw OutputError(segment_path(static_cast<int>(k)).string() +
                        ": missing (the checkpoint's snapshots are in it; was the output folder changed?)");
  std::error_code ec;
  for (int k = static_cast<int>(sealed);; ++k) {  // segments sealed after this checkpoint: redone
    if (!std::filesystem::exists(segment_path(k))) break;
    std::filesystem::remove(segment_path(k), ec);
  }
  // the open segment was created with the mesh; the mesh of the merged file comes from segment 0
  H5Fclose(file_);
  open_segment(false);
  sealed_ = static_cast<int>(sealed);
  steps_.clear();
  std::size_t c = 0, pos = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    Written w{steps[k], times[k], {}, static_cast<int>(segments[k])};
    const auto nf = comps.at(c++);
    for (std::int64_t f = 0; f < nf; ++f) {
      const auto end = names.find('\n', pos);
      w.fields.emplace_back(names.substr(pos, end - pos), static_cast<int>(comps.at(c++)));
      pos = end + 1;
    }
    steps_.push_back(std::move(w));
  }
}

SnapshotWriter::~SnapshotWriter() {
  if (finished_) return;
  if (file_ >= 0) H5Fclose(file_);
  std::error_code ec;
  std::filesystem::remove(h5_part_, ec);
}

void SnapshotWriter::add(std::int64_t step, double time, const std::vector<SnapshotField>& fields) {
  const auto n = static_cast<std::size_t>(mesh_.point_count());
  const std::string name = step_group(step);
  hid_t g = H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) throw OutputError("HDF5: cannot create group " + name + " (snapshot of this step written twice?)");
  Written w{step, time, {}};
  for (const auto& f : fields) {
    if (f.values.size() != n * static_cast<std::size_t>(f.components)) {
      H5Gclose(g);
      throw OutputError("SnapshotWriter: field '" + f.name + "' has " + std::to_string(f.values.size()) +
                        " values, expected " + std::to_string(n * static_cast<std::size_t>(f.components)));
    }
    write_dataset(g, f.name, f.values.data(), n, static_cast<hsize_t>(f.components),
                  double_ ? H5T_IEEE_F64LE : H5T_IEEE_F32LE);
    w.fields.emplace_back(f.name, f.components);
  }
  w.segment = sealed_;
  H5Gclose(g);
  H5Fflush(file_, H5F_SCOPE_LOCAL);
  steps_.push_back(std::move(w));
}

std::filesystem::path SnapshotWriter::finish() {
  check(H5Fclose(file_), "closing " + h5_part_.string());
  file_ = -1;
  std::error_code ec;
  if (sealed_ > 0) {  // merge the segments: mesh from the first, each snapshot from its own
    std::filesystem::rename(h5_part_, segment_path(sealed_), ec);
    if (ec) throw OutputError(segment_path(sealed_).string() + ": cannot rename (" + ec.message() + ")");
    hid_t out = H5Fcreate(h5_part_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (out < 0) throw OutputError(h5_part_.string() + ": cannot create HDF5 file");
    for (int k = 0; k <= sealed_; ++k) {
      const auto seg = segment_path(k);
      hid_t in = H5Fopen(seg.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      if (in < 0) {
        H5Fclose(out);
        throw OutputError(seg.string() + ": cannot open snapshot segment");
      }
      herr_t st = k == 0 ? H5Ocopy(in, "mesh", out, "mesh", H5P_DEFAULT, H5P_DEFAULT) : 0;
      for (const auto& w : steps_)
        if (w.segment == k && st >= 0) {
          const std::string g = step_group(w.step);
          st = H5Ocopy(in, g.c_str(), out, g.c_str(), H5P_DEFAULT, H5P_DEFAULT);
        }
      H5Fclose(in);
      if (st < 0) {
        H5Fclose(out);
        throw OutputError(seg.string() + ": cannot copy its snapshots into " + h5_part_.string());
      }
    }
    check(H5Fclose(out), "closing " + h5_part_.string());
  }
  std::filesystem::rename(h5_part_, h5_, ec);
  if (ec) throw OutputError(h5_.string() + ": cannot rename into place (" + ec.message() + ")");
  for (int k = 0; k <= sealed_ && sealed_ > 0; ++k) std::filesystem::remove(segment_path(k), ec);
  finished_ = true;

  const std::string h5name = h5_.filename().string();
  const auto np = mesh_.point_count();
  const std::size_t ncell = mesh_.cells.empty() ? static_cast<std::size_t>(np)
                                                : mesh_.cells.size() / static_cast<std::size_t>(mesh_.nodes_per_cell);
  const int prec = double_ ? 8 : 4;
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"snapshots\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  x << std::setprecision(17);
  for (const auto& w : steps_) {
    x << "   <Grid Name=\"" << step_group(w.step) << "\" GridType=\"Uniform\">\n";
    x << "    <Time Value=\"" << w.time << "\"/>\n";
    if (mesh_.cells.empty()) {
      x << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << np << "\" NodesPerElement=\"1\"/>\n";
    } else {
      x << "    <Topology TopologyType=\"" << mesh_.cell_type << "\" NumberOfElements=\"" << ncell << "\">\n"
        << "     <DataItem Dimensions=\"" << ncell << " " << mesh_.nodes_per_cell
        << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5name << ":/mesh/cells</DataItem>\n"
        << "    </Topology>\n";
    }
    x << "    <Geometry GeometryType=\"" << (mesh_.dim == 2 ? "XY" : "XYZ") << "\">\n"
      << "     <DataItem Dimensions=\"" << np << " " << mesh_.dim
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5name << ":/mesh/points</DataItem>\n"
      << "    </Geometry>\n";
    for (const auto& [name, comps] : w.fields) {
      const char* type = comps == 1 ? "Scalar" : "Vector";
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n"
        << "     <DataItem Dimensions=\"" << np;
      if (comps > 1) x << " " << comps;
      x << "\" NumberType=\"Float\" Precision=\"" << prec << "\" Format=\"HDF\">" << h5name << ":/"
        << step_group(w.step) << "/" << name << "</DataItem>\n    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_text_file(xdmf_, x.str());
  return xdmf_;
}

}  // namespace polymech::io
