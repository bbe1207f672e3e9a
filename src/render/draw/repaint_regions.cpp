#include "render/draw/repaint_regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "core/error.hpp"

namespace collide::render {
namespace {

// Changed quads closer than this are drawn as one region: a region costs a pass over every
// primitive (llvmpipe sets each up and culls it), a few pixels more cost little.
constexpr double kJoinGapPx = 16.0;

bool sameClip(const std::optional<frame::PixelRect>& a, const std::optional<frame::PixelRect>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->x0 == b->x0 && a->y0 == b->y0 && a->x1 == b->x1 && a->y1 == b->y1);
}

double area(const frame::PixelRect& r) {
  return r.width() * r.height();
}

frame::PixelRect unite(const frame::PixelRect& a, const frame::PixelRect& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

bool near(const frame::PixelRect& a, const frame::PixelRect& b, double gap_px) {
  return a.x0 - gap_px <= b.x1 && b.x0 - gap_px <= a.x1 && a.y0 - gap_px <= b.y1 &&
         b.y0 - gap_px <= a.y1;
}

// Collects the pixel boxes of quads (six vertices each) into a list of changed rectangles.
class ChangeList {
 public:
  ChangeList(int width_px, int height_px) : width_px_(width_px), height_px_(height_px) {}

  // The whole-pixel box of `count` vertices from `first` (a pixel is drawn only if its centre
  // lies inside a triangle; one pixel more on each side for safety).
  template <typename V>
  void addQuads(const V* first, std::size_t count) {
    for (std::size_t q = 0; q + kVerticesPerShape <= count; q += kVerticesPerShape) {
      double x0 = std::numeric_limits<double>::max(), y0 = x0;
      double x1 = std::numeric_limits<double>::lowest(), y1 = x1;
      for (std::size_t v = q; v < q + kVerticesPerShape; ++v) {
        x0 = std::min(x0, static_cast<double>(first[v].x_px));
        x1 = std::max(x1, static_cast<double>(first[v].x_px));
        y0 = std::min(y0, static_cast<double>(first[v].y_px));
        y1 = std::max(y1, static_cast<double>(first[v].y_px));
      }
      add({std::floor(x0) - 1.0, std::floor(y0) - 1.0, std::ceil(x1) + 1.0, std::ceil(y1) + 1.0});
    }
  }

  void addWholeFrame() { add({0.0, 0.0, double(width_px_), double(height_px_)}); }

  // The rectangles joined where near each other, then pairwise at the least added area until at
  // most `max_regions` remain.
  std::vector<frame::PixelRect> merged(std::size_t max_regions) {
    bool joined = true;
    while (joined) {
      joined = false;
      for (std::size_t i = 0; i < rects_.size(); ++i) {
        for (std::size_t j = i + 1; j < rects_.size();) {
          if (near(rects_[i], rects_[j], kJoinGapPx)) {
            rects_[i] = unite(rects_[i], rects_[j]);
            rects_.erase(rects_.begin() + static_cast<std::ptrdiff_t>(j));
            joined = true;
          } else {
            ++j;
          }
        }
      }
    }
    while (rects_.size() > max_regions) {
      std::size_t best_i = 0, best_j = 1;
      double best_growth = std::numeric_limits<double>::max();
      for (std::size_t i = 0; i < rects_.size(); ++i) {
        for (std::size_t j = i + 1; j < rects_.size(); ++j) {
          const double growth =
              area(unite(rects_[i], rects_[j])) - area(rects_[i]) - area(rects_[j]);
          if (growth < best_growth) best_growth = growth, best_i = i, best_j = j;
        }
      }
      rects_[best_i] = unite(rects_[best_i], rects_[best_j]);
      rects_.erase(rects_.begin() + static_cast<std::ptrdiff_t>(best_j));
    }
    return rects_;
  }

 private:
  void add(const frame::PixelRect& r) {
    const frame::PixelRect inside{std::max(r.x0, 0.0), std::max(r.y0, 0.0),
                                  std::min(r.x1, double(width_px_)),
                                  std::min(r.y1, double(height_px_))};
    if (inside.x1 > inside.x0 && inside.y1 > inside.y0) rects_.push_back(inside);
  }

  int width_px_, height_px_;
  std::vector<frame::PixelRect> rects_;
};

template <typename V>
bool sameQuad(const V* a, const V* b) {
  return std::memcmp(a, b, sizeof(V) * kVerticesPerShape) == 0;
}

// Compares one batch's run of quads (shapes or glyphs) before and now. Runs of equal length are
// compared quad by quad: only the quads that differ changed (each pixel elsewhere is covered by
// the same quads in the same order). Otherwise the quads between the longest equal beginning and
// end changed.
template <typename V>
void compareRuns(const V* before, std::size_t before_count, const V* now, std::size_t now_count,
                 ChangeList& changes) {
  const std::size_t q = kVerticesPerShape;
  if (before_count == now_count) {
    for (std::size_t i = 0; i + q <= now_count; i += q) {
      if (sameQuad(before + i, now + i)) continue;
      changes.addQuads(before + i, q);
      changes.addQuads(now + i, q);
    }
    return;
  }
  std::size_t head = 0;
  while (head + q <= std::min(before_count, now_count) && sameQuad(before + head, now + head)) {
    head += q;
  }
  std::size_t tail = 0;
  while (head + tail + q <= std::min(before_count, now_count) &&
         sameQuad(before + before_count - tail - q, now + now_count - tail - q)) {
    tail += q;
  }
  changes.addQuads(before + head, before_count - head - tail);
  changes.addQuads(now + head, now_count - head - tail);
}

}  // namespace

void CanvasRecord::keep(const MeshCanvas& canvas) {
  shapes.assign(canvas.shapeVertices().begin(), canvas.shapeVertices().end());
  text.assign(canvas.textVertices().begin(), canvas.textVertices().end());
  batches.assign(canvas.batches().begin(), canvas.batches().end());
}

std::vector<frame::PixelRect> changedRegions(const CanvasRecord& before, const MeshCanvas& now,
                                             int width_px, int height_px, std::size_t max_regions) {
  COLLIDE_ASSERT(max_regions >= 1, "changedRegions: at least one region");
  ChangeList changes(width_px, height_px);
  const std::vector<DrawBatch>& now_batches = now.batches();
  if (before.batches.size() != now_batches.size()) {
    changes.addWholeFrame();
    return changes.merged(max_regions);
  }
  for (std::size_t b = 0; b < now_batches.size(); ++b) {
    const DrawBatch& old_batch = before.batches[b];
    const DrawBatch& new_batch = now_batches[b];
    const Vertex* old_shapes = before.shapes.data() + old_batch.shape_first;
    const Vertex* new_shapes = now.shapeVertices().data() + new_batch.shape_first;
    const TextVertex* old_text = before.text.data() + old_batch.text_first;
    const TextVertex* new_text = now.textVertices().data() + new_batch.text_first;
    if (!sameClip(old_batch.clip, new_batch.clip)) {
      // Every quad of the batch may be clipped differently: all of them changed.
      changes.addQuads(old_shapes, old_batch.shape_count);
      changes.addQuads(new_shapes, new_batch.shape_count);
      changes.addQuads(old_text, old_batch.text_count);
      changes.addQuads(new_text, new_batch.text_count);
      continue;
    }
    compareRuns(old_shapes, old_batch.shape_count, new_shapes, new_batch.shape_count, changes);
    compareRuns(old_text, old_batch.text_count, new_text, new_batch.text_count, changes);
  }
  return changes.merged(max_regions);
}

}  // namespace collide::render
