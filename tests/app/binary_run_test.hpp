#pragma once
// A fixture for tests of the real `collide` binary (COLLIDE_BINARY, defined by the test target):
// a fresh directory of the test's own, named after it and removed afterwards, and the binary run
// with its stdout and stderr in stdout.txt and stderr.txt there.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "scratch.hpp"

namespace collide::test {

class BinaryRunTest : public ::testing::Test {
 protected:
  // `prefix`: the start of the directory's name, before the test's own name.
  explicit BinaryRunTest(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    dir_ = makeUniqueTempDir(
        prefix_ + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
        "_");
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs the binary with `args`, stdout and stderr into files; returns the exit status (124 when
  // it ran for more than 5 minutes and was killed).
  int collide(const std::string& args) {
    const std::string command = shellQuoted(COLLIDE_BINARY) + " " + args + " >" +
                                shellQuoted((dir_ / "stdout.txt").string()) + " 2>" +
                                shellQuoted((dir_ / "stderr.txt").string());
    return runShellBounded(command);
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace collide::test
