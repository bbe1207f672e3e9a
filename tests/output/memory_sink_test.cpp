#include "output/memory_sink.hpp"

#include <gtest/gtest.h>

#include "output/test_support.hpp"

namespace collide::output {
namespace {

TEST(MemorySinkTest, KeepsUprightCopiesOfEveryFrame) {
  MemorySink sink;
  const FrameFormat format{20, 10, 24};
  sink.begin(format);
  EXPECT_TRUE(sink.begun());
  const core::Image first = test::makeFrame(20, 10, 0);
  const core::Image second = test::makeFrame(20, 10, 1);
  std::vector<std::uint8_t> storage;
  sink.write(first.view());
  sink.write(test::bottomUpView(second, storage));
  storage.assign(storage.size(), 0);  // the sink must have copied, not referenced
  sink.finish();

  EXPECT_TRUE(sink.finished());
  EXPECT_EQ(sink.format().fps, 24);
  ASSERT_EQ(sink.frames().size(), 2u);
  EXPECT_EQ(test::maxChannelDifference(sink.frames()[0], first), 0);
  EXPECT_EQ(test::maxChannelDifference(sink.frames()[1], second), 0);
}

}  // namespace
}  // namespace collide::output
