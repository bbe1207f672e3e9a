// What the process keeps at its end (output/process_end.hpp). Its own binary: the declarations last
// for the whole process, and no other test may run after them.
#include "output/process_end.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace collide::app {
namespace {

// Counts its own destruction, as a renderer's teardown would run.
std::shared_ptr<void> drawer(int& destroyed) {
  return std::shared_ptr<void>(new int(0), [&destroyed](void* object) {
    ++destroyed;
    delete static_cast<int*>(object);
  });
}

// A test calling runCli(), and batch, draw many pictures in one process: each drawer goes once its
// picture is written. Only the program drawing its one picture keeps it (and ends at once), except
// in the sanitizer build, whose leak check must see the teardown.
TEST(ProcessEndTest, OnlyTheProgramsOnePictureKeepsItsDrawer) {
  int destroyed = 0;
  output::keepForProcessEnd(drawer(destroyed));  // nothing declared: a test, or batch
  EXPECT_EQ(destroyed, 1);
  EXPECT_FALSE(output::keepsForProcessEnd());

  output::declareOnePictureProcess();  // `still` run in-process by a test
  output::keepForProcessEnd(drawer(destroyed));
  EXPECT_EQ(destroyed, 2);
  EXPECT_FALSE(output::keepsForProcessEnd());

  output::declareProgramProcess();  // main() of the program
  if (output::kLeaksCheckedAtExit) {
    EXPECT_FALSE(output::keepsForProcessEnd());
    output::keepForProcessEnd(drawer(destroyed));
    EXPECT_EQ(destroyed, 3);
  } else {
    EXPECT_TRUE(output::keepsForProcessEnd());
    output::keepForProcessEnd(drawer(destroyed));
    EXPECT_EQ(destroyed, 2);  // kept, never destroyed: the process would end now (endIfKept)
  }
}

}  // namespace
}  // namespace collide::app
