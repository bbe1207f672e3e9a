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

// A lesson renders its video too (twice: MP4 and WebM).
bool hasVideo(const JobSettings& settings) {
  const auto has = [&](BatchFormat format) {
    return std::find(settings.formats.begin(), settings.formats.end(), format) !=
           settings.formats.end();
  };
  return has(BatchFormat::kMp4) || has(BatchFormat::kLesson);
}

}  // namespace

std::vector<JobShape> jobShapes(const std::vector<BatchJob>& jobs, const JobSettings& settings) {
  std::vector<JobShape> shapes(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    try {
      const scene::SceneDesc scene = scene::loadScene(jobs[i].scene, jobs[i].overrides);
      shapes[i] = {true, settings.duration_s.value_or(scene.duration_s), scene.bodies.size(),
                   scene.dimensions};
    } catch (const core::Error&) {
      shapes[i] = JobShape{};
    }
  }
  return shapes;
}

double estimatedWork(const JobShape& shape, const JobSettings& settings) {
  if (!shape.loaded) return 0.0;
  const double frames = hasVideo(settings) ? std::max(1.0, shape.duration_s * settings.fps) : 1.0;
  return frames * (1.0 + static_cast<double>(shape.bodies) / kBodiesPerJob);
}

double estimatedWork(const BatchJob& job, const JobSettings& settings) {
  return estimatedWork(jobShapes({job}, settings).front(), settings);
}

std::vector<std::size_t> longestFirst(const std::vector<JobShape>& shapes,
                                      const JobSettings& settings) {
  std::vector<double> work(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) work[i] = estimatedWork(shapes[i], settings);
  std::vector<std::size_t> order(shapes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
  return order;
}

std::vector<std::size_t> longestFirst(const std::vector<BatchJob>& jobs,
                                      const JobSettings& settings) {
  return longestFirst(jobShapes(jobs, settings), settings);
}

}  // namespace collide::app
