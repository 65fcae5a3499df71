// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/render/picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "tessella/render/colour_map.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::render {

namespace {

constexpr double kMargin = 12;       // pixels around the drawing
constexpr double kBarSpace = 110;    // pixels right of the drawing for the colour bar
constexpr double kTitleSpace = 26;   // pixels above the drawing for the title
// The built-in quantity `size` colours by area (2D) or volume (3D).
constexpr const char* kSizeName = "size";

struct Area {
  double x0, y0, x1, y1;
};

Area drawingArea(const PictureOptions& o) {
  const bool bar = o.colour_bar && !o.property.empty();
  return {kMargin, kMargin + (o.title.empty() ? 0 : kTitleSpace), o.width - kMargin - (bar ? kBarSpace : 0),
          o.height - kMargin};
}

// Screen axes for a view direction: u to the right, w up, both orthogonal to it.
void screenAxes(const Vec3& view, Vec3& u, Vec3& w) {
  const Vec3 up = std::abs(view.z()) < 0.9 ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  u = up.cross(view).normalized();
  w = view.cross(u);
}

// A polygon to fill: a 2D cell, or an outer wall of a 3D cell.
struct Polygon {
  CellId cell;
  std::vector<VertexId> loop;
  double depth = 0;
};

std::vector<Polygon> visiblePolygons(const Tissue& t, const View& view) {
  std::vector<Polygon> out;
  const CellComplex& k = t.topology();
  const auto add = [&](CellId c, std::span<const VertexId> loop) {
    Polygon p{c, {loop.begin(), loop.end()}, 0};
    for (VertexId v : loop) p.depth += view.depth(t.position(v));
    p.depth /= static_cast<double>(std::max<std::size_t>(loop.size(), 1));
    out.push_back(std::move(p));
  };
  if (t.dim() == 3) {
    for (FaceId f : t.faces()) {
      const auto volumes = k.faceVolumes(f);
      if (volumes.size() == 1) add(handle_cast<CellId>(volumes[0]), k.faceVertices(f));
    }
  } else {
    for (CellId c : t.cells()) add(c, k.faceVertices(t.cellFace(c)));
  }
  // Painter's order: far polygons first, so near ones cover them.
  std::stable_sort(out.begin(), out.end(), [](const Polygon& a, const Polygon& b) { return a.depth < b.depth; });
  return out;
}

template <typename T>
bool copyColumn(const PropertyColumnBase& column, std::vector<double>& out) {
  if (column.type() != typeid(T)) return false;
  const auto& values = static_cast<const PropertyColumn<T>&>(column).values();
  for (std::size_t i = 0; i < out.size() && i < values.size(); ++i) out[i] = static_cast<double>(values[i]);
  return true;
}

bool copyScalar(const PropertyColumnBase& c, std::vector<double>& out) {
  return copyColumn<double>(c, out) || copyColumn<float>(c, out) || copyColumn<std::int64_t>(c, out) ||
         copyColumn<std::int32_t>(c, out) || copyColumn<std::uint64_t>(c, out) || copyColumn<std::uint32_t>(c, out) ||
         copyColumn<std::int16_t>(c, out) || copyColumn<std::uint16_t>(c, out) || copyColumn<std::int8_t>(c, out) ||
         copyColumn<std::uint8_t>(c, out) || copyColumn<char>(c, out);
}

std::string scalarPropertyNames(const Tissue& t) {
  std::string names = kSizeName;
  std::vector<double> scratch(t.cellSlots());
  for (const auto& name : t.cellProperties().names())
    if (copyScalar(*t.cellProperties().find(name), scratch)) names += ", " + name;
  return names;
}

// "1.5", "0.000123", "1.2e+06": short labels for the colour bar.
std::string label(double x) { return formatNumber(x, 4); }

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

void drawColourBar(cairo_t* cr, const PictureOptions& o, const ColourRange& range) {
  const double x = o.width - kBarSpace + 16, w = 18;
  const Area a = drawingArea(o);
  const double y0 = a.y0 + 18, y1 = a.y1 - 8;
  cairo_pattern_t* gradient = cairo_pattern_create_linear(0, y1, 0, y0);
  for (int i = 0; i <= 16; ++i) {
    const Rgb c = viridis(i / 16.0);
    cairo_pattern_add_color_stop_rgb(gradient, i / 16.0, c[0], c[1], c[2]);
  }
  cairo_rectangle(cr, x, y0, w, y1 - y0);
  cairo_set_source(cr, gradient);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(gradient);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);

  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
  const auto text = [&](double tx, double ty, const std::string& s) {
    cairo_move_to(cr, tx, ty);
    cairo_show_text(cr, s.c_str());
  };
  text(x - 6, y0 - 6, o.property);
  text(x + w + 4, y0 + 4, label(range.high));
  text(x + w + 4, 0.5 * (y0 + y1) + 4, label(0.5 * (range.low + range.high)));
  text(x + w + 4, y1 + 4, label(range.low));
}

}  // namespace

View::View(const PictureOptions& options, double min_u, double max_u, double min_w, double max_w) {
  if (!(options.view.norm() > 0) || !options.view.allFinite())
    throw InputError("picture: the view direction must be a non-zero vector");
  if (options.width < 16 || options.height < 16)
    throw InputError("picture: the size must be at least 16 x 16 pixels, got " + std::to_string(options.width) +
                     " x " + std::to_string(options.height));
  view_ = options.view.normalized();
  screenAxes(view_, u_, w_);
  const Area a = drawingArea(options);
  const double du = std::max(max_u - min_u, 1e-300), dw = std::max(max_w - min_w, 1e-300);
  scale_ = std::min((a.x1 - a.x0) / du, (a.y1 - a.y0) / dw);
  if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
  // Centre the tissue in the drawing area.
  offset_x_ = 0.5 * (a.x0 + a.x1) - scale_ * 0.5 * (min_u + max_u);
  offset_y_ = 0.5 * (a.y0 + a.y1) + scale_ * 0.5 * (min_w + max_w);
}

std::array<double, 2> View::pixel(const Vec3& p) const {
  return {offset_x_ + scale_ * p.dot(u_), offset_y_ - scale_ * p.dot(w_)};
}

ViewExtent::ViewExtent(const Vec3& view) {
  if (!(view.norm() > 0) || !view.allFinite()) throw InputError("picture: the view direction must be a non-zero vector");
  screenAxes(view.normalized(), u_, w_);
  min_u_ = min_w_ = std::numeric_limits<double>::infinity();
  max_u_ = max_w_ = -min_u_;
}

void ViewExtent::add(const Tissue& t) {
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    min_u_ = std::min(min_u_, p.dot(u_)), max_u_ = std::max(max_u_, p.dot(u_));
    min_w_ = std::min(min_w_, p.dot(w_)), max_w_ = std::max(max_w_, p.dot(w_));
  }
}

View ViewExtent::fit(const PictureOptions& options) const {
  if (!(min_u_ <= max_u_)) return View(options, 0, 0, 0, 0);  // no vertex: an empty picture
  return View(options, min_u_, max_u_, min_w_, max_w_);
}

View fitView(const std::vector<const Tissue*>& tissues, const PictureOptions& options) {
  ViewExtent extent(options.view);
  for (const Tissue* t : tissues) extent.add(*t);
  return extent.fit(options);
}

std::vector<double> cellValues(const Tissue& tissue, const std::string& property) {
  std::vector<double> out(tissue.cellSlots(), std::numeric_limits<double>::quiet_NaN());
  const PropertyColumnBase* column = tissue.cellProperties().find(property);
  if (column) {
    if (!copyScalar(*column, out))
      throw InputError("cell property '" + property + "' is not a number per cell and cannot colour the cells " +
                       "(scalar cell properties: " + scalarPropertyNames(tissue) + ")");
  } else if (property == kSizeName) {
    for (CellId c : tissue.cells()) out[c.index()] = cellMeasure(tissue, c);
  } else {
    throw InputError("no cell property '" + property + "' (scalar cell properties: " + scalarPropertyNames(tissue) +
                     ")");
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!tissue.alive(CellId(static_cast<Index>(i)))) out[i] = std::numeric_limits<double>::quiet_NaN();
  return out;
}

std::optional<ColourRange> valueRange(const std::vector<double>& values) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (double v : values)
    if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
  if (!(low <= high)) return std::nullopt;
  if (low == high) {  // one value: centre it in the map
    const double pad = low == 0 ? 1.0 : 0.5 * std::abs(low);
    low -= pad, high += pad;
  }
  return ColourRange{low, high};
}

void writePicture(const Tissue& tissue, const View& view, const PictureOptions& options, const std::string& path) {
  std::vector<double> values;
  ColourRange range;
  if (!options.property.empty()) {
    values = cellValues(tissue, options.property);
    range = options.range ? *options.range : valueRange(values).value_or(ColourRange{});
    if (!(range.high > range.low) || !std::isfinite(range.low) || !std::isfinite(range.high))
      throw InputError("picture: the colour range must be finite with low < high, got " + formatNumber(range.low) +
                       " .. " + formatNumber(range.high));
  }
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, options.width, options.height));
  std::unique_ptr<cairo_t, ContextDeleter> context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
    throw InputError("picture: cannot draw " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                     " pixels: " + cairo_status_to_string(cairo_status(cr)));
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  const std::vector<Polygon> polygons = visiblePolygons(tissue, view);
  // Walls thin enough not to hide small cells: a tenth of a typical cell's width.
  double mean_area = 0;
  for (CellId c : tissue.cells()) mean_area += std::abs(cellMeasure(tissue, c));
  mean_area /= static_cast<double>(std::max<std::size_t>(tissue.numCells(), 1));
  const double cell_width = std::pow(mean_area, tissue.dim() == 3 ? 1.0 / 3.0 : 0.5) * view.pixelsPerUnit();
  cairo_set_line_width(cr, std::clamp(0.06 * cell_width, 0.25, 1.5));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Polygon& p : polygons) {
    for (std::size_t i = 0; i < p.loop.size(); ++i) {
      const auto [x, y] = view.pixel(tissue.position(p.loop[i]));
      i == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    Rgb fill = {0.85, 0.9, 0.8};
    if (!values.empty()) fill = viridis((values[p.cell.index()] - range.low) / (range.high - range.low));
    cairo_set_source_rgb(cr, fill[0], fill[1], fill[2]);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_stroke(cr);
  }
  if (!options.title.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 16);
    cairo_move_to(cr, kMargin, kMargin + 16);
    cairo_show_text(cr, options.title.c_str());
  }
  if (options.colour_bar && !options.property.empty()) drawColourBar(cr, options, range);
  cairo_surface_flush(surface.get());
  const cairo_status_t written = cairo_surface_write_to_png(surface.get(), path.c_str());
  if (written != CAIRO_STATUS_SUCCESS)
    throw InputError("cannot write picture '" + path + "': " + cairo_status_to_string(written));
}

}  // namespace tessella::render
