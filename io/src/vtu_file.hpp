#pragma once
// The VTK side of every .vtu this module writes or reads: writer settings
// (appended raw binary, 64-bit headers, the chosen compressor), atomic
// replacement, and VTK errors turned into InputError.

#include <string>

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "tessella/io/vtu.hpp"

namespace tessella::io::detail {

/// Writes `grid` to `path` atomically; InputError naming the path on failure.
void writeGridFile(vtkUnstructuredGrid* grid, const std::string& path, const VtuOptions& options);

/// Reads an unstructured grid; InputError naming the path if it is missing,
/// not a VTK XML UnstructuredGrid file, or unreadable.
vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path);

}  // namespace tessella::io::detail
