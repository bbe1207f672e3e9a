#include "app/batch_order.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"
#include "scene/scene_io.hpp"

namespace collide::app {
namespace {

// Bodies that cost as much as the rest of a job (drawing, encoding, start-up): the fit named in
// batch_order.hpp.
constexpr double kBodiesPerJob = 70.0;

bool hasVideo(const JobSettings& settings) {
  return std::find(settings.formats.begin(), settings.formats.end(), BatchFormat::kMp4) !=
         settings.formats.end();
}

}  // namespace

double estimatedWork(const BatchJob& job, const JobSettings& settings) {
  scene::SceneDesc scene;
  try {
    scene = scene::loadScene(job.scene, job.overrides);
  } catch (const core::Error&) {
    return 0.0;
  }
  const double duration_s = settings.duration_s.value_or(scene.duration_s);
  const double frames = hasVideo(settings) ? std::max(1.0, duration_s * settings.fps) : 1.0;
  return frames * (1.0 + static_cast<double>(scene.bodies.size()) / kBodiesPerJob);
}

std::vector<std::size_t> longestFirst(const std::vector<BatchJob>& jobs,
                                      const JobSettings& settings) {
  std::vector<double> work(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) work[i] = estimatedWork(jobs[i], settings);
  std::vector<std::size_t> order(jobs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
  return order;
}

}  // namespace collide::app
