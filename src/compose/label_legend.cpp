// SPDX-License-Identifier: MIT
#include "compose/label_legend.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "compose/label_cost.hpp"
#include "compose/legend_placement.hpp"
#include "core/vec.hpp"

namespace collide::compose {
namespace {

// The texts of the `listed` labels.
std::vector<std::string> textsOf(const std::vector<Label>& labels,
                                 const std::vector<std::size_t>& listed) {
  std::vector<std::string> texts;
  for (std::size_t k : listed) texts.push_back(*labels[k].text);
  return texts;
}

// The widths of the `listed` labels.
std::vector<double> widthsOf(const std::vector<Label>& labels,
                             const std::vector<std::size_t>& listed) {
  std::vector<double> widths;
  for (std::size_t k : listed) widths.push_back(labels[k].size.x());
  return widths;
}

// By body, each body's mass before its readout: a mass stays listed while readouts join the
// legend and leave it (an arrow that gains or loses its room), so that it keeps its row as they
// come and go below it.
void sortByBody(const std::vector<Label>& labels, std::vector<std::size_t>& ks) {
  std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) {
    if (labels[a].body != labels[b].body) return labels[a].body < labels[b].body;
    return !labels[a].velocity && labels[b].velocity;
  });
}

// Whether label k is a readout by an arrow.
bool isArrowReadout(const std::vector<Label>& labels, const LabelScene& scene, std::size_t k) {
  return labels[k].velocity && scene.arrows[labels[k].body];
}

// A label placed by its body (and its leader) as an obstacle to the legend.
void addPlaced(const Label& label, LabelScene& scene) {
  const Box& box = label.candidates[static_cast<std::size_t>(label.chosen)];
  scene.obstacles.addText(box);
  if (label.needs_leader[static_cast<std::size_t>(label.chosen)]) {
    const Leader leader = leaderOf(label, box, scene);
    scene.obstacles.addLeader(leader.from, leader.to);
  }
}

using LegendCorners = std::optional<std::vector<core::Vec2>>;

// A legend by its bodies stands at most this many of its lines from them, and only where they
// (and their arrows) stand within this many of its widths across: bodies farther apart than
// that (two balls at either end of a throw) are no place to stand by.
constexpr double kLegendNearLines = 4.0;
constexpr double kLegendNearSpanWidths = 1.5;
// A legend whose every line stood there the frame before keeps its place while its bodies stay
// within this many lines, twice as far as it is placed: a ball thrown up from beside its legend
// line leaves it for a few frames before its label finds room by it, and a line that chased it
// would jump from place to place meanwhile.
constexpr double kLegendKeptLines = 2.0 * kLegendNearLines;

// The search for a legend's place, step by step, each tried only where the one before found
// none (`at_` empty).
class LegendListing {
 public:
  LegendListing(std::vector<Label>& labels, LabelScene& scene, LabelArrangement& arrangement,
                const PanelText& text, std::vector<bool>& gives_way,
                std::vector<std::size_t> listed)
      : labels_(labels),
        scene_(scene),
        arrangement_(arrangement),
        text_(text),
        gives_way_(gives_way),
        without_labels_(scene.obstacles),
        listed_(std::move(listed)) {}

  // Only where the frame before listed them (keptPlace); false, and nothing changed, where not.
  bool listKept() {
    const Obstacles with_labels = scene_.obstacles;
    keepPlaced(listed_);
    at_ = keptPlace(listed_, widthsOf(labels_, listed_));
    if (!at_) {
      scene_.obstacles = with_labels;
      return false;
    }
    write();
    return true;
  }

  void list() {
    keepPlaced(listed_);
    at_ = place(listed_);
    // A printed figure's 1D scene keeps lines above its arrows for a legend of all its labels
    // (frame::printLabelLines): where the masses that gave way find no line left beside the
    // readouts, the readouts join them there, as those lines were measured.
    if (!at_ && !text_.panel.two_d && text_.where.label_lines_below == 0) withEveryReadout();
    if (!at_) legendFirst();
    if (!at_) fewerListed();
    if (at_) {
      write();
    } else {
      writeWrapped();
    }
  }

 private:
  // The labels placed by their bodies, but for `except`, as obstacles to the legend.
  void keepPlaced(const std::vector<std::size_t>& except) {
    scene_.obstacles = without_labels_;
    for (std::size_t k = 0; k < labels_.size(); ++k) {
      const Label& label = labels_[k];
      if (label.chosen < 0 || std::find(except.begin(), except.end(), k) != except.end()) continue;
      addPlaced(label, scene_);
    }
  }

  // Where the frame before listed them (riding with the body it stood by) where that is free,
  // else by the bodies it names (and the arrows of the readouts it lists) where they stand
  // together and it has room there, else in the scene's free corner; by_ says which body it
  // stands by (-1: none).
  LegendCorners place(const std::vector<std::size_t>& listed) {
    by_ = -1;
    if (listed.empty()) return std::nullopt;
    const std::vector<double> widths = widthsOf(labels_, listed);
    if (LegendCorners kept = keptPlace(listed, widths)) return kept;
    Box near = scene_.obstacles.bodies()[labels_[listed.front()].body].bounds;
    const auto take = [&near](const core::Vec2& p) {
      near = {std::min(near.x0, p.x()), std::min(near.y0, p.y()), std::max(near.x1, p.x()),
              std::max(near.y1, p.y())};
    };
    bool arrows = false;  // it lists a readout by an arrow
    for (std::size_t k : listed) {
      const Box& body = scene_.obstacles.bodies()[labels_[k].body].bounds;
      take({body.x0, body.y0});
      take({body.x1, body.y1});
      const auto& arrow = scene_.arrows[labels_[k].body];
      if (labels_[k].velocity && arrow) {
        take(arrow->first);
        take(arrow->second);
        arrows = true;
      }
    }
    // Along a track, under the arrows' rows where each line stands by its own body or arrow
    // there, as keptPlace keeps it.
    LegendAccepts under_arrows_ok;
    if (arrows && !text_.panel.two_d) {
      under_arrows_ok = [&](const std::vector<core::Vec2>& at) {
        return byTheirBodies(listed, at);
      };
    }
    const double widest = *std::max_element(widths.begin(), widths.end());
    // Not in a strobe: its images and their numbers crowd the bodies' surroundings.
    if (text_.panel.ghosts.empty() && near.x1 - near.x0 <= kLegendNearSpanWidths * widest) {
      if (LegendCorners by =
              placeLegendNear(widths, scene_.obstacles, text_.layout, text_.line_px, near,
                              kLegendNearLines * text_.line_px, under_arrows_ok)) {
        by_ = static_cast<int>(labels_[listed.front()].body);
        return by;
      }
    }
    // A track's legend in rows, fewest first (a printed figure's scene keeps lines measured
    // for its legend: label_lines_below 0).
    const bool fewest_rows = !text_.panel.two_d && text_.where.label_lines_below > 0;
    return placeLegend(widths, scene_.obstacles, text_.layout, text_.line_px, SIZE_MAX,
                       fewest_rows);
  }

  // The centre of body `body`, pixels.
  core::Vec2 centreOf(int body) const {
    return scene_.obstacles.bodies()[static_cast<std::size_t>(body)].bounds.center();
  }

  // Whether a line of label k at `box` stands within `lines` of its lines of its body or its
  // arrow.
  bool byItsBody(std::size_t k, const Box& box, double lines = kLegendNearLines) const {
    const Label& label = labels_[k];
    double apart = scene_.obstacles.bodies()[label.body].distanceTo(box);
    if (const auto& arrow = scene_.arrows[label.body]) {
      apart = std::min(apart, distance(box, arrow->first, arrow->second));
    }
    return apart <= lines * text_.line_px;
  }

  // Whether each line at `at` stands within `lines` of its lines of its body or its arrow
  // (kLegendNearLines: as a legend placed by its bodies does).
  bool byTheirBodies(const std::vector<std::size_t>& listed, const std::vector<core::Vec2>& at,
                     double lines = kLegendNearLines) const {
    for (std::size_t n = 0; n < listed.size(); ++n) {
      const Label& label = labels_[listed[n]];
      const Box box{at[n].x(), at[n].y(), at[n].x() + label.size.x(), at[n].y() + text_.line_px};
      if (!byItsBody(listed[n], box, lines)) return false;
    }
    return true;
  }

  // Where the frame before listed them (LabelSlot::legend), the new ones beside them: a legend
  // by its bodies carried along by the body it stood by where that is free, else where it stood.
  LegendCorners keptPlace(const std::vector<std::size_t>& listed,
                          const std::vector<double>& widths) {
    const LegendLine* first = nullptr;
    for (std::size_t k : listed) {
      if (first == nullptr && labels_[k].wanted_legend) first = &*labels_[k].wanted_legend;
    }
    if (first == nullptr) return std::nullopt;
    const int bodies = static_cast<int>(scene_.obstacles.bodies().size());
    by_ = first->by >= 0 && first->by < bodies ? first->by : -1;
    const core::Vec2 carried = by_ >= 0 ? centreOf(by_) - first->by_px : core::Vec2{0.0, 0.0};
    for (const bool riding : {false, true}) {
      if (riding && by_ < 0) continue;
      std::vector<std::optional<KeptLine>> wanted;
      for (std::size_t k : listed) {
        const std::optional<LegendLine>& was = labels_[k].wanted_legend;
        // One legend: the lines that stood as the first one did.
        const bool with_first = was && was->by == first->by && was->by_px == first->by_px &&
                                was->first_px == first->first_px;
        const core::Vec2 moved = riding ? carried : core::Vec2{0.0, 0.0};
        wanted.push_back(with_first
                             ? std::optional<KeptLine>(KeptLine{was->px + moved, was->width_px})
                             : std::nullopt);
      }
      // A new line of a legend by its bodies goes beside the others where it too stands by its
      // own body.
      const LegendLineAccepts by_its_body = [&](std::size_t n, const Box& box) {
        return by_ < 0 || byItsBody(listed[n], box);
      };
      LegendCorners at =
          keepLegend(widths, wanted, scene_.obstacles, text_.layout, text_.line_px, by_its_body);
      const bool all_kept = std::all_of(wanted.begin(), wanted.end(),
                                        [](const auto& line) { return line.has_value(); });
      const double lines = all_kept ? kLegendKeptLines : kLegendNearLines;
      if (at && (by_ < 0 || byTheirBodies(listed, *at, lines))) return at;
    }
    by_ = -1;
    return std::nullopt;
  }

  void withEveryReadout() {
    std::vector<std::size_t> all = listed_;
    for (std::size_t k = 0; k < labels_.size(); ++k) {
      if (isArrowReadout(labels_, scene_, k) && std::find(all.begin(), all.end(), k) == all.end())
        all.push_back(k);
    }
    sortByBody(labels_, all);
    keepPlaced(all);
    at_ = place(all);
    if (at_) {
      listed_ = all;
    } else {
      keepPlaced(listed_);
    }
  }

  // No room for it among the labels placed: the legend takes its place first, and the labels by
  // their bodies look for places around it (they have more than one).
  void legendFirst() {
    const Obstacles with_labels = scene_.obstacles;
    std::vector<int> was;
    for (const Label& label : labels_) was.push_back(label.chosen);
    scene_.obstacles = without_labels_;
    at_ = place(listed_);
    if (at_) {
      for (std::size_t n = 0; n < listed_.size(); ++n) {
        const core::Vec2& corner = (*at_)[n];
        scene_.obstacles.addText({corner.x(), corner.y(), corner.x() + labels_[listed_[n]].size.x(),
                                  corner.y() + text_.line_px});
        labels_[listed_[n]].in_legend = true;
      }
      arrangement_.arrange();
      for (const Label& label : labels_) {
        if (!label.in_legend && !arrangement_.fits(label)) at_.reset();
      }
    }
    if (!at_) {
      for (std::size_t k = 0; k < labels_.size(); ++k) {
        labels_[k].chosen = was[k];
        labels_[k].in_legend = false;
      }
      scene_.obstacles = with_labels;
    }
  }

  // No room for them all: the readouts that fit by their arrows stay there, the others go to a
  // smaller legend.
  void fewerListed() {
    std::vector<std::size_t> lost;
    for (std::size_t k : listed_) {
      if (gives_way_[k]) {
        lost.push_back(k);
      } else {
        addPlaced(labels_[k], scene_);
      }
    }
    listed_ = lost;
    at_ = place(listed_);
  }

  void write() {
    for (std::size_t n = 0; n < listed_.size(); ++n) {
      Label& label = labels_[listed_[n]];
      text_.panel.legend.entries.push_back(
          {static_cast<int>(label.body), *label.text, (*at_)[n], !label.velocity});
      label.legend = LegendLine{(*at_)[n], label.size.x(), by_,
                                by_ >= 0 ? centreOf(by_) : core::Vec2{0.0, 0.0}, (*at_)[0]};
      label.chosen = -1;
      gives_way_[listed_[n]] = true;
    }
  }

  // Still no room (long translated texts in a narrow scene): one column of the texts each on two
  // lines, the second indented by an em.
  void writeWrapped() {
    const double size = text_.size_px;
    const std::optional<std::vector<WrappedText>> wrapped =
        wrapInTwo(textsOf(labels_, listed_), text_.metrics, size);
    if (!wrapped) return;
    std::vector<double> widths;
    for (const WrappedText& w : *wrapped) {
      widths.push_back(w.first_px);
      widths.push_back(size + w.second_px);
    }
    at_ = placeLegend(widths, scene_.obstacles, text_.layout, text_.line_px, 1);
    for (std::size_t n = 0; at_ && n < listed_.size(); ++n) {
      Label& label = labels_[listed_[n]];
      const int body = static_cast<int>(label.body);
      frame::ReadoutLegend& legend = text_.panel.legend;
      legend.entries.push_back({body, (*wrapped)[n].first, (*at_)[2 * n], !label.velocity});
      legend.entries.push_back(
          {body, (*wrapped)[n].second, (*at_)[2 * n + 1] + core::Vec2{size, 0.0}, !label.velocity});
      label.chosen = -1;
      gives_way_[listed_[n]] = true;
    }
  }

  std::vector<Label>& labels_;
  LabelScene& scene_;
  LabelArrangement& arrangement_;
  const PanelText& text_;
  std::vector<bool>& gives_way_;
  const Obstacles without_labels_;
  std::vector<std::size_t> listed_;
  LegendCorners at_;
  int by_ = -1;  // the body at_ rides with (-1: none)
};

}  // namespace

void listInLegend(std::vector<Label>& labels, LabelScene& scene, LabelArrangement& arrangement,
                  const PanelText& text, std::vector<bool>& gives_way, bool readout_gives_way,
                  const std::vector<bool>& staying) {
  if (std::find(staying.begin(), staying.end(), true) != staying.end()) {
    std::vector<std::size_t> listed;
    for (std::size_t k = 0; k < labels.size(); ++k) {
      if (isArrowReadout(labels, scene, k) || (gives_way[k] && !labels[k].text->empty())) {
        listed.push_back(k);
      }
    }
    sortByBody(labels, listed);
    if (LegendListing(labels, scene, arrangement, text, gives_way, listed).listKept()) return;
  }
  // An arrow's value is never lost: where a readout found no room by its arrow, every arrow's
  // readout goes into one legend in a free place of the scene (a table reads better than some
  // values by their arrows and the rest in a list), and the bodies carry their numbers. Nor is
  // a mass: a mass label with no room by its body joins the legend ("m₁ = 1.00 kg" beside the
  // block numbered 1).
  std::vector<std::size_t> listed;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const bool readout = isArrowReadout(labels, scene, k);
    if ((readout && readout_gives_way) || (gives_way[k] && !labels[k].text->empty())) {
      listed.push_back(k);
    }
  }
  sortByBody(labels, listed);
  if (listed.empty()) return;
  LegendListing(labels, scene, arrangement, text, gives_way, std::move(listed)).list();
}

}  // namespace collide::compose
