// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Pictures of a tissue as PNG files, drawn with Cairo: no ParaView, no
// display. 2D and curved tissues are drawn cell by cell with their walls; 3D
// tissues by their outer walls, seen from a chosen direction (orthographic,
// far walls drawn first). Cells are coloured by a cell property through the
// viridis map, with a colour bar.
//
//   render::PictureOptions o;
//   o.property = "auxin";
//   render::writePicture(tissue, render::fitView({&tissue}, o), o, "auxin.png");

#include <optional>
#include <string>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella::render {

/// The values a picture's colours span: `low` is the first colour of the map,
/// `high` the last.
struct ColourRange {
  double low = 0.0, high = 1.0;
};

struct PictureOptions {
  /// Cell property to colour by (any scalar type), or "" for plain cells.
  std::string property;
  int width = 800, height = 800;  ///< pixels
  /// Direction from the tissue towards the viewer (the default looks down
  /// on the xy plane, x to the right and y up).
  Vec3 view = Vec3(0, 0, 1);
  /// None: the property's own range in this picture.
  std::optional<ColourRange> range;
  bool colour_bar = true;
  /// Text at the top left ("t = 1.5"); "" for none.
  std::string title;
};

/// Where a point lands in the picture: an orthographic projection along
/// `view` onto the drawing area, fitted to the tissues it was made for with
/// one scale for both axes.
class View {
 public:
  View(const PictureOptions& options, double min_u, double max_u, double min_w, double max_w);
  /// Pixel coordinates (x to the right, y down) of a point.
  std::array<double, 2> pixel(const Vec3& p) const;
  /// Distance towards the viewer: larger is nearer.
  double depth(const Vec3& p) const { return p.dot(view_); }
  double pixelsPerUnit() const { return scale_; }

 private:
  Vec3 view_, u_, w_;
  double scale_ = 1, offset_x_ = 0, offset_y_ = 0;
};

/// The extent of tissues on the screen axes of a view direction: add the
/// frames of a series one by one, then fit one View to all of them, so the
/// frames share it and growth shows.
class ViewExtent {
 public:
  /// InputError for a zero or non-finite direction.
  explicit ViewExtent(const Vec3& view);
  void add(const Tissue& tissue);
  /// InputError for a size under 16 pixels.
  View fit(const PictureOptions& options) const;

 private:
  Vec3 u_, w_;
  double min_u_, max_u_, min_w_, max_w_;
};

/// The view that frames every tissue in `tissues` (ViewExtent over them).
View fitView(const std::vector<const Tissue*>& tissues, const PictureOptions& options);

/// The value of `property` per cell slot (NaN for dead slots), converted to
/// double from any scalar type. InputError naming the property and listing
/// the tissue's scalar cell properties when it is missing or not a scalar.
std::vector<double> cellValues(const Tissue& tissue, const std::string& property);

/// Smallest and largest finite value of `values`, widened to a non-empty
/// interval; none when there is no finite value.
std::optional<ColourRange> valueRange(const std::vector<double>& values);

/// Draws the tissue and writes the PNG. InputError naming the path when it
/// cannot be written, or the property when it cannot colour the cells.
void writePicture(const Tissue& tissue, const View& view, const PictureOptions& options, const std::string& path);

}  // namespace tessella::render
