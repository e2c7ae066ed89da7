// Checkpoint files (io/checkpoint.hpp) and the snapshot writer's segments (io/output.hpp): records
// read back byte for byte, only the newest two kept, a damaged or cut-short newest file skipped for
// the one before, and a writer resumed from a checkpoint merges its sealed segments into one file
// holding exactly the snapshots up to the checkpoint and those written after the restart.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>

#include "io/checkpoint.hpp"
#include "io/output.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
using polymech::models::Archive;

namespace {

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path d = fs::temp_directory_path() / (std::string("polymech_checkpoint_test_") + info->name());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

Archive sample(std::int64_t step) {
  Archive a;
  a.put("step", step);
  a.put_vector("values", std::vector<double>{1.0 / 3.0, -0.0, 1e-310, static_cast<double>(step)});
  a.put_string("key", "app=test");
  a.put_columns("series", std::vector<std::vector<double>>{{1, 2}, {}, {3}});
  return a;
}

bool has_group(const fs::path& file, const std::string& g) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return false;
  const bool yes = H5Lexists(f, g.c_str(), H5P_DEFAULT) > 0;
  H5Fclose(f);
  return yes;
}

}  // namespace

TEST(Checkpoint, RecordsReadBackExactlyAndTheNewestTwoAreKept) {
  const auto dir = temp_dir();
  io::CheckpointStore store(dir / "checkpoints");
  EXPECT_FALSE(store.latest().has_value());
  for (std::int64_t s : {10, 20, 30}) store.write(s, sample(s));
  ASSERT_EQ(store.files().size(), 2u);
  const auto c = store.latest();
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->step, 30);
  EXPECT_EQ(c->archive.get<std::int64_t>("step"), 30);
  const auto v = c->archive.get_vector<double>("values");
  const auto w = sample(30).get_vector<double>("values");
  ASSERT_EQ(v.size(), w.size());
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_EQ(std::memcmp(&v[k], &w[k], sizeof(double)), 0) << k;
  EXPECT_EQ(c->archive.get_string("key"), "app=test");
  const auto cols = c->archive.get_columns<double>("series");
  ASSERT_EQ(cols.size(), 3u);
  EXPECT_EQ(cols[0], (std::vector<double>{1, 2}));
  EXPECT_TRUE(cols[1].empty());
  EXPECT_THROW(c->archive.get<int>("step"), std::runtime_error);  // 8 bytes are not an int
  EXPECT_THROW(c->archive.bytes("missing"), std::runtime_error);
  store.clear();
  EXPECT_TRUE(store.files().empty());
}

TEST(Checkpoint, ADamagedNewestFileFallsBackToTheOneBefore) {
  const auto dir = temp_dir();
  io::CheckpointStore store(dir);
  store.write(100, sample(100));
  const auto newest = store.write(200, sample(200));
  {  // one flipped byte in the middle
    std::fstream f(newest, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    f.put('\x7f');
  }
  auto c = store.latest();
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->step, 100);
  fs::resize_file(c->file, fs::file_size(c->file) / 2);  // cut short, as by a full disk
  EXPECT_FALSE(store.latest().has_value());
  EXPECT_THROW(io::CheckpointStore::read(c->file), std::runtime_error);
  // a part file (a write that was killed) is never taken for a checkpoint
  std::ofstream(dir / "checkpoint_000000000300.bin.part") << "half";
  EXPECT_EQ(store.files().size(), 2u);
}

TEST(Checkpoint, SnapshotSegmentsMergeAfterARestart) {
  const auto dir = temp_dir();
  io::SnapshotMesh mesh;
  mesh.dim = 2;
  mesh.points = {0, 0, 1, 0, 0, 1};
  auto field = [](double v) { return std::vector<io::SnapshotField>{{"u", 1, {v, v + 1, v + 2}}}; };
  Archive at_20;
  {
    io::SnapshotWriter w(dir, "fields", mesh);
    w.add(0, 0.0, field(0));
    w.add(10, 1.0, field(10));
    Archive at_10;
    w.save(at_10);  // checkpoint at step 10
    w.add(20, 2.0, field(20));
    w.save(at_20);  // checkpoint at step 20
    w.add(30, 3.0, field(30));
    // killed here: the writer is never finished (its destructor removes only the open part file)
  }
  EXPECT_TRUE(fs::exists(dir / "fields.seg0000.h5.part"));
  EXPECT_TRUE(fs::exists(dir / "fields.seg0001.h5.part"));
  EXPECT_FALSE(fs::exists(dir / "fields.h5"));
  io::SnapshotWriter w(dir, "fields", mesh);
  w.resume(at_20);
  EXPECT_EQ(w.snapshots(), 3u);
  w.add(30, 3.0, field(31));  // redone after the restart
  w.add(40, 4.0, field(40));
  w.finish();
  const auto h5 = dir / "fields.h5";
  for (const char* g : {"mesh", "step_00000000", "step_00000010", "step_00000020", "step_00000030", "step_00000040"})
    EXPECT_TRUE(has_group(h5, g)) << g;
  for (const auto& e : fs::directory_iterator(dir))  // the segments are gone once merged
    EXPECT_NE(e.path().extension(), ".part") << e.path();
  hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t d = H5Dopen2(f, "step_00000030/u", H5P_DEFAULT);
  float v[3];
  H5Dread(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
  H5Dclose(d);
  H5Fclose(f);
  EXPECT_EQ(v[0], 31.0f) << "the snapshot written after the restart, not the killed run's";
}
