// placeOutput and OutputFile on every kind of thing a path can name, in a scratch directory.
#include "output/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace collide::output {
namespace {
namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("collide_output_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputFileTest, NewAndRegularFilesAreReplacedThroughATemporaryFile) {
  EXPECT_EQ(placeOutput(dir_ / "new.json").route, OutputRoute::kReplace);
  std::ofstream(dir_ / "old.json") << "earlier";
  OutputFile file(dir_ / "old.json");
  EXPECT_EQ(file.route(), OutputRoute::kReplace);
  EXPECT_NE(file.writePath(), dir_ / "old.json");
  std::ofstream(file.writePath()) << "new";
  // Written through the held directory (output/temp_file.hpp): a hidden file beside the target.
  EXPECT_TRUE(fs::exists(dir_ / file.writePath().filename()));
  EXPECT_EQ(file.writePath().filename().string().front(), '.');
  file.commit();
  std::ifstream in(dir_ / "old.json");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "new");
}

TEST_F(OutputFileTest, AnUncommittedFileLeavesTheTargetAndNoTemporary) {
  std::ofstream(dir_ / "kept.json") << "earlier";
  {
    OutputFile file(dir_ / "kept.json");
    std::ofstream(file.writePath()) << "half";
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(OutputFileTest, ALinkIsFollowedToTheFileItNames) {
  fs::create_directories(dir_ / "real");
  std::ofstream(dir_ / "real" / "x.json") << "earlier";
  fs::create_symlink("real/x.json", dir_ / "link.json");
  const OutputPlace place = placeOutput(dir_ / "link.json");
  EXPECT_EQ(place.route, OutputRoute::kReplace);
  EXPECT_EQ(place.path, fs::canonical(dir_ / "real" / "x.json"));
  // A dangling link: the file it names is created, in the directory the link points into.
  fs::create_symlink("real/new.json", dir_ / "dangling.json");
  const OutputPlace dangling = placeOutput(dir_ / "dangling.json");
  EXPECT_EQ(dangling.route, OutputRoute::kReplace);
  EXPECT_EQ(dangling.path, dir_ / "real" / "new.json");
}

TEST_F(OutputFileTest, FifosAreWrittenInPlaceAndNeverRemoved) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  {
    OutputFile file(dir_ / "pipe");
    EXPECT_EQ(file.route(), OutputRoute::kInPlace);
    EXPECT_EQ(file.writePath(), dir_ / "pipe");
    EXPECT_TRUE(file.streamed());
  }  // destroyed uncommitted: a FIFO is not ours to remove
  EXPECT_TRUE(fs::is_fifo(dir_ / "pipe"));
}

TEST_F(OutputFileTest, DirectoriesAndLinkLoopsAreRefused) {
  fs::create_directories(dir_ / "d");
  EXPECT_EQ(placeOutput(dir_ / "d").route, OutputRoute::kRefused);
  EXPECT_EQ(placeOutput(dir_ / "d").what, "a directory");
  EXPECT_THROW(OutputFile{dir_ / "d"}, core::InputError);
  fs::create_symlink("loop", dir_ / "loop");
  EXPECT_EQ(placeOutput(dir_ / "loop").route, OutputRoute::kRefused);
  fs::create_symlink("missing/x.json", dir_ / "nowhere.json");
  EXPECT_EQ(placeOutput(dir_ / "nowhere.json").route, OutputRoute::kRefused);
}

TEST_F(OutputFileTest, DashIsStdout) {
  EXPECT_EQ(placeOutput("-").route, OutputRoute::kStdout);
}

}  // namespace
}  // namespace collide::output
