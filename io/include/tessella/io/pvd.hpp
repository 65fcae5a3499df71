// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// ParaView collection files (.pvd): the list of a time series' datasets.
//
//   <VTKFile type="Collection" version="0.1" byte_order="LittleEndian">
//     <Collection>
//       <DataSet timestep="0.5" group="" part="0" file="tissue_000001.vtu"/>
//     </Collection>
//   </VTKFile>
//
// File names are relative to the .pvd's directory, so a series can be moved.

#include <span>
#include <string>
#include <vector>

namespace tessella::io {

struct PvdEntry {
  double time = 0.0;
  std::string file;  ///< relative to the .pvd's directory
};

/// Writes the collection atomically (temporary file, then rename); times are
/// written with 17 significant digits, so they read back exactly. InputError
/// naming the path if it cannot be written.
void writePvdFile(const std::string& path, std::span<const PvdEntry> entries, bool durable = false);

/// Parses a collection; InputError naming the path and the problem if the
/// file is missing, not XML, not a Collection, or a DataSet lacks its
/// timestep or file.
std::vector<PvdEntry> readPvdFile(const std::string& path);

}  // namespace tessella::io
