// Output: files appear only when complete (".part" while writing, removed on failure), HDF5
// snapshots read back exactly, the XDMF index points at the datasets that exist, CSV round-trips.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/output.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;

namespace {

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path d = fs::temp_directory_path() / (std::string("polymech_io_test_") + info->name());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<double> read_dataset(const fs::path& file, const std::string& name) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0);
  hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(d, 0) << name;
  hid_t space = H5Dget_space(d);
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<double> out(n);
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return out;
}

}  // namespace

TEST(Output, AtomicFileAppearsOnlyWhenCommitted) {
  const fs::path d = temp_dir();
  {
    io::AtomicFile f(d / "a.txt");
    f.stream() << "half";
    EXPECT_TRUE(fs::exists(d / "a.txt.part"));
    EXPECT_FALSE(fs::exists(d / "a.txt"));
  }  // destroyed without commit: an error path
  EXPECT_FALSE(fs::exists(d / "a.txt.part"));
  EXPECT_FALSE(fs::exists(d / "a.txt"));
  io::write_text_file(d / "b.txt", "whole\n");
  EXPECT_EQ(slurp(d / "b.txt"), "whole\n");
  EXPECT_FALSE(fs::exists(d / "b.txt.part"));
}

TEST(Output, UnwritableFolderIsAClearError) {
  try {
    io::write_text_file("/proc/polymech/x.json", "{}");
    FAIL() << "no error";
  } catch (const io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/polymech/x.json.part: cannot open for writing"), std::string::npos) << e.what();
  }
}

TEST(Output, CsvAndJson) {
  const fs::path d = temp_dir();
  io::write_csv(d / "t.csv", {"time", "value"}, {{0.0, 0.5}, {1.0, 1.0 / 3.0}});
  EXPECT_EQ(slurp(d / "t.csv"), "time,value\n0,1\n0.5,0.33333333333333331\n");
  EXPECT_THROW(io::write_csv(d / "bad.csv", {"a", "b"}, {{1.0}, {1.0, 2.0}}), io::OutputError);
  EXPECT_FALSE(fs::exists(d / "bad.csv"));
  io::write_json(d / "s.json", {{"cp", 6001.0}});
  EXPECT_NE(slurp(d / "s.json").find("\"cp\": 6001.0"), std::string::npos);
}

TEST(Output, SnapshotsReadBackAndXdmfIndexesThem) {
  const fs::path d = temp_dir();
  io::SnapshotMesh mesh;
  mesh.dim = 2;
  mesh.points = {0, 0, 1, 0, 0, 1};
  fs::path xdmf;
  {
    io::SnapshotWriter w(d, "fields", mesh, /*double_precision=*/true);
    w.add(0, 0.0, {{"u", 2, {1, 2, 3, 4, 5, 6}}, {"e", 1, {0.1, 0.2, 0.3}}});
    w.add(10, 2e-8, {{"u", 2, {6, 5, 4, 3, 2, 1}}, {"e", 1, {0.3, 0.2, 0.1}}});
    EXPECT_TRUE(fs::exists(d / "fields.h5.part"));
    EXPECT_FALSE(fs::exists(d / "fields.h5"));
    EXPECT_THROW(w.add(11, 0.0, {{"e", 1, {1.0}}}), io::OutputError);  // wrong length
    xdmf = w.finish();
  }
  EXPECT_FALSE(fs::exists(d / "fields.h5.part"));
  EXPECT_EQ(read_dataset(d / "fields.h5", "/mesh/points"), mesh.points);
  EXPECT_EQ(read_dataset(d / "fields.h5", "/step_00000010/u"), (std::vector<double>{6, 5, 4, 3, 2, 1}));
  const std::string x = slurp(xdmf);
  EXPECT_NE(x.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(x.find("<Time Value=\"2e-08\"/>"), std::string::npos);
  EXPECT_NE(x.find("fields.h5:/step_00000010/u</DataItem>"), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"3 2\""), std::string::npos);
  EXPECT_NE(x.find("GeometryType=\"XY\""), std::string::npos);
}

TEST(Output, AbandonedSnapshotWriterLeavesNothing) {
  const fs::path d = temp_dir();
  io::SnapshotMesh mesh;
  mesh.points = {0, 0, 1, 1};
  {
    io::SnapshotWriter w(d, "fields", mesh);
    w.add(0, 0.0, {{"e", 1, {1, 2}}});
  }  // an exception unwinds past the writer
  EXPECT_FALSE(fs::exists(d / "fields.h5"));
  EXPECT_FALSE(fs::exists(d / "fields.h5.part"));
  EXPECT_FALSE(fs::exists(d / "fields.xdmf"));
}
