// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Tissue snapshots as VTK XML unstructured grids (.vtu), through the VTK library.
//
// 2D cells are written as VTK polygons (with 3D points for surface tissues),
// 3D cells as VTK polyhedra with their faces given, outward. Only live cells
// are written, with the live vertices numbered compactly. Every registered
// cell property becomes cell data under its own name, every vertex property
// point data, plus the derived `area` (2D) or `volume` (3D). Data are binary,
// appended, compressed as chosen. Field data record the tissue's dimension,
// embedding and time, so that reading back restores them. docs/output.md
// lists every array and the types that can be written.

#include <map>
#include <string>
#include <vector>

#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/properties.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {
struct GeometryCache;  // tessella/tissue/geometry.hpp
}

namespace tessella::io {

enum class Compression { None, LZ4, ZLib };

/// "none", "lz4", "zlib": the names config keys, the CLI and Python use.
const EnumTable<Compression>& compressions();
/// A name of compressions(), in any case; InputError naming the value otherwise.
Compression parseCompression(const std::string& name);
const char* compressionName(Compression c);

struct VtuOptions {
  /// LZ4 by default: on a 10^6-cell snapshot (bench/io_bench) it cuts the
  /// file to ~28% at ~1.6x the CPU time of no compression; zlib gets ~11%
  /// but costs ~10x (level 5) the CPU time of none.
  Compression compression = Compression::LZ4;
  /// 1 (fastest) .. 9 (smallest), as VTK's compressors define it. LZ4 speed
  /// and size barely change with it; for zlib, level 1 gave the same size as
  /// 5 at ~40% of the time on tissue data, and 9 was ~35x slower than 5.
  int compression_level = 5;
  /// Flush the file to disk (fsync) before it replaces the old one, so that
  /// even a power cut leaves a complete file. Off by default: renaming a
  /// finished temporary already protects against a killed or crashed run.
  bool durable = false;
};

/// What a run keeps beside its tissue so that a restart continues it exactly
/// (its clock, its random stream): text values by key, written as the field
/// array `tessella_run_state`. Keys must be non-empty and hold no '='.
using RunState = std::map<std::string, std::string>;

/// Writes a snapshot atomically (temporary file, then rename): a crash never
/// leaves a half-written file under `path`. Throws InputError naming the path
/// when the file cannot be written (missing directory, disk full) and when
/// options.compression_level is outside 1..9. The derived area / volume
/// comes from `geometry` when given (a cache shared with the caller, e.g. a
/// Simulation's: computed there only if stale), else is computed for the write.
void writeTissueVtu(const Tissue& tissue, const std::string& path, const VtuOptions& options = {},
                    const RunState& state = {}, GeometryCache* geometry = nullptr);

/// Reads a snapshot written by writeTissueVtu back into a tissue (topology,
/// positions, time, every cell and vertex property with its division policy
/// and default value except the built-in lineage columns, which are restored
/// as lineage). InputError on a missing or malformed file, naming the path
/// and what is wrong; also when the file crashes VTK's reader (which parses
/// it in a worker process first) or an array does not match the checksum
/// written with it (docs/output.md, "Damaged files").
Tissue readTissueVtu(const std::string& path);

/// A snapshot's tissue and the run state written with it (empty when none was).
struct Snapshot {
  Tissue tissue;
  RunState state;
};
Snapshot readSnapshot(const std::string& path);

/// Whether a property column has a type writeTissueVtu can store: arithmetic
/// types (not bool), Vec3, Eigen::Vector2d, Sym3 and Mat3.
bool isWritableProperty(const PropertyColumnBase& column);
/// Names of the columns of a store that writeTissueVtu skips (so that a
/// caller can warn about them).
std::vector<std::string> unwritableProperties(const PropertyStore& store);

}  // namespace tessella::io
