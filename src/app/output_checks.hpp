// SPDX-License-Identifier: MIT
#pragma once
// The files each command writes, listed before any work for output::OutputPlan (every path checked,
// none twice, none an input, none too large): the output, its side files (alt text, captions,
// LaTeX, Markdown, a batch's manifest) and, where it can be told up front, how large each will
// be about.
#include <string>
#include <vector>

#include "app/batch_order.hpp"
#include "app/batch_plan.hpp"
#include "app/batch_worker.hpp"
#include "app/picture_pipeline.hpp"
#include "app/render_pipeline.hpp"
#include "output/output_plan.hpp"

namespace collide::app {

std::vector<output::PlannedOutput> videoOutputs(const VideoRequest& request);
std::vector<output::PlannedOutput> stillOutputs(const StillRequest& request);
std::vector<output::PlannedOutput> pictureOutputs(const PictureRequest& request);

// `collide data`'s --csv table of `scene` at `step_s`, its size from its rows and columns.
output::PlannedOutput csvOutput(const std::string& path, const scene::SceneDesc& scene,
                                double step_s);

// Every file of every job (`shapes`: jobShapes of the same jobs) and the manifest.
std::vector<output::PlannedOutput> batchOutputs(const std::vector<BatchJob>& jobs,
                                                const std::vector<JobShape>& shapes,
                                                const JobSettings& settings,
                                                const std::string& manifest_path);

}  // namespace collide::app
