// A panel's readouts (heading, info line, caption, velocity scale; the energy bar between them is
// draw_bar.cpp's) and its momentum diagram inset.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "frame/mark_sizes.hpp"
#include "render/draw/draw_bar.hpp"
#include "render/draw/frame_drawing.hpp"
#include "text/text_wrap.hpp"

namespace collide::render {
namespace {

// The info line and the caption are drawn down to this share of their size where at their own
// they would cut their text or part a vector from its unit (PanelReadouts::shrunkSize).
constexpr double kShrinkFloor = frame::kTextShrinkFloor;

// A panel's readouts drawn into their places: the heading, the velocity scale, the info line and
// the caption (the energy bar between them is drawBar's). The heading and the caption start where
// the language starts reading; the info line beside the heading goes to the other end, the scale
// arrow to the caption's end.
class PanelReadouts {
 public:
  PanelReadouts(const frame::PanelModel& panel, const frame::FrameStyle& style,
                const frame::PanelLayout& where, const frame::FrameLayout& layout, Canvas& canvas)
      : panel_(panel),
        style_(style),
        where_(where),
        layout_(layout),
        canvas_(canvas),
        rtl_(style.right_to_left),
        reading_(rtl_ ? HAlign::kRight : HAlign::kLeft),
        // Heading and info on one line; not under a zero-height heading (a side column without
        // one).
        single_line_(where.heading.y0 == where.info.y0 && where.heading.height() > 0.0 &&
                     !where.info_small),
        info_lines_(std::max(1, where.info_lines)),
        caption_lines_(std::max(1, where.caption_lines)),
        heading_end_(start(where.heading)) {}

  void draw() {
    drawHeading();
    const double scale_width = drawScale();
    drawInfo();
    if (panel_.show_energy_bar) drawBar(panel_.energy_bar, style_, where_, layout_, canvas_);
    drawCaption(scale_width);
  }

 private:
  double start(const frame::PixelRect& box) const { return rtl_ ? box.x1 : box.x0; }
  double end(const frame::PixelRect& box) const { return rtl_ ? box.x0 : box.x1; }

  void drawHeading() {
    if (panel_.heading.empty()) return;
    // The heading's line: the first of the info's lines where they share the top.
    const double heading_h =
        single_line_ ? where_.heading.height() / info_lines_ : where_.heading.height();
    const std::string text =
        canvas_.painter().fitWhole(panel_.heading, layout_.text_px, where_.heading.width());
    const DrawnItemScope item(canvas_.shapes(), "heading", "title");
    heading_end_ =
        end(canvas_.text(text, {start(where_.heading), where_.heading.y0 + 0.5 * heading_h},
                         layout_.text_px, style_.text, reading_, VAlign::kMiddle));
  }

  // The velocity scale, stated once: at the right end of the caption's last line (the caption
  // gives way from its end, where it repeats the velocities written beside the arrows), at the
  // end of its own row under a side column's caption, or in a comparison grid's heading line
  // after the heading. Returns the room it takes at the caption's end, gap included.
  double drawScale() {
    if (!(panel_.scale_arrow_mps > 0.0 && panel_.arrow_m_per_mps > 0.0 &&
          !panel_.scale_arrow_label.empty())) {
      return 0.0;
    }
    const bool own_row = where_.scale_row.height() > 0.0;
    const bool scale_in_caption = where_.caption.height() > 0.0 && !own_row;
    const frame::WorldToPixel to_px = frame::panelMapping(panel_, where_, layout_);
    const frame::ArrowShape shape =
        frame::scaleArrowShape(panel_.scale_arrow_mps, panel_, layout_, to_px);
    const double label_width = canvas_.painter().width(panel_.scale_arrow_label, layout_.small_px);
    const double width = shape.length_px + layout_.gap_px + label_width;
    const frame::PixelRect row =
        own_row ? where_.scale_row
        : scale_in_caption
            ? frame::PixelRect{where_.caption.x0,
                               where_.caption.y1 - where_.caption.height() / caption_lines_,
                               where_.caption.x1, where_.caption.y1}
            : where_.heading;
    const double after_heading = panel_.heading.empty() ? 0.0 : layout_.text_px;
    const double x0 = scale_in_caption || own_row ? (rtl_ ? row.x0 : row.x1 - width)
                      : rtl_                      ? heading_end_ - after_heading - width
                                                  : heading_end_ + after_heading;
    const double mid = 0.5 * (row.y0 + row.y1);
    if (!(x0 >= row.x0 && x0 + width <= row.x1)) return 0.0;
    const DrawnItemScope item(canvas_.shapes(), "scale", "scale", -1,
                              drawnArrow({x0, mid}, {1.0, 0.0}, shape, panel_.scale_arrow_mps,
                                         panel_.arrow_m_per_mps * to_px.px_per_m));
    drawArrowShape({x0, mid}, {1.0, 0.0}, shape, style_.arrow, canvas_.shapes());
    canvas_.text(panel_.scale_arrow_label, {x0 + shape.length_px + layout_.gap_px, mid},
                 layout_.small_px, style_.text, HAlign::kLeft, VAlign::kMiddle);
    if (scale_in_caption) return width + layout_.text_px;  // frame::captionScaleRoomPx
    if (!own_row) heading_end_ = rtl_ ? x0 : x0 + width;
    return 0.0;
  }

  void drawInfo() {
    if (panel_.info.empty() || where_.info_lines <= 0) return;
    const HAlign facing = rtl_ ? HAlign::kLeft : HAlign::kRight;
    const double line_h = where_.info.height() / info_lines_;
    const double beside = rtl_ ? heading_end_ - where_.info.x0 : where_.info.x1 - heading_end_;
    // An em from the heading (or the scale arrow after it), as fitSinglePanel counted the
    // info's lines; none where nothing stands before it.
    const double after = heading_end_ == start(where_.heading) ? 0.0 : layout_.text_px;
    const double room = single_line_ ? beside - after : where_.info.width();
    const double size = infoSize(single_line_ ? layout_.text_px : layout_.small_px, room);
    // At least as many lines as the shot's widest info takes, so their number holds still.
    const std::size_t least =
        panel_.info_shot.empty()
            ? 0
            : canvas_.painter().wrap(panel_.info_shot, size, room, info_lines_).size();
    const std::vector<std::string> lines =
        canvas_.painter().wrap(panel_.info, size, room, info_lines_, panel_.info_like, least);
    const DrawnItemScope item(canvas_.shapes(), "info", "readout");
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const double mid = where_.info.y0 + (i + 0.5) * line_h;
      if (single_line_) {
        canvas_.text(lines[i], {end(where_.info), mid}, size, style_.text, facing, VAlign::kMiddle);
      } else {
        canvas_.text(lines[i], {start(where_.info), mid}, size, style_.text, reading_,
                     VAlign::kMiddle);
      }
    }
  }

  // A text's size: `size`, or where the video's widest text (`widest`: the pattern the layout
  // counts its lines from, so the size holds through the video) takes more than `lines` lines
  // (`count` of them at a size) or parts what belongs together at it (a vector and its unit,
  // "(−0.0665, −0.0358)" | "kg·m/s"; a speed and its direction), the largest whole pixel size
  // down to kShrinkFloor of it that holds it; none does: `size`, its text parted where it must
  // be (issue 37: text that does not fit is wrapped or shrunk, never cut). A printed figure's
  // text is at its floor already (its layout scale raised above the frame height).
  double shrunkSize(const std::string& widest, double size, double room, int lines,
                    const std::function<std::size_t(double px)>& count) {
    if (widest.empty() || layout_.scale_px > layout_.height_px) return size;
    const text::TextWidth measure = [this](std::string_view line, double px) {
      return canvas_.painter().width(line, px);
    };
    for (double px = size; px >= std::ceil(kShrinkFloor * size); px -= 1.0) {
      if (text::widestUnbrokenPx(widest, px, measure) <= room &&
          count(px) <= static_cast<std::size_t>(lines)) {
        return px;
      }
    }
    return size;
  }

  double infoSize(double size, double room) {
    const std::string& widest = panel_.info_pattern.empty() ? panel_.info : panel_.info_pattern;
    const text::TextWidth measure = [this](std::string_view line, double at) {
      return canvas_.painter().width(line, at);
    };
    // The widest info's lines at each size tried: counted once per video where it is kept.
    return shrunkSize(widest, size, room, info_lines_, [&](double px) {
      return panel_.info_widest ? panel_.info_widest->lines(px, room, measure)
                                : text::wrapText(widest, px, room, measure).size();
    });
  }

  // `text` in the caption's lines, broken like `like` and spread over at least `least` lines:
  // at the caption's width, or where the last line of `shape` (`text` itself, or the widest
  // caption of its shape, whose last line reaches furthest) or its own runs into the scale
  // arrow's room (`scale_width`), with that room taken from every line (captionLinesBesideScale's
  // rule, as layoutFrame counted the lines).
  std::vector<std::string> captionLines(const std::string& text, const std::string& like,
                                        const std::string& shape, std::size_t least,
                                        double scale_width) {
    TextPainter& painter = canvas_.painter();
    const double full = where_.caption.width();
    const double narrow = std::max(0.0, full - scale_width);
    // As the layout decides it (captionLinesBesideScale): on the lines the text takes by itself.
    const bool beside_scale =
        reachesScale(painter.wrap(shape, caption_px_, full, caption_lines_, shape), scale_width);
    std::vector<std::string> lines =
        painter.wrap(text, caption_px_, beside_scale ? narrow : full, caption_lines_, like, least);
    if (!beside_scale && reachesScale(lines, scale_width)) {
      lines = painter.wrap(text, caption_px_, narrow, caption_lines_, like, least);
    }
    return lines;
  }

  // Whether the caption's last line runs into the scale arrow's room at its end.
  bool reachesScale(const std::vector<std::string>& lines, double scale_width) {
    return scale_width > 0.0 && !lines.empty() &&
           canvas_.painter().width(lines.back(), caption_px_) >
               where_.caption.width() - scale_width;
  }

  // Broken like the widest caption of its shape, in at least as many lines as the shot's widest
  // caption takes, so neither its breaks nor its number of lines move while the shot plays.
  void drawCaption(double scale_width) {
    if (panel_.caption.empty() || !(where_.caption.height() > 0.0)) return;
    const std::string& widest =
        panel_.caption_pattern.empty() ? panel_.caption : panel_.caption_pattern;
    const text::TextWidth measure = [this](std::string_view line, double at) {
      return canvas_.painter().width(line, at);
    };
    // At most the lines the layout kept: the most the widest caption of any shape takes (the
    // widest among them; counted once per size), else those of the widest.
    caption_px_ = shrunkSize(
        widest, layout_.small_px, where_.caption.width(), caption_lines_, [&](double px) {
          return panel_.caption_shapes
                     ? panel_.caption_shapes->captionLines(px, where_.caption.width(), scale_width,
                                                           measure)
                     : text::captionLinesBesideScale(widest, px, where_.caption.width(),
                                                     scale_width, measure)
                           .size();
        });
    const std::string& shot = panel_.caption_shot;
    const std::size_t least =
        shot.empty() ? 0 : captionLines(shot, {}, shot, 0, scale_width).size();
    const std::string& shape = panel_.caption_like.empty() ? panel_.caption : panel_.caption_like;
    const std::vector<std::string> lines =
        captionLines(panel_.caption, panel_.caption_like, shape, least, scale_width);
    const double line_h = where_.caption.height() / caption_lines_;
    const DrawnItemScope item(canvas_.shapes(), "caption", "caption");
    for (std::size_t i = 0; i < lines.size(); ++i) {
      canvas_.text(lines[i], {start(where_.caption), where_.caption.y0 + (i + 0.5) * line_h},
                   caption_px_, style_.muted_text, reading_, VAlign::kMiddle);
    }
  }

  const frame::PanelModel& panel_;
  const frame::FrameStyle& style_;
  const frame::PanelLayout& where_;
  const frame::FrameLayout& layout_;
  Canvas& canvas_;
  const bool rtl_;
  const HAlign reading_;
  const bool single_line_;
  const int info_lines_, caption_lines_;
  double heading_end_;       // where the heading (and what follows) stops
  double caption_px_ = 0.0;  // the caption's size (shrunkSize)
};

}  // namespace

void drawPanelReadouts(const frame::PanelModel& panel, const frame::FrameStyle& style,
                       const frame::PanelLayout& where, const frame::FrameLayout& layout,
                       Canvas& canvas) {
  PanelReadouts(panel, style, where, layout, canvas).draw();
}

void drawMomentumInset(const frame::PanelModel& panel, const frame::FrameStyle& style,
                       const frame::PanelLayout& where, const frame::FrameLayout& layout,
                       Canvas& canvas) {
  // A box too small for its title and labels (a small printed figure) is left out rather than
  // drawn unreadable.
  const std::optional<frame::PixelRect> placed = frame::momentumBox(panel, where, layout);
  if (!placed) return;
  const frame::PixelRect& box = *placed;
  const frame::MomentumDiagram& diagram = *panel.momentum;
  ShapeSink& mesh = canvas.shapes();
  mesh.addRect(box, style.inset_background);
  mesh.addRectFrame(box, std::max(1.0, 0.5 * layout.bar_frame_px), style.bar_frame);
  const double size = layout.small_px, pad = 0.5 * size;
  // A translation longer than the box ("cantidad de movimiento") ends in an ellipsis.
  canvas.text(canvas.painter().elide(diagram.title, size, box.width() - 2.0 * pad),
              {box.x0 + pad, box.y0 + pad}, size, style.muted_text, HAlign::kLeft, VAlign::kTop);

  const frame::MomentumChainPlot plot = frame::momentumChainPlot(diagram, *placed, layout);
  const double shaft = 0.6 * layout.arrow_shaft_px, head_l = 0.6 * layout.arrow_head_length_px,
               head_w = 0.6 * layout.arrow_head_width_px;
  const auto toBox = [&](const core::Vec2& p) -> core::Vec2 {
    return core::Vec2{p.x(), -p.y()} * plot.px_per_Ns;
  };
  core::Vec2 sum{0.0, 0.0};
  for (const frame::MomentumArrow& arrow : diagram.arrows) sum += arrow.momentum_Ns;
  // 1D: each arrow one row lower than the last (a staircase), the sum on the bottom row.
  const std::size_t rows = diagram.arrows.size() + 1;
  const double row_step = plot.one_d ? std::min(plot.area.height() / rows, 1.2 * size) : 0.0;
  const double first_row = 0.5 * (plot.area.y0 + plot.area.y1) - 0.5 * row_step * (rows - 1);
  core::Vec2 tail = plot.start_px;
  for (std::size_t i = 0; i < diagram.arrows.size(); ++i) {
    const frame::MomentumArrow& arrow = diagram.arrows[i];
    const core::Vec2 d = toBox(arrow.momentum_Ns);
    if (plot.one_d) tail.y() = first_row + row_step * i;
    if (d.norm() > 0.5) {
      mesh.addArrow(tail, d.normalized(), d.norm(), shaft, head_l, head_w, arrow.color);
      if (!arrow.label.empty()) {
        const core::Vec2 mid = tail + 0.5 * d;
        const core::Vec2 side_dir =
            plot.one_d ? core::Vec2{0.0, -1.0} : core::Vec2{d.y(), -d.x()}.normalized();
        // Beside the arrow's middle, on the side away from it: a label left of a steep arrow
        // ends there rather than reaching back over the shaft.
        const HAlign across = side_dir.x() < -0.5  ? HAlign::kRight
                              : side_dir.x() > 0.5 ? HAlign::kLeft
                                                   : HAlign::kCenter;
        canvas.text(arrow.label, mid + (0.5 * head_w + 0.2 * size) * side_dir, size, style.text,
                    across, plot.one_d || side_dir.y() < 0 ? VAlign::kBottom : VAlign::kTop);
      }
    }
    tail += d;
  }
  const core::Vec2 sum_tail =
      plot.one_d ? core::Vec2{plot.start_px.x(), first_row + row_step * (rows - 1)} : plot.start_px;
  const core::Vec2 sum_d = toBox(sum);
  if (sum_d.norm() > 0.5) {
    mesh.addArrow(sum_tail, sum_d.normalized(), sum_d.norm(), 1.4 * shaft, head_l, head_w,
                  style.text);
  }
  const core::Vec2 side_dir = plot.one_d || sum_d.norm() <= 0.5
                                  ? core::Vec2{0.0, 1.0}
                                  : core::Vec2{-sum_d.y(), sum_d.x()}.normalized();
  canvas.text(diagram.sum_label, sum_tail + 0.5 * sum_d + (0.5 * head_w + 0.2 * size) * side_dir,
              size, style.text, HAlign::kCenter,
              side_dir.y() >= 0 ? VAlign::kTop : VAlign::kBottom);

  // Its own scale, stated: a bar of a round momentum with end ticks, its value beside it.
  if (plot.scale_bar_px > 0.0) {
    const double y = plot.scale_bar_y_px, x0 = box.x0 + pad, tick = 0.3 * size;
    const double x1 = x0 + plot.scale_bar_px;
    const double thin = std::max(1.0, 0.5 * layout.line_px);
    mesh.addLine({x0, y}, {x1, y}, thin, style.muted_text);
    for (double x : {x0, x1}) mesh.addLine({x, y - tick}, {x, y + tick}, thin, style.muted_text);
    canvas.text(canvas.painter().elide(diagram.scale_bar_label, size,
                                       std::max(0.0, box.x1 - pad - (x1 + pad))),
                {x1 + pad, y}, size, style.muted_text, HAlign::kLeft, VAlign::kMiddle);
  }
}

}  // namespace collide::render
