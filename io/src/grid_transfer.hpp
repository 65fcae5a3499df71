// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: a parsed vtkUnstructuredGrid handed from the worker process that
// parsed it to the caller, so that the caller does not parse the file again.
// The worker writes the grid's arrays (points, cell arrays, point, cell and
// field data: plain data arrays and string arrays, with names, value types,
// component and tuple counts) to a memory file; the caller rebuilds the grid
// from those bytes, checking every count and size against what it holds.

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace tessella::io::detail {

/// Writes `grid` to the file `fd` (from its current position). False, with
/// the bytes written so far meaningless, when the grid holds an array that
/// cannot be sent (a bit array, an array of another layout) or a write fails.
bool sendGrid(vtkUnstructuredGrid* grid, int fd);

/// The grid sendGrid wrote to `fd` (read from its start), or nullptr when the
/// bytes are not one (too short, a count or a type that makes no sense).
vtkSmartPointer<vtkUnstructuredGrid> receiveGrid(int fd);

}  // namespace tessella::io::detail
