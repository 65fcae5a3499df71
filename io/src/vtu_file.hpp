// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The VTK side of every .vtu this module writes or reads: writer settings
// (appended raw binary, 64-bit headers, the chosen compressor), atomic
// replacement, and VTK errors turned into InputError.

#include <functional>
#include <string>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "tessella/io/vtu.hpp"

namespace tessella::io::detail {

/// Writes `grid` to `path` atomically; InputError naming the path on failure.
void writeGridFile(vtkUnstructuredGrid* grid, const std::string& path, const VtuOptions& options);

/// Reads an unstructured grid; InputError naming the path if it is missing,
/// not a VTK XML UnstructuredGrid file, or unreadable. VTK parses the file
/// first in a worker process, so a file that crashes VTK's reader, or makes
/// it allocate without bound or hang, is an InputError too.
vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path);

/// The same, and `check` (which throws InputError for a grid it refuses)
/// runs on the grid in the worker, which then hands the grid over: the file
/// is parsed once. (When the grid holds an array that cannot be handed over,
/// this process parses the file again and runs `check` here.)
vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path,
                                                  const std::function<void(vtkUnstructuredGrid*)>& check);

/// The same for a VTK XML PolyData (.vtp) file.
vtkSmartPointer<vtkPolyData> readPolyDataFile(const std::string& path);

/// InputError naming `path` unless what a reader walks without further
/// checks is consistent: 3D points, a type for every cell, cell offsets that
/// start at 0, never decrease and end at the connectivity's size.
void checkCellArrays(vtkUnstructuredGrid* grid, const std::string& path);

/// The same for the polygons of a PolyData: 3D points, polygon offsets that
/// start at 0, never decrease and end at the connectivity's size.
void checkPolyArrays(vtkPolyData* data, const std::string& path);

}  // namespace tessella::io::detail
