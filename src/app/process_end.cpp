#include "app/process_end.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <utility>

namespace collide::app {
namespace {

std::atomic<bool> program_process{false};
std::atomic<bool> one_picture{false};
// Never destroyed: the process ends with it alive (std::_Exit below).
std::atomic<std::shared_ptr<void>*> kept{nullptr};

}  // namespace

void declareProgramProcess() {
  program_process = true;
}

void declareOnePictureProcess() {
  one_picture = true;
}

bool drawsOnePicture() {
  return one_picture;
}

bool keepsForProcessEnd() {
  // A leak checker must see the teardown: what it checks is then what the program frees.
  return !kLeaksCheckedAtExit && program_process && one_picture;
}

void keepForProcessEnd(std::shared_ptr<void> drawer) {
  if (!keepsForProcessEnd() || kept.load() != nullptr) return;  // `drawer` goes now
  kept = new std::shared_ptr<void>(std::move(drawer));
}

void endIfKept(int exit_code) {
  if (kept.load() == nullptr) return;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(exit_code);
}

}  // namespace collide::app
