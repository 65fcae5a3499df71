// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// CRC-32 checksums of the arrays of a snapshot, so that a damaged file that
// VTK still decodes (a flipped bit in a coordinate, a connectivity entry, a
// property value or an array's size) is refused instead of loaded.
//
// Every array of the grid is covered, found generically, so that an array a
// future writer adds is covered without further code: the points, the cell
// arrays (connectivity, offsets, types, and the face stream and face
// locations of polyhedra), and every point-data, cell-data and field-data
// array except the checksum list itself. Each is keyed by where it sits and
// its name ("points", "cells/offsets", "cell_data/growth",
// "field_data/TimeValue"). A checksum covers the array's tuple and component
// counts, its value type (kind and size) and its values as decoded,
// canonically: integers as 64-bit, float and double as their own bits,
// little-endian; strings as length and bytes. The integer cell arrays count
// as "integers" of any width: VTK chooses their width when it reads them.
//
// The list is the string field array kChecksumArray, one entry per array,
// sorted by key: "<8 hex digits> <key>".

#include <string>

#include <vtkUnstructuredGrid.h>

namespace tessella::io::detail {

inline constexpr const char* kChecksumArray = "tessella_checksums";

/// Adds (or replaces) the checksum list in the grid's field data. Call it
/// last, once the grid holds every array it is written with.
void addChecksums(vtkUnstructuredGrid* grid);

/// Checks every array the grid's checksum list names; files without the
/// list (older snapshots, other writers) pass. InputError naming `path` and
/// the array when an array is missing or its contents differ, or when the
/// list is malformed.
void verifyChecksums(vtkUnstructuredGrid* grid, const std::string& path);

}  // namespace tessella::io::detail
