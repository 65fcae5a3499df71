// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The frames of a whole run: one PNG per snapshot of a series, one view and
// one colour range for all of them, and a movie when ffmpeg is installed.

#include <string>
#include <vector>

#include "tessella/render/picture.hpp"

namespace tessella::render {

struct SeriesPictureOptions {
  PictureOptions picture;
  /// Every n-th snapshot (the last one always).
  int every = 1;
  /// Also encode movie.mp4 with ffmpeg, when it is on the PATH.
  bool movie = true;
};

struct SeriesPictures {
  std::vector<std::string> frames;  ///< written PNG files, in time order
  std::string movie;                ///< "" when none was made
  std::string movie_note;           ///< why not, when none was made
  ColourRange range;                ///< the one colour range of the frames
};

/// `source` is a run directory (its tissue.pvd), a .pvd file or one .vtu
/// snapshot. Frames are written to `out_dir` as frame_000000.png, ...
/// (created if missing). InputError naming the file for a missing or broken
/// series, and the property as writePicture does.
SeriesPictures writeSeriesPictures(const std::string& source, const std::string& out_dir,
                                   const SeriesPictureOptions& options);

}  // namespace tessella::render
