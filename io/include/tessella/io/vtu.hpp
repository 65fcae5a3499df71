#pragma once
// Tissue snapshots as VTK XML unstructured grids (.vtu), through the VTK library.
//
// 2D cells are written as VTK polygons, 3D cells as VTK polyhedra with their
// faces given. Every registered cell property becomes cell data under its
// own name, plus the derived `area` (2D) or `volume` (3D). Data are binary,
// appended, compressed as chosen.

#include <string>

#include "tessella/tissue/tissue.hpp"

namespace tessella::io {

enum class Compression { None, LZ4, ZLib };

/// Parses "none" | "lz4" | "zlib"; InputError naming the value otherwise.
Compression parseCompression(const std::string& name);
const char* compressionName(Compression c);

struct VtuOptions {
  /// LZ4 by default: zlib is 30-50x slower to write for a few % smaller files.
  Compression compression = Compression::LZ4;
};

/// Writes a snapshot atomically (temporary file, then rename): a crash never
/// leaves a half-written file under `path`.
void writeTissueVtu(const Tissue& tissue, const std::string& path, const VtuOptions& options = {});

/// Reads a snapshot written by writeTissueVtu back into a tissue (topology,
/// positions, every cell property with a Copy policy except the built-in
/// lineage columns, which are restored as lineage). InputError on a missing
/// or malformed file, naming the path and what is wrong.
Tissue readTissueVtu(const std::string& path);

}  // namespace tessella::io
